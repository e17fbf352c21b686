// The motion of fix wall/stress's wall (doc/model.md §4) as functions of its state alone:
// the one home of its velocity Verlet, its force and its box check, for StressWall (every
// host's CPU fix) and for the device kernels of fix wall/stress/kk, which keep the state on
// the device between steps.
#ifndef PW_WALLS_WALL_MOTION_H
#define PW_WALLS_WALL_MOTION_H

#include "pw_inline.h"
#include "walls/wall_contact.h"

namespace porewater {

// The host's box in z, as the wall sees it at a force evaluation.
struct WallBox {
  double bottom, top;
  bool top_shrink_wrapped;    // a shrink-wrapped top follows the grains
  double area;                // L_x L_y
};

// The wall between two of its hooks.
struct WallState {
  double z, v;               // position; velocity (the half-step one from initial_integrate on)
  double force;              // on the wall at the last force evaluation: grain_force − S·L_x·L_y + plate_damping
  double grain_force;        // sum of the grains' contact forces on the wall (≥ 0)
  double grain_damping;      // the grain–wall dashpots' share of grain_force
  double plate_damping;      // the plate dashpot's force on the wall, −γ_p v
  double applied_stress;     // S at the last force evaluation
  double spring_energy;      // ½ k_n δ² summed over the grain–wall contacts
};

// half a velocity Verlet kick: v + ½Δt F/M
PW_INLINE void wall_kick(WallState &w, const double dt, const double mass)
{
  w.v += 0.5 * dt * w.force / mass;
}

// initial_integrate: the kick, then the drift z += Δt v
PW_INLINE void wall_initial_integrate(WallState &w, const double dt, const double mass)
{
  wall_kick(w, dt, mass);
  w.z += dt * w.v;
}

// post_force: the force on the wall from the grains' totals {force on the wall, spring
// energy, dashpots' share} (summed over every rank), the stress S and the plate dashpot
// on the half-step velocity, as the grains' contact forces use theirs
PW_INLINE void wall_post_force(WallState &w, const double grain_force, const double spring_energy,
                               const double grain_damping, const double stress, const double area,
                               const double gamma_plate)
{
  w.applied_stress = stress;
  w.grain_force = grain_force;
  w.spring_energy = spring_energy;
  w.grain_damping = grain_damping;
  w.plate_damping = plate_damping_force(w.v, gamma_plate);
  w.force = w.grain_force - w.applied_stress * area + w.plate_damping;
}

// Whether the wall is still in the box; a shrink-wrapped top follows the grains, so the
// wall may rise above it by the box's height
enum WallVerdict { WALL_IN_BOX = 0, WALL_NOT_FINITE, WALL_BELOW_BOX, WALL_ABOVE_BOX };
PW_INLINE double wall_box_top(const WallBox &box)
{
  return box.top_shrink_wrapped ? box.top + (box.top - box.bottom) : box.top;
}
PW_INLINE int wall_verdict(const WallState &w, const WallBox &box)
{
  // written so that a NaN is never in the box: every comparison with it is false
  const bool finite = w.z - w.z == 0.0 && w.v - w.v == 0.0;
  if (finite && w.z >= box.bottom && w.z <= wall_box_top(box)) return WALL_IN_BOX;
  if (!finite) return WALL_NOT_FINITE;
  return w.z < box.bottom ? WALL_BELOW_BOX : WALL_ABOVE_BOX;
}

}    // namespace porewater

#endif
