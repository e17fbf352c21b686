// What an equal-style variable's formula reads, as far as its text tells: the first of its
// terms that reads per-atom data (LAMMPS' and LIGGGHTS' variable syntax), for the styles'
// `variables global` promise (a /kk style then copies no atom array to the host before it
// evaluates the variable), so that a formula that breaks the promise visibly is refused.
#ifndef PW_INPUT_FORMULA_H
#define PW_INPUT_FORMULA_H

#include <functional>
#include <string>

namespace porewater {

// The first term of `formula` that reads per-atom data, described ("xcm(), a group
// function"), or "" if its text names none: group functions, per-atom values (x[5]),
// computes (c_ID: a compute reads the atoms), the thermo keywords summed over the atoms
// (pe, temp, press, ...) and, through `formula_of` (the formula of another variable, "" if
// unknown), the equal-style variables it names (v_name); fixes' values (f_ID), time, step,
// numbers and the box's keywords read none.
std::string atom_data_read_by(const std::string &formula,
                              const std::function<std::string(const std::string &)> &formula_of,
                              int depth = 0);

}    // namespace porewater

#endif
