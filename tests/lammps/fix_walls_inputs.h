// Scenes for the tests of fix wall/stress, shear/stress and nve/sphere/ty3, as LAMMPS input.
#ifndef PW_TEST_FIX_WALLS_INPUTS_H
#define PW_TEST_FIX_WALLS_INPUTS_H

#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace pwtest {

// grains of diameter 1 and mass 1
const std::string unit_grains = "set type 1 diameter 1.0\nset type 1 density 1.90985931710274\n";

// An nx × ny × nz simple cubic stack of touching grains (centres at half-integers) in a box
// periodic in x and y, bounded (f) in z from 0 to zhi; group `bottom` is the lowest layer and
// `mobile` the rest. Frictionless contacts of stiffness kn (newton off, as pair
// linear/coulomb/kk needs). No integrator, no wall.
inline std::string cubic_stack(int nx, int ny, int nz, double zhi, double kn = 1.0e4)
{
  auto s = [](double v) {
    return std::to_string(v);
  };
  return "units lj\natom_style sphere\natom_modify map array\nboundary p p f\nnewton off\n"
         "comm_modify vel yes\n"
         "lattice sc 1.0 origin 0.5 0.5 0.5\n"
         "region box block 0 " +
      s(nx) + " 0 " + s(ny) + " 0 " + s(zhi) +
      " units box\n"
      "create_box 1 box\n"
      "region stack block 0 " +
      s(nx) + " 0 " + s(ny) + " 0 " + s(nz) +
      " units box\n"
      "create_atoms 1 region stack\n" +
      unit_grains + "pair_style linear/coulomb\npair_coeff * * " + s(kn) +
      " 0 0\n"
      "neighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\n"
      "region low block INF INF INF INF INF 1 units box\n"
      "group bottom region low\ngroup mobile subtract all bottom\n";
}

// `x` keyed by the lattice site each grain started on (from `x0`, centres at half-integers)
// instead of by atom ID: create_atoms numbers the grains differently on different numbers
// of ranks
inline std::map<long, std::vector<double>> by_site(const std::map<long, std::vector<double>> &x0,
                                                   const std::map<long, std::vector<double>> &x)
{
  std::map<long, std::vector<double>> out;
  for (const auto &kv : x0) {
    const auto &p = kv.second;
    const long site =
        std::lround(2 * p[0]) + 1000 * (std::lround(2 * p[1]) + 1000 * std::lround(2 * p[2]));
    out[site] = x.at(kv.first);
  }
  return out;
}

// Commands that write, at the end of a script run by pwtest::run_lmp, the values of
// `expressions` (e.g. "f_w[1]") to `name`.values and all positions to `name`.dump.
inline std::string save_results(const std::string &name,
                                const std::vector<std::string> &expressions)
{
  std::string print = "print \"";
  for (const auto &e : expressions) print += "$(" + e + ":%.17g) ";
  return print + "\" file " + name + ".values screen no\n" + "write_dump all custom " + name +
      ".dump id x y z modify sort id format float %.17g\n";
}

inline std::vector<double> read_values(const std::string &name)
{
  std::ifstream in(name + ".values");
  std::vector<double> out;
  double v;
  while (in >> v) out.push_back(v);
  if (out.empty()) throw std::runtime_error("no values in " + name + ".values");
  return out;
}

// the files run_lmp, save_results and write_restart left for `name`
inline void remove_results(const std::string &name)
{
  for (const char *ext : {".values", ".dump", ".restart"}) std::remove((name + ext).c_str());
  std::remove(("in." + name).c_str());
  std::remove(("log." + name).c_str());
}

// A restart-split run (`split`) reproduces the unsplit one (`whole`) bit for bit: every
// saved value and every position, as printed with 17 digits. Removes both runs' files.
inline void expect_identical_results(const std::string &whole, const std::string &split,
                                     const std::string &tag)
{
  EXPECT_EQ(read_values(split), read_values(whole)) << tag;
  EXPECT_EQ(max_abs_diff(read_dump(whole + ".dump"), read_dump(split + ".dump")), 0.0) << tag;
  remove_results(whole);
  remove_results(split);
}

}    // namespace pwtest

#endif
