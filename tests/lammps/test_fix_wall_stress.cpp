// fix wall/stress and wall/stress/kk: free fall under a constant and a ramped stress,
// equilibrium on a cubic stack, virial, restarts, KOKKOS, MPI and input errors.
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

// an empty box 2 × 3 (area 6) from z = 0 to 10, periodic in x and y
void empty_box(Lammps &l)
{
  l.commands("units lj\natom_style sphere\nboundary p p f\n"
             "region box block 0 2 0 3 0 10\ncreate_box 1 box\ntimestep 0.01\n");
}

// the 3 × 3 × 4 stack resting on its held bottom layer, damped, under the wall: S = 10
// on 9 columns of 4 springs in series (kn = 1e4) compresses each contact by S/kn = 1e-3
const double STACK_STRESS = 10.0, STACK_KN = 1.0e4;
void loaded_stack(Lammps &l, const std::string &stress = "10")
{
  l.commands(pwtest::cubic_stack(3, 3, 4, 8.0, STACK_KN));
  l.commands("timestep 5e-4\nfix hold bottom setforce 0 0 0\nfix integrate all nve/sphere\n"
             "fix damp mobile viscous 20\n");
  l.command("fix w all wall/stress z auto stress " + stress + " mass 9 kn 1e4 damping 100");
}

std::string style_of(Lammps &l, const char *id)
{
  return l.lmp->modify->fix[l.lmp->modify->find_fix(id)]->style;
}

}    // namespace

TEST(FixWallStress, FreeWallFollowsTheParabola)
{
  // no grains: M z'' = −S L_x L_y, a = −0.5 · 6 / 6. Velocity Verlet is exact for a constant
  // acceleration, so only round-off remains: ~300 additions of O(10) numbers, ≤ 1e-12
  Lammps l;
  empty_box(l);
  l.command("fix w all wall/stress z 8 stress 0.5 mass 6 kn 100");
  const double a = -0.5, z0 = 8.0;
  for (int n = 1; n <= 6; n++) {
    l.command("run 50");    // separate runs: the wall's state carries over
    const double t = 0.5 * n;
    EXPECT_NEAR(l.equal("f_w[1]"), z0 + 0.5 * a * t * t, 1e-12) << "t = " << t;
    EXPECT_NEAR(l.equal("f_w[2]"), a * t, 1e-12) << "t = " << t;
  }
  EXPECT_EQ(l.equal("f_w[3]"), 0.0);    // no grain touches it
  EXPECT_EQ(l.equal("f_w[4]"), 0.5);
}

TEST(FixWallStress, RampedStressIsAppliedAtTheCurrentTime)
{
  // S = c t: with a = −k t (k = c L_x L_y / M) velocity Verlet's velocity is exact and its
  // position lags the cubic by exactly k T Δt²/6: z = z0 − k (T³ − T Δt²)/6. Evaluating S
  // one step late would change z by O(k T² Δt) = 1e-2 here.
  Lammps l;
  empty_box(l);
  l.command("variable s equal 2.0*time");
  l.command("fix w all wall/stress z 9 stress v_s mass 6 kn 100");
  l.command("run 200");
  const double k = 2.0, dt = 0.01, T = 2.0;
  EXPECT_NEAR(l.equal("f_w[1]"), 9.0 - k * (T * T * T - T * dt * dt) / 6.0, 1e-12);
  EXPECT_NEAR(l.equal("f_w[2]"), -k * T * T / 2.0, 1e-12);
  EXPECT_NEAR(l.equal("f_w[4]"), 2.0 * T, 1e-12);
}

TEST(FixWallStress, WallOnCubicStackCarriesTheAppliedStress)
{
  Lammps l;
  loaded_stack(l);
  l.command("run 0");
  EXPECT_DOUBLE_EQ(l.equal("f_w[1]"), 4.0);    // auto: on the highest grain's top
  l.command("run 10000");
  // damped: the residual falls ~300-fold per time unit (measured), ~1e-13 left at t = 5
  const double delta = STACK_STRESS / STACK_KN;
  EXPECT_NEAR(l.equal("f_w[3]"), STACK_STRESS, 1e-8 * STACK_STRESS);
  EXPECT_NEAR(l.equal("f_w[1]"), 4.0 - 4.0 * delta, 1e-9);    // 4 springs in series
  EXPECT_NEAR(l.equal("f_w[2]"), 0.0, 1e-9);
  EXPECT_NEAR(l.equal("f_w"), 9 * 0.5 * STACK_KN * delta * delta, 1e-9);

  // virial: pzz with the wall's share minus pzz without it is Σ (z_i − z_w) f_z,i / V
  const double z_wall = l.equal("f_w[1]");
  double expected = 0.0;
  for (const auto &kv : l.gather3("x")) {
    const double overlap = kv.second[2] + 0.5 - z_wall;
    if (overlap > 0.0) expected += (kv.second[2] - z_wall) * (-STACK_KN * overlap);
  }
  l.command("thermo_style custom step pzz");    // recomputed by each run 0
  l.command("fix_modify w virial yes");
  l.command("run 0");
  const double with_wall = l.thermo("pzz");
  l.command("fix_modify w virial no");
  l.command("run 0");
  const double without_wall = l.thermo("pzz");
  const double volume = 3.0 * 3.0 * 8.0;
  ASSERT_GT(expected, 0.0);
  EXPECT_NEAR((with_wall - without_wall) * volume, expected, 1e-9 * expected);
}

// ---------------------------------------------------------------------------------------

namespace {

struct WallRun {
  double z, v, stress;
  std::map<long, std::vector<double>> x;
};

WallRun record(Lammps &l)
{
  return {l.equal("f_w[1]"), l.equal("f_w[2]"), l.equal("f_w[3]"), l.gather3("x")};
}

// the stack under an oscillating stress, still ringing: a moving wall in contact. Written with
// step·dt: this LAMMPS version restarts `time` at 0 after read_restart
const char *OSCILLATING = "variable s equal 10.0+5.0*sin(2*PI*step*dt/0.3)";

}    // namespace

TEST(FixWallStress, RestartSplitRunEqualsUnsplitRun)
{
  // separate lmp processes, as users run them
  const std::vector<std::string> values = {"f_w[1]", "f_w[2]", "f_w[3]", "f_w[4]"};
  const std::string fixes = "fix hold bottom setforce 0 0 0\nfix integrate all nve/sphere\n"
                            "fix damp mobile viscous 20\n"
                            "fix w all wall/stress z auto stress v_s mass 9 kn 1e4 damping 100\n";
  for (const std::string accel : {"", "-k on t 1 -sf kk"}) {
    const std::string tag = accel.empty() ? "cpu" : "kk";
    const std::string whole = "pw_wall_whole_" + tag, split = "pw_wall_split_" + tag;
    pwtest::run_lmp(std::string(OSCILLATING) + "\n" + pwtest::cubic_stack(3, 3, 4, 8.0) +
                        "timestep 5e-4\n" + fixes + "run 1500\nwrite_restart " + split +
                        ".restart\nrun 1500\n" + pwtest::save_results(whole, values),
                    accel, whole);
    // `auto` is ignored: the restart holds the wall's position, velocity and force
    pwtest::run_lmp("newton off\nread_restart " + split + ".restart\n" + OSCILLATING + "\n" +
                        "comm_modify vel yes\nneighbor 0.2 bin\nneigh_modify delay 0 every 1 "
                        "check yes\n" +
                        fixes + "run 1500\n" + pwtest::save_results(split, values),
                    accel, split);
    ASSERT_GT(std::fabs(pwtest::read_values(whole)[1]), 1e-4) << tag;    // the wall is moving
    // same operations in the same order; the displacement carries on from the restart
    pwtest::expect_identical_results(whole, split, tag);
  }
}

TEST(FixWallStress, KokkosEqualsCpu)
{
  WallRun run[2];
  std::string style[2];
  const Accel accel[2] = {Accel::none, Accel::kokkos};
  for (int k = 0; k < 2; k++) {
    Lammps l(accel[k]);
    l.command(OSCILLATING);
    loaded_stack(l, "v_s");
    l.command("fix_modify w virial yes");
    l.command("run 3000");
    run[k] = record(l);
    style[k] = style_of(l, "w");
  }
  EXPECT_EQ(style[1], "wall/stress/kk");
  std::printf(
      "[ report ] wall/stress/kk vs CPU after 3000 steps: |dz| %.1e |dv| %.1e |dstress| %.1e "
      "max |dx| %.1e\n",
      std::fabs(run[1].z - run[0].z), std::fabs(run[1].v - run[0].v),
      std::fabs(run[1].stress - run[0].stress), pwtest::max_abs_diff(run[0].x, run[1].x));
  // same arithmetic per grain, sums in another order: round-off in damped dynamics
  EXPECT_NEAR(run[1].z, run[0].z, 1e-12);
  EXPECT_NEAR(run[1].v, run[0].v, 1e-10);
  EXPECT_NEAR(run[1].stress, run[0].stress, 1e-9);
  EXPECT_LE(pwtest::max_abs_diff(run[0].x, run[1].x), 1e-12);
}

TEST(FixWallStress, KokkosVirialEqualsCpuVirial)
{
  double pzz[2];
  const Accel accel[2] = {Accel::none, Accel::kokkos};
  for (int k = 0; k < 2; k++) {
    Lammps l(accel[k]);
    loaded_stack(l);
    l.command("run 2000");
    l.command("thermo_style custom step pzz");
    l.command("fix_modify w virial yes");
    l.command("run 0");
    const double with_wall = l.thermo("pzz");
    l.command("fix_modify w virial no");
    l.command("run 0");
    pzz[k] = with_wall - l.thermo("pzz");
  }
  ASSERT_GT(pzz[0], 0.0);
  std::printf("[ report ] wall virial pzz: CPU %.15g, kk %.15g\n", pzz[0], pzz[1]);
  EXPECT_NEAR(pzz[1], pzz[0], 1e-10 * pzz[0]);
}

TEST(FixWallStress, MpiDecompositionDoesNotChangeTheWall)
{
  // under mpirun -np 2 and 3 a decomposed run against a serial one on each rank
  auto run = [](MPI_Comm comm) {
    Lammps l(Accel::none, comm);
    l.command(OSCILLATING);
    l.commands(pwtest::cubic_stack(6, 6, 5, 9.0));
    const auto x0 = l.gather3("x");
    l.commands("timestep 5e-4\nfix hold bottom setforce 0 0 0\nfix integrate all nve/sphere\n"
               "fix damp mobile viscous 20\n"
               "fix w all wall/stress z auto stress v_s mass 36 kn 1e4 damping 100\nrun 1000\n");
    WallRun r = record(l);
    r.x = pwtest::by_site(x0, r.x);
    return r;
  };
  const WallRun parallel = run(MPI_COMM_WORLD);
  const WallRun serial = run(MPI_COMM_SELF);
  std::printf("[ report ] wall/stress decomposed vs serial: |dz| %.1e |dv| %.1e |dstress| %.1e "
              "max |dx| %.1e\n",
              std::fabs(parallel.z - serial.z), std::fabs(parallel.v - serial.v),
              std::fabs(parallel.stress - serial.stress),
              pwtest::max_abs_diff(parallel.x, serial.x));
  // reductions and neighbor lists in another order: round-off
  EXPECT_NEAR(parallel.z, serial.z, 1e-12);
  EXPECT_NEAR(parallel.v, serial.v, 1e-10);
  EXPECT_NEAR(parallel.stress, serial.stress, 1e-9);
  EXPECT_LE(pwtest::max_abs_diff(parallel.x, serial.x), 1e-12);
}

// ---------------------------------------------------------------------------------------

namespace {


}    // namespace

TEST(FixWallStress, BadInputGivesClearErrors)
{
  {
    Lammps l;
    empty_box(l);
    const std::string fix = "fix w all wall/stress ";
    expect_error(l, fix + "z 8 stress 0.5 mass 6", "missing required keyword(s): kn");
    expect_error(l, fix + "z 8 stress 0.5 mass 6 kn", "kn expects a number > 0, but the command ends there");
    expect_error(l, fix + "z 8 stress 0.5 mass -6 kn 100", "mass expects a finite number > 0, got '-6'");
    expect_error(l, fix + "z top stress 0.5 mass 6 kn 100", "z expects auto or a finite number, got 'top'");
    expect_error(l, fix + "z 8 stress high mass 6 kn 100",
                 "stress expects a finite number or v_name, got 'high'");
    expect_error(l, fix + "z 8 stress 0.5 mass 6 kn stiff", "kn expects a finite number > 0, got 'stiff'");
    expect_error(l, fix + "z 8 stress 0.5 mass 6 kn 0", "kn expects a finite number > 0, got '0'");
    expect_error(l, fix + "z 8 stress 0.5 mass 6 kn 100 damping -1", "damping expects a finite number >= 0, got '-1'");
    expect_error(l, fix + "z 8 stress 0.5 mass 6 kn 100 wiggle 1",
                 "unknown keyword 'wiggle' (allowed: z, stress, mass, kn, damping)");
    expect_error(l, fix + "z 8 stress v_nope mass 6 kn 100\nrun 0",
                 "variable nope for stress does not exist");
    l.command("unfix w");
    expect_error(l, "variable perat atom x\n" + fix + "z 8 stress v_perat mass 6 kn 100\nrun 0",
                 "variable perat for stress is not equal-style");
    l.command("unfix w");
    expect_error(l, fix + "z auto stress 1 mass 6 kn 100\nrun 0", "z auto needs grains");
    l.command("unfix w");
    // pulled up (S < 0) it leaves through the top: a = 1, z = 8 + t²/2 passes 10 at t = 2
    expect_error(l, fix + "z 8 stress -1 mass 6 kn 100\nrun 300", "above the box top 10");
    l.command("unfix w");
    expect_error(l, fix + "z 1 stress 1 mass 6 kn 100\nrun 300", "below the box bottom 0");
    l.command("unfix w");
    // a stress that overflows makes the wall's velocity infinite in the first step
    expect_error(l, "reset_timestep 0\nvariable inf equal 1e308*10\n" + fix + "z 8 stress v_inf mass 6 kn 100\nrun 10",
                 "the wall ran away at step 1: z = -inf, v = -inf");
  }
  {
    Lammps l;
    l.commands("units lj\natom_style sphere\nboundary p p p\n"
               "region box block 0 2 0 3 0 10\ncreate_box 1 box\n");
    expect_error(l, "fix w all wall/stress z 8 stress 0.5 mass 6 kn 100",
                 "needs a z-bounded box: boundary f, fm or fs in z");
  }
}

TEST(FixWallStress, WallLeavingTheBoxNamesTheStep)
{
  Lammps l;
  empty_box(l);
  l.command("fix w all wall/stress z 8 stress -1 mass 6 kn 100");
  try {
    l.command("run 300");
    ADD_FAILURE() << "the wall left the box silently";
  } catch (std::exception &e) {
    // z = 8 + t²/2 with t = 0.01 n passes 10 at n = 200 (round-off: step 200 or 201)
    const std::string msg = e.what();
    EXPECT_TRUE(msg.find("at step 200,") != std::string::npos ||
                msg.find("at step 201,") != std::string::npos)
        << msg;
  }
}

TEST(FixWallStress, TidalStressNearZeroKeepsThePlateBoundedAndNegativeIsCaught)
{
  // N -> 0: S = 10 - A sin^2(pi t / 2.5) over one tidal period. With A = 0.999 S0 the bed
  // is almost unloaded at t = 1.25 (S = 0.01). Quasi-statically z = 4 - 4 S/kn <= 4 (the
  // free stack top), and the plate moves at most at v = 4 A pi/(2.5 kn) = 5.0e-3; lifted
  // off at that speed under the smallest stress it rises at most v^2 M / (2 S_min L_x L_y)
  // = 1.26e-3. Downward, a load applied at once overshoots at most twice the static
  // compression 4 S0/kn = 4e-3.
  const double A = 9.99, S_min = STACK_STRESS - A;
  const double v_max = 4.0 * A * std::acos(-1.0) / (2.5 * STACK_KN);
  const double rise = v_max * v_max * 9.0 / (2.0 * S_min * 9.0);
  {
    Lammps l;
    l.command("variable s equal 10-9.99*sin(PI*step*dt/2.5)^2");
    loaded_stack(l, "v_s");
    double z_max = -1.0, z_min = 1e9;
    for (int n = 0; n < 50; n++) {    // 5000 steps of 5e-4: one period
      l.command("run 100");
      const double z = l.equal("f_w[1]");
      ASSERT_TRUE(std::isfinite(z) && std::isfinite(l.equal("f_w[2]")));
      z_max = std::max(z_max, z);
      z_min = std::min(z_min, z);
    }
    std::printf("[ report ] S down to %.3g: plate z in [%.6f, %.6f], bounds [%.6f, %.6f]\n",
                S_min, z_min, z_max, 4.0 - 8.0 * STACK_STRESS / STACK_KN, 4.0 + rise);
    EXPECT_LE(z_max, 4.0 + rise);
    EXPECT_GE(z_min, 4.0 - 8.0 * STACK_STRESS / STACK_KN);
  }
  {
    // A = 3 S0: S = -20 pulls the plate off the bed and out of the box, which stops the run
    Lammps l;
    l.command("variable s equal 10-30*sin(PI*step*dt/2.5)^2");
    loaded_stack(l, "v_s");
    expect_error(l, "run 5000", "above the box top 8");
  }
}
