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
