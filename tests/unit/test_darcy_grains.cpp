// Grain <-> grid coupling of fix darcy/pressure (darcy_grains.h): deposition of volume,
// momentum and the predicted position, non-finite grains, the fluid force, and a stencil
// that stays inside the grid for any input.
#include "darcy_grains.h"

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
  deposit_grain(grid, layout, x[0], x[1], x[2], v[0], v[1], v[2], volume, interval, add);
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
  deposit_grain(grid, layout, x[0] + v[0] * interval, x[1] + v[1] * interval,
                x[2] + v[2] * interval, 0.0, 0.0, 0.0, volume, 0.0, add_moved);
  for (int c = 0; c < n; ++c)
    EXPECT_EQ(slots[layout.predicted_volume(c)], moved[layout.volume(c)]) << c;
}

TEST(DarcyGrains, NonFiniteGrainIsCountedNotDeposited)
{
  const DepositLayout layout{cell_count(grid)};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> slots(layout.size(), 0.0);
  auto add = [&slots](int slot, double value) { slots[slot] += value; };
  deposit_grain(grid, layout, nan, 1.2, 0.3, 0.0, 0.0, 0.0, 1e-3, 0.1, add);
  deposit_grain(grid, layout, 0.0, 1.2, 0.3, 0.0, 0.0, -inf, 1e-3, 0.1, add);
  EXPECT_EQ(slots[layout.nonfinite()], 2.0);
  for (int s = 0; s < layout.nonfinite(); ++s) ASSERT_EQ(slots[s], 0.0) << s;
}

TEST(DarcyGrains, FluidForceIsMinusVolumeTimesGradientAndBuoyancy)
{
  // a uniform gradient interpolates to itself anywhere, folded or wrapped
  const int n = cell_count(grid);
  const double grad[3] = {2.0, -3.0, 50.0}, rho_g[3] = {0.0, 0.0, -9810.0};
  std::vector<double> field(3 * n);
  for (int c = 0; c < n; ++c)
    for (int d = 0; d < 3; ++d) field[3 * c + d] = grad[d];
  const double volume = 1e-4;
  for (const auto &x : {std::vector<double>{0.17, 1.12, 0.21}, std::vector<double>{-0.29, 1.6, 0.6}}) {
    double f[3];
    fluid_force(grid, field.data(), rho_g, x[0], x[1], x[2], volume, f);
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
  // points all over the grid, across the periodic seams and up to half a cell outside it
  // in z: the block's corner cells are the stencil's, and deposits summed per block and
  // folded into the cells equal the per-cell deposits to round-off (sums reordered)
  const StencilBlocks blocks{grid.nx, grid.ny, grid.nz};
  const DepositLayout layout{cell_count(grid)};
  std::vector<double> direct(layout.size(), 0.0), per_block(40 * blocks.count(), 0.0);
  auto add = [&direct](int slot, double value) { direct[slot] += value; };
  const double volume = 1e-4, v[3] = {0.3, -0.2, 0.5}, interval = 0.05;
  int points = 0;
  for (double x = -0.35; x < 0.25; x += 0.037)
    for (double y = 1.05; y < 1.65; y += 0.041)
      for (double z = 0.2 - 0.49 * grid.dz; z < 0.2 + 6.49 * grid.dz; z += 0.023) {
        const StencilBase at = stencil_base(grid, x, y, z);
        const StencilBase ahead =
            stencil_base(grid, x + v[0] * interval, y + v[1] * interval, z + v[2] * interval);
        const int block = blocks.block(at), block_ahead = blocks.block(ahead);
        if (block_ahead < 0) continue;    // the predicted point left the blocks' range
        ASSERT_GE(block, 0) << x << " " << y << " " << z;
        int idx[8], from_block[8];
        corner_cells(grid, at, idx);
        corner_cells(grid, blocks.base(block), from_block);
        for (int c = 0; c < 8; ++c) ASSERT_EQ(from_block[c], idx[c]);
        double w[8], w_ahead[8];
        corner_weights(at, w);
        corner_weights(ahead, w_ahead);
        deposit_corners(w, w_ahead, volume, v[0], v[1], v[2], [&](int c, int q, double value) {
          per_block[40 * (q < 4 ? block : block_ahead) + 8 * q + c] += value;
        });
        deposit_grain(grid, layout, x, y, z, v[0], v[1], v[2], volume, interval, add);
        ++points;
      }
  ASSERT_GT(points, 1000);
  std::vector<double> folded(layout.size(), 0.0);
  for (int block = 0; block < blocks.count(); ++block) {
    int idx[8];
    corner_cells(grid, blocks.base(block), idx);
    for (int c = 0; c < 8; ++c) {
      folded[layout.volume(idx[c])] += per_block[40 * block + c];
      for (int d = 0; d < 3; ++d)
        folded[layout.momentum(idx[c]) + d] += per_block[40 * block + 8 * (1 + d) + c];
      folded[layout.predicted_volume(idx[c])] += per_block[40 * block + 32 + c];
    }
  }
  // both orders of a slot's sum lie within n u sum|terms| of the exact sum (recursive
  // summation bound, n <= points terms, u = 1.1e-16, sum|terms| <= points * volume * 1)
  const double bound = 2.0 * points * 1.1e-16 * points * volume;
  for (int s = 0; s < layout.size(); ++s) EXPECT_NEAR(folded[s], direct[s], bound) << s;
  EXPECT_EQ(blocks.block(stencil_base(grid, 0.0, 1.3, 0.2 - 0.51 * grid.dz)), -1);
  EXPECT_EQ(blocks.block(stencil_base(grid, 0.0, 1.3, 0.2 + 6.51 * grid.dz)), -1);
}
