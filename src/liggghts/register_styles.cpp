// Every style this package adds to LIGGGHTS: the only file that includes them all.
#include "style_registry.h"

namespace porewater_liggghts {

void register_styles(StyleSink &sink)
{
  // The adapters (fix darcy/pressure, ...) over the engine-agnostic core are added here,
  // e.g. sink.fix("darcy/pressure", &fix_creator<FixDarcyPressureLiggghts>);
  (void) sink;
}

}    // namespace porewater_liggghts
