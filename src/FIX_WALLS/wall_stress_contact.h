// Grain–wall contact of fix wall/stress (MODEL.md §4), written once and called by the CPU
// fix, the KOKKOS fix and the unit tests.
#ifndef PW_WALL_STRESS_CONTACT_H
#define PW_WALL_STRESS_CONTACT_H

#include "pw_inline.h"

namespace porewater {

struct WallContact {
  double force_z;    // on the grain, ≤ 0; its reaction −force_z pushes the wall up
  double energy;     // ½ k_n δ² stored in the spring
};

// A grain of centre height z, radius r and vertical velocity v_z below a frictionless
// horizontal wall at z_wall (normal −z) moving at v_wall: linear spring k_n on the overlap
// δ = z + r − z_wall > 0 and viscous damping γ on the normal velocity relative to the wall.
PW_INLINE WallContact wall_contact(const double z, const double radius, const double v_z,
                                   const double z_wall, const double v_wall, const double kn,
                                   const double gamma)
{
  WallContact c = {0.0, 0.0};
  const double overlap = z + radius - z_wall;
  if (overlap <= 0.0) return c;
  const double force = -kn * overlap - gamma * (v_z - v_wall);
  c.force_z = force < 0.0 ? force : 0.0;    // a separating grain is released, never pulled
  c.energy = 0.5 * kn * overlap * overlap;
  return c;
}

}    // namespace porewater

#endif
