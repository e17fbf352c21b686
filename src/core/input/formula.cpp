#include "input/formula.h"

#include <cctype>
#include <set>

namespace porewater {

namespace {

// LAMMPS' group functions and its per-atom vectors in a formula (name( and name[)
const std::set<std::string> GROUP_FUNCTIONS = {
    "count", "mass", "charge", "xcm", "vcm", "fcm", "bound", "gyration", "ke", "angmom",
    "torque", "inertia", "omega"};
const std::set<std::string> ATOM_VALUES = {"id", "mass", "type", "mol", "radius", "q", "x", "y",
                                           "z", "vx", "vy", "vz", "fx", "fy", "fz"};
// thermo keywords whose value is a sum over the atoms (the others: time, step, the box, counts)
const std::set<std::string> ATOM_THERMO = {
    "temp", "press", "pe", "ke", "etotal", "enthalpy", "evdwl", "ecoul", "epair", "ebond",
    "eangle", "edihed", "eimp", "emol", "elong", "etail", "density", "pxx", "pyy", "pzz",
    "pxy", "pxz", "pyz", "fmax", "fnorm", "ecouple", "econserve"};

}    // namespace

std::string atom_data_read_by(const std::string &formula,
                              const std::function<std::string(const std::string &)> &formula_of,
                              int depth)
{
  const size_t n = formula.size();
  for (size_t i = 0; i < n;) {
    const char c = formula[i];
    if (!(std::isalpha((unsigned char) c) || c == '_')) {
      // a number's exponent (1e5) is not a name
      if (std::isdigit((unsigned char) c) || c == '.')
        while (i < n && (std::isalnum((unsigned char) formula[i]) || formula[i] == '.')) ++i;
      else
        ++i;
      continue;
    }
    size_t j = i;
    while (j < n && (std::isalnum((unsigned char) formula[j]) || formula[j] == '_')) ++j;
    const std::string name = formula.substr(i, j - i);
    const char next = j < n ? formula[j] : '\0';
    i = j;
    if (name.compare(0, 2, "c_") == 0) return name + ", a compute";
    if (name.compare(0, 2, "v_") == 0 && depth < 20) {
      const std::string inner = formula_of(name.substr(2));
      const std::string read = atom_data_read_by(inner, formula_of, depth + 1);
      if (!read.empty()) return read + " in variable " + name.substr(2);
      continue;
    }
    if (name.compare(0, 2, "f_") == 0) continue;
    if (next == '(' && GROUP_FUNCTIONS.count(name)) return name + "(), a group function";
    if (next == '[' && ATOM_VALUES.count(name)) return name + "[], a per-atom value";
    if (next != '(' && ATOM_THERMO.count(name)) return name + ", a thermo keyword over the atoms";
  }
  return "";
}

}    // namespace porewater
