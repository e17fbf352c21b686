// The rigid shear plate of fix shear/stress (doc/model.md §4): its acceleration, and the
// per-grain kernels of the CPU and KOKKOS fixes over a grain accessor G (grains/host_grains.h).
#ifndef PW_WALLS_SHEAR_PLATE_H
#define PW_WALLS_SHEAR_PLATE_H

#include "pw_inline.h"

namespace porewater {

// x-acceleration every grain of the plate shares: applied shear force τ·L_x·L_y plus the
// x-forces of all other interactions on the plate's grains, over the plate mass M.
PW_INLINE double plate_acceleration(const double tau, const double area, const double sum_fx,
                                    const double plate_mass)
{
  return (tau * area + sum_fx) / plate_mass;
}

// The plate between two force evaluations, and the step of its post_force that follows the
// group's sums {ΣF_x, Σ m x_unwrapped, Σ m} (summed over every rank): the one home of its
// bookkeeping, for RigidPlate (every host's CPU fix) and the device kernels of fix
// shear/stress/kk, which keep this state on the device between steps.
struct PlateState {
  double displacement;        // mass-weighted mean unwrapped x of the group − reference_x
  double reference_x;         // that mean where the displacement was zero
  double resisting_stress;    // −ΣF_x/(L_x L_y), ΣF_x before the plate's own force
  double force_per_mass;      // a_plate in force units per mass (a / ftm2v in LAMMPS)
};
enum PlateVerdict { PLATE_MOVING = 0, PLATE_EMPTY, PLATE_RAN_AWAY, PLATE_NOT_FINITE };
// What went wrong: the one-step displacement (PLATE_RAN_AWAY) or the acceleration
// (PLATE_NOT_FINITE) a message quotes.
struct PlateStepResult {
  int verdict;
  double value;
};
// A new run (setup) carries the displacement on from where it was; otherwise the plate may
// move at most `bound` (half the neighbor skin) in one step, beyond which contacts could be
// missed. After PLATE_EMPTY or PLATE_RAN_AWAY the state is as it was.
PW_INLINE PlateStepResult plate_post_force(PlateState &p, const double *sums, const bool setup,
                                           const double area, const double tau,
                                           const double plate_mass, const double force_to_velocity,
                                           const double bound)
{
  if (sums[2] <= 0.0) return PlateStepResult{PLATE_EMPTY, 0.0};
  const double mean_x = sums[1] / sums[2];
  const double reference_x = setup ? mean_x - p.displacement : p.reference_x;
  const double displacement = mean_x - reference_x;
  const double moved = displacement - p.displacement;
  if (!setup && !(moved <= bound && -moved <= bound)) return PlateStepResult{PLATE_RAN_AWAY, moved};
  const double a = plate_acceleration(tau, area, sums[0], plate_mass);
  p.reference_x = reference_x;
  p.displacement = displacement;
  p.resisting_stress = -sums[0] / area;
  if (!(a - a == 0.0)) return PlateStepResult{PLATE_NOT_FINITE, a};
  p.force_per_mass = a / force_to_velocity;
  return PlateStepResult{PLATE_MOVING, a};
}

// How a host packs a grain's periodic image counts into one integer, and the box lengths
// that unwrap them (an orthogonal box: Domain::h[0], h[5], h[4] of LAMMPS).
struct ImageUnwrap {
  long long mask, max;
  int bits, bits2;
  double xprd, xy, xz;
  // x of a grain at x with these images, as if it had never been wrapped
  template <class Image> PW_INLINE double x(const double x, const Image image) const
  {
    const long long packed = (long long) image;
    const int xbox = (int) ((packed & mask) - max);
    const int ybox = (int) ((packed >> bits & mask) - max);
    const int zbox = (int) ((packed >> bits2) - max);
    return x + xprd * xbox + xy * ybox + xz * zbox;
  }
};

// {ΣF_x, Σ m x_unwrapped, Σ m} over the plate's grains
template <class G> struct PlateSums {
  static constexpr int count = 3;
  G g;
  int groupbit;
  ImageUnwrap unwrap;
  PW_INLINE void operator()(const int i, double *sums) const
  {
    if (!(g.mask(i) & groupbit)) return;
    sums[0] += g.f(i, 0);
    sums[1] += g.rmass(i) * unwrap.x(g.x(i, 0), g.image(i));
    sums[2] += g.rmass(i);
  }
};

// {Σ m v_x, Σ m} over the plate's grains
template <class G> struct PlateMomentum {
  static constexpr int count = 2;
  G g;
  int groupbit;
  PW_INLINE void operator()(const int i, double *sums) const
  {
    if (!(g.mask(i) & groupbit)) return;
    sums[0] += g.rmass(i) * g.v(i, 0);
    sums[1] += g.rmass(i);
  }
};

// every grain of the plate its share m·a of the plate's x-force; y and rotation locked
template <class G> struct PlateMotion {
  G g;
  int groupbit;
  double force_per_mass;    // a_plate in force units per mass (a / ftm2v in LAMMPS)
  PW_INLINE void operator()(const int i) const
  {
    if (!(g.mask(i) & groupbit)) return;
    g.f(i, 0) = g.rmass(i) * force_per_mass;
    g.f(i, 1) = 0.0;
    g.v(i, 1) = 0.0;
    for (int k = 0; k < 3; k++) g.torque(i, k) = g.omega(i, k) = 0.0;
  }
};

// v_x = velocity for the plate's grains (one plate, one velocity)
template <class G> struct PlateVelocity {
  G g;
  int groupbit;
  double velocity;
  PW_INLINE void operator()(const int i) const
  {
    if (g.mask(i) & groupbit) g.v(i, 0) = velocity;
  }
};

}    // namespace porewater

#endif
