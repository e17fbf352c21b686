// Every style this package adds to LIGGGHTS: the only file that includes them all.
#include "style_registry.h"

#include "fix_darcy_pressure.h"
#include "fix_shear_stress.h"
#include "fix_wall_stress.h"

namespace porewater_liggghts {

void register_styles(StyleSink &sink)
{
  sink.fix("darcy/pressure", &fix_creator<FixDarcyPressure>);
  sink.fix("wall/stress", &fix_creator<FixWallStress>);
  sink.fix("shear/stress", &fix_creator<FixShearStress>);
}

}    // namespace porewater_liggghts
