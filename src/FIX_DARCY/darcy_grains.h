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

// x - x is NaN for inf and NaN: a grain with a non-finite position or velocity
PW_INLINE bool grain_is_finite(double x0, double x1, double x2, double v0, double v1, double v2)
{
  const double sum = x0 + x1 + x2 + v0 + v1 + v2;
  return sum - sum == 0.0;
}

// What one grain of volume V and velocity v deposits with weights w at x and weights wp at
// the predicted position: s*V and s*V*v at x, s*V at x + v*interval, per stencil corner c.
// add(c, q, value) accumulates quantity q (0: volume, 1-3: momentum x, y, z; 4: predicted
// volume) of corner c.
template <class Add>
PW_INLINE void deposit_corners(const double w[8], const double wp[8], double volume,
                               double v0, double v1, double v2, const Add &add)
{
  double sv[8];    // quantity by quantity over the corners: contiguous runs of 8 to vectorise
  for (int c = 0; c < 8; ++c) sv[c] = w[c] * volume;
  for (int c = 0; c < 8; ++c) add(c, 0, sv[c]);
  for (int c = 0; c < 8; ++c) add(c, 1, sv[c] * v0);
  for (int c = 0; c < 8; ++c) add(c, 2, sv[c] * v1);
  for (int c = 0; c < 8; ++c) add(c, 3, sv[c] * v2);
  for (int c = 0; c < 8; ++c) add(c, 4, wp[c] * volume);
}

// Deposit one grain of volume V at x with velocity v into the cells of its stencils (see
// deposit_corners). add(slot, value) accumulates (a plain += on the CPU, an atomic add in
// a KOKKOS kernel). A grain whose position or velocity is not finite deposits nothing
// and is counted instead.
template <class Add>
PW_INLINE void deposit_grain(const GridGeom &g, const DepositLayout &layout, double x0,
                             double x1, double x2, double v0, double v1, double v2,
                             double volume, double interval, const Add &add)
{
  if (!grain_is_finite(x0, x1, x2, v0, v1, v2)) {
    add(layout.nonfinite(), 1.0);
    return;
  }
  int idx[8], pidx[8];
  double w[8], pw[8];
  stencil(g, x0, x1, x2, idx, w);
  stencil(g, x0 + v0 * interval, x1 + v1 * interval, x2 + v2 * interval, pidx, pw);
  deposit_corners(w, pw, volume, v0, v1, v2, [&](int c, int q, double value) {
    if (q == 0) add(layout.volume(idx[c]), value);
    else if (q < 4) add(layout.momentum(idx[c]) + q - 1, value);
    else add(layout.predicted_volume(pidx[c]), value);
  });
}

// The lattice cells ("blocks") of 2x2x2 cell centres that stencils span, for summing
// deposits per block and corner (contiguous, no per-corner cell index) and folding them
// into the cells once per fluid step; and for a per-block table of the corner values of
// a field. Block (i0, j0, k0): i0, j0 wrapped periodically, k0 in [-1, nz-1], which holds
// every point less than half a cell below or above the grid.
struct StencilBlocks {
  int nx, ny, nz;
  PW_INLINE int count() const { return nx * ny * (nz + 1); }
  // the block of a stencil base, -1 if it lies further outside the grid in z
  PW_INLINE int block(const StencilBase &b) const
  {
    if (b.k0 < -1 || b.k0 >= nz) return -1;
    return wrap_index(b.i0, nx) + nx * (wrap_index(b.j0, ny) + ny * (b.k0 + 1));
  }
  // a base of that block (fractions 0), for corner_cells
  PW_INLINE StencilBase base(int block) const
  {
    return StencilBase{block % nx, (block / nx) % ny, block / (nx * ny) - 1, 0.0, 0.0, 0.0};
  }
};

// The 3 components of a cell-centre vector field (interleaved xyz) at the 8 cells idx,
// corner-major and padded to 4 (so that the components are summed side by side):
// out[4*c + d], out[4*c + 3] = 0.
PW_INLINE void corner_vectors(const double *field, const int idx[8], double out[32])
{
  for (int c = 0; c < 8; ++c) {
    for (int d = 0; d < 3; ++d) out[4 * c + d] = field[3 * idx[c] + d];
    out[4 * c + 3] = 0.0;
  }
}

// Fluid force f = -V (grad p + rho_f g) on a grain of volume V: grad p interpolated with
// the stencil weights w from the gradients at the 8 stencil cells (corner_vectors); the
// second term is buoyancy (rho_g = rho_f g).
PW_INLINE void fluid_force_from_corners(const double corner_gradient[32], const double rho_g[3],
                                        const double w[8], double volume, double f[3])
{
  double sum[4] = {0.0, 0.0, 0.0, 0.0};
  for (int c = 0; c < 8; ++c)
    for (int d = 0; d < 4; ++d) sum[d] += w[c] * corner_gradient[4 * c + d];
  for (int d = 0; d < 3; ++d) f[d] = -volume * (sum[d] + rho_g[d]);
}

// The same for a grain at x, from the cell-centre gradients (interleaved xyz).
PW_INLINE void fluid_force(const GridGeom &g, const double *pressure_gradient,
                           const double rho_g[3], double x0, double x1, double x2,
                           double volume, double f[3])
{
  int idx[8];
  double w[8], corner_gradient[32];
  stencil(g, x0, x1, x2, idx, w);
  corner_vectors(pressure_gradient, idx, corner_gradient);
  fluid_force_from_corners(corner_gradient, rho_g, w, volume, f);
}

}  // namespace porewater

#endif
