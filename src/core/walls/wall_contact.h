// Grain–wall contact of fix wall/stress (doc/model.md §4) and the floor of fix nve/sphere/bed,
// written once: the laws, and the per-grain kernel of the CPU and KOKKOS wall/stress over a
// grain accessor G (grains/host_grains.h).
#ifndef PW_WALLS_WALL_CONTACT_H
#define PW_WALLS_WALL_CONTACT_H

#include "pw_inline.h"

namespace porewater {

// The velocity the grain–wall dashpot acts on (fix wall/stress keyword damping_velocity)
enum WallDampingVelocity {
  WALL_DAMPING_RELATIVE = 0,    // v_z − v_wall: grain and wall moving together feel none
  WALL_DAMPING_ABSOLUTE = 1     // v_z in the lab frame, as the original program (sphere)
};

struct WallContact {
  double force_z;      // on the grain, ≤ 0; its reaction −force_z pushes the wall up
  double energy;       // ½ k_n δ² stored in the spring
  double damping_z;    // the dashpot's share of force_z: force_z − (−k_n δ)
};

// A grain of centre height z, radius r and vertical velocity v_z below a frictionless
// horizontal wall at z_wall (normal −z) moving at v_wall: linear spring k_n on the overlap
// δ = z + r − z_wall > 0 and a dashpot γ on the grain's normal velocity, relative to the
// wall (WALL_DAMPING_RELATIVE) or in the lab frame (WALL_DAMPING_ABSOLUTE). The force is
// clipped so that it never pulls the grain towards the wall; the wall takes the reaction
// in both forms. The dashpot's pair of forces, −γ v_d on the grain and +γ v_d on the wall
// (v_d the damped velocity), dissipates γ v_d (v_z − v_wall): in the relative form
// γ (v_z − v_wall)² ≥ 0; in the absolute form nothing when grain and wall move together,
// and it feeds energy in when v_z and v_z − v_wall have opposite signs.
PW_INLINE WallContact wall_contact(const double z, const double radius, const double v_z,
                                   const double z_wall, const double v_wall, const double kn,
                                   const double gamma, const int velocity = WALL_DAMPING_RELATIVE)
{
  WallContact c = {0.0, 0.0, 0.0};
  const double overlap = z + radius - z_wall;
  if (overlap <= 0.0) return c;
  const double damped = velocity == WALL_DAMPING_ABSOLUTE ? v_z : v_z - v_wall;
  const double spring = -kn * overlap;
  const double force = spring - gamma * damped;
  c.force_z = force < 0.0 ? force : 0.0;    // a separating grain is released, never pulled
  c.energy = 0.5 * kn * overlap * overlap;
  c.damping_z = c.force_z - spring;
  return c;
}

// The floor of fix nve/sphere/bed: a fixed, frictionless, undamped plane at z_floor (normal
// +z) under a grain of centre height z and radius r. The linear spring k_n on the overlap
// δ = z_floor + r − z > 0 pushes it up; LAMMPS' fix wall/gran hooke with γ_n = μ = 0 is the
// same law, evaluated in another order (its force differs from this one by round-off).
PW_INLINE double floor_force(const double z, const double radius, const double z_floor,
                             const double kn)
{
  const double overlap = z_floor + radius - z;
  return overlap > 0.0 ? kn * overlap : 0.0;
}

// A dashpot on the wall's own vertical velocity (keyword plate_damping): the force on the
// wall, −γ_p v_wall. It damps the plate on the bed whatever the grains touching it do.
PW_INLINE double plate_damping_force(const double v_wall, const double gamma_plate)
{
  return -gamma_plate * v_wall;
}

// Every grain of the group against the wall: f_z += the contact force; sums {force on the
// wall, spring energy, zz virial, the dashpots' share of the force on the wall};
// per_atom(i, w) receives each grain's virial (the CPU fix keeps per-atom virials, the
// KOKKOS one only the global).
// per_atom for a CPU host that keeps per-atom virials as double* rows (LAMMPS' and
// LIGGGHTS' Fix::vatom): grain i's zz part; none when vatom is null
struct PerAtomVirialZZ {
  double **vatom;
  void operator()(int i, double w) const
  {
    if (vatom) vatom[i][2] += w;
  }
};

template <class G, class PerAtomVirial> struct WallContacts {
  static constexpr int count = 4;
  G g;
  PerAtomVirial per_atom;
  int groupbit;
  double z_wall, v_wall, kn, gamma;
  int damping_velocity;
  PW_INLINE void operator()(const int i, double *sums) const
  {
    if (!(g.mask(i) & groupbit)) return;
    const double z = g.x(i, 2), radius = g.radius(i);
    if (z + radius - z_wall <= 0.0) return;    // out of reach: adds nothing (most grains)
    const WallContact c = wall_contact(z, radius, g.v(i, 2), z_wall, v_wall, kn, gamma,
                                       damping_velocity);
    g.f(i, 2) += c.force_z;
    sums[0] -= c.force_z;
    sums[1] += c.energy;
    sums[3] -= c.damping_z;
    if (c.force_z != 0.0) {
      const double w = (z - z_wall) * c.force_z;
      sums[2] += w;
      per_atom(i, w);
    }
  }
};

}    // namespace porewater

#endif
