// fix shear/stress and shear/stress/kk: a free plate under τ, resisting forces, a plate
// pressed by fix wall/stress onto a frictional bed, restarts, KOKKOS, MPI and input errors.
#include "fix_walls_inputs.h"
#include "lammps_fixture.h"

#include "fix.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using pwtest::Accel;
using pwtest::Lammps;
using pwtest::expect_error;

namespace {

// six grains 2 apart in one layer (no contacts) in a 6 × 4 box (area 24), moving in y and z
// and spinning. τ = 0.5, M = 12: the plate's acceleration is τ L_x L_y / M = 1.
const double PLATE_ACCELERATION = 1.0;
void free_layer(Lammps &l, const std::string &integrator)
{
  l.commands("units lj\natom_style sphere\natom_modify map array\nboundary p p f\n"
             "comm_modify vel yes\nlattice sc 0.125 origin 0.5 0.5 0.5\n"
             "region box block 0 6 0 4 -4 8 units box\ncreate_box 1 box\n"
             "region layer block 0 6 0 4 0 2 units box\ncreate_atoms 1 region layer\n" +
             pwtest::unit_grains +
             "velocity all create 1.0 4321 loop geom\nvelocity all set 0 NULL NULL\n"
             "set group all omega 0.3 -0.2 0.5\n"
             "pair_style zero 1.0\npair_coeff * *\nneighbor 0.2 bin\ntimestep 0.001\n");
  l.command("fix integrate all " + integrator);
}

// two layers of the cubic stack with friction μ = 0.5: the bottom one fixed (not integrated),
// the top one (`mobile`) pressed on it by the wall at σ = 10 until settled, then sheared as
// the plate at τ. Each column's contact holds at most μσ = 5 per unit area; A/M = 1.
std::string sheared_stack_fixes(double tau, int nxy)
{
  const std::string columns = std::to_string(nxy * nxy);
  return "pair_coeff * * 1e4 1e4 0.5\ntimestep 5e-4\nfix integrate mobile nve/sphere\n"
         "fix w all wall/stress z auto stress 10 mass " +
      columns +
      " kn 1e4 damping 100\n"
      "run 2000\n"
      "fix s mobile shear/stress tau " +
      std::to_string(tau) + " mass " + columns + "\n";
}
std::string sheared_stack(double tau)
{
  return pwtest::cubic_stack(3, 3, 2, 5.0) + sheared_stack_fixes(tau, 3);
}

struct PlateRun {
  double velocity, displacement, stress;
  std::map<long, std::vector<double>> x;
};

PlateRun record(Lammps &l)
{
  return {l.equal("f_s[1]"), l.equal("f_s[2]"), l.equal("f_s[3]"), l.gather3("x")};
}

}    // namespace

TEST(FixShearStress, FreeLayerMovesAsOneRigidPlate)
{
  for (const std::string integrator : {"nve/sphere", "nve/sphere/ty3"}) {
    Lammps l;
    free_layer(l, integrator);
    l.command("fix s all shear/stress tau 0.5 mass 12");
    l.command("run 0");
    const auto x0 = l.gather3("x");
    const auto v0 = l.gather3("v");
    l.command("run 1000");
    const double t = 1.0, a = PLATE_ACCELERATION;
    // constant acceleration: both integrators are exact up to round-off (1000 steps: 1e-12)
    EXPECT_NEAR(l.equal("f_s[1]"), a * t, 1e-12) << integrator;
    EXPECT_NEAR(l.equal("f_s[2]"), 0.5 * a * t * t, 1e-12) << integrator;
    EXPECT_EQ(l.equal("f_s[3]"), 0.0) << integrator;    // nothing resists
    const auto x = l.gather3("x"), v = l.gather3("v"), omega = l.gather3("omega");
    ASSERT_EQ(x.size(), 6u);
    for (const auto &kv : x) {
      const long id = kv.first;
      EXPECT_NEAR(v.at(id)[0], a * t, 1e-12) << integrator << " grain " << id;
      EXPECT_NEAR(kv.second[0] - x0.at(id)[0], 0.5 * a * t * t, 1e-12) << id;
      EXPECT_EQ(v.at(id)[1], 0.0) << id;    // y locked
      EXPECT_EQ(kv.second[1], x0.at(id)[1]) << id;
      for (int k = 0; k < 3; k++) EXPECT_EQ(omega.at(id)[k], 0.0) << id;    // no rotation
      // vertical motion stays each grain's own
      EXPECT_NEAR(kv.second[2] - x0.at(id)[2], v0.at(id)[2] * t, 1e-12) << id;
    }
  }
}

TEST(FixShearStress, ForcesOnTheLayerResistTheShear)
{
  // fix addforce (defined before shear/stress) pulls each of the 6 grains by −0.1 in x:
  // a = (τA + ΣF_x)/M = (12 − 0.6)/12, resisting stress −ΣF_x/A = 0.6/24
  Lammps l;
  free_layer(l, "nve/sphere");
  l.command("fix drag all addforce -0.1 0.05 0.0");
  l.command("fix s all shear/stress tau 0.5 mass 12");
  l.command("run 1000");
  const double a = (12.0 - 0.6) / 12.0;
  EXPECT_NEAR(l.equal("f_s[1]"), a, 1e-12);
  EXPECT_NEAR(l.equal("f_s[2]"), 0.5 * a, 1e-12);
  EXPECT_NEAR(l.equal("f_s[3]"), 0.6 / 24.0, 1e-15);
  EXPECT_EQ(l.equal("vy[1]"), 0.0);    // the y-pull is cancelled too
}

TEST(FixShearStress, PlateSticksBelowAndSlidesAboveTheFrictionLimit)
{
  // the wall presses the plate onto the fixed layer at σ ≈ 10 per column (A/M = 1)
  const double kt = 1.0e4, mu = 0.5;
  {
    // τ = 2 < μσ: held by the undamped tangential springs (kt per column, no sliding) the
    // plate rings between 0 and 2τ/kt
    Lammps l;
    l.commands(sheared_stack(2.0));
    double worst = 0.0;
    for (int n = 0; n < 20; n++) {
      l.command("run 100");
      worst = std::max(worst, std::fabs(l.equal("f_s[2]")));
    }
    std::printf("[ report ] tau 2: max displacement %.4e (elastic bound 2tau/kt = %.4e)\n", worst,
                2 * 2.0 / kt);
    EXPECT_GT(worst, 1.5 * 2.0 / kt);
    EXPECT_LT(worst, 1.05 * 2 * 2.0 / kt);    // 5%: the springs tilt with the wall's settling
  }
  {
    // τ = 8 > μσ: the contacts slide, friction resists with at most μ f_n, so the plate
    // runs ahead of ½(τ − μσ)t²
    Lammps l;
    l.commands(sheared_stack(8.0));
    l.command("run 200");
    const double t = 0.1, sigma = l.equal("f_w[3]"), resisting = l.equal("f_s[3]");
    const double displacement = l.equal("f_s[2]");
    std::printf("[ report ] tau 8 at t = 0.1: displacement %.4e (kinetic bound %.4e), resisting "
                "stress %.4f (mu sigma = %.4f)\n",
                displacement, 0.5 * (8.0 - mu * sigma) * t * t, resisting, mu * sigma);
    EXPECT_GT(displacement, 0.5 * (8.0 - mu * sigma) * t * t);
    EXPECT_LE(resisting, mu * sigma);
    EXPECT_GT(resisting, 0.9 * mu * sigma);    // sliding, with the normals tilted by ~1°
  }
}

TEST(FixShearStress, RestartSplitRunEqualsUnsplitRun)
{
  // separate lmp processes, as users run them: within one process LAMMPS 29Sep2021 names the
  // contacts' history fix by a process-wide pair counter, so a second instance would not
  // find the frictional histories in the restart file
  const std::vector<std::string> values = {"f_s[1]", "f_s[2]", "f_s[3]"};
  for (const std::string accel : {"", "-k on t 1 -sf kk"}) {
    const std::string tag = accel.empty() ? "cpu" : "kk";
    const std::string whole = "pw_shear_whole_" + tag, split = "pw_shear_split_" + tag;
    pwtest::run_lmp(sheared_stack(3.0) + "run 1000\nwrite_restart " + split +
                        ".restart\nrun 1000\n" + pwtest::save_results(whole, values),
                    accel, whole);
    pwtest::run_lmp(
        "newton off\nread_restart " + split +
            ".restart\n"
            "comm_modify vel yes\nneighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\n"
            "fix integrate mobile nve/sphere\n"
            "fix w all wall/stress z auto stress 10 mass 9 kn 1e4 damping 100\n"
            "fix s mobile shear/stress tau 3.0 mass 9\nrun 1000\n" +
            pwtest::save_results(split, values),
        accel, split);
    ASSERT_GT(std::fabs(pwtest::read_values(whole)[1]), 1e-4) << tag;    // the plate has moved
    // same operations in the same order; the displacement carries on from the restart
    pwtest::expect_identical_results(whole, split, tag);
  }
}

TEST(FixShearStress, KokkosEqualsCpu)
{
  PlateRun run[2];
  std::string style[2];
  const Accel accel[2] = {Accel::none, Accel::kokkos};
  for (int k = 0; k < 2; k++) {
    Lammps l(accel[k]);
    l.commands(sheared_stack(3.0));
    l.command("run 2000");
    run[k] = record(l);
    style[k] = l.lmp->modify->fix[l.lmp->modify->find_fix("s")]->style;
  }
  EXPECT_EQ(style[1], "shear/stress/kk");
  ASSERT_GT(std::fabs(run[0].displacement), 1e-4);
  std::printf("[ report ] shear/stress/kk vs CPU after 2000 steps: |dd| %.1e |dv| %.1e |dstress| "
              "%.1e max |dx| %.1e\n",
              std::fabs(run[1].displacement - run[0].displacement),
              std::fabs(run[1].velocity - run[0].velocity),
              std::fabs(run[1].stress - run[0].stress), pwtest::max_abs_diff(run[0].x, run[1].x));
  // frictional contacts summed in another order: round-off amplified by 2000 steps
  EXPECT_NEAR(run[1].displacement, run[0].displacement, 1e-10);
  EXPECT_NEAR(run[1].velocity, run[0].velocity, 1e-9);
  EXPECT_NEAR(run[1].stress, run[0].stress, 1e-8);
  EXPECT_LE(pwtest::max_abs_diff(run[0].x, run[1].x), 1e-10);
}

TEST(FixShearStress, MpiDecompositionDoesNotChangeThePlate)
{
  auto run = [](MPI_Comm comm) {
    Lammps l(Accel::none, comm);
    l.commands(pwtest::cubic_stack(6, 6, 2, 5.0));
    const auto x0 = l.gather3("x");
    l.commands(sheared_stack_fixes(3.0, 6));
    l.command("run 1000");
    PlateRun r = record(l);
    r.x = pwtest::by_site(x0, r.x);
    return r;
  };
  const PlateRun parallel = run(MPI_COMM_WORLD);
  const PlateRun serial = run(MPI_COMM_SELF);
  std::printf("[ report ] shear/stress decomposed vs serial: |dd| %.1e |dv| %.1e |dstress| %.1e "
              "max |dx| %.1e\n",
              std::fabs(parallel.displacement - serial.displacement),
              std::fabs(parallel.velocity - serial.velocity),
              std::fabs(parallel.stress - serial.stress),
              pwtest::max_abs_diff(parallel.x, serial.x));
  EXPECT_NEAR(parallel.displacement, serial.displacement, 1e-10);
  EXPECT_NEAR(parallel.velocity, serial.velocity, 1e-9);
  EXPECT_NEAR(parallel.stress, serial.stress, 1e-8);
  EXPECT_LE(pwtest::max_abs_diff(parallel.x, serial.x), 1e-10);
}

TEST(FixShearStress, BadInputAndRunawayGiveClearErrors)
{
  Lammps l;
  free_layer(l, "nve/sphere");
  expect_error(l, "fix s all shear/stress tau 0.5", "missing required keyword(s): mass");
  expect_error(l, "fix s all shear/stress tau 0.5 mass", "mass expects a number > 0, but the command ends there");
  expect_error(l, "fix s all shear/stress tau 0.5 mass 0", "mass expects a finite number > 0, got '0'");
  expect_error(l, "fix s all shear/stress tau v_tau mass 1", "tau expects a finite number, got 'v_tau'");
  expect_error(l, "fix s all shear/stress tau 0.5 mass 1 lock y",
               "unknown keyword 'lock' (allowed: tau, mass)");
  expect_error(l, "group none empty\nfix s none shear/stress tau 0.5 mass 1\nrun 0",
               "group none has no grains");
  l.command("unfix s");
  // a = 2400: the plate moves a·n·Δt² in step n, more than half the skin (0.1) at n ≈ 42
  expect_error(l, "fix s all shear/stress tau 1200 mass 12\nrun 100", "the plate ran away at step");
}
