// The per-style test matrix, one harness for every style of the plugin. A style describes
// itself once as a StyleCase (test_style_matrix.cpp: its scenes, what is compared, how
// closely and why, its bad inputs); these tests run it:
//
//   KokkosEqualsCpu                  the scene with -sf kk equals the CPU run, and the /kk
//                                    style was the one that ran
//   RestartSplitRunEqualsUnsplitRun  write_restart half-way and read_restart in another lmp
//                                    process, as users run them: bit for bit (CPU; Kokkos...:
//                                    the same with -sf kk)
//   MpiDecompositionEqualsSerial     a run on MPI_COMM_WORLD equals a serial (MPI_COMM_SELF)
//                                    run on each rank; ctest runs every test named *Mpi*
//                                    again under mpirun -np 2 and -np 3 (KokkosMpi...: the
//                                    same with -sf kk, whose styles keep their state on the
//                                    host on several ranks and on the device on one)
//   BadInputNamesTheKeyword          each bad input stops with its message (CPU; Kokkos...:
//                                    the /kk style)
//
// The tests named Kokkos* are skipped on a LAMMPS without KOKKOS (PW_SKIP_WITHOUT_KOKKOS).
//
// The physics of each style (analytic solutions, native-style equivalence, energy budgets)
// is tested in its own test_*.cpp. This header defines the tests: include it in one file.
#ifndef PW_TEST_STYLE_MATRIX_H
#define PW_TEST_STYLE_MATRIX_H

#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace pwtest {

// a tolerance meaning: not compared in this test
const double NOT_COMPARED = -1.0;

// One quantity compared between two runs of a scene.
struct Observable {
  enum Kind { value, per_atom, field };
  Kind kind;
  // value: an equal-style expression ("f_w[1]", "ke"); per_atom: an atom property or a fix's
  // per-atom array of 3 columns ("x" (unwrapped), "omega", "f_fl"); field: a per-cell field
  // of the case's fix ("pressure"), read through Fix::extract (the restart test, whose runs
  // are lmp processes, compares it through the final restart file)
  std::string name;
  int size;             // field: the number of cells
  double kokkos, mpi;   // the largest |difference| allowed: /kk vs CPU, decomposed vs serial
  bool relative;        // ... as a fraction of the reference run's largest |value|
  double floor;         // if >= 0: the reference run's largest |value| must exceed it, so
                        // that the comparison cannot pass on a scene at rest

  Observable relative_to_largest() const
  {
    Observable o = *this;
    o.relative = true;
    return o;
  }
  Observable above(double smallest) const
  {
    Observable o = *this;
    o.floor = smallest;
    return o;
  }
};
inline Observable value(const std::string &expression, double kokkos, double mpi)
{
  return {Observable::value, expression, 1, kokkos, mpi, false, -1.0};
}
inline Observable per_atom(const std::string &name, double kokkos, double mpi)
{
  return {Observable::per_atom, name, 3, kokkos, mpi, false, -1.0};
}
inline Observable field(const std::string &name, int size, double kokkos, double mpi)
{
  return {Observable::field, name, size, kokkos, mpi, false, -1.0};
}

// A scene as LAMMPS input and how long it runs.
struct Scene {
  std::string setup;       // box, grains, contacts, settings
  std::string commands;    // the style's and its integrators' commands
  int steps;               // the run (the restart test: before write_restart, and again after)
};

// How a run goes on from its restart file.
struct RestartSplit {
  Scene scene;
  std::string before_read;    // what must come before read_restart (e.g. newton off)
  std::string settings;       // what a restart file does not carry (variables, comm,
                              // neighbor, thermo, fixes without state)
  std::string commands;       // the style's and its integrators' commands, issued again
  // optional control: commands instead of `commands` that lose the stored state; the run
  // must then move some grain by more than `control_moves` (the test can see a lost state)
  std::string control;
  double control_moves = 0;
};

// Commands that must stop with an error whose message contains `needle`.
struct BadInput {
  enum Under { cpu_and_kokkos, cpu, kokkos };
  std::string input;
  std::string needle;
  std::string setup;    // after the scene, before `input`: must succeed
  std::string scene;    // instead of the case's bad-input scene, if not empty
  Under under;
};

struct StyleCase {
  std::string name;      // the tests' suffix, e.g. FixWallStress
  std::string style;     // e.g. "wall/stress": the CPU runs use it, the /kk runs style + "/kk"
  std::string fix_id;    // the fix of that style in the scenes; empty for a pair style
  // > 0: the grains of the MPI scene start within a quarter of this spacing of the sites of
  // a lattice, and the MPI test matches per-atom values by starting site (create_atoms
  // numbers grains by rank); 0: by atom ID, as the other tests do
  double lattice = 0;
  std::vector<Observable> observables;
  Scene kokkos;          // KokkosEqualsCpu
  Scene mpi;             // MpiDecompositionEqualsSerial
  RestartSplit restart;  // RestartSplitRunEqualsUnsplitRun
  std::string bad_scene;  // the scene the bad inputs are given in
  std::vector<BadInput> bad_inputs;
};

// gtest prints a failing test's parameter: its name, not its bytes
inline void PrintTo(const StyleCase &c, std::ostream *os) { *os << c.name; }

// ---- runs in this process -------------------------------------------------------------

using Site = std::array<long, 3>;

// what one run observed: per observable its numbers, per-atom ones in the order of `sites`
struct Snapshot {
  std::string style;    // the case's style as LAMMPS resolved it
  std::vector<Site> sites;
  std::vector<std::vector<double>> observed;
};

inline bool is_rank0()
{
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  return me == 0;
}

// the scene on `comm`, with or without KOKKOS; per-atom values by starting site or atom ID
inline Snapshot run_scene(const StyleCase &c, const Scene &scene, Accel accel, MPI_Comm comm,
                          bool by_site = false)
{
  Lammps l(accel, comm);
  l.commands(scene.setup);
  l.commands(scene.commands);
  Snapshot s;
  s.style = c.fix_id.empty() ? l.pair_style() : l.fix_style(c.fix_id);
  std::map<long, Site> key;    // by atom ID
  std::map<Site, long> id;
  for (const auto &kv : l.gather3("x")) {
    Site site = {kv.first, 0, 0};
    if (by_site)
      for (int d = 0; d < 3; d++) site[d] = std::lround(2.0 * kv.second[d] / c.lattice);
    key[kv.first] = site;
    id[site] = kv.first;
  }
  if (id.size() != key.size()) throw std::runtime_error(c.name + ": two grains on one site");
  for (const auto &kv : id) s.sites.push_back(kv.first);

  l.command("run " + std::to_string(scene.steps));
  for (const Observable &o : c.observables) {
    std::vector<double> numbers;
    if (o.kind == Observable::value) {
      numbers.push_back(l.equal(o.name));
    } else if (o.kind == Observable::field) {
      numbers = l.fix_field(c.fix_id, o.name.c_str(), o.size);
    } else {
      const auto by_id = o.name == "x" ? l.unwrapped() : l.gather3(o.name);
      for (const auto &kv : id) {
        const auto &v = by_id.at(kv.second);
        numbers.insert(numbers.end(), v.begin(), v.end());
      }
    }
    s.observed.push_back(numbers);
  }
  return s;
}

inline double largest_magnitude(const std::vector<double> &v)
{
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

// `other` equals `reference` within each observable's tolerance for this test (`mpi`: the
// decomposed-vs-serial one, else /kk-vs-CPU)
inline void expect_close(const StyleCase &c, const Snapshot &reference, const Snapshot &other,
                         bool mpi, const std::string &what)
{
  ASSERT_FALSE(reference.sites.empty());
  ASSERT_EQ(reference.sites, other.sites) << what << ": not the same grains";
  std::string report = "[ report ] " + c.name + " " + what + ":";
  for (size_t k = 0; k < c.observables.size(); k++) {
    const Observable &o = c.observables[k];
    const double largest = largest_magnitude(reference.observed[k]);
    if (o.floor >= 0) EXPECT_GT(largest, o.floor) << o.name << ": the scene is at rest";
    const double tolerance = mpi ? o.mpi : o.kokkos;
    if (tolerance < 0) continue;
    const double diff = max_abs_diff(reference.observed[k], other.observed[k]);
    char line[160];
    std::snprintf(line, sizeof(line), o.relative ? " %s %.1e of %.1e" : " %s %.1e", o.name.c_str(),
                  diff, largest);
    report += line;
    EXPECT_LE(diff, o.relative ? tolerance * largest : tolerance) << what << ": " << o.name;
  }
  if (is_rank0()) std::printf("%s\n", report.c_str());
}

// ---- runs in lmp processes of their own -----------------------------------------------

inline std::vector<double> read_values(const std::string &name)
{
  std::ifstream in(name + ".values");
  if (!in) throw std::runtime_error("no file " + name + ".values");
  std::vector<double> out;
  double v;
  while (in >> v) out.push_back(v);
  return out;
}

// the dump columns of a per-atom observable
inline std::string dump_columns(const Observable &o)
{
  if (o.name == "x") return " xu yu zu";
  if (o.name.compare(0, 2, "f_") == 0 || o.name.compare(0, 2, "c_") == 0)
    return " " + o.name + "[1] " + o.name + "[2] " + o.name + "[3]";
  return " " + o.name + "x " + o.name + "y " + o.name + "z";
}

// Commands that write, at the end of a script run by run_lmp, the case's observables to
// `name`.values (equal-style ones, 17 digits) and `name`.dump (per-atom ones by atom ID),
// and the final state to `name`.end.restart.
inline std::string save_results(const StyleCase &c, const std::string &name)
{
  std::string print = "print \"", columns = "id";
  for (const Observable &o : c.observables) {
    if (o.kind == Observable::value) print += "$(" + o.name + ":%.17g) ";
    if (o.kind == Observable::per_atom) columns += dump_columns(o);
  }
  return print + "\" file " + name + ".values screen no\n" + "write_dump all custom " + name +
      ".dump " + columns + " modify sort id format float %.17g\n" + "write_restart " + name +
      ".end.restart\n";
}

// The largest |value| of each value and per-atom observable in the files save_results wrote
// (fields: 0)
inline std::vector<double> largest_saved(const StyleCase &c, const std::string &name)
{
  const std::vector<double> values = read_values(name);
  const auto atoms = read_dump(name + ".dump");
  std::vector<double> largest;
  size_t value = 0, column = 0;
  for (const Observable &o : c.observables) {
    double m = 0.0;
    if (o.kind == Observable::value) m = std::fabs(values.at(value++));
    if (o.kind == Observable::per_atom) {
      for (const auto &kv : atoms)
        for (int k = 0; k < 3; k++) m = std::max(m, std::fabs(kv.second.at(column + k)));
      column += 3;
    }
    largest.push_back(m);
  }
  return largest;
}

inline std::string file_bytes(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("no file " + path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// the files run_lmp and save_results left for `name`
inline void remove_results(const std::string &name)
{
  for (const char *ext : {".values", ".dump", ".restart", ".end.restart"})
    std::remove((name + ext).c_str());
  std::remove(("in." + name).c_str());
  std::remove(("log." + name).c_str());
}

// Two dumps hold the same grains with the same values, bit for bit (17 printed digits), if
// `expect_identical`. Returns the largest |difference| in each column after id.
inline std::vector<double> compare_dumps(const std::string &a, const std::string &b,
                                         bool expect_identical, const std::string &what)
{
  const auto da = read_dump(a + ".dump"), db = read_dump(b + ".dump");
  EXPECT_EQ(da.size(), db.size()) << what;
  int differ = 0;
  std::vector<double> worst(da.begin()->second.size(), 0.0);
  for (const auto &kv : da) {
    const auto other = db.find(kv.first);
    if (other == db.end()) {
      ADD_FAILURE() << what << ": atom " << kv.first << " is missing from " << b << ".dump";
      continue;
    }
    for (size_t k = 0; k < worst.size(); k++)
      worst[k] = std::max(worst[k], std::fabs(kv.second.at(k) - other->second.at(k)));
    if (kv.second != other->second && differ++ == 0 && expect_identical)
      ADD_FAILURE() << what << ": atom " << kv.first << " differs (the first of the atoms that do)";
  }
  if (expect_identical) EXPECT_EQ(differ, 0) << what << ": atoms whose values differ";
  return worst;
}

// the first of the dump columns (after id) of per-atom observable `name`
inline size_t dump_column(const StyleCase &c, const std::string &name)
{
  size_t column = 0;
  for (const Observable &o : c.observables) {
    if (o.kind != Observable::per_atom) continue;
    if (o.name == name) return column;
    column += 3;
  }
  throw std::runtime_error(c.name + ": no per-atom observable " + name);
}

// ---- the tests ------------------------------------------------------------------------

class StyleMatrix : public ::testing::TestWithParam<StyleCase> {};

TEST_P(StyleMatrix, KokkosEqualsCpu)
{
  PW_SKIP_WITHOUT_KOKKOS();
  const StyleCase &c = GetParam();
  const Snapshot cpu = run_scene(c, c.kokkos, Accel::none, MPI_COMM_WORLD);
  const Snapshot kk = run_scene(c, c.kokkos, Accel::kokkos, MPI_COMM_WORLD);
  EXPECT_EQ(cpu.style, c.style);
  EXPECT_EQ(kk.style, c.style + "/kk");
  expect_close(c, cpu, kk, false, "/kk vs CPU after " + std::to_string(c.kokkos.steps) + " steps");
}

// under mpirun -np 2 and 3 (ctest lammps.test_style_matrix.np2, .np3) a run decomposed
// over the ranks against a serial run on each rank; with one rank serial against serial
inline void expect_decomposition_equals_serial(const StyleCase &c, Accel accel)
{
  const bool by_site = c.lattice > 0;
  const Snapshot parallel = run_scene(c, c.mpi, accel, MPI_COMM_WORLD, by_site);
  const Snapshot serial = run_scene(c, c.mpi, accel, MPI_COMM_SELF, by_site);
  EXPECT_EQ(parallel.style, c.style + (accel == Accel::kokkos ? "/kk" : ""));
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  expect_close(c, serial, parallel, true,
               std::to_string(ranks) + " ranks vs serial after " + std::to_string(c.mpi.steps) +
                   " steps" + (accel == Accel::kokkos ? " (/kk)" : ""));
}

TEST_P(StyleMatrix, MpiDecompositionEqualsSerial)
{
  expect_decomposition_equals_serial(GetParam(), Accel::none);
}

TEST_P(StyleMatrix, KokkosMpiDecompositionEqualsSerial)
{
  PW_SKIP_WITHOUT_KOKKOS();
  expect_decomposition_equals_serial(GetParam(), Accel::kokkos);
}

// Separate lmp processes, as users run them: within one process LAMMPS 29Sep2021 names the
// contacts' history fix by a process-wide pair counter, so a second instance would not find
// the histories in the restart file. The same operations in the same order: every value and
// per-atom value bit for bit (17 printed digits), and the final restart files, which hold
// all of the state (velocities, spins, contact histories, the styles' own state such as the
// wall's motion or the pressure field), byte for byte. `accel`: lmp's acceleration switches.
inline void expect_restart_split_equals_unsplit(const StyleCase &c, const std::string &accel)
{
  const RestartSplit &r = c.restart;
  const std::string run = "run " + std::to_string(r.scene.steps) + "\n";
  {
    const std::string tag = c.name + (accel.empty() ? "_cpu" : "_kk");
    const std::string whole = "pw_whole_" + tag, split = "pw_split_" + tag,
                      control = "pw_control_" + tag;
    run_lmp(r.scene.setup + r.scene.commands + run + "write_restart " + split + ".restart\n" +
                run + save_results(c, whole),
            accel, whole);
    // 4Feb2025 writes into the file's header whether the input gave `atom_modify map`
    // (Atom::map_user), which read_restart does not restore (the map itself it does): the
    // resumed input repeats the command, as the same final file needs it to
    const std::string map = "atom_modify map array\n";
    const std::string resume = (r.scene.setup.find(map) != std::string::npos ? map : "") +
        r.before_read + "read_restart " + split + ".restart\n" + r.settings;
    run_lmp(resume + r.commands + run + save_results(c, split), accel, split);

    const std::vector<double> largest = largest_saved(c, whole);
    for (size_t k = 0; k < c.observables.size(); k++)
      if (c.observables[k].floor >= 0 && c.observables[k].kind != Observable::field)
        EXPECT_GT(largest[k], c.observables[k].floor)
            << tag << ": " << c.observables[k].name << ": the scene is at rest";
    EXPECT_EQ(read_values(split), read_values(whole)) << tag;
    compare_dumps(whole, split, true, tag);
    EXPECT_TRUE(file_bytes(whole + ".end.restart") == file_bytes(split + ".end.restart"))
        << tag << ": the final restart files differ";

    if (!r.control.empty()) {
      run_lmp(resume + r.control + run + save_results(c, control), accel, control);
      const std::vector<double> lost = compare_dumps(whole, control, false, tag);
      const size_t x = dump_column(c, "x");
      const double moved = std::max(lost.at(x), std::max(lost.at(x + 1), lost.at(x + 2)));
      std::printf("[ report ] %s: without the stored state the run differs by %.2e\n",
                  tag.c_str(), moved);
      EXPECT_GT(moved, r.control_moves) << tag;
      remove_results(control);
    }
    remove_results(whole);
    remove_results(split);
  }
}

TEST_P(StyleMatrix, RestartSplitRunEqualsUnsplitRun)
{
  expect_restart_split_equals_unsplit(GetParam(), "");
}

TEST_P(StyleMatrix, KokkosRestartSplitRunEqualsUnsplitRun)
{
  PW_SKIP_WITHOUT_KOKKOS();
  expect_restart_split_equals_unsplit(GetParam(), "-k on t 1 -sf kk");
}

// each of the case's bad inputs meant for `accel` stops with its message; returns how many
inline int expect_bad_inputs_named(const StyleCase &c, Accel accel)
{
  int tried = 0;
  for (const BadInput &b : c.bad_inputs) {
    if ((b.under == BadInput::cpu && accel == Accel::kokkos) ||
        (b.under == BadInput::kokkos && accel == Accel::none))
      continue;
    SCOPED_TRACE((accel == Accel::kokkos ? "/kk: " : "cpu: ") + b.input);
    tried++;
    Lammps l(accel);
    try {
      l.commands(b.scene.empty() ? c.bad_scene : b.scene);
      l.commands(b.setup);
    } catch (std::exception &e) {
      ADD_FAILURE() << "the commands before the bad input failed: " << e.what();
      continue;
    }
    expect_error(l, b.input, b.needle);
  }
  return tried;
}

TEST_P(StyleMatrix, BadInputNamesTheKeyword)
{
  EXPECT_GT(expect_bad_inputs_named(GetParam(), Accel::none), 0);
}

TEST_P(StyleMatrix, KokkosBadInputNamesTheKeyword)
{
  PW_SKIP_WITHOUT_KOKKOS();
  EXPECT_GT(expect_bad_inputs_named(GetParam(), Accel::kokkos), 0);
}

}    // namespace pwtest

#endif
