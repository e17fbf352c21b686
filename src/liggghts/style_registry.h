// Adding styles to a running LIGGGHTS without rebuilding it.
//
// LIGGGHTS has no `plugin` command: `pair_style` looks names up in Force::pair_map (public)
// and `fix` in Modify::fix_map (private). The launcher constructs LAMMPS_NS::LAMMPS, hands
// a StyleSink to a registration function and only then reads the input.
#ifndef PW_LIGGGHTS_STYLE_REGISTRY_H
#define PW_LIGGGHTS_STYLE_REGISTRY_H

#include "liggghts_compat.h"

namespace porewater_liggghts {

// Receives every style a registration function offers.
class StyleSink {
 public:
  virtual ~StyleSink() = default;
  virtual void fix(const char *name, FixCreator create) = 0;
  virtual void pair(const char *name, PairCreator create) = 0;
};

using RegisterFunction = void (*)(StyleSink &);

// The package's styles (register_styles.cpp: the only file that includes every style).
void register_styles(StyleSink &sink);

// Inserts the styles of `fn` into the maps of `lmp`; a name LIGGGHTS already has is an
// error (the stock style is never shadowed). Returns the names added, comma separated.
std::string install_styles(LAMMPS_NS::LAMMPS *lmp, RegisterFunction fn);

// The names `fn` offers ("fix a, fix b, pair c"), without a LAMMPS instance.
std::string style_names(RegisterFunction fn);

}    // namespace porewater_liggghts

#endif
