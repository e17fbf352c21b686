// fix print/every: a line at every multiple of N, never at a run's setup, so that a run made
// of chunks writes each line once: the lines of LAMMPS' fix print with a variable N that
// names the next multiple (what examples/tidal_shear used), written beside it in the same
// runs, and the same with /kk.
#include "granular_inputs.h"
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

using pwtest::Accel;
using pwtest::Lammps;

namespace {

std::vector<std::string> lines_of(const std::string &file)
{
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// the frictional gas run in chunks that end on and between multiples of 5, the same text
// printed by print/every 5 and by LAMMPS' fix print with the next multiple as its N
void chunks_print_each_line_once(Accel accel)
{
  const std::string mine = accel == Accel::kokkos ? "every_kk.txt" : "every.txt";
  const std::string lammps = accel == Accel::kokkos ? "print_kk.txt" : "print.txt";
  {
    Lammps l(accel);
    l.commands(pwtest::frictional_gas());
    l.commands("variable s equal step\nvariable next equal (floor(step/5)+1)*5\n"
               "fix every all print/every 5 \"${s} $(ke:%.17g)\" file " + mine + " screen no title '# rows'\n"
               "fix print all print v_next \"${s} $(ke:%.17g)\" file " + lammps + " screen no title '# rows'\n");
    l.command("run 12");    // ends between multiples
    l.command("run 8");     // ends on one: the next run's setup at step 20 prints nothing
    l.command("run 10");
  }
  const auto every = lines_of(mine), print = lines_of(lammps);
  ASSERT_EQ(every.size(), 7u);    // the title, steps 5, 10, ..., 30
  EXPECT_EQ(every, print);
  for (int k = 1; k <= 6; ++k) EXPECT_EQ(every[k].substr(0, every[k].find(' ')), std::to_string(5 * k));
}

}    // namespace

PW_TEST_CPU_AND_KOKKOS(FixPrintEvery, ChunksPrintEachLineOnceAsFixPrintWithTheNextStep,
                       chunks_print_each_line_once)

TEST(FixPrintEvery, AppendKeepsTheFileAndAddsItsTitle)
{
  {
    Lammps l;
    l.commands(pwtest::frictional_gas());
    l.commands("fix every all print/every 4 \"$(step) first\" file appended.txt screen no\nrun 8\n");
  }
  {
    Lammps l;
    l.commands(pwtest::frictional_gas());
    l.commands("fix every all print/every 4 \"$(step) second\" append appended.txt screen no "
               "title '# continued'\nrun 4\n");
  }
  const std::vector<std::string> expected = {"# Fix print/every output for fix every", "4 first",
                                             "8 first", "# continued", "4 second"};
  EXPECT_EQ(lines_of("appended.txt"), expected);
}

TEST(FixPrintEvery, BadInputsNameTheKeyword)
{
  Lammps l;
  l.commands(pwtest::frictional_gas());
  const std::string fix = "fix p all print/every ";
  pwtest::expect_error(l, fix + "0 text", "N expects an integer >= 1, got '0'");
  pwtest::expect_error(l, fix + "v_n text", "N expects an integer >= 1, got 'v_n'");
  pwtest::expect_error(l, fix + "5", "text expects a string, but the command ends there");
  pwtest::expect_error(l, fix + "5 text screen maybe", "screen expects yes or no, got 'maybe'");
  pwtest::expect_error(l, fix + "5 text file", "file expects a file name, but the command ends there");
  pwtest::expect_error(l, fix + "5 text every 2",
                       "unknown keyword 'every' (allowed: file, append, screen, title)");
  pwtest::expect_error(l, fix + "5 text file /nonexistent/dir/rows.txt", "cannot open file");
}
