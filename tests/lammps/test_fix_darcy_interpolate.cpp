// fix darcy/pressure `interpolate fluid`: the force on each grain is interpolated on fluid
// steps and whenever LAMMPS re-neighbors, and held in between. Checked exactly against
// `interpolate step` on identical trajectories (a setforce after the fix zeroes the
// forces, so both modes move the grains alike and only the recorded fluid force differs).
#include "darcy_inputs.h"
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

using Forces = std::map<long, std::vector<double>>;

// the 64 grains of darcy_inputs.h moving through their closed box on a 2 x 2 x 2 grid: their
// motion makes the pressure, and so its gradient, differ from cell to cell
void moving_grains(Lammps &l, const std::string &interpolate, const std::string &neigh,
                   bool zero_forces = true)
{
  l.commands(pwtest::grains_in_box + "velocity all create 0.5 4928 loop geom\n" + neigh + "\n");
  l.command(pwtest::closed_box_fluid + " initial 1 every 5 interpolate " + interpolate);
  if (zero_forces) l.command("fix zero all setforce 0.0 0.0 0.0");
}

// the fluid forces of one run of `steps` steps, by timestep (a dump per step, full
// precision). One LAMMPS instance at a time: the plugin registers its styles with one.
std::map<long, Forces> forces_by_step(const std::string &interpolate, const std::string &neigh,
                                      int steps, Accel accel = Accel::none)
{
  const std::string prefix = "pw_interp_" + interpolate + ".";
  {
    Lammps l(accel);
    moving_grains(l, interpolate, neigh);
    l.command("dump d all custom 1 " + prefix + "* id f_fl[1] f_fl[2] f_fl[3]");
    l.command("dump_modify d format float %.17g sort id");
    l.command("run " + std::to_string(steps));
  }
  std::map<long, Forces> out;
  for (long now = 0; now <= steps; ++now) {
    const std::string file = prefix + std::to_string(now);
    out[now] = pwtest::read_dump(file);
    std::remove(file.c_str());
  }
  return out;
}

}    // namespace

// Re-neighboring every 7 steps (check no) so that its steps are known: the held force is
// the one interpolated at the latest multiple of 5 (fluid step) or of 7 (re-neighboring).
TEST(FixDarcyInterpolate, HeldForceIsTheOneInterpolatedAtTheLastFluidStepOrReneighboring)
{
  const std::string every7 = "neigh_modify every 7 delay 0 check no";
  const auto by_step = forces_by_step("step", every7, 60);
  const auto held = forces_by_step("fluid", every7, 60);
  int differ = 0;
  for (const auto &step : held) {
    const long now = step.first;
    const long refreshed = std::max(now / 5 * 5, now / 7 * 7);
    // bit for bit (17 digits): the same interpolation at the same positions
    EXPECT_EQ(step.second, by_step.at(refreshed)) << "step " << now;
    differ += step.second != by_step.at(now);
  }
  EXPECT_GT(differ, 30);    // held forces are not the step's: the test can see it
}

TEST(FixDarcyInterpolate, ReneighboringEveryStepMakesTheModesIdentical)
{
  const std::string every1 = "neigh_modify every 1 delay 0 check no";
  EXPECT_EQ(forces_by_step("fluid", every1, 20), forces_by_step("step", every1, 20));
}

TEST(FixDarcyInterpolate, KokkosHoldsTheSameForcesAsTheCpuFix)
{
  PW_SKIP_WITHOUT_KOKKOS();
  const std::string every7 = "neigh_modify every 7 delay 0 check no";
  const auto cpu = forces_by_step("fluid", every7, 30);
  const auto kk = forces_by_step("fluid", every7, 30, Accel::kokkos);
  // the same inline interpolation; the deposits are summed in another order (atomics),
  // so p and its gradient agree to round-off: 1e-12 of the largest force
  double largest = 0.0, worst = 0.0;
  for (const auto &step : cpu)
    for (const auto &kv : step.second)
      for (int d = 0; d < 3; ++d) {
        largest = std::max(largest, std::fabs(kv.second[d]));
        worst = std::max(worst, std::fabs(kv.second[d] - kk.at(step.first).at(kv.first)[d]));
      }
  EXPECT_GT(largest, 0.0);
  EXPECT_LE(worst, 1e-12 * largest);
}

TEST(FixDarcyInterpolate, HeldForcesMpiMoveGrainsAsInSerial)
{
  // mpirun -np 2 and 3 via ctest: the grains move under the held fluid forces alone; ranks
  // re-neighbor together, so every rank refreshes on the same steps as a serial run
  auto run = [](MPI_Comm comm) {
    Lammps l(Accel::none, comm);
    moving_grains(l, "fluid", "", false);
    l.commands("compute push all reduce sumsq f_fl[1] f_fl[2] f_fl[3]\n"
               "thermo_style custom step c_push[1] c_push[2] c_push[3]\nthermo 100\nrun 100");
    EXPECT_GT(l.equal("c_push[1]+c_push[2]+c_push[3]"), 0.0);    // the fluid pushes grains
    return l.unwrapped();
  };
  const auto parallel = run(MPI_COMM_WORLD);
  const auto serial = run(MPI_COMM_SELF);
  // round-off: the deposits are summed over ranks in another order (as the other
  // darcy Mpi tests allow)
  EXPECT_LE(pwtest::max_abs_diff(parallel, serial), 1e-10);
}
