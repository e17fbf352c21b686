// Drives LAMMPS through its C++ library interface for the tests: one instance per object,
// with the porewater plugin loaded, plain or with KOKKOS (OpenMP) and -sf kk. What the host
// LAMMPS has (KOKKOS or not, its version) comes from CMake (src/lammps/CMakeLists.txt).
#ifndef PW_TEST_LAMMPS_FIXTURE_H
#define PW_TEST_LAMMPS_FIXTURE_H

#include "atom.h"
#include "domain.h"
#include "fix.h"
#include "force.h"
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

#if !defined(PW_HOST_KOKKOS) || !defined(PW_HOST_VERSION)
#error "tests/lammps/CMakeLists.txt defines PW_HOST_KOKKOS and PW_HOST_VERSION"
#endif

namespace pwtest {

enum class Accel { none, kokkos };

// whether the host LAMMPS has the KOKKOS package: the plugin has /kk styles only then
constexpr bool host_has_kokkos = PW_HOST_KOKKOS != 0;
// the host's LAMMPS version as a number, e.g. 20210929, 20250204
constexpr long host_version = PW_HOST_VERSION;

}    // namespace pwtest

// The first statement of every test that runs a /kk style: on a LAMMPS without KOKKOS the
// test is skipped, saying why (ctest reports it as skipped), never passed without
// running. Tests that also check CPU physics keep that in a CPU test of their own.
#define PW_SKIP_WITHOUT_KOKKOS()                                                            \
  if (!pwtest::host_has_kokkos)                                                             \
  GTEST_SKIP() << "this LAMMPS has no KOKKOS package, so the plugin has no /kk styles"

// Two tests of one check: suite.name runs check(Accel::none), suite.Kokkos<name> runs
// check(Accel::kokkos) and is skipped on a LAMMPS without KOKKOS.
#define PW_TEST_CPU_AND_KOKKOS(suite, name, check)                                          \
  TEST(suite, name) { check(pwtest::Accel::none); }                                          \
  TEST(suite, Kokkos##name)                                                                  \
  {                                                                                          \
    PW_SKIP_WITHOUT_KOKKOS();                                                                \
    check(pwtest::Accel::kokkos);                                                            \
  }

// The first statement of a test of commands that only LAMMPS since `version` has.
#define PW_SKIP_BEFORE_LAMMPS(version, what)                                                \
  if (pwtest::host_version < (version))                                                     \
  GTEST_SKIP() << "LAMMPS " << pwtest::host_version << " has no " << (what)

namespace pwtest {

// Only one instance may exist at a time: LAMMPS keeps the list of loaded plugins per
// process, so a second live instance would not see the plugin's styles.
class Lammps {
 public:
  explicit Lammps(Accel accel = Accel::none, MPI_Comm comm = MPI_COMM_WORLD,
                  std::vector<std::string> extra = {})
  {
    std::vector<std::string> args = {"lmp", "-log", "none", "-screen", "none", "-nocite"};
    if (accel == Accel::kokkos && !host_has_kokkos)
      throw std::logic_error("a /kk run on a LAMMPS without KOKKOS: the test must begin with "
                             "PW_SKIP_WITHOUT_KOKKOS()");
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

  // per-atom 3-vector of all atoms by tag (gathered over ranks): an atom property ("x",
  // "v", "omega") or a fix's or compute's per-atom array of 3 columns ("f_fl", "c_id")
  std::map<long, std::vector<double>> gather3(const std::string &name)
  {
    const long natoms = (long) lmp->atom->natoms;
    std::vector<double> data(3 * natoms);
    char *cname = const_cast<char *>(name.c_str());
    if (name.compare(0, 2, "f_") == 0 || name.compare(0, 2, "c_") == 0)
      lammps_gather(lmp, cname, 1, 3, data.data());
    else
      lammps_gather_atoms(lmp, cname, 1, 3, data.data());
    std::map<long, std::vector<double>> out;
    for (long i = 0; i < natoms; i++)
      out[i + 1] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
    return out;
  }

  // the style of fix `id` ("" if there is none) and of the pair style
  std::string fix_style(const std::string &id)
  {
    const int i = lmp->modify->find_fix(id);
    return i < 0 ? "" : lmp->modify->fix[i]->style;
  }
  std::string pair_style() { return lmp->force->pair_style ? lmp->force->pair_style : ""; }

  // a per-cell field of fix `id` (flat, x fastest) via Fix::extract, e.g. "pressure"
  std::vector<double> fix_field(const std::string &id, const char *name, int size)
  {
    int dim = 0;
    LAMMPS_NS::Fix *fix = lmp->modify->fix[lmp->modify->find_fix(id)];
    const double *data = (const double *) fix->extract(name, dim);
    if (!data) throw std::runtime_error("fix " + id + " has no field " + name);
    return std::vector<double>(data, data + size);
  }

  LAMMPS_NS::LAMMPS *lmp;
};

// largest component-wise difference of two arrays of numbers
inline double max_abs_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  if (a.size() != b.size()) throw std::runtime_error("max_abs_diff: sizes differ");
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); i++) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

// largest component-wise difference of two gathered per-atom arrays
inline double max_abs_diff(const std::map<long, std::vector<double>> &a,
                           const std::map<long, std::vector<double>> &b)
{
  double worst = 0.0;
  for (const auto &kv : a) worst = std::max(worst, max_abs_diff(kv.second, b.at(kv.first)));
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

// the rows of a write_dump custom file whose first column is id (e.g. id xu yu zu), by id
inline std::map<long, std::vector<double>> read_dump(const std::string &file)
{
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line) && line.rfind("ITEM: ATOMS", 0) != 0) {}
  if (line.rfind("ITEM: ATOMS", 0) != 0) throw std::runtime_error("no atoms in dump " + file);
  std::istringstream header(line.substr(11));
  std::string column;
  int columns = 0;
  while (header >> column) columns++;
  std::map<long, std::vector<double>> out;
  long id;
  while (columns > 1 && in >> id) {
    std::vector<double> row(columns - 1);
    for (double &v : row) in >> v;
    out[id] = row;
  }
  if (out.empty()) throw std::runtime_error("no atoms in dump " + file);
  return out;
}

}    // namespace pwtest

#endif
