// Grain–wall contact of fix wall/stress (doc/model.md §4), written once: the law, and the
// per-grain kernel of the CPU and KOKKOS fixes over a grain accessor G (grains/host_grains.h).
#ifndef PW_WALLS_WALL_CONTACT_H
#define PW_WALLS_WALL_CONTACT_H

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

// Every grain of the group against the wall: f_z += the contact force; sums {force on the
// wall, spring energy, zz virial}; per_atom(i, w) receives each grain's virial (the CPU fix
// keeps per-atom virials, the KOKKOS one only the global).
template <class G, class PerAtomVirial> struct WallContacts {
  static constexpr int count = 3;
  G g;
  PerAtomVirial per_atom;
  int groupbit;
  double z_wall, v_wall, kn, gamma;
  PW_INLINE void operator()(const int i, double *sums) const
  {
    if (!(g.mask(i) & groupbit)) return;
    const WallContact c = wall_contact(g.x(i, 2), g.radius(i), g.v(i, 2), z_wall, v_wall, kn, gamma);
    g.f(i, 2) += c.force_z;
    sums[0] -= c.force_z;
    sums[1] += c.energy;
    if (c.force_z != 0.0) {
      const double w = (g.x(i, 2) - z_wall) * c.force_z;
      sums[2] += w;
      per_atom(i, w);
    }
  }
};

}    // namespace porewater

#endif
