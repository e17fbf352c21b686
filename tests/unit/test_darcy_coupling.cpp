// Grain <-> grid coupling of fix darcy/pressure (darcy/coupling.h): deposition of volume,
// momentum and the predicted position, non-finite grains, the fluid force (both seepage
// forces), a stencil that stays inside the grid for any input, and the per-block path the
// fixes run equal to the per-cell one.
#include "darcy/coupling.h"

#include <gtest/gtest.h>

#include <cmath>
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
    porosity[c] = 0.3 + 0.01 * c;    // read by seepage full only
  }
  const double volume = 1e-4;
  for (const auto &x : {std::vector<double>{0.17, 1.12, 0.21}, std::vector<double>{-0.29, 1.6, 0.6}}) {
    double f[3];
    fluid_force_from_cells(grid, field.data(), porosity.data(), rho_g, x[0], x[1], x[2], volume,
                           SEEPAGE_PRESSURE, f);
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
  // round-off (the same eight products, summed in the same order) at every point
  const CouplingGrid cg = coupling_grid(grid);
  const int n = cell_count(grid);
  std::vector<double> gradient(3 * n), porosity(n), table(cg.gradient_table_size());
  for (int c = 0; c < 3 * n; ++c) gradient[c] = std::sin(0.37 * c) * 1e3;
  for (int c = 0; c < n; ++c) porosity[c] = 0.4 + 0.3 * std::sin(0.53 * c);
  fill_gradient_table(cg, gradient.data(), porosity.data(), table.data());
  for (const int seepage : {SEEPAGE_PRESSURE, SEEPAGE_FULL}) {
    const FluidForceField field{table.data(), gradient.data(), porosity.data(),
                                {0.0, 0.0, -9810.0}, 0, seepage};
    int compared = 0;
    for (double x = -0.35; x < 0.25; x += 0.043)
      for (double y = 1.05; y < 1.65; y += 0.047)
        for (double z = 0.2 - 1.5 * grid.dz; z < 0.2 + 7.5 * grid.dz; z += 0.029) {
          double w[8], f_block[3], f_cells[3];
          const int block = grain_stencil(cg, x, y, z, w);
          grain_fluid_force(cg, field, block, w, x, y, z, 1e-4, f_block);
          fluid_force_from_cells(grid, gradient.data(), porosity.data(), field.rho_g, x, y, z,
                                 1e-4, seepage, f_cells);
          for (int d = 0; d < 3; ++d)
            ASSERT_EQ(f_block[d], f_cells[d]) << x << " " << y << " " << z << " seepage " << seepage;
          compared += block >= 0;
        }
    ASSERT_GT(compared, 1000);
  }
}

TEST(DarcyGrains, FullSeepageDividesThePressureForceByTheSolidFractionAtTheGrain)
{
  // A hand-made grid: cell porosities and gradients set here, not made by grains. At points
  // all over it (wrapped, folded at the bottom and top, beyond it in z), with phi and grad p
  // interpolated here by the grid's own stencil and interpolate() (the path compute
  // darcy/grain reports phi by): seepage pressure is -V (grad p + rho_f g) to the bit, as it
  // always was; seepage full is -V (grad p/(1 - phi) + rho_f g), to round-off (the force
  // sums phi with the gradient, in the same order: a few ulps of 1/(1 - phi)).
  const CouplingGrid cg = coupling_grid(grid);
  const int n = cell_count(grid);
  std::vector<double> gradient(3 * n), porosity(n), table(cg.gradient_table_size());
  for (int c = 0; c < 3 * n; ++c) gradient[c] = 2e3 * std::cos(0.41 * c) + 500.0;
  for (int c = 0; c < n; ++c) porosity[c] = 0.45 + 0.35 * std::sin(0.29 * c + 1.0);    // 0.1-0.8
  fill_gradient_table(cg, gradient.data(), porosity.data(), table.data());
  const double rho_g[3] = {0.0, 0.0, -9810.0}, volume = 3e-5;
  const FluidForceField pressure{table.data(), gradient.data(), porosity.data(),
                                 {rho_g[0], rho_g[1], rho_g[2]}, 0, SEEPAGE_PRESSURE};
  FluidForceField full = pressure;
  full.seepage = SEEPAGE_FULL;
  double lowest = 1.0, highest = 0.0;
  int points = 0;
  for (double x = -0.35; x < 0.25; x += 0.051)
    for (double y = 1.05; y < 1.65; y += 0.053)
      for (double z = 0.2 - 1.5 * grid.dz; z < 0.2 + 7.5 * grid.dz; z += 0.031) {
        int idx[8];
        double ws[8];
        stencil(grid, x, y, z, idx, ws);
        const double phi = interpolate(porosity.data(), 1, idx, ws);
        double w[8], f_pressure[3], f_full[3];
        const int block = grain_stencil(cg, x, y, z, w);
        grain_fluid_force(cg, pressure, block, w, x, y, z, volume, f_pressure);
        grain_fluid_force(cg, full, block, w, x, y, z, volume, f_full);
        for (int d = 0; d < 3; ++d) {
          const double g = interpolate(gradient.data() + d, 3, idx, ws);
          ASSERT_EQ(f_pressure[d], -volume * (g + rho_g[d])) << x << " " << y << " " << z;
          const double expected = -volume * (g / (1.0 - phi) + rho_g[d]);
          ASSERT_NEAR(f_full[d], expected, 1e-13 * volume * std::fabs(g) / (1.0 - phi))
              << x << " " << y << " " << z;
        }
        lowest = std::min(lowest, phi);
        highest = std::max(highest, phi);
        ++points;
      }
  // the factor 1/(1 - phi) was exercised from near 1 to several
  EXPECT_LT(lowest, 0.2);
  EXPECT_GT(highest, 0.7);
  EXPECT_GT(points, 1000);
  EXPECT_EQ(seepage_factor(SEEPAGE_PRESSURE, 0.38), 1.0);
  EXPECT_EQ(seepage_factor(SEEPAGE_FULL, 0.375), 1.6);
}
