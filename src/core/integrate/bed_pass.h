// The per-grain passes of fix nve/sphere/bed (doc/fix_nve_sphere_bed.rst), shared by the CPU
// fix and its KOKKOS variant over a grain accessor G (grains/host_grains.h). One pass over
// the grains does what LAMMPS' own fixes do in six (wall/gran as a floor, gravity, setforce
// 0 0 NULL with nve on the held base, nve/sphere on the rest), with their arithmetic, so
// that the grains move bit for bit as under those fixes; the floor's law
// (walls/wall_contact.h) is wall/gran's evaluated in another order, equal to round-off.
#ifndef PW_INTEGRATE_BED_PASS_H
#define PW_INTEGRATE_BED_PASS_H

#include "pw_inline.h"
#include "walls/wall_contact.h"

namespace porewater {

// The step sizes of velocity Verlet as LAMMPS' fix nve and nve/sphere compute them:
// dtf = ½Δt·ftm2v, dtv = Δt, and dtfrotate = dtf/0.4 for a solid sphere (I = 0.4 m r²)
struct VerletSteps {
  double dtf, dtv, dtfrotate;
};
PW_INLINE VerletSteps verlet_steps(const double dt, const double ftm2v)
{
  const double dtf = 0.5 * dt * ftm2v;
  return {dtf, dt, dtf / 0.4};
}

// Half a kick of grain i: v += ½Δt f/m, ω += ½Δt T/I; a held grain only v_z (its x- and
// y-forces ignored, as if zeroed; no rotation)
template <class G>
PW_INLINE void bed_kick(const G &g, const int i, const bool held, const VerletSteps &s)
{
  const double dtfm = s.dtf / g.rmass(i);
  if (held) {
    g.v(i, 2) += dtfm * g.f(i, 2);
    return;
  }
  for (int k = 0; k < 3; k++) g.v(i, k) += dtfm * g.f(i, k);
  const double r = g.radius(i);
  const double dtirotate = s.dtfrotate / (r * r * g.rmass(i));
  for (int k = 0; k < 3; k++) g.omega(i, k) += dtirotate * g.torque(i, k);
}

// before the forces: half a kick, then the drift x += Δt v (fix nve/sphere updates ω after
// x; neither reads the other, so the bits are the same)
template <class G> struct BedInitial {
  G g;
  int groupbit, heldbit;
  VerletSteps steps;
  PW_INLINE void operator()(const int i) const
  {
    const int mask = g.mask(i);
    if (!(mask & groupbit)) return;
    bed_kick(g, i, (mask & heldbit) != 0, steps);
    for (int k = 0; k < 3; k++) g.x(i, k) += steps.dtv * g.v(i, k);
  }
};

// after the forces: the second half kick
template <class G> struct BedFinal {
  G g;
  int groupbit, heldbit;
  VerletSteps steps;
  PW_INLINE void operator()(const int i) const
  {
    const int mask = g.mask(i);
    if (mask & groupbit) bed_kick(g, i, (mask & heldbit) != 0, steps);
  }
};

// the body forces, in the order of the fixes they replace: the floor on the fix's grains,
// then gravity −m g ẑ on those of its own group (any group, as fix gravity)
template <class G> struct BedForces {
  G g;
  int groupbit, gravitybit;
  int floor;    // 0: no floor
  double z_floor, kn;
  double gravity_z;    // the acceleration along z, −g (force/mass units, as fix gravity's)
  PW_INLINE void operator()(const int i) const
  {
    const int mask = g.mask(i);
    // most grains are out of the floor's reach: they add nothing, as under wall/gran
    if (floor && (mask & groupbit) && g.x(i, 2) - g.radius(i) < z_floor)
      g.f(i, 2) += floor_force(g.x(i, 2), g.radius(i), z_floor, kn);
    if (mask & gravitybit) g.f(i, 2) += g.rmass(i) * gravity_z;
  }
};

}    // namespace porewater

#endif
