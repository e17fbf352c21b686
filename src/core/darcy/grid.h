// Header-only geometry of the Darcy pore-pressure grid (doc/model.md §3): cells, stencils,
// Kozeny-Carman, shared by the solver, the grain coupling and the KOKKOS kernels.
// Everything here is device-safe: PODs, raw pointers, ints, doubles and the <cmath>
// functions CUDA provides.
#ifndef PW_DARCY_GRID_H
#define PW_DARCY_GRID_H

#include "pw_inline.h"

#include <cmath>

namespace porewater {

// Cell-centred grid over [xlo, xlo+nx*dx) x [ylo, ylo+ny*dy) x [zlo, zlo+nz*dz],
// periodic in x and y. Cell (i,j,k) has flat index i + nx*(j + ny*k) and centre
// (xlo + (i+1/2) dx, ylo + (j+1/2) dy, zlo + (k+1/2) dz).
struct GridGeom {
  double xlo, ylo, zlo;
  double dx, dy, dz;
  int nx, ny, nz;
};

PW_INLINE int cell_count(const GridGeom &g) { return g.nx * g.ny * g.nz; }

PW_INLINE double cell_volume(const GridGeom &g) { return g.dx * g.dy * g.dz; }

PW_INLINE int cell_index(const GridGeom &g, int i, int j, int k)
{
  return i + g.nx * (j + g.ny * k);
}

// Periodic wrap of a cell index into [0, n). The stencil's indices lie in [-1, n] for
// grains inside the box: those skip the integer division (same result).
PW_INLINE int wrap_index(int i, int n)
{
  if (i >= 0 && i < n) return i;
  if (i == -1) return n - 1;
  if (i == n) return 0;
  const int r = i % n;
  return r < 0 ? r + n : r;
}

// floor(u) as an int for |u| <= 1e9 (cell_coordinate's range): truncate, then step down
// for negative non-integers. Equal to (int) floor(u) there, without the libm call (or its
// SSE2 emulation) that the host build makes of floor.
PW_INLINE int floor_to_int(double u)
{
  const int i = (int) u;
  return i - (u < (double) i ? 1 : 0);
}

// Mirror a layer index at the bottom face (cell -1 -> 0, -2 -> 1) and at the top face
// (cell n -> n-1): weight outside the grid is folded back, as if the grains were
// mirrored at the impermeable bottom and at the top.
PW_INLINE int mirror_index(int k, int n)
{
  if (k < 0) k = -1 - k;
  if (k >= n) k = 2 * n - 1 - k;
  return k < 0 ? 0 : (k >= n ? n - 1 : k);  // points more than a grid height outside
}

// 1-D hat weight: 1 - |d|/delta for |d| < delta, else 0.
PW_INLINE double hat_weight(double d, double delta)
{
  const double w = 1.0 - fabs(d) / delta;
  return w > 0.0 ? w : 0.0;
}

// Trilinear weight s(d) = prod_a (1 - |d_a|/Delta_a) of a point at offset d from a centre.
PW_INLINE double trilinear_weight(const GridGeom &g, double ddx, double ddy, double ddz)
{
  return hat_weight(ddx, g.dx) * hat_weight(ddy, g.dy) * hat_weight(ddz, g.dz);
}

// Kozeny-Carman permeability k = kc phi^3/(1-phi)^2, capped at kmax when kmax > 0.
PW_INLINE double kozeny_carman(double porosity, double kc, double kmax)
{
  const double solid = 1.0 - porosity;
  const double k = kc * porosity * porosity * porosity / (solid * solid);
  return (kmax > 0.0 && k > kmax) ? kmax : k;
}

// Harmonic mean of two face permeabilities (zero if either is zero: no flux).
PW_INLINE double harmonic_mean(double a, double b)
{
  return (a > 0.0 && b > 0.0) ? 2.0 * a * b / (a + b) : 0.0;
}

PW_INLINE double clamp_porosity(double porosity, double porosity_min, double porosity_max)
{
  return porosity < porosity_min ? porosity_min
                                 : (porosity > porosity_max ? porosity_max : porosity);
}

// u kept within +-1e9 (NaN to -1e9) so that stencil's int casts are defined for any
// input; callers that care check finiteness themselves. Comparisons, not fmin/fmax:
// those stay library calls without -ffinite-math-only.
PW_INLINE double cell_coordinate(double u)
{
  const double above = u > -1e9 ? u : -1e9;
  return above < 1e9 ? above : 1e9;
}

// Where a point sits in the lattice of cell centres: the centre (i0, j0, k0) at or below
// it in each axis (unwrapped, unmirrored) and its fractions f in [0, 1) towards the next.
struct StencilBase {
  int i0, j0, k0;
  double fx, fy, fz;
};

// The map of stencil_base from points to the lattice: origin and reciprocal spacings
// (a loop over grains builds it once rather than dividing per grain).
struct LatticeMap {
  double xlo, ylo, zlo;
  double inv_dx, inv_dy, inv_dz;
};

PW_INLINE LatticeMap lattice_map(const GridGeom &g)
{
  return LatticeMap{g.xlo, g.ylo, g.zlo, 1.0 / g.dx, 1.0 / g.dy, 1.0 / g.dz};
}

PW_INLINE StencilBase stencil_base(const LatticeMap &m, double x, double y, double z)
{
  // position in units of cells from centre 0
  const double ux = cell_coordinate((x - m.xlo) * m.inv_dx - 0.5);
  const double uy = cell_coordinate((y - m.ylo) * m.inv_dy - 0.5);
  const double uz = cell_coordinate((z - m.zlo) * m.inv_dz - 0.5);
  StencilBase b;
  b.i0 = floor_to_int(ux);
  b.j0 = floor_to_int(uy);
  b.k0 = floor_to_int(uz);
  b.fx = ux - b.i0;
  b.fy = uy - b.j0;
  b.fz = uz - b.k0;
  return b;
}

PW_INLINE StencilBase stencil_base(const GridGeom &g, double x, double y, double z)
{
  return stencil_base(lattice_map(g), x, y, z);
}

// Trilinear weights of the 8 corners c = a + 2b + 4e, (i0+a, j0+b, k0+e), of the base's
// lattice cell: the product of the 1-D weights 1 - f (a = 0) and f (a = 1) per axis.
PW_INLINE void corner_weights(const StencilBase &b, double w[8])
{
  const double wx[2] = {1.0 - b.fx, b.fx}, wy[2] = {1.0 - b.fy, b.fy};
  const double wz[2] = {1.0 - b.fz, b.fz};
  for (int c = 0; c < 8; ++c) w[c] = wx[c & 1] * wy[(c >> 1) & 1] * wz[c >> 2];
}

// The grid cells of those corners: wrapped in x and y, mirrored into the grid in z.
PW_INLINE void corner_cells(const GridGeom &g, const StencilBase &b, int idx[8])
{
  const int ii[2] = {wrap_index(b.i0, g.nx), wrap_index(b.i0 + 1, g.nx)};
  const int jj[2] = {wrap_index(b.j0, g.ny), wrap_index(b.j0 + 1, g.ny)};
  const int kk[2] = {mirror_index(b.k0, g.nz), mirror_index(b.k0 + 1, g.nz)};
  for (int c = 0; c < 8; ++c) idx[c] = cell_index(g, ii[c & 1], jj[(c >> 1) & 1], kk[c >> 2]);
}

// The 8 (cell index, weight) pairs of the trilinear stencil of point (x,y,z): equal to
// trilinear_weight(point - centre) for every cell, periodic in x and y, with the weight
// of cells below the bottom / above the top layer folded into the mirrored cells, so
// the weights always sum to 1 (deposited volume is conserved). Indices may repeat.
PW_INLINE void stencil(const GridGeom &g, double x, double y, double z, int idx[8],
                       double w[8])
{
  const StencilBase b = stencil_base(g, x, y, z);
  corner_weights(b, w);
  corner_cells(g, b, idx);
}

// Interpolate a cell field to a point from its stencil; field[stride*cell] is the value
// (stride 3 with an offset pointer picks one component of an interleaved vector field).
PW_INLINE double interpolate(const double *field, int stride, const int idx[8],
                             const double w[8])
{
  double sum = 0.0;
  for (int c = 0; c < 8; ++c) sum += w[c] * field[stride * idx[c]];
  return sum;
}

}  // namespace porewater

#endif
