// Reading a restart file whose fix state does not fit the command that picks it up: the run
// stops with a message that says what differs (the fix's grid here; the header checks of
// every fix's state are unit-tested in tests/unit/test_input.cpp).
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

using pwtest::Accel;
using pwtest::Lammps;

namespace {
const char *BOX = "units lj\natom_style sphere\nboundary p p f\nregion box block 0 1 0 1 0 1\n"
                  "create_box 1 box\ntimestep 0.01\n";
const std::string FLUID = "viscosity 1 compressibility 1 density 1 permeability 1 initial 5";
}    // namespace

namespace {

void another_grid_is_refused(Accel accel)
{
  const std::string file = accel == Accel::none ? "pw_mismatch.restart" : "pw_mismatch_kk.restart";
  {
    Lammps l(accel);
    l.commands(BOX);
    l.command("fix fl all darcy/pressure grid 2 2 4 " + FLUID);
    l.command("run 3");
    l.command("write_restart " + file);
  }
  Lammps l(accel);
  l.command("read_restart " + file);
  pwtest::expect_error(l, "fix fl all darcy/pressure grid 2 2 5 " + FLUID,
                       "the grid of the restart file (2x2x4 cells of 0.5 x 0.5 x 0.25 from (0, 0, 0)) "
                       "differs from this command's (2x2x5 cells of 0.5 x 0.5 x 0.2 from (0, 0, 0))");
  std::remove(file.c_str());
}

}    // namespace

PW_TEST_CPU_AND_KOKKOS(RestartMismatch, FluidStateOfAnotherGridIsRefusedNamingBothGrids,
                       another_grid_is_refused)

TEST(RestartMismatch, FluidStateOfTheSameGridCarriesOn)
{
  {
    Lammps l;
    l.commands(BOX);
    l.command("fix fl all darcy/pressure grid 2 2 4 " + FLUID);
    l.command("run 3");
    l.command("write_restart pw_match.restart");
  }
  Lammps l;
  l.command("read_restart pw_match.restart");
  l.command("fix fl all darcy/pressure grid 2 2 4 viscosity 1 compressibility 1 density 1 "
            "permeability 1 initial 0");
  l.command("run 0");
  // the restarted p (relaxing from 5 towards the top's 0), not the command's initial 0
  EXPECT_GT(l.equal("f_fl[3]"), 1.0);
  std::remove("pw_match.restart");
}
