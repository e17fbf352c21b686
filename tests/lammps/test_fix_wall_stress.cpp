// fix wall/stress and wall/stress/kk: free fall under a constant and a ramped stress,
// equilibrium on a cubic stack, the grains within reach (CPU), the dashpots (on the plate; on the grains relative to it or
// in the lab frame), the virial (also of /kk), a wall leaving the box, a tidal stress near
// zero. KOKKOS, MPI, restarts and input errors: the style matrix
// (test_style_matrix.cpp).
#include "fix_walls_inputs.h"
#include "lammps_fixture.h"
#include "walls/wall_contact.h"

#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using pwtest::Accel;
using pwtest::Lammps;
using pwtest::expect_error;
using pwtest::STACK_KN;
using pwtest::STACK_STRESS;

namespace {

void empty_box(Lammps &l) { l.commands(pwtest::empty_box); }
void loaded_stack(Lammps &l, const std::string &stress = "10", const std::string &options = "")
{
  l.commands(pwtest::loaded_stack(stress, options));
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

// The CPU fix visits only the grains within reach of the wall, listed when LAMMPS
// re-neighbors and again whenever the wall has come down by half the skin since. A wall
// dropped from 4 above the stack's top falls onto grains at rest (nothing re-neighbors: the
// list is rebuilt by the wall's own travel, 40 times) and rings on them: it moves exactly
// as when every step re-neighbors (the list built anew each step), bit for bit.
TEST(FixWallStress, WallFallingOntoGrainsAtRestMovesAsWithListsBuiltEveryStep)
{
  auto fall = [](const std::string &neigh) {
    Lammps l;
    l.commands(pwtest::cubic_stack(3, 3, 4, 10.0, STACK_KN) + neigh + "\ntimestep 5e-4\n"
               "fix hold bottom setforce 0 0 0\nfix integrate all nve/sphere\n"
               "fix w all wall/stress z 8 stress 10 mass 9 kn 1e4 damping 100\n"
               "variable zw equal f_w[1]\nvariable fw equal f_w[3]\n");
    std::vector<double> path;
    for (int k = 0; k < 30; k++) {
      l.command("run 100");
      path.push_back(l.equal("v_zw"));
      path.push_back(l.equal("v_fw"));
    }
    return path;
  };
  const auto listed = fall("neigh_modify delay 0 every 1 check yes");
  const auto every_step = fall("neigh_modify delay 0 every 1 check no");
  EXPECT_EQ(listed, every_step);
  // it reached the grains and pressed on them: the wall below the stack's top (4)
  EXPECT_LT(*std::min_element(listed.begin(), listed.end()), 4.0);
  double pressed = 0.0;
  for (size_t k = 1; k < listed.size(); k += 2) pressed = std::max(pressed, listed[k]);
  EXPECT_GT(pressed, 1.0);
}

TEST(FixWallStress, PlateDampingGivesTheTerminalVelocity)
{
  // no grains: M v' = -S L_x L_y - gamma_p v, v = -v_inf (1 - exp(-gamma_p t/M)) with
  // v_inf = S L_x L_y/gamma_p = 0.25 and M/gamma_p = 0.5. The explicit dashpot (on the
  // half-step velocity) errs by O(gamma_p dt/M) = 2% of the transient's change per unit
  // time constant: measured 1.2e-3 at t = 1; at t = 10 (20 time constants) the terminal
  // velocity, a fixed point of the scheme, is reached to e^-20.
  Lammps l;
  empty_box(l);
  l.command("fix w all wall/stress z 9 stress 0.5 mass 6 kn 100 plate_damping 12");
  l.command("run 100");
  EXPECT_NEAR(l.equal("f_w[2]"), -0.25 * (1.0 - std::exp(-2.0)), 2e-3);
  l.command("run 900");
  EXPECT_NEAR(l.equal("f_w[2]"), -0.25, 1e-8);
  EXPECT_NEAR(l.equal("f_w[6]"), 0.5, 1e-7);    // the dashpot carries the applied stress
  EXPECT_EQ(l.equal("f_w[5]"), 0.0);            // no grain: no grain-wall dashpot
}

TEST(FixWallStress, DampingVelocityFormsOnAMovingWall)
{
  // The stack under the oscillating stress, the wall and the grains below it moving: the
  // grain force and its dashpot share (f_w[3], f_w[5]) are those of the inline contact law
  // summed over the grains, with the velocity relative to the wall or in the lab frame.
  double share[2];
  const char *forms[2] = {"relative", "absolute"};
  for (int k = 0; k < 2; k++) {
    Lammps l;
    l.commands(pwtest::oscillating_stress);
    loaded_stack(l, "v_s", std::string("damping_velocity ") + forms[k]);
    l.command("run 1500");
    l.command("run 0");    // forces from the positions and (full-step) velocities as they are
    // the wall as the fix holds it (an equal-style variable rounds it by a few ulp)
    int dim = 0;
    LAMMPS_NS::Fix *wall = l.lmp->modify->fix[l.lmp->modify->find_fix("w")];
    const double z_w = *(double *) wall->extract("z_wall", dim);
    const double v_w = *(double *) wall->extract("v_wall", dim);
    ASSERT_GT(std::fabs(v_w), 1e-4) << forms[k];    // the wall is moving
    const auto x = l.gather3("x"), v = l.gather3("v");
    double force = 0.0, damping = 0.0;
    for (const auto &kv : x) {
      const porewater::WallContact c = porewater::wall_contact(
          kv.second[2], 0.5, v.at(kv.first)[2], z_w, v_w, STACK_KN, 100.0,
          k == 0 ? porewater::WALL_DAMPING_RELATIVE : porewater::WALL_DAMPING_ABSOLUTE);
      force -= c.force_z;
      damping -= c.damping_z;
    }
    ASSERT_GT(force, 0.0);
    EXPECT_NEAR(l.equal("f_w[3]") * 9.0, force, 1e-12 * force) << forms[k];
    EXPECT_NEAR(l.equal("f_w[5]") * 9.0, damping, 1e-12 * force) << forms[k];
    share[k] = damping;
  }
  std::printf("[ report ] dashpot share of the grain force on a moving wall: relative %.4g, "
              "absolute %.4g\n", share[0], share[1]);
  EXPECT_GT(std::fabs(share[0] - share[1]), 1e-3 * std::fabs(share[0]));
}

TEST(FixWallStress, KokkosVirialEqualsCpuVirial)
{
  PW_SKIP_WITHOUT_KOKKOS();
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

// On one rank fix wall/stress/kk keeps the wall on the device during a run and brings it
// to the host where it is read. Read in every hook of every step (a variable of fix
// addforce in post_force, after the wall: the half-step velocity; thermo at the step's
// end), over runs that each end there, reading it must change nothing.
TEST(FixWallStress, KokkosWallReadInEveryHookChangesNothing)
{
  PW_SKIP_WITHOUT_KOKKOS();
  auto end_of = [](bool read) {
    Lammps l(Accel::kokkos);
    l.commands(pwtest::oscillating_stress);
    loaded_stack(l, "v_s");
    if (read)
      l.commands("variable zero equal 0*f_w[2]\nfix read all addforce 0.0 0.0 v_zero\n"
                 "thermo_style custom step f_w[1] f_w[2] f_w[3]\nthermo 1\n");
    for (int k = 0; k < 12; ++k) l.command("run 30");
    return std::vector<double>{l.equal("f_w[1]"), l.equal("f_w[2]"), l.equal("f_w[3]"),
                               l.equal("f_w[6]"), l.equal("z[36]"), l.equal("vz[36]")};
  };
  const std::vector<double> unread = end_of(false);
  ASSERT_NE(unread[1], 0.0);    // the wall still moves
  EXPECT_EQ(end_of(true), unread);
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
