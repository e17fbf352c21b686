// Reading a restart file whose fix state does not fit the command that picks it up: the run
// stops with a message that says what differs (the fix's grid and its seepage force here;
// the header checks of every fix's state are unit-tested in tests/unit/test_input.cpp).
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

// a restart file of fix fl on the 2 x 2 x 4 grid with these fluid keywords, after 3 steps
void write_fluid_restart(Accel accel, const std::string &fluid, const std::string &file)
{
  Lammps l(accel);
  l.commands(BOX);
  l.command("fix fl all darcy/pressure grid 2 2 4 " + fluid);
  l.command("run 3");
  l.command("write_restart " + file);
}

void another_grid_is_refused(Accel accel)
{
  const std::string file = accel == Accel::none ? "pw_mismatch.restart" : "pw_mismatch_kk.restart";
  write_fluid_restart(accel, FLUID, file);
  Lammps l(accel);
  l.command("read_restart " + file);
  pwtest::expect_error(l, "fix fl all darcy/pressure grid 2 2 5 " + FLUID,
                       "the grid of the restart file (2x2x4 cells of 0.5 x 0.5 x 0.25 from (0, 0, 0)) "
                       "differs from this command's (2x2x5 cells of 0.5 x 0.5 x 0.2 from (0, 0, 0))");
  std::remove(file.c_str());
}

// the force on the grains is part of the run's model: a continuation with the other refuses
void another_seepage_is_refused(Accel accel)
{
  const std::string file = accel == Accel::none ? "pw_seepage.restart" : "pw_seepage_kk.restart";
  write_fluid_restart(accel, FLUID + " seepage full", file);
  {
    Lammps l(accel);
    l.command("read_restart " + file);
    pwtest::expect_error(l, "fix fl all darcy/pressure grid 2 2 4 " + FLUID,
                         "the restart file's run had seepage full, this command has seepage "
                         "pressure: continue with the force the run started with");
  }
  Lammps l(accel);
  l.command("read_restart " + file);
  l.command("fix fl all darcy/pressure grid 2 2 4 " + FLUID + " seepage full initial 0");
  l.command("run 0");
  EXPECT_GT(l.equal("f_fl[3]"), 1.0);    // the restarted p, not the command's initial 0
  std::remove(file.c_str());
}

}    // namespace

PW_TEST_CPU_AND_KOKKOS(RestartMismatch, FluidStateOfAnotherGridIsRefusedNamingBothGrids,
                       another_grid_is_refused)
PW_TEST_CPU_AND_KOKKOS(RestartMismatch, FluidStateOfTheOtherSeepageForceIsRefusedNamingBoth,
                       another_seepage_is_refused)

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
