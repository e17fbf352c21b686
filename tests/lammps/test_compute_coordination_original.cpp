// compute coordination/original against a hand-made configuration whose count by the
// original program's rules (src/core/analysis/original_contacts.h) is known: pairs that
// touch across the periodic x and y boundaries, a pair with a fixed grain, a pair just
// apart and a grain on the floor wall count nothing; one free pair inside the box counts.
// compute contact/atom on the same grains counts every touching pair.
#include "lammps_fixture.h"

using pwtest::Lammps;

namespace {

// radius 0.01 m; overlaps of 3 mm (within the pair style's limit of half a radius), the pair
// just apart has a 1 mm gap
const char *const grains =
    "units si\natom_style sphere\natom_modify map array\nboundary p p f\nnewton off\n"
    "comm_modify vel yes\nregion box block 0 0.2 0 0.2 0 0.2\ncreate_box 1 box\n"
    "create_atoms 1 single 0.005 0.1 0.1\ncreate_atoms 1 single 0.188 0.1 0.1\n"      // 1-2 across x
    "create_atoms 1 single 0.05 0.004 0.1\ncreate_atoms 1 single 0.05 0.187 0.1\n"    // 3-4 across y
    "create_atoms 1 single 0.1 0.1 0.1\ncreate_atoms 1 single 0.117 0.1 0.1\n"       // 5-6 counted
    "create_atoms 1 single 0.1 0.05 0.1\ncreate_atoms 1 single 0.1 0.067 0.1\n"      // 7-8, 8 fixed
    "create_atoms 1 single 0.1 0.15 0.1\ncreate_atoms 1 single 0.1 0.171 0.1\n"      // 9-10 apart
    "create_atoms 1 single 0.15 0.15 0.008\n"                                          // 11 on the floor
    "set type 1 diameter 0.02\nset type 1 density 2600\ntimestep 1e-6\n"
    "pair_style linear/coulomb\npair_coeff * * 1e7 1e7 0.5\n"
    "fix floor all wall/gran hooke 1e7 NULL 0.0 NULL 0.0 0 zplane 0.0 NULL\n"
    "group fixed id 8\n"
    "compute original all coordination/original fixed fixed\n"
    "compute contacts all contact/atom\ncompute native all reduce sum c_contacts\n"
    "thermo_style custom step c_original c_native\n";

void counts_as_the_original(pwtest::Accel accel)
{
  Lammps l(accel);
  l.commands(grains);
  l.command("run 0");
  // the per-grain counts of all ranks, by atom ID
  std::vector<double> counted(11);
  lammps_gather(l.lmp, const_cast<char *>("c_original"), 1, 1, counted.data());
  for (int id = 1; id <= 11; ++id)
    EXPECT_EQ(counted[id - 1], (id == 5 || id == 6) ? 1.0 : 0.0) << "grain " << id;
  // the mean over all 11 grains, the fixed one counting zero (the counts are exact; an
  // equal-style variable carries the mean to ~1e-16)
  EXPECT_NEAR(l.equal("c_original"), 2.0 / 11.0, 1e-14);
  // LAMMPS' own count: the pairs across x and y, the free pair and the one with the fixed grain
  EXPECT_EQ(l.equal("c_native"), 8.0);
}

// A run ends where the compute was last evaluated and the next one's setup re-lists the
// atoms at that same step: the count must follow them. Grain 11 is moved between the runs
// from the floor to touch grain 9 (no other pair changes); a list kept from the first run
// (LAMMPS 29Sep2021's build_one, lammps_compat.h) never had that pair and counts 2/11 again.
void counts_after_a_new_run_at_the_same_step(pwtest::Accel accel)
{
  Lammps l(accel);
  l.commands(grains);
  l.command("run 0");
  EXPECT_NEAR(l.equal("c_original"), 2.0 / 11.0, 1e-14);
  l.command("set atom 11 x 0.117 y 0.15 z 0.1");
  l.command("run 0");
  EXPECT_NEAR(l.equal("c_original"), 4.0 / 11.0, 1e-14);
}

}    // namespace

PW_TEST_CPU_AND_KOKKOS(ComputeCoordinationOriginal, CountsAsTheOriginalProgram,
                       counts_as_the_original)
PW_TEST_CPU_AND_KOKKOS(ComputeCoordinationOriginal, CountsTheGrainsOfANewRunAtTheSameStep,
                       counts_after_a_new_run_at_the_same_step)

// a bad keyword and an unknown group are named (one LAMMPS instance at a time)
TEST(ComputeCoordinationOriginal, NamesWhatItExpects)
{
  const std::string setup = std::string(grains).substr(0, std::string(grains).find("compute original"));
  {
    Lammps l;
    pwtest::expect_error(l, setup + "compute original all coordination/original frozen fixed\n",
                         "expects `fixed GROUP-ID`");
  }
  Lammps l;
  pwtest::expect_error(l, setup + "compute original all coordination/original fixed held\n",
                       "fixed: no group named held");
}
