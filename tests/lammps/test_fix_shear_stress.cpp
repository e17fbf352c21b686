// fix shear/stress: a free plate under τ, resisting forces, a plate pressed by fix
// wall/stress onto a frictional bed. KOKKOS, MPI, restarts and input errors: the style
// matrix (test_style_matrix.cpp).
#include "fix_walls_inputs.h"
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using pwtest::Accel;
using pwtest::Lammps;
using pwtest::PLATE_ACCELERATION;
using pwtest::sheared_stack;

namespace {

void free_layer(Lammps &l, const std::string &integrator)
{
  l.commands(pwtest::free_layer(integrator));
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

// The CPU fix visits the plate's grains listed at the last re-neighboring: LAMMPS sorts and
// moves grains only then. Six grains outside the group sit between the plate's in its rows
// and stream by at v_x = -3, so that LAMMPS re-neighbors every ~33 steps and sorts the
// grains each time (atom_modify sort 1: by x within a row, so the two kinds trade places in
// memory): the plate still accelerates at exactly τA/M, and the others feel nothing.
TEST(FixShearStress, PlateFollowsItsGrainsThroughSorting)
{
  Lammps l;
  free_layer(l, "nve/sphere");
  for (const char *site : {"2 1 1", "4 1 1", "0 1 1", "2 3 1", "4 3 1", "0 3 1"})
    l.command(std::string("create_atoms 1 single ") + site + " units box");
  l.commands("group other id 7:12\ngroup plate subtract all other\n" + pwtest::unit_grains +
             "velocity other set -3.0 0.0 0.0 units box\n"
             "atom_modify sort 1 0.5\nneigh_modify delay 0 every 1 check yes\n"
             "fix s plate shear/stress tau 0.5 mass 12\nrun 0");
  const auto x0 = l.unwrapped();
  std::vector<int> index0;
  for (long tag = 1; tag <= 12; tag++) index0.push_back(l.atom()->map(tag));
  l.command("run 1000");
  const auto x = l.unwrapped();
  int moved_in_memory = 0;
  for (long tag = 1; tag <= 12; tag++) moved_in_memory += l.atom()->map(tag) != index0[tag - 1];
  EXPECT_GT(moved_in_memory, 0);    // the grains were sorted
  ASSERT_EQ(x.size(), 12u);
  for (const auto &kv : x) {
    const bool in_plate = kv.first <= 6;
    // t = 1: the plate moved a t²/2 = 0.5, the others -3 t (exact up to round-off)
    EXPECT_NEAR(kv.second[0], x0.at(kv.first)[0] + (in_plate ? 0.5 : -3.0), 1e-12) << kv.first;
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

// On one rank fix shear/stress/kk (with wall/stress/kk on it) keeps the plate on the device
// during a run and brings it to the host where it is read: read every step (thermo) over
// runs of 30 steps, reading must change nothing.
TEST(FixShearStress, KokkosPlateReadEveryStepChangesNothing)
{
  PW_SKIP_WITHOUT_KOKKOS();
  auto end_of = [](bool read) {
    Lammps l(Accel::kokkos);
    l.commands(sheared_stack(8.0));
    if (read) l.commands("thermo_style custom step f_s[1] f_s[2] f_s[3] f_w[1]\nthermo 1\n");
    for (int k = 0; k < 6; ++k) l.command("run 30");
    return std::vector<double>{l.equal("f_s[1]"), l.equal("f_s[2]"), l.equal("f_s[3]"),
                               l.equal("f_w[2]"), l.equal("x[10]"), l.equal("vx[10]")};
  };
  const std::vector<double> unread = end_of(false);
  ASSERT_GT(unread[1], 0.0);    // the plate slides
  EXPECT_EQ(end_of(true), unread);
}
