// Drives LAMMPS through its C++ library interface for the tests: one instance per object,
// with the porewater plugin loaded, plain or with KOKKOS (OpenMP) and -sf kk.
#ifndef PW_TEST_LAMMPS_FIXTURE_H
#define PW_TEST_LAMMPS_FIXTURE_H

#include "atom.h"
#include "domain.h"
#include "input.h"
#include "lammps.h"
#include "library.h"
#include "modify.h"
#include "variable.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace pwtest {

enum class Accel { none, kokkos };

// Only one instance may exist at a time: LAMMPS keeps the list of loaded plugins per
// process, so a second live instance would not see the plugin's styles.
class Lammps {
 public:
  explicit Lammps(Accel accel = Accel::none, MPI_Comm comm = MPI_COMM_WORLD,
                  std::vector<std::string> extra = {})
  {
    std::vector<std::string> args = {"lmp", "-log", "none", "-screen", "none", "-nocite"};
    if (accel == Accel::kokkos) args.insert(args.end(), {"-k", "on", "t", "1", "-sf", "kk"});
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char *> argv;
    for (auto &a : args) argv.push_back(const_cast<char *>(a.c_str()));
    lmp = new LAMMPS_NS::LAMMPS((int) argv.size(), argv.data(), comm);
    command(std::string("plugin load ") + PW_PLUGIN_PATH);
  }
  ~Lammps() { delete lmp; }
  Lammps(const Lammps &) = delete;
  Lammps &operator=(const Lammps &) = delete;

  // one command; a LAMMPS error becomes a C++ exception with its message
  void command(const std::string &line) { lmp->input->one(line); }
  // several newline-separated commands
  void commands(const std::string &block)
  {
    std::istringstream in(block);
    std::string line;
    while (std::getline(in, line))
      if (line.find_first_not_of(" \t") != std::string::npos) command(line);
  }
  double thermo(const char *keyword) { return lammps_get_thermo(lmp, keyword); }
  double equal(const std::string &expr)
  {
    command("variable pwtest_tmp equal " + expr);
    return lmp->input->variable->compute_equal("v_pwtest_tmp");
  }
  LAMMPS_NS::Atom *atom() { return lmp->atom; }

  // a per-atom 3-vector of the atom with this tag (serial runs), e.g. atom()->omega
  const double *of_tag(double **array, long tag) { return array[lmp->atom->map(tag)]; }

  // unwrapped positions of all atoms by tag, so a grain that crossed a periodic boundary
  // compares by its true displacement
  std::map<long, std::vector<double>> unwrapped()
  {
    auto x = gather3("x");
    const long natoms = (long) lmp->atom->natoms;
    std::vector<int> image(natoms);
    lammps_gather_atoms(lmp, const_cast<char *>("image"), 0, 1, image.data());
    for (long i = 0; i < natoms; i++) {
      double xi[3] = {x[i + 1][0], x[i + 1][1], x[i + 1][2]};
      double u[3];
      lmp->domain->unmap(xi, (LAMMPS_NS::imageint) image[i], u);
      x[i + 1] = {u[0], u[1], u[2]};
    }
    return x;
  }

  // per-atom vector of all atoms by tag (gathered over ranks), e.g. "x", "v", "omega"
  std::map<long, std::vector<double>> gather3(const char *name)
  {
    const long natoms = (long) lmp->atom->natoms;
    std::vector<double> data(3 * natoms);
    lammps_gather_atoms(lmp, const_cast<char *>(name), 1, 3, data.data());
    std::map<long, std::vector<double>> out;
    for (long i = 0; i < natoms; i++)
      out[i + 1] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
    return out;
  }

  LAMMPS_NS::LAMMPS *lmp;
};

// largest component-wise difference of two gathered per-atom arrays
inline double max_abs_diff(const std::map<long, std::vector<double>> &a,
                           const std::map<long, std::vector<double>> &b)
{
  double worst = 0.0;
  for (const auto &kv : a) {
    const auto &u = kv.second;
    const auto &w = b.at(kv.first);
    for (int k = 0; k < 3; k++) worst = std::max(worst, std::abs(u[k] - w[k]));
  }
  return worst;
}

// `commands` must stop with a LAMMPS error whose message contains `needle`
inline void expect_error(Lammps &l, const std::string &commands, const std::string &needle)
{
  try {
    l.commands(commands);
    ADD_FAILURE() << "no error for: " << commands;
  } catch (std::exception &e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos)
        << commands << " -> " << e.what();
  }
}

// "{}" in `fmt` replaced by `arg`
inline std::string format(const std::string &fmt, const std::string &arg)
{
  std::string out = fmt;
  return out.replace(out.find("{}"), 2, arg);
}

// Runs our lmp on `script` (the plugin loaded first) in a separate process, as users do.
inline void run_lmp(const std::string &script, const std::string &args = "",
                    const std::string &name = "pwtest_subprocess")
{
  const std::string input = "in." + name;
  std::ofstream(input) << "plugin load " << PW_PLUGIN_PATH << "\n" << script;
  const std::string cmd = std::string(PW_LMP) + " -in " + input + " -log log." + name +
                          " -screen none " + args;
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("lmp failed: " + cmd);
}

// id xu yu zu rows of a write_dump custom file, by atom id
inline std::map<long, std::vector<double>> read_dump(const std::string &file)
{
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line) && line.rfind("ITEM: ATOMS", 0) != 0) {}
  std::map<long, std::vector<double>> out;
  long id;
  double x, y, z;
  while (in >> id >> x >> y >> z) out[id] = {x, y, z};
  if (out.empty()) throw std::runtime_error("no atoms in dump " + file);
  return out;
}

}    // namespace pwtest

#endif
