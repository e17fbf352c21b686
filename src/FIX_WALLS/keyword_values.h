// Parsing keyword values of the fixes in this folder, with errors that name the fix and the
// keyword. Uses LAMMPS: include from fix sources only.
#ifndef PW_KEYWORD_VALUES_H
#define PW_KEYWORD_VALUES_H

#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <string>

namespace porewater {

// `value` of `key` as a number; `alternatives` (e.g. " or auto") completes the error message
inline double keyword_number(LAMMPS_NS::LAMMPS *lmp, const std::string &style,
                             const std::string &key, const char *value,
                             const char *alternatives = "")
{
  if (!LAMMPS_NS::utils::is_double(value))
    lmp->error->all(FLERR, "Illegal fix {} command: {} must be a number{}, not {}", style, key,
                    alternatives, value);
  return LAMMPS_NS::utils::numeric(FLERR, value, false, lmp);
}

}    // namespace porewater

#endif
