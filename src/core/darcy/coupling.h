// Grain <-> grid coupling of fix darcy/pressure (doc/model.md §3), the one algorithm the
// CPU fix, the KOKKOS fix (of every host) and the tests run: what one grain deposits on the
// grid and the fluid force it feels. Device-safe like grid.h.
//
// Deposits are summed per stencil block and corner (contiguous adds, no per-corner cell
// index) and folded into the cells once per fluid step; the force is interpolated from a
// per-block table of the corner gradients. A grain whose stencil lies further outside the
// grid in z than any block reaches deposits into, and reads from, the cells directly.
#ifndef PW_DARCY_COUPLING_H
#define PW_DARCY_COUPLING_H

#include "darcy/grid.h"

namespace porewater {

PW_INLINE double sphere_volume(double radius)
{
  return 4.0 / 3.0 * 3.14159265358979323846 * radius * radius * radius;
}

// The cell deposits of one fluid step in one array, so that one reduction sums them over
// ranks: [solid volume at x (n) | solid momentum at x (3n, xyz interleaved) | solid volume
// at the predicted position x + v*interval (n) | number of grains skipped as non-finite
// (1)], n = number of cells.
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

// The quantities a grain deposits at each stencil corner: 0 volume, 1-3 momentum x, y, z
// (all at x), 4 volume at the predicted position.
enum { DEPOSITS_PER_CORNER = 5, CORNERS = 8 };

// What one grain of volume V and velocity v deposits with weights w at x and weights wp at
// the predicted position, per stencil corner c: out[8q + c] is quantity q of corner c
// (0: s*V, 1-3: s*V*v_x, v_y, v_z, all at x; 4: s*V at x + v*interval). Computed apart from
// the adds, so that the adds of a block run over contiguous slots (vectorised on the CPU).
PW_INLINE void deposit_corners(const double w[8], const double wp[8], double volume,
                               double v0, double v1, double v2, double out[40])
{
  for (int c = 0; c < 8; ++c) {
    const double sv = w[c] * volume;
    out[c] = sv;
    out[8 + c] = sv * v0;
    out[16 + c] = sv * v1;
    out[24 + c] = sv * v2;
    out[32 + c] = wp[c] * volume;
  }
}

// Deposit one grain straight into the cells of its stencils (DepositLayout slots).
template <class Add>
PW_INLINE void deposit_grain_in_cells(const GridGeom &g, const DepositLayout &layout, double x0,
                                      double x1, double x2, double v0, double v1, double v2,
                                      double volume, double interval, const Add &add)
{
  int idx[8], pidx[8];
  double w[8], pw[8];
  stencil(g, x0, x1, x2, idx, w);
  stencil(g, x0 + v0 * interval, x1 + v1 * interval, x2 + v2 * interval, pidx, pw);
  double d[DEPOSITS_PER_CORNER * CORNERS];
  deposit_corners(w, pw, volume, v0, v1, v2, d);
  for (int c = 0; c < CORNERS; ++c) add(layout.volume(idx[c]), d[c]);
  for (int q = 1; q < 4; ++q)
    for (int c = 0; c < CORNERS; ++c) add(layout.momentum(idx[c]) + q - 1, d[CORNERS * q + c]);
  for (int c = 0; c < CORNERS; ++c) add(layout.predicted_volume(pidx[c]), d[CORNERS * 4 + c]);
}

// The lattice cells ("blocks") of 2x2x2 cell centres that stencils span. Block (i0, j0, k0):
// i0, j0 wrapped periodically, k0 in [-1, nz-1], which holds every point less than half a
// cell below or above the grid.
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

// The coupling's view of the grid, and where one rank's grains deposit:
// [per block: quantity q (DEPOSITS_PER_CORNER) x corner c (8) | the cells (DepositLayout)].
struct CouplingGrid {
  GridGeom geom;
  LatticeMap map;
  StencilBlocks blocks;
  DepositLayout cells;
  static constexpr int BLOCK_DEPOSITS = DEPOSITS_PER_CORNER * CORNERS;
  static constexpr int BLOCK_GRADIENT = 4 * CORNERS;    // 3 components and phi per corner
  PW_INLINE int block_sums() const { return BLOCK_DEPOSITS * blocks.count(); }
  PW_INLINE int cell_sums() const { return block_sums(); }    // offset of the cell deposits
  PW_INLINE int sums_size() const { return block_sums() + cells.size(); }
  PW_INLINE int gradient_table_size() const { return BLOCK_GRADIENT * blocks.count(); }
};

PW_INLINE CouplingGrid coupling_grid(const GridGeom &g)
{
  return CouplingGrid{g, lattice_map(g), StencilBlocks{g.nx, g.ny, g.nz},
                      DepositLayout{cell_count(g)}};
}

// One grain's deposit into the sums of a CouplingGrid layout, through `add`: add(slot,
// value) accumulates one slot, add.row(offset) gives a row r with r(k, value) accumulating
// slot offset + k (a plain += on the CPU, where the compiler then adds a block's corners
// side by side; a scatter or atomic add in a KOKKOS kernel). Returns the grain's block at
// x, its corner weights there in w, for the force of the same step; -1 when it deposited
// into the cells directly (or nothing: a non-finite grain, counted instead).
template <class Add>
PW_INLINE int deposit_grain(const CouplingGrid &cg, double x0, double x1, double x2, double v0,
                            double v1, double v2, double volume, double interval, double w[8],
                            const Add &add)
{
  if (!grain_is_finite(x0, x1, x2, v0, v1, v2)) {
    add(cg.cell_sums() + cg.cells.nonfinite(), 1.0);
    return -1;
  }
  const StencilBase at = stencil_base(cg.map, x0, x1, x2);
  const StencilBase ahead =
      stencil_base(cg.map, x0 + v0 * interval, x1 + v1 * interval, x2 + v2 * interval);
  const int block = cg.blocks.block(at), block_ahead = cg.blocks.block(ahead);
  if (block < 0 || block_ahead < 0) {
    const int cells = cg.cell_sums();
    deposit_grain_in_cells(cg.geom, cg.cells, x0, x1, x2, v0, v1, v2, volume, interval,
                           [&](int slot, double value) { add(cells + slot, value); });
    return -1;
  }
  double w_ahead[8];
  corner_weights(at, w);
  corner_weights(ahead, w_ahead);
  double d[CouplingGrid::BLOCK_DEPOSITS];
  deposit_corners(w, w_ahead, volume, v0, v1, v2, d);
  const auto sum_at = add.row(CouplingGrid::BLOCK_DEPOSITS * block);
  for (int k = 0; k < 4 * CORNERS; ++k) sum_at(k, d[k]);
  const auto sum_ahead = add.row(CouplingGrid::BLOCK_DEPOSITS * block_ahead);
  for (int k = 4 * CORNERS; k < CouplingGrid::BLOCK_DEPOSITS; ++k) sum_ahead(k, d[k]);
  return block;
}

// The `add` of deposit_grain over a plain array.
struct AddTo {
  double *sums;
  struct Row {
    double *base;
    PW_INLINE void operator()(int k, double value) const { base[k] += value; }
  };
  PW_INLINE void operator()(int slot, double value) const { sums[slot] += value; }
  PW_INLINE Row row(int offset) const { return Row{sums + offset}; }
};

// The block of a grain at x and its corner weights there (-1: outside every block).
PW_INLINE int grain_stencil(const CouplingGrid &cg, double x0, double x1, double x2, double w[8])
{
  const StencilBase at = stencil_base(cg.map, x0, x1, x2);
  corner_weights(at, w);
  return cg.blocks.block(at);
}

// Add the per-block sums into the cell deposits: sums in CouplingGrid layout.
inline void fold_block_deposits(const CouplingGrid &cg, double *sums)
{
  double *cells = sums + cg.cell_sums();
  for (int block = 0; block < cg.blocks.count(); ++block) {
    const double *from = sums + CouplingGrid::BLOCK_DEPOSITS * block;
    int idx[8];
    corner_cells(cg.geom, cg.blocks.base(block), idx);
    for (int c = 0; c < CORNERS; ++c) {
      cells[cg.cells.volume(idx[c])] += from[c];
      for (int d = 0; d < 3; ++d)
        cells[cg.cells.momentum(idx[c]) + d] += from[CORNERS * (1 + d) + c];
      cells[cg.cells.predicted_volume(idx[c])] += from[CORNERS * 4 + c];
    }
  }
}

// The 3 components of a cell-centre vector field (interleaved xyz) at the 8 cells idx,
// corner-major and padded to 4 with a cell-centre scalar (so that the components are
// summed side by side and the scalar comes interpolated with the same weights):
// out[4*c + d], out[4*c + 3] = scalar[idx[c]].
PW_INLINE void corner_vectors(const double *field, const double *scalar, const int idx[8],
                              double out[32])
{
  for (int c = 0; c < 8; ++c) {
    for (int d = 0; d < 3; ++d) out[4 * c + d] = field[3 * idx[c] + d];
    out[4 * c + 3] = scalar[idx[c]];
  }
}

// The table of corner force gradients per block (BLOCK_GRADIENT values a block) from the
// cells' force gradient (fill_force_gradient), each corner padded with its cell's porosity,
// once per fluid step.
inline void fill_gradient_table(const CouplingGrid &cg, const double *force_gradient,
                                const double *porosity, double *table)
{
  for (int block = 0; block < cg.blocks.count(); ++block) {
    int idx[8];
    corner_cells(cg.geom, cg.blocks.base(block), idx);
    corner_vectors(force_gradient, porosity, idx, table + CouplingGrid::BLOCK_GRADIENT * block);
  }
}

// Which share of the water's force per bulk volume, -grad p, the grains take (doc/model.md
// §3): SEEPAGE_PRESSURE the pressure gradient on their own volume alone, -V grad p (the
// paper's: the grains carry 1 - phi of it); SEEPAGE_FULL that and the drag of the flow
// through them, -V grad p/(1 - phi) (Biot's, Terzaghi's sigma' = sigma - p).
enum Seepage { SEEPAGE_PRESSURE = 0, SEEPAGE_FULL = 1 };

// A cell's factor on grad p under `seepage`, at its porosity phi (clamped below 1 by the
// solver): 1, or 1/(1 - phi)
PW_INLINE double seepage_factor(int seepage, double porosity)
{
  return seepage == SEEPAGE_FULL ? 1.0 / (1.0 - porosity) : 1.0;
}

// The cells' force gradient, what the grains' force interpolates: grad p_c times the cell's
// seepage_factor. A grain of volume V_i with weights w_ic takes -V_i sum_c w_ic g_c, and the
// same weights built the cell's solid volume sum_i w_ic V_i = (1 - phi_c) V_cell: summed over
// the grains, SEEPAGE_FULL gives -sum_c grad p_c V_cell, the water's whole force on the
// cells, and SEEPAGE_PRESSURE -sum_c grad p_c (1 - phi_c) V_cell, to round-off wherever phi_c
// is not clamped and the grains have not moved since the deposit (doc/model.md §3).
inline void fill_force_gradient(int ncells, int seepage, const double *gradient,
                                const double *porosity, double *force_gradient)
{
  for (int c = 0; c < ncells; ++c) {
    const double factor = seepage_factor(seepage, porosity[c]);
    for (int d = 0; d < 3; ++d) force_gradient[3 * c + d] = factor * gradient[3 * c + d];
  }
}

// Fluid force f = -V (g + rho_f g) on a grain of volume V: the force gradient g interpolated
// with the stencil weights w from the corners' (corner_vectors of fill_force_gradient's);
// the second term is buoyancy (rho_g = rho_f g)
PW_INLINE void fluid_force_from_corners(const double corner_gradient[32], const double rho_g[3],
                                        const double w[8], double volume, double f[3])
{
  double sum[4] = {0.0, 0.0, 0.0, 0.0};
  for (int c = 0; c < 8; ++c)
    for (int d = 0; d < 4; ++d) sum[d] += w[c] * corner_gradient[4 * c + d];
  for (int d = 0; d < 3; ++d) f[d] = -volume * (sum[d] + rho_g[d]);
}

// The same for a grain at x, from the cells' force gradients (interleaved xyz) and porosities.
PW_INLINE void fluid_force_from_cells(const GridGeom &g, const double *force_gradient,
                                      const double *porosity, const double rho_g[3], double x0,
                                      double x1, double x2, double volume, double f[3])
{
  int idx[8];
  double w[8], corner_gradient[32];
  stencil(g, x0, x1, x2, idx, w);
  corner_vectors(force_gradient, porosity, idx, corner_gradient);
  fluid_force_from_corners(corner_gradient, rho_g, w, volume, f);
}

// What the force on the grains reads after a fluid step: the per-block corner force
// gradients and porosities and, for grains outside every block, the cells' force gradients
// and porosities (fill_force_gradient: the seepage force is in them); rho_f g.
struct FluidForceField {
  const double *gradient_table;
  const double *cell_gradient;
  const double *cell_porosity;
  double rho_g[3];
  int horizontal_only_bit;    // grains of this group bit get no vertical fluid force (novertical)
};

// The fluid force on a grain at x with block `block` and weights w (grain_stencil or
// deposit_grain of this step).
PW_INLINE void grain_fluid_force(const CouplingGrid &cg, const FluidForceField &field,
                                 const int block, const double w[8], double x0, double x1,
                                 double x2, double volume, double f[3])
{
  if (block >= 0)
    fluid_force_from_corners(field.gradient_table + CouplingGrid::BLOCK_GRADIENT * block,
                             field.rho_g, w, volume, f);
  else
    fluid_force_from_cells(cg.geom, field.cell_gradient, field.cell_porosity, field.rho_g, x0,
                           x1, x2, volume, f);
}

// ---------------------------------------------------------------------------------------
// The two per-grain kernels of the fix, over a grain accessor G (grains/host_grains.h), the
// grains' stored stencils S (s.block(i) an int&, s.weights(i) 8 doubles) and their held
// fluid forces H (h(i, d) a double&).

// Grain i deposits (CouplingGrid layout) and keeps its stencil at x.
template <class G, class S, class Add>
PW_INLINE void deposit_grain(const CouplingGrid &cg, const G &g, const S &stencils,
                             const int groupbit, const double interval, const int i, const Add &add)
{
  stencils.block(i) = -1;
  if (!(g.mask(i) & groupbit)) return;
  stencils.block(i) = deposit_grain(cg, g.x(i, 0), g.x(i, 1), g.x(i, 2), g.v(i, 0), g.v(i, 1),
                                    g.v(i, 2), sphere_volume(g.radius(i)), interval,
                                    stencils.weights(i), add);
}

// f += the fluid force on grain i, also held in h; from the stencil its deposit of this
// step kept (stored) or from its position now; its horizontal part only for the grains of
// field.horizontal_only_bit. Zero outside the group.
template <class G, class S, class H>
PW_INLINE void apply_fluid_force(const CouplingGrid &cg, const FluidForceField &field,
                                 const G &g, const S &stencils, const H &held, const int groupbit,
                                 const bool stored, const int i)
{
  double f[3] = {0.0, 0.0, 0.0};
  if (g.mask(i) & groupbit) {
    const double x0 = g.x(i, 0), x1 = g.x(i, 1), x2 = g.x(i, 2);
    double w[8];
    const double *weights = w;
    int block;
    if (stored) {
      block = stencils.block(i);
      weights = stencils.weights(i);
    } else {
      block = grain_stencil(cg, x0, x1, x2, w);
    }
    grain_fluid_force(cg, field, block, weights, x0, x1, x2, sphere_volume(g.radius(i)), f);
    if (g.mask(i) & field.horizontal_only_bit) f[2] = 0.0;
    g.f(i, 0) += f[0];
    g.f(i, 1) += f[1];
    g.f(i, 2) += f[2];
  }
  held(i, 0) = f[0];
  held(i, 1) = f[1];
  held(i, 2) = f[2];
}

// f += the fluid force held for grain i (`interpolate fluid` between fluid steps)
template <class G, class H> PW_INLINE void add_held_fluid_force(const G &g, const H &held, const int i)
{
  for (int d = 0; d < 3; ++d) g.f(i, d) += held(i, d);
}

}    // namespace porewater

#endif
