// Grain <-> grid coupling of fix darcy/pressure (darcy/coupling.h): deposition of volume,
// momentum and the predicted position, non-finite grains, the fluid force (both seepage
// forces), a stencil that stays inside the grid for any input, and the per-block path the
// fixes run equal to the per-cell one.
#include "darcy/coupling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

using namespace porewater;

namespace {

const GridGeom grid{-0.3, 1.1, 0.2, 0.1, 0.13, 0.07, 5, 4, 6};    // unequal, offset

double sum(const std::vector<double> &v, int begin, int end, int stride = 1)
{
  double s = 0.0;
  for (int i = begin; i < end; i += stride) s += v[i];
  return s;
}

}    // namespace

TEST(DarcyGrains, DepositConservesVolumeAndMomentumAndPredictsPosition)
{
  const DepositLayout layout{cell_count(grid)};
  const int n = layout.ncells;
  const double volume = sphere_volume(0.02), v[3] = {0.3, -0.2, 0.5}, interval = 0.04;
  EXPECT_DOUBLE_EQ(volume, 4.0 / 3.0 * 3.14159265358979323846 * 8e-6);
  // near the periodic seam in x and the bottom, where the stencil wraps and folds
  const double x[3] = {0.17, 1.12, 0.21};
  std::vector<double> slots(layout.size(), 0.0);
  auto add = [&slots](int slot, double value) { slots[slot] += value; };
  deposit_grain_in_cells(grid, layout, x[0], x[1], x[2], v[0], v[1], v[2], volume, interval, add);
  // 8 weights summing to 1: round-off only
  EXPECT_NEAR(sum(slots, layout.volume(0), layout.volume(n)), volume, 1e-15 * volume);
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(sum(slots, layout.momentum(0) + d, layout.momentum(n), 3), volume * v[d],
                1e-15 * volume);
  EXPECT_NEAR(sum(slots, layout.predicted_volume(0), layout.predicted_volume(n)), volume,
              1e-15 * volume);
  EXPECT_EQ(slots[layout.nonfinite()], 0.0);

  // the predicted part is the deposit of a grain at x + v*interval
  std::vector<double> moved(layout.size(), 0.0);
  auto add_moved = [&moved](int slot, double value) { moved[slot] += value; };
  deposit_grain_in_cells(grid, layout, x[0] + v[0] * interval, x[1] + v[1] * interval,
                x[2] + v[2] * interval, 0.0, 0.0, 0.0, volume, 0.0, add_moved);
  for (int c = 0; c < n; ++c)
    EXPECT_EQ(slots[layout.predicted_volume(c)], moved[layout.volume(c)]) << c;
}

TEST(DarcyGrains, NonFiniteGrainIsCountedNotDeposited)
{
  const CouplingGrid cg = coupling_grid(grid);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> slots(cg.sums_size(), 0.0);
  const AddTo add{slots.data()};
  double w[8];
  EXPECT_EQ(deposit_grain(cg, nan, 1.2, 0.3, 0.0, 0.0, 0.0, 1e-3, 0.1, w, add), -1);
  EXPECT_EQ(deposit_grain(cg, 0.0, 1.2, 0.3, 0.0, 0.0, -inf, 1e-3, 0.1, w, add), -1);
  const int counted = cg.cell_sums() + cg.cells.nonfinite();
  EXPECT_EQ(slots[counted], 2.0);
  for (int s = 0; s < counted; ++s) ASSERT_EQ(slots[s], 0.0) << s;
}

TEST(DarcyGrains, FluidForceIsMinusVolumeTimesGradientAndBuoyancy)
{
  // a uniform gradient interpolates to itself anywhere, folded or wrapped
  const int n = cell_count(grid);
  const double grad[3] = {2.0, -3.0, 50.0}, rho_g[3] = {0.0, 0.0, -9810.0};
  std::vector<double> field(3 * n), porosity(n);
  for (int c = 0; c < n; ++c) {
    for (int d = 0; d < 3; ++d) field[3 * c + d] = grad[d];
    porosity[c] = 0.3 + 0.01 * c;    // padding: not read by the force
  }
  const double volume = 1e-4;
  for (const auto &x : {std::vector<double>{0.17, 1.12, 0.21}, std::vector<double>{-0.29, 1.6, 0.6}}) {
    double f[3];
    fluid_force_from_cells(grid, field.data(), porosity.data(), rho_g, x[0], x[1], x[2], volume, f);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(f[d], -volume * (grad[d] + rho_g[d]), 1e-15);
  }
}

TEST(DarcyGrains, StencilStaysInsideTheGridForAnyPoint)
{
  // NaN and far-away points (a grain that blew up) must not index outside the grid
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {nan, inf, -inf, 1e300, -1e300, 3e9}) {
    for (int axis = 0; axis < 3; ++axis) {
      double p[3] = {0.0, 1.3, 0.4};
      p[axis] = bad;
      int idx[8];
      double w[8];
      stencil(grid, p[0], p[1], p[2], idx, w);
      for (int c = 0; c < 8; ++c) {
        EXPECT_GE(idx[c], 0) << bad << " axis " << axis;
        EXPECT_LT(idx[c], cell_count(grid)) << bad << " axis " << axis;
      }
    }
  }
}

TEST(DarcyGrains, BlockOfAStencilHasTheSameCellsAndFoldsToTheSameDeposits)
{
  // points all over the grid, across the periodic seams and beyond it in z: the block's
  // corner cells are the stencil's, and what the fixes deposit (per block where the stencils
  // have one, per cell where not) folded into the cells equals the per-cell deposits to
  // round-off (sums reordered)
  const CouplingGrid cg = coupling_grid(grid);
  const DepositLayout &layout = cg.cells;
  std::vector<double> direct(layout.size(), 0.0), sums(cg.sums_size(), 0.0);
  auto add_direct = [&direct](int slot, double value) { direct[slot] += value; };
  const AddTo add{sums.data()};
  const double volume = 1e-4, v[3] = {0.3, -0.2, 0.5}, interval = 0.05;
  int points = 0, in_blocks = 0;
  for (double x = -0.35; x < 0.25; x += 0.037)
    for (double y = 1.05; y < 1.65; y += 0.041)
      for (double z = 0.2 - 1.5 * grid.dz; z < 0.2 + 7.5 * grid.dz; z += 0.023) {
        const StencilBase at = stencil_base(grid, x, y, z);
        double w[8];
        const int block = deposit_grain(cg, x, y, z, v[0], v[1], v[2], volume, interval, w, add);
        deposit_grain_in_cells(grid, layout, x, y, z, v[0], v[1], v[2], volume, interval, add_direct);
        ++points;
        if (block < 0) continue;
        ++in_blocks;
        ASSERT_EQ(block, cg.blocks.block(at));
        int idx[8], from_block[8];
        corner_cells(grid, at, idx);
        corner_cells(grid, cg.blocks.base(block), from_block);
        double expected_w[8];
        corner_weights(at, expected_w);
        for (int c = 0; c < 8; ++c) {
          ASSERT_EQ(from_block[c], idx[c]);
          ASSERT_EQ(w[c], expected_w[c]);
        }
        double w_again[8];
        ASSERT_EQ(grain_stencil(cg, x, y, z, w_again), block);
      }
  ASSERT_GT(in_blocks, 1000);
  ASSERT_GT(points - in_blocks, 100);    // and the per-cell path taken too
  fold_block_deposits(cg, sums.data());
  // both orders of a slot's sum lie within n u sum|terms| of the exact sum (recursive
  // summation bound, n <= points terms, u = 1.1e-16, sum|terms| <= points * volume * 1)
  const double bound = 2.0 * points * 1.1e-16 * points * volume;
  for (int s = 0; s < layout.size(); ++s)
    EXPECT_NEAR(sums[cg.cell_sums() + s], direct[s], bound) << s;
  EXPECT_EQ(cg.blocks.block(stencil_base(grid, 0.0, 1.3, 0.2 - 0.51 * grid.dz)), -1);
  EXPECT_EQ(cg.blocks.block(stencil_base(grid, 0.0, 1.3, 0.2 + 6.51 * grid.dz)), -1);
}

TEST(DarcyGrains, ForceFromTheBlockTableEqualsTheForceFromTheCells)
{
  // a varied gradient field; the table path the fixes run and the per-cell path agree to
  // round-off (the same eight products, summed in the same order) at every point, under
  // either seepage force
  const CouplingGrid cg = coupling_grid(grid);
  const int n = cell_count(grid);
  std::vector<double> gradient(3 * n), porosity(n), force_gradient(3 * n),
      table(cg.gradient_table_size());
  for (int c = 0; c < 3 * n; ++c) gradient[c] = std::sin(0.37 * c) * 1e3;
  for (int c = 0; c < n; ++c) porosity[c] = 0.4 + 0.3 * std::sin(0.53 * c);
  for (const int seepage : {SEEPAGE_PRESSURE, SEEPAGE_FULL}) {
    fill_force_gradient(n, seepage, gradient.data(), porosity.data(), force_gradient.data());
    fill_gradient_table(cg, force_gradient.data(), porosity.data(), table.data());
    const FluidForceField field{table.data(), force_gradient.data(), porosity.data(),
                                {0.0, 0.0, -9810.0}, 0};
    int compared = 0;
    for (double x = -0.35; x < 0.25; x += 0.043)
      for (double y = 1.05; y < 1.65; y += 0.047)
        for (double z = 0.2 - 1.5 * grid.dz; z < 0.2 + 7.5 * grid.dz; z += 0.029) {
          double w[8], f_block[3], f_cells[3];
          const int block = grain_stencil(cg, x, y, z, w);
          grain_fluid_force(cg, field, block, w, x, y, z, 1e-4, f_block);
          fluid_force_from_cells(grid, force_gradient.data(), porosity.data(), field.rho_g, x, y,
                                 z, 1e-4, f_cells);
          for (int d = 0; d < 3; ++d)
            ASSERT_EQ(f_block[d], f_cells[d]) << x << " " << y << " " << z << " seepage " << seepage;
          compared += block >= 0;
        }
    ASSERT_GT(compared, 1000);
  }
}

TEST(DarcyGrains, FullSeepageInterpolatesEachCellsGradientOverItsSolidFraction)
{
  // A hand-made grid: cell porosities and gradients set here, not made by grains. At points
  // all over it (wrapped, folded at the bottom and top, beyond it in z), with the grid's own
  // stencil and interpolate(): seepage pressure is -V (grad p + rho_f g) to the bit, as it
  // always was; seepage full is -V (sum_c w_c grad p_c/(1 - phi_c) + rho_f g), each cell's
  // gradient over its own solid fraction (what conserves the water's force), to round-off
  const CouplingGrid cg = coupling_grid(grid);
  const int n = cell_count(grid);
  std::vector<double> gradient(3 * n), porosity(n), quotient(3 * n);
  for (int c = 0; c < 3 * n; ++c) gradient[c] = 2e3 * std::cos(0.41 * c) + 500.0;
  for (int c = 0; c < n; ++c) porosity[c] = 0.45 + 0.35 * std::sin(0.29 * c + 1.0);    // 0.1-0.8
  for (int c = 0; c < 3 * n; ++c) quotient[c] = gradient[c] / (1.0 - porosity[c / 3]);
  std::vector<double> g_pressure(3 * n), g_full(3 * n), t_pressure(cg.gradient_table_size()),
      t_full(cg.gradient_table_size());
  fill_force_gradient(n, SEEPAGE_PRESSURE, gradient.data(), porosity.data(), g_pressure.data());
  fill_force_gradient(n, SEEPAGE_FULL, gradient.data(), porosity.data(), g_full.data());
  fill_gradient_table(cg, g_pressure.data(), porosity.data(), t_pressure.data());
  fill_gradient_table(cg, g_full.data(), porosity.data(), t_full.data());
  const double rho_g[3] = {0.0, 0.0, -9810.0}, volume = 3e-5;
  const FluidForceField pressure{t_pressure.data(), g_pressure.data(), porosity.data(),
                                 {rho_g[0], rho_g[1], rho_g[2]}, 0};
  const FluidForceField full{t_full.data(), g_full.data(), porosity.data(),
                             {rho_g[0], rho_g[1], rho_g[2]}, 0};
  int points = 0;
  for (double x = -0.35; x < 0.25; x += 0.051)
    for (double y = 1.05; y < 1.65; y += 0.053)
      for (double z = 0.2 - 1.5 * grid.dz; z < 0.2 + 7.5 * grid.dz; z += 0.031) {
        int idx[8];
        double ws[8];
        stencil(grid, x, y, z, idx, ws);
        double w[8], f_pressure[3], f_full[3];
        const int block = grain_stencil(cg, x, y, z, w);
        grain_fluid_force(cg, pressure, block, w, x, y, z, volume, f_pressure);
        grain_fluid_force(cg, full, block, w, x, y, z, volume, f_full);
        for (int d = 0; d < 3; ++d) {
          const double g = interpolate(gradient.data() + d, 3, idx, ws);
          ASSERT_EQ(f_pressure[d], -volume * (g + rho_g[d])) << x << " " << y << " " << z;
          const double q = interpolate(quotient.data() + d, 3, idx, ws);
          ASSERT_NEAR(f_full[d], -volume * (q + rho_g[d]), 1e-13 * volume * std::fabs(q))
              << x << " " << y << " " << z;
        }
        ++points;
      }
  EXPECT_GT(points, 1000);
  EXPECT_EQ(seepage_factor(SEEPAGE_PRESSURE, 0.38), 1.0);
  EXPECT_EQ(seepage_factor(SEEPAGE_FULL, 0.375), 1.6);
}

TEST(DarcyGrains, GrainForcesSumToTheWatersForceOnTheCells)
{
  // Grains of random sizes all over the grid (wrapped, folded at the bottom and top, beyond
  // it in z: outside every block), deposited as the fix deposits them; each cell's porosity
  // from their deposits (not clamped), a random gradient per cell. Summed over the grains
  // (their forces at the deposit's stencils, as on a fluid step), seepage full gives the
  // water's whole force on the cells, -sum_c grad p_c V_cell, and seepage pressure its
  // solids' share, -sum_c grad p_c (1 - phi_c) V_cell, both to round-off; the old
  // interpolation of grad p/(1 - phi at the grain) missed the first by 2-7 % here (control)
  const CouplingGrid cg = coupling_grid(grid);
  const int n = cell_count(grid);
  const double v_cell = cell_volume(grid);
  std::vector<double> sums(cg.sums_size(), 0.0);
  const AddTo add{sums.data()};
  struct Grain {
    double x[3], volume, w[8];
    int block;
  };
  std::vector<Grain> grains;
  unsigned seed = 12345u;
  auto uniform = [&seed]() {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) / 16777216.0;
  };
  for (int i = 0; i < 1500; ++i) {
    Grain g;
    g.x[0] = grid.xlo + grid.nx * grid.dx * (1.2 * uniform() - 0.1);
    g.x[1] = grid.ylo + grid.ny * grid.dy * (1.2 * uniform() - 0.1);
    g.x[2] = grid.zlo + grid.nz * grid.dz * (1.3 * uniform() - 0.15);
    g.volume = sphere_volume(0.010 + 0.008 * uniform());
    g.block = deposit_grain(cg, g.x[0], g.x[1], g.x[2], 0.0, 0.0, 0.0, g.volume, 0.0, g.w, add);
    if (g.block < 0) grain_stencil(cg, g.x[0], g.x[1], g.x[2], g.w);
    grains.push_back(g);
  }
  fold_block_deposits(cg, sums.data());
  std::vector<double> porosity(n), gradient(3 * n);
  double lowest = 1.0, highest = 0.0;
  for (int c = 0; c < n; ++c) {
    porosity[c] = 1.0 - sums[cg.cell_sums() + cg.cells.volume(c)] / v_cell;
    lowest = std::min(lowest, porosity[c]);
    highest = std::max(highest, porosity[c]);
    for (int d = 0; d < 3; ++d) gradient[3 * c + d] = 1e3 * (uniform() - 0.3);
  }
  ASSERT_GT(lowest, 0.05);    // every cell holds grains, none overfull
  ASSERT_LT(highest, 0.95);
  const double rho_g[3] = {0.0, 0.0, 0.0};
  for (const int seepage : {SEEPAGE_PRESSURE, SEEPAGE_FULL}) {
    std::vector<double> force_gradient(3 * n), table(cg.gradient_table_size());
    fill_force_gradient(n, seepage, gradient.data(), porosity.data(), force_gradient.data());
    fill_gradient_table(cg, force_gradient.data(), porosity.data(), table.data());
    const FluidForceField field{table.data(), force_gradient.data(), porosity.data(),
                                {rho_g[0], rho_g[1], rho_g[2]}, 0};
    double total[3] = {0.0, 0.0, 0.0}, expected[3] = {0.0, 0.0, 0.0}, scale = 0.0;
    double old_way[3] = {0.0, 0.0, 0.0};
    for (const Grain &g : grains) {
      double f[3];
      grain_fluid_force(cg, field, g.block, g.w, g.x[0], g.x[1], g.x[2], g.volume, f);
      int idx[8];
      double ws[8];
      stencil(grid, g.x[0], g.x[1], g.x[2], idx, ws);
      const double phi = interpolate(porosity.data(), 1, idx, ws);
      for (int d = 0; d < 3; ++d) {
        total[d] += f[d];
        old_way[d] -= g.volume * interpolate(gradient.data() + d, 3, idx, ws) / (1.0 - phi);
      }
    }
    for (int c = 0; c < n; ++c)
      for (int d = 0; d < 3; ++d) {
        const double share = seepage == SEEPAGE_FULL ? 1.0 : 1.0 - porosity[c];
        expected[d] -= gradient[3 * c + d] * share * v_cell;
        scale += std::fabs(gradient[3 * c + d]) * v_cell;
      }
    std::printf("[ report ] seepage %d: grains %.6g %.6g %.6g, cells %.6g %.6g %.6g, the old "
                "interpolation %.6g %.6g %.6g\n",
                seepage, total[0], total[1], total[2], expected[0], expected[1], expected[2],
                old_way[0], old_way[1], old_way[2]);
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(total[d], expected[d], 1e-12 * scale) << "seepage " << seepage << " axis " << d;
      if (seepage == SEEPAGE_FULL)
        EXPECT_GT(std::fabs(old_way[d] - expected[d]), 1e-2 * std::fabs(expected[d])) << d;
    }
  }
}
