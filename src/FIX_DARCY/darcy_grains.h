// Grain <-> grid coupling of fix darcy/pressure (MODEL.md §3), shared by the CPU fix and
// its KOKKOS kernels: what one grain deposits on the grid and the fluid force it feels.
// Device-safe like darcy_kernels.h.
#ifndef PW_DARCY_GRAINS_H
#define PW_DARCY_GRAINS_H

#include "darcy_kernels.h"

namespace porewater {

PW_INLINE double sphere_volume(double radius)
{
  return 4.0 / 3.0 * 3.14159265358979323846 * radius * radius * radius;
}

// All deposits of one fluid step in one array, so that one reduction sums them over ranks:
// [solid volume at x (n) | solid momentum at x (3n, xyz interleaved) | solid volume at the
// predicted position x + v*interval (n) | number of grains skipped as non-finite (1)],
// n = number of cells.
struct DepositLayout {
  int ncells;
  PW_INLINE int size() const { return 5 * ncells + 1; }
  PW_INLINE int volume(int cell) const { return cell; }
  PW_INLINE int momentum(int cell) const { return ncells + 3 * cell; }
  PW_INLINE int predicted_volume(int cell) const { return 4 * ncells + cell; }
  PW_INLINE int nonfinite() const { return 5 * ncells; }
};

// Deposit one grain of volume V at x with velocity v: s*V and s*V*v at x and s*V at
// x + v*interval, with the stencil's weights s. add(slot, value) accumulates (a plain
// += on the CPU, an atomic add in a KOKKOS kernel). A grain whose position or velocity
// is not finite deposits nothing and is counted instead (x - x is NaN for inf and NaN).
// This overload also returns the stencil of x in idx, w (for fluid_force_from_stencil on
// the same positions) and whether the grain was finite (idx, w are unset when not).
template <class Add>
PW_INLINE bool deposit_grain(const GridGeom &g, const DepositLayout &layout, double x0,
                             double x1, double x2, double v0, double v1, double v2,
                             double volume, double interval, const Add &add, int idx[8],
                             double w[8])
{
  const double sum = x0 + x1 + x2 + v0 + v1 + v2;
  if (!(sum - sum == 0.0)) {
    add(layout.nonfinite(), 1.0);
    return false;
  }
  stencil(g, x0, x1, x2, idx, w);
  for (int c = 0; c < 8; ++c) {
    const double sv = w[c] * volume;
    add(layout.volume(idx[c]), sv);
    add(layout.momentum(idx[c]) + 0, sv * v0);
    add(layout.momentum(idx[c]) + 1, sv * v1);
    add(layout.momentum(idx[c]) + 2, sv * v2);
  }
  int pidx[8];
  double pw[8];
  stencil(g, x0 + v0 * interval, x1 + v1 * interval, x2 + v2 * interval, pidx, pw);
  for (int c = 0; c < 8; ++c) add(layout.predicted_volume(pidx[c]), pw[c] * volume);
  return true;
}

template <class Add>
PW_INLINE void deposit_grain(const GridGeom &g, const DepositLayout &layout, double x0,
                             double x1, double x2, double v0, double v1, double v2,
                             double volume, double interval, const Add &add)
{
  int idx[8];
  double w[8];
  deposit_grain(g, layout, x0, x1, x2, v0, v1, v2, volume, interval, add, idx, w);
}

// Fluid force f = -V (grad p + rho_f g) on a grain of volume V at x: grad p interpolated
// from the cell-centre gradients (interleaved xyz) with the deposition stencil; the
// second term is buoyancy (rho_g = rho_f g).
// The same from the grain's stencil (idx, w), e.g. the one deposit_grain returned.
PW_INLINE void fluid_force_from_stencil(const double *pressure_gradient, const double rho_g[3],
                                        const int idx[8], const double w[8], double volume,
                                        double f[3])
{
  for (int d = 0; d < 3; ++d)
    f[d] = -volume * (interpolate(pressure_gradient + d, 3, idx, w) + rho_g[d]);
}

PW_INLINE void fluid_force(const GridGeom &g, const double *pressure_gradient,
                           const double rho_g[3], double x0, double x1, double x2,
                           double volume, double f[3])
{
  int idx[8];
  double w[8];
  stencil(g, x0, x1, x2, idx, w);
  fluid_force_from_stencil(pressure_gradient, rho_g, idx, w, volume, f);
}

}  // namespace porewater

#endif
