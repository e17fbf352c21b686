// fix nve/sphere/bed/kk's fused pass (FIX_WALLS/fix_nve_sphere_bed_pass_kokkos.h) against the
// same fixes each on its own (`fuse no`), and every way a LAMMPS user runs a bed in pieces
// against the uninterrupted run, with the /kk styles and, as the reference, the CPU ones.
//
// The scene: the loose bed under the package's fixes in the example's order (nve/sphere/bed,
// a wall on top, the pore water with fluid steps every 5 and its force held between, the top
// layer sheared as a plate), on one rank and one thread: every kernel then adds each grain's
// forces in the same order and reduces in the same order, so fused and unfused runs, and a
// run continued without its setup, must agree bit for bit (EXPECT_EQ on every number).
#include "fix_walls_inputs.h"
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using pwtest::Accel;
using pwtest::Lammps;

namespace {

const char *const BED = "fix grains all nve/sphere/bed held bottom gravity 1.0 bed floor 0.0 2000";
const char *const WALL = "fix w all wall/stress z auto stress 0.5 mass 25 kn 2000 damping 1\n";
const char *const DARCY =
    "fix fl all darcy/pressure grid 2 2 4 zhi 8 viscosity 1 compressibility 0.01 density 0.5 "
    "permeability 0.01 kmax 0.01 gravity 0 0 -1 every 5 interpolate fluid\n";
const char *const PLATE = "fix s top shear/stress tau 0.2 mass 5\n";
const std::string NOTHING = "fix nothing all addforce 0.0 0.0 0.0\n";    // adds nothing
const char *const TOP = "region high block INF INF INF INF 4.2 INF units box\ngroup top region high\n";

enum Member { WALL_FIX = 1, DARCY_FIX = 2, PLATE_FIX = 4 };

// the fixes of `members` after the bed fix (`bed_extra` on its line), in the pass' order
std::string fixes(int members, const std::string &bed_extra = "")
{
  std::string s = std::string(TOP) + BED + bed_extra + "\n";
  if (members & WALL_FIX) s += WALL;
  if (members & DARCY_FIX) s += DARCY;
  if (members & PLATE_FIX) s += PLATE;
  return s;
}

// every grain's x, v, omega and f, then the wall's, the plate's and the fluid's vectors
// (those of the fixes present)
std::vector<double> state(Lammps &l)
{
  std::vector<double> out;
  for (const char *name : {"x", "v", "omega", "f"})
    for (const auto &kv : l.gather3(name)) out.insert(out.end(), kv.second.begin(), kv.second.end());
  const std::vector<std::pair<std::string, const char *>> vectors = {
      {"w", "f_w[1]"}, {"w", "f_w[2]"}, {"w", "f_w[3]"}, {"s", "f_s[1]"},
      {"s", "f_s[2]"}, {"s", "f_s[3]"}, {"fl", "f_fl[1]"}};
  for (const auto &v : vectors)
    if (!l.fix_style(v.first).empty()) out.push_back(l.equal(v.second));
  return out;
}

// the scene with `setup` (the fixes), then `runs`, on the ranks of `comm`
std::vector<double> run(Accel accel, const std::string &setup, const std::string &runs,
                        MPI_Comm comm = MPI_COMM_WORLD)
{
  Lammps l(accel, comm);
  l.commands(pwtest::loose_bed() + setup);
  l.commands(runs);
  return state(l);
}

// the scene has moved: the plate's layer, if any, by more than round-off
void expect_moved(const std::vector<double> &a, const std::vector<double> &b)
{
  ASSERT_EQ(a.size(), b.size());
  EXPECT_GT(pwtest::max_abs_diff(a, b), 1e-6) << "the runs compared did not move the grains";
}

std::string members_named(int m)
{
  std::string s;
  if (m & WALL_FIX) s += " wall";
  if (m & DARCY_FIX) s += " darcy";
  if (m & PLATE_FIX) s += " plate";
  return s;
}

}    // namespace

// Each subset of wall, darcy and plate in the pass' order: fused against `fuse no`, over two
// runs (the second's setup composes the pass again), bit for bit; and the same as the CPU
// styles to round-off
TEST(FusedPass, KokkosEachSubsetFusedEqualsEachFixOnItsOwn)
{
  PW_SKIP_WITHOUT_KOKKOS();
  for (int members = 1; members < 8; ++members) {
    SCOPED_TRACE("members:" + members_named(members));
    const std::string runs = "run 150\nrun 150\n";
    const std::vector<double> fused = run(Accel::kokkos, fixes(members), runs);
    const std::vector<double> own = run(Accel::kokkos, fixes(members, " fuse no"), runs);
    EXPECT_EQ(fused, own);
    const std::vector<double> cpu = run(Accel::none, fixes(members), runs);
    EXPECT_LT(pwtest::max_abs_diff(fused, cpu), 1e-8);
    expect_moved(fused, run(Accel::kokkos, fixes(members), "run 0\n"));
  }
}

// Orders that end the pass early: a fix between the bed and the wall (nothing joins), and
// the plate before the wall (the plate joins; the wall, after it, steps on its own)
TEST(FusedPass, KokkosOrdersThatEndThePassEqualEachFixOnItsOwn)
{
  PW_SKIP_WITHOUT_KOKKOS();
  for (const bool fuse : {true, false}) {
    const std::string bed = std::string(TOP) + BED + (fuse ? "" : " fuse no") + "\n";
    const std::vector<std::string> orders = {bed + NOTHING + WALL + DARCY + PLATE,
                                             bed + PLATE + WALL + DARCY,
                                             bed + WALL + NOTHING + DARCY + PLATE};
    for (size_t k = 0; k < orders.size(); ++k) {
      SCOPED_TRACE("order " + std::to_string(k) + (fuse ? ", fused" : ", fuse no"));
      const std::string runs = "run 150\nrun 150\n";
      const std::vector<double> kk = run(Accel::kokkos, orders[k], runs);
      const std::vector<double> reference =
          run(Accel::kokkos, std::string(TOP) + BED + " fuse no\n" + orders[k].substr(bed.size()), runs);
      EXPECT_EQ(kk, reference);
    }
  }
}

namespace {

// Every way of running the scene in pieces without a setup between the pieces, against the
// uninterrupted run, bit for bit: run 150 + run 150 pre no; run 300 every 100 pre no; a fix
// added and deleted between such runs; steps whose thermo output asks for the pressure (the
// wall's virial)
void continuations_equal_the_uninterrupted_run(Accel accel)
{
  const std::string scene = fixes(WALL_FIX | DARCY_FIX | PLATE_FIX);
  const std::vector<double> whole = run(accel, scene, "run 300\n");
  expect_moved(whole, run(accel, scene, "run 0\n"));

  EXPECT_EQ(run(accel, scene, "run 150\nrun 150 pre no\n"), whole) << "run N pre no";
  EXPECT_EQ(run(accel, scene, "run 300 pre no every 100 \"variable n equal step\"\n"), whole)
      << "run N pre no every M";
  EXPECT_EQ(run(accel, scene, "thermo_style custom step pe press\nthermo 7\nrun 300\n"), whole)
      << "the pressure in the thermo output";
  // between runs, a fix after the plate (its layer's motion then moves back to the plate's
  // post_force), deleted again: it adds nothing
  EXPECT_EQ(run(accel, scene, "run 100\n" + NOTHING + "run 100 pre no\nunfix nothing\nrun 100 pre no\n"),
            whole)
      << "a fix added and deleted between runs without their setup";
}

// The same pieces with a setup between them (`run N` twice, `run N every M`, a fix added
// and deleted between runs). A setup re-neighbours and sorts the grains, whose contacts
// then sum in another order (round-off), and it evaluates every force anew: the wall's
// dashpot at the grains' whole-step velocities where a step has their half-step ones, and
// the held fluid force (`interpolate fluid`), which follows each re-neighbouring, at the
// setup's. Without these two (damping 0, `interpolate step`) the pieces equal the
// uninterrupted run to round-off (measured 1.7e-12 CPU, 2.9e-12 /kk; the /kk and CPU runs of
// the same pieces differ by 2e-12; the two forces move the run by 4e-4); with them, the /kk
// run of the pieces equals the CPU run of the same pieces to round-off
const std::vector<std::string> PIECES_WITH_SETUP = {
    "run 150\nrun 150\n", "run 300 every 100 \"variable n equal step\"\n",
    "run 100\n" + NOTHING + "run 100\nunfix nothing\nrun 100\n"};

void pieces_with_setup_equal_the_uninterrupted_run_without_setup_forces(Accel accel)
{
  std::string scene = std::string(TOP) + BED + "\n" +
      "fix w all wall/stress z auto stress 0.5 mass 25 kn 2000 damping 0\n" + DARCY + PLATE;
  scene.replace(scene.find("interpolate fluid"), 17, "interpolate step");
  const std::vector<double> whole = run(accel, scene, "run 300\n");
  double worst = 0.0;
  for (const std::string &pieces : PIECES_WITH_SETUP)
    worst = std::max(worst, pwtest::max_abs_diff(run(accel, scene, pieces), whole));
  std::printf("[ report ] pieces with a setup against the uninterrupted run: %.3g\n", worst);
  EXPECT_LT(worst, 1e-10);
}

}    // namespace

PW_TEST_CPU_AND_KOKKOS(FusedPass, ContinuationsWithoutSetupEqualTheUninterruptedRun,
                       continuations_equal_the_uninterrupted_run)
PW_TEST_CPU_AND_KOKKOS(FusedPass, PiecesWithSetupEqualTheUninterruptedRunWithoutSetupForces,
                       pieces_with_setup_equal_the_uninterrupted_run_without_setup_forces)

TEST(FusedPass, KokkosPiecesWithSetupEqualTheCpuPieces)
{
  PW_SKIP_WITHOUT_KOKKOS();
  const std::string scene = fixes(WALL_FIX | DARCY_FIX | PLATE_FIX);
  double worst = 0.0, setup_moves = 0.0;
  const std::vector<double> whole = run(Accel::none, scene, "run 300\n");
  for (const std::string &pieces : PIECES_WITH_SETUP) {
    const std::vector<double> cpu = run(Accel::none, scene, pieces);
    worst = std::max(worst, pwtest::max_abs_diff(run(Accel::kokkos, scene, pieces), cpu));
    setup_moves = std::max(setup_moves, pwtest::max_abs_diff(cpu, whole));
  }
  std::printf("[ report ] /kk against CPU, pieces with a setup: %.3g (the setup moves the run "
              "by %.3g)\n",
              worst, setup_moves);
  EXPECT_LT(worst, 1e-8);
}

// On 2 and 3 ranks (ctest's np2, np3) the /kk fixes keep their states on the host and nothing
// fuses: the scene as on one rank (MPI_COMM_SELF, where the pass runs) to round-off, as the
// CPU styles meet it
TEST(FusedPass, KokkosMpiSceneEqualsOneRank)
{
  PW_SKIP_WITHOUT_KOKKOS();
  const std::string scene = fixes(WALL_FIX | DARCY_FIX | PLATE_FIX), runs = "run 150\nrun 150\n";
  const double kk = pwtest::max_abs_diff(run(Accel::kokkos, scene, runs, MPI_COMM_WORLD),
                                         run(Accel::kokkos, scene, runs, MPI_COMM_SELF));
  const double cpu = pwtest::max_abs_diff(run(Accel::none, scene, runs, MPI_COMM_WORLD),
                                          run(Accel::none, scene, runs, MPI_COMM_SELF));
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0)
    std::printf("[ report ] decomposed against one rank: /kk %.3g, CPU %.3g\n", kk, cpu);
  EXPECT_LT(kk, 1e-8);
  EXPECT_LT(cpu, 1e-8);
}

namespace {

// the lines of lmp's log that `script` wrote with the /kk styles
std::string log_of(const std::string &script, const std::string &name)
{
  pwtest::run_lmp(pwtest::loose_bed() + script + "run 10\n", "-k on t 1 -sf kk", name);
  std::ifstream in("log." + name);
  std::stringstream text;
  text << in.rdbuf();
  std::remove(("log." + name).c_str());
  std::remove(("in." + name).c_str());
  return text.str();
}

}    // namespace

// The log line of each run's setup names the fixes that joined, or why none did
TEST(FusedPass, KokkosLogLineNamesTheFixesThatJoined)
{
  PW_SKIP_WITHOUT_KOKKOS();
  const std::string all = fixes(WALL_FIX | DARCY_FIX | PLATE_FIX);
  EXPECT_NE(log_of(all, "pwtest_pass_all")
                .find("fix nve/sphere/bed/kk grains: fused pass of post_force with "
                      "wall/stress/kk w (the wall's step), darcy/pressure/kk fl (its held force "
                      "between fluid steps), shear/stress/kk s (its sums and step); the layer's "
                      "motion in the bed's final_integrate"),
            std::string::npos);
  EXPECT_NE(log_of(fixes(WALL_FIX | DARCY_FIX | PLATE_FIX, " fuse no"), "pwtest_pass_off")
                .find("fix nve/sphere/bed/kk grains: fused pass off (fuse no)"),
            std::string::npos);
  const std::string between = std::string(TOP) + BED + "\nfix nothing all addforce 0 0 0\n" + WALL;
  EXPECT_NE(log_of(between, "pwtest_pass_none")
                .find("fix nve/sphere/bed/kk grains: no fused pass: fix addforce nothing, the "
                      "next post_force fix, cannot join (its forces come in its place)"),
            std::string::npos);
}

// `fuse` takes yes or no, and says so
TEST(FusedPass, FuseKeywordNamesItsValues)
{
  Lammps l;
  l.commands(pwtest::loose_bed());
  pwtest::expect_error(l, std::string(BED) + " fuse maybe",
                       "fuse");
}
