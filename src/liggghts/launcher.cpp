#include "launcher.h"

#include "error.h"
#include "input.h"
#include "signal_handling.h"
#include "universe.h"

#include <mpi.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#ifndef PW_LIGGGHTS_VERSION_PREFIX
#error "PW_LIGGGHTS_VERSION_PREFIX (e.g. \"LIGGGHTS-PUBLIC 3.8.0\") comes from CMake"
#endif

using namespace LAMMPS_NS;

namespace porewater_liggghts {
namespace {

bool is(const char *arg, const char *name, const char *abbrev = nullptr)
{
  return strcmp(arg, name) == 0 || (abbrev && strcmp(arg, abbrev) == 0);
}

// How many values follow a LIGGGHTS command-line switch, as LAMMPS::LAMMPS parses them.
// -1: one, then every word up to the next "-..." (-partition); -2: two, then the same (-var).
int switch_values(const char *arg)
{
  if (is(arg, "-partition", "-p")) return -1;
  if (is(arg, "-var", "-v")) return -2;
  if (is(arg, "-seedtolerant", "-st") || is(arg, "-wb") || is(arg, "-nocite", "-nc") ||
      is(arg, "-help", "-h"))
    return 0;
  if (is(arg, "-reorder", "-ro") || is(arg, "-restart", "-r")) return 2;
  if (is(arg, "-restart_offset", "-roff")) return 3;
  return 1;    // -in -screen -log -echo -pscreen -plog -cuda -domain -suffix -uid -thermo
}

// The command line with -restart/-restart_offset taken out: LIGGGHTS runs that conversion
// inside its constructor, before any style could be added, so the launcher runs it itself.
struct CommandLine {
  std::vector<char *> args;    // for LAMMPS_NS::LAMMPS
  std::vector<std::string> restart;    // restart file, data file[, tag offset]
  bool help = false;
};

CommandLine split_command_line(int argc, char **argv)
{
  CommandLine line;
  line.args.push_back(argv[0]);
  int i = 1;
  while (i < argc) {
    const char *sw = argv[i];
    const int n = switch_values(sw);
    int end = i + 1;
    if (n >= 0) {
      end = std::min(argc, i + 1 + n);
    } else {
      end = std::min(argc, i + 1 + (n == -2 ? 2 : 1));
      while (end < argc && argv[end][0] != '-') ++end;
    }
    const bool restart = is(sw, "-restart", "-r") || is(sw, "-restart_offset", "-roff");
    if (restart && end == i + 1 + n) {
      line.restart.assign(argv + i + 1, argv + end);
    } else {
      line.help = line.help || is(sw, "-help", "-h");
      line.args.insert(line.args.end(), argv + i, argv + end);
    }
    i = end;
  }
  line.args.push_back(nullptr);
  return line;
}

void install_signal_handlers()
{
  struct sigaction int_action, usr1_action;
  memset(&int_action, 0, sizeof(int_action));
  memset(&usr1_action, 0, sizeof(usr1_action));
  int_action.sa_handler = SignalHandler::int_handler;
  sigaction(SIGINT, &int_action, nullptr);
  // Open MPI turns a SIGINT to mpirun into a SIGTERM to the ranks (as LIGGGHTS' main)
  sigaction(SIGTERM, &int_action, nullptr);
  usr1_action.sa_handler = SignalHandler::usr1_handler;
  sigaction(SIGUSR1, &usr1_action, nullptr);
}

// This executable was compiled against one LIGGGHTS' headers; the library that loaded must
// be that LIGGGHTS (class layouts are not checked by the dynamic linker).
void check_library_version(LAMMPS *lmp)
{
  // Universe::version reads "Version LIGGGHTS-PUBLIC 3.8.0, compiled ..."
  const std::string version = lmp->universe->version ? lmp->universe->version : "";
  const std::string expected = std::string("Version ") + PW_LIGGGHTS_VERSION_PREFIX;
  const char after = version.size() > expected.size() ? version[expected.size()] : '\0';
  if (version.compare(0, expected.size(), expected) == 0 && (after == ',' || after == '\0'))
    return;
  const std::string message = std::string("porewater was built for ") +
      PW_LIGGGHTS_VERSION_PREFIX + ", but the LIGGGHTS library is " + version +
      ": rebuild it (bash scripts/setup.sh)";
  lmp->error->universe_all(FLERR, message.c_str());
}

}    // namespace

int run_launcher(int argc, char **argv, RegisterFunction fn)
{
  install_signal_handlers();
  MPI_Init(&argc, &argv);

  CommandLine line = split_command_line(argc, argv);
  if (line.help) {
    int me = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &me);
    if (me == 0) printf("Styles added by porewater: %s\n\n", style_names(fn).c_str());
  }

  LAMMPS *lmp = new LAMMPS(static_cast<int>(line.args.size()) - 1, line.args.data(),
                           MPI_COMM_WORLD);
  check_library_version(lmp);
  const std::string names = install_styles(lmp, fn);
  if (!names.empty()) print_all(lmp, "porewater styles: " + names);

  if (line.restart.empty()) {
    lmp->input->file();
  } else {
    // as LAMMPS::LAMMPS does for -restart / -restart_offset
    lmp->input->one(("read_restart " + line.restart[0]).c_str());
    std::string write = "write_data " + line.restart[1];
    if (line.restart.size() == 3 && atoi(line.restart[2].c_str()) != 0)
      write += " tag_offset " + line.restart[2];
    lmp->input->one(write.c_str());
  }
  delete lmp;

  MPI_Finalize();
  return 0;
}

}    // namespace porewater_liggghts
