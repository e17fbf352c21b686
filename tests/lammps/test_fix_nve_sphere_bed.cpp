// fix nve/sphere/bed against the LAMMPS fixes it replaces (gravity, setforce 0 0 NULL + nve
// on the held base, nve/sphere; wall/gran hooke as the floor) on a loose bed settling onto
// the floor: bit for bit where the arithmetic is the same, to round-off for the floor. Its
// KOKKOS variant, MPI runs, restarts and input errors: the style matrix
// (test_style_matrix.cpp).
#include "fix_walls_inputs.h"
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

using pwtest::Accel;
using pwtest::Lammps;

namespace {

using PerAtom = std::map<long, std::vector<double>>;
struct Motion {
  PerAtom x, v, omega;
};

// the loose bed with `fixes`, run `steps` steps
Motion settle(const std::string &fixes, int steps)
{
  Lammps l;
  l.commands(pwtest::loose_bed() + fixes + "run " + std::to_string(steps));
  return {l.gather3("x"), l.gather3("v"), l.gather3("omega")};
}

const std::string BED = "fix grains all nve/sphere/bed held bottom gravity 1.0 bed";
const int STEPS = 3000;    // the bed falls onto its base, which is pushed onto the floor

}    // namespace

// the integrators, gravity and the held base with LAMMPS' floor in both runs: the same
// arithmetic in the same order, so the same bits (EXPECT_EQ on every component)
TEST(FixNVESphereBed, MovesGrainsBitForBitAsLammpsOwnFixes)
{
  const Motion native = settle(pwtest::bed_fixes_native(), STEPS);
  const Motion ours = settle(pwtest::native_floor() + BED + "\n", STEPS);
  EXPECT_EQ(ours.x, native.x);
  EXPECT_EQ(ours.v, native.v);
  EXPECT_EQ(ours.omega, native.omega);
  // the test can see a difference: the bed moved, and the base reached the floor
  const Motion start = settle(pwtest::bed_fixes_native(), 0);
  EXPECT_GT(pwtest::max_abs_diff(native.x, start.x), 0.5);
  double lowest = 1.0;
  for (const auto &kv : native.x) lowest = std::min(lowest, kv.second[2]);
  EXPECT_LT(lowest, 0.5);    // some grain of the base overlaps the floor
}

// the held base: x and y as they started, no rotation, only z moves
TEST(FixNVESphereBed, HeldGrainsMoveAlongZOnly)
{
  Lammps l;
  l.commands(pwtest::loose_bed() + BED + " floor 0.0 2000\nrun 0");
  const PerAtom x0 = l.gather3("x");
  l.command("run " + std::to_string(STEPS));
  const PerAtom x = l.gather3("x"), omega = l.gather3("omega");
  int held = 0;
  double sank = 0.0;
  for (const auto &kv : x0) {
    if (kv.second[2] > 1.0) continue;    // group bottom: z < 1
    held++;
    EXPECT_EQ(x.at(kv.first)[0], kv.second[0]);
    EXPECT_EQ(x.at(kv.first)[1], kv.second[1]);
    EXPECT_EQ(omega.at(kv.first), std::vector<double>({0.0, 0.0, 0.0}));
    sank = std::max(sank, kv.second[2] - x.at(kv.first)[2]);
  }
  EXPECT_EQ(held, 25);
  EXPECT_GT(sank, 0.02);    // the base was pushed down onto the floor (0.025 below it)
}

// The floor alone, on grains at rest at heights that overlap it from 0 to 0.4 of a radius
// (no contacts between them): its force is k_n (r − z), as LAMMPS' wall/gran hooke with
// γ_n = μ = 0 computes it to the last bits (that one evaluates z·k_n(r − |z|)/|z|: a few
// ulps apart), and nothing above the reach
TEST(FixNVESphereBed, FloorPushesAsWallGranHooke)
{
  auto floor_forces = [](const std::string &floor) {
    Lammps l;
    l.commands("units lj\natom_style sphere\natom_modify map array\nboundary p p f\n"
               "region box block 0 20 0 2 0 5 units box\ncreate_box 1 box\n");
    for (int k = 0; k < 10; k++)    // z = 0.3 + 0.025 k: overlap 0.2 ... 0, then 0.5 above
      l.command("create_atoms 1 single " + std::to_string(2 * k + 1) + " 1 " +
                std::to_string(k < 9 ? 0.3 + 0.025 * k : 1.0) + " units box");
    l.commands(pwtest::unit_grains + "pair_style zero 1.0\npair_coeff * *\n" + floor +
               "run 0");
    return std::make_pair(l.gather3("f"), l.gather3("x"));
  };
  const auto native = floor_forces(pwtest::native_floor());
  const auto ours = floor_forces("fix grains all nve/sphere/bed floor 0.0 2000\n");
  for (const auto &kv : ours.first) {
    const double z = ours.second.at(kv.first)[2];
    const double expected = z < 0.5 ? pwtest::BED_KN * (0.5 - z) : 0.0;
    EXPECT_EQ(kv.second[0], 0.0);
    EXPECT_EQ(kv.second[1], 0.0);
    EXPECT_EQ(kv.second[2], expected) << "z " << z;    // floor_force's own arithmetic
    // the native force: 4 ulps of the largest force (k_n · 0.2 = 400)
    EXPECT_NEAR(native.first.at(kv.first)[2], expected, 4 * 2.2e-16 * 400.0) << "z " << z;
    EXPECT_NEAR(kv.second[2], native.first.at(kv.first)[2], 4 * 2.2e-16 * 400.0) << "z " << z;
  }
}

// the whole step with our floor in place of LAMMPS': the floor's forces differ by round-off
// (above), which the bed's contacts amplify step by step. Compared with the spread of
// round-off: the largest difference LAMMPS' own fixes make with the floor's k_n one ulp
// larger or smaller; measured: 0.51x (LAMMPS 29Sep2021) and 0.53x (4Feb2025) that spread.
// A floor law wrong by one part in 1e6 lies far outside (the control)
TEST(FixNVESphereBed, WithItsFloorMovesGrainsAsLammpsOwnFixesToRoundOff)
{
  const Motion native = settle(pwtest::bed_fixes_native(), STEPS);
  double spread = 0.0;
  for (const char *kn : {"2000.0000000000002", "1999.9999999999998"}) {
    const Motion ulp = settle(pwtest::bed_fixes_native(pwtest::native_floor(kn)), STEPS);
    spread = std::max(spread, pwtest::max_abs_diff(ulp.x, native.x));
  }
  const Motion ours = settle(BED + std::string(" floor 0.0 2000\n"), STEPS);
  const double worst = pwtest::max_abs_diff(ours.x, native.x);
  std::printf("[ report ] after %d steps, largest |x - x_native|: ours %.3e, k_n one ulp off %.3e\n",
              STEPS, worst, spread);
  EXPECT_GT(spread, 0.0);
  EXPECT_LE(worst, 3.0 * spread);    // host_compare's rule: 3x the spread of round-off
  const Motion stiffer = settle(BED + std::string(" floor 0.0 2000.002\n"), STEPS);
  EXPECT_GT(pwtest::max_abs_diff(stiffer.x, native.x), 100.0 * spread);
}

namespace {

// The loose bed under the package's other fixes, in the example's order: nve/sphere/bed,
// a wall on top, the pore water (fluid steps every 5, the force held between), the top
// layer sheared as a plate; `between` after the bed fix. Every grain's position and
// velocity and the wall's and plate's vectors after two runs.
std::vector<double> bed_under_every_fix(Accel accel, const std::string &between)
{
  Lammps l(accel);
  l.commands(pwtest::loose_bed() +
             "region high block INF INF INF INF 4.2 INF units box\ngroup top region high\n"
             "fix grains all nve/sphere/bed held bottom gravity 1.0 bed floor 0.0 2000\n" +
             between +
             "fix w all wall/stress z auto stress 0.5 mass 25 kn 2000 damping 1\n"
             "fix fl all darcy/pressure grid 2 2 4 zhi 8 viscosity 1 compressibility 0.01 "
             "density 0.5 permeability 0.01 kmax 0.01 gravity 0 0 -1 every 5 interpolate fluid\n"
             "fix s top shear/stress tau 0.2 mass 5\n");
  l.command("run 150");
  l.command("run 150");
  std::vector<double> out;
  for (const char *name : {"x", "v", "omega"})
    for (const auto &kv : l.gather3(name)) out.insert(out.end(), kv.second.begin(), kv.second.end());
  for (const char *q : {"f_w[1]", "f_w[2]", "f_w[3]", "f_s[1]", "f_s[2]", "f_s[3]", "f_fl[1]"})
    out.push_back(l.equal(q));
  return out;
}

}    // namespace

// On one rank fix nve/sphere/bed/kk's post_force kernel also runs the grain work of the
// wall, of the fluid between fluid steps and the plate's sums, and its final kernel moves
// the plate's layer: the same as each fix's own kernels (a fix between them, adding
// nothing, stops the pass), bit for bit; and as the CPU fixes to round-off.
TEST(FixNVESphereBed, KokkosPassOfTheFixesAfterItEqualsTheirOwnKernels)
{
  PW_SKIP_WITHOUT_KOKKOS();
  const std::vector<double> pass = bed_under_every_fix(Accel::kokkos, "");
  const std::vector<double> own =
      bed_under_every_fix(Accel::kokkos, "fix nothing all addforce 0.0 0.0 0.0\n");
  ASSERT_EQ(pass.size(), own.size());
  EXPECT_EQ(pass, own);
  const std::vector<double> cpu = bed_under_every_fix(Accel::none, "");
  double worst = 0.0;
  for (size_t k = 0; k < cpu.size(); ++k) worst = std::max(worst, std::fabs(pass[k] - cpu[k]));
  std::printf("[ report ] kk pass against CPU: largest difference %.3g\n", worst);
  EXPECT_LT(worst, 1e-8);
  EXPECT_NE(pass[pass.size() - 2], 0.0);    // the plate moved
}
