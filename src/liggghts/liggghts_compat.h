// What this package needs from Debian's LIGGGHTS-PUBLIC 3.8 headers, in one place.
//
// LIGGGHTS 3.x is built on LAMMPS of 23 Nov 2013: `error->all(FLERR, const char *)` only
// (no fmt), `force->numeric`, FixConst masks of that era, `pack_comm`/`unpack_comm`,
// `Fix::restart(char *)`. Style creators are plain function pointers kept in
// `Force::pair_map` (public) and `Modify::fix_map` (private); see style_registry.h.
#ifndef PW_LIGGGHTS_COMPAT_H
#define PW_LIGGGHTS_COMPAT_H

#include "lammps.h"
#include "version.h"

#include <string>

namespace LAMMPS_NS {
class Fix;
class Pair;
}    // namespace LAMMPS_NS

namespace porewater_liggghts {

// The creator signatures of Modify::fix_map and Force::pair_map.
using FixCreator = LAMMPS_NS::Fix *(*) (LAMMPS_NS::LAMMPS *, int, char **);
using PairCreator = LAMMPS_NS::Pair *(*) (LAMMPS_NS::LAMMPS *);

template <class T> LAMMPS_NS::Fix *fix_creator(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}

template <class T> LAMMPS_NS::Pair *pair_creator(LAMMPS_NS::LAMMPS *lmp)
{
  return new T(lmp);
}

namespace detail {
constexpr bool same_text(const char *a, const char *b)
{
  return *a == *b && (*a == '\0' || same_text(a + 1, b + 1));
}
}    // namespace detail

// LIGGGHTS 3.x headers name the LAMMPS they fork; another base means another API.
static_assert(detail::same_text(LAMMPS_VERSION, "23 Nov 2013"),
              "these LIGGGHTS headers are not LIGGGHTS 3.x (LAMMPS 23 Nov 2013)");

// Error::all/one take `const char *`; these take the composed message.
[[noreturn]] void error_all(LAMMPS_NS::LAMMPS *lmp, const char *file, int line,
                            const std::string &message);
[[noreturn]] void error_one(LAMMPS_NS::LAMMPS *lmp, const char *file, int line,
                            const std::string &message);

// Rank 0 writes `text` to the screen and the log file (as LIGGGHTS' own messages).
void print_all(LAMMPS_NS::LAMMPS *lmp, const std::string &text);

}    // namespace porewater_liggghts

#endif
