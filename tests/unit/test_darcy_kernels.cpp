// Header-only Darcy kernels: hat/trilinear weights, stencil with periodic wrap and
// mirrored bottom/top, Kozeny-Carman, harmonic mean, clamps.
#include "darcy/grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

using namespace porewater;

namespace {

GridGeom test_grid()
{
  // deliberately unequal cell sizes and an offset origin
  return GridGeom{-0.3, 1.1, 0.2, 0.1, 0.13, 0.07, 5, 4, 6};
}

double centre(double lo, double delta, int i) { return lo + (i + 0.5) * delta; }

// Sum the stencil weights per cell (indices may repeat after folding).
std::map<int, double> weights_by_cell(const GridGeom &g, double x, double y, double z)
{
  int idx[8];
  double w[8];
  stencil(g, x, y, z, idx, w);
  std::map<int, double> by_cell;
  for (int c = 0; c < 8; ++c) {
    EXPECT_GE(idx[c], 0);
    EXPECT_LT(idx[c], cell_count(g));
    EXPECT_GE(w[c], 0.0);
    by_cell[idx[c]] += w[c];
  }
  return by_cell;
}

double total(const std::map<int, double> &m)
{
  double s = 0.0;
  for (const auto &kv : m) s += kv.second;
  return s;
}

}  // namespace

TEST(DarcyKernels, HatWeightValues)
{
  // exact binary fractions: exact equality is the right check
  EXPECT_EQ(hat_weight(0.0, 2.0), 1.0);
  EXPECT_EQ(hat_weight(0.5, 2.0), 0.75);
  EXPECT_EQ(hat_weight(-0.5, 2.0), 0.75);
  EXPECT_EQ(hat_weight(1.0, 2.0), 0.5);
  EXPECT_EQ(hat_weight(2.0, 2.0), 0.0);
  EXPECT_EQ(hat_weight(-3.0, 2.0), 0.0);
  const GridGeom g = test_grid();
  // product of the three 1-D hats; 1e-15: a few roundings of O(1) numbers
  EXPECT_NEAR(trilinear_weight(g, 0.05, -0.013, 0.0), 0.5 * 0.9, 1e-15);
  EXPECT_EQ(trilinear_weight(g, 0.0, 0.0, 0.07), 0.0);
}

TEST(DarcyKernels, IndexWrapAndMirror)
{
  EXPECT_EQ(wrap_index(-1, 5), 4);
  EXPECT_EQ(wrap_index(5, 5), 0);
  EXPECT_EQ(wrap_index(11, 5), 1);
  EXPECT_EQ(wrap_index(-6, 5), 4);
  EXPECT_EQ(mirror_index(-1, 6), 0);
  EXPECT_EQ(mirror_index(-2, 6), 1);
  EXPECT_EQ(mirror_index(6, 6), 5);
  EXPECT_EQ(mirror_index(7, 6), 4);
  EXPECT_EQ(mirror_index(3, 6), 3);
  EXPECT_EQ(mirror_index(-1, 1), 0);
  EXPECT_EQ(mirror_index(1, 1), 0);
}

TEST(DarcyKernels, KozenyCarmanAndCap)
{
  // k = 2 * 0.125 / 0.25 = 1 exactly (binary fractions)
  EXPECT_EQ(kozeny_carman(0.5, 2.0, 0.0), 1.0);
  EXPECT_EQ(kozeny_carman(0.5, 2.0, -1.0), 1.0);  // kmax <= 0: no cap
  EXPECT_EQ(kozeny_carman(0.5, 2.0, 0.25), 0.25);
  EXPECT_EQ(kozeny_carman(0.5, 2.0, 4.0), 1.0);   // cap above the value: no effect
  // phi = 0.38, kc = 3.5e-13 (Table S1): relative 1e-14, a handful of roundings
  const double k = 3.5e-13 * 0.38 * 0.38 * 0.38 / (0.62 * 0.62);
  EXPECT_NEAR(kozeny_carman(0.38, 3.5e-13, 0.0), k, 1e-14 * k);
  EXPECT_NEAR(k, 4.99e-14, 0.01e-14);  // hand value
}

TEST(DarcyKernels, HarmonicMeanAndClamp)
{
  EXPECT_EQ(harmonic_mean(1.0, 3.0), 1.5);
  EXPECT_EQ(harmonic_mean(2.5, 2.5), 2.5);
  EXPECT_EQ(harmonic_mean(0.0, 3.0), 0.0);
  EXPECT_EQ(harmonic_mean(0.0, 0.0), 0.0);
  EXPECT_EQ(clamp_porosity(0.05, 0.1, 0.9), 0.1);
  EXPECT_EQ(clamp_porosity(1.0, 0.1, 0.9), 0.9);
  EXPECT_EQ(clamp_porosity(0.4, 0.1, 0.9), 0.4);
}

TEST(DarcyKernels, StencilMatchesHatWeightsInside)
{
  // away from the bottom and top, the stencil weight of each cell is the hat weight of
  // the offset to its centre; 1e-14: roundings of O(1) fractions
  const GridGeom g = test_grid();
  const double x = -0.3 + 0.237, y = 1.1 + 0.301, z = 0.2 + 0.19;
  const auto by_cell = weights_by_cell(g, x, y, z);
  EXPECT_EQ(by_cell.size(), 8u);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const double s = trilinear_weight(g, x - centre(g.xlo, g.dx, i),
                                          y - centre(g.ylo, g.dy, j), z - centre(g.zlo, g.dz, k));
        const auto it = by_cell.find(cell_index(g, i, j, k));
        EXPECT_NEAR(it == by_cell.end() ? 0.0 : it->second, s, 1e-14);
      }
  // at a cell centre all weight is in that cell
  const auto at_centre = weights_by_cell(g, centre(g.xlo, g.dx, 2), centre(g.ylo, g.dy, 1),
                                         centre(g.zlo, g.dz, 3));
  EXPECT_NEAR(at_centre.at(cell_index(g, 2, 1, 3)), 1.0, 1e-14);
}

TEST(DarcyKernels, StencilWeightsSumToOneEverywhere)
{
  // random points over the whole domain plus a margin, to hit the bottom, the top and
  // the periodic seams; 1e-14: sum of 8 products of O(1) numbers
  const GridGeom g = test_grid();
  const double lx = g.nx * g.dx, ly = g.ny * g.dy, lz = g.nz * g.dz;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.02, 1.02);
  for (int n = 0; n < 2000; ++n) {
    const double x = g.xlo + u(rng) * lx, y = g.ylo + u(rng) * ly, z = g.zlo + u(rng) * lz;
    EXPECT_NEAR(total(weights_by_cell(g, x, y, z)), 1.0, 1e-14) << x << " " << y << " " << z;
  }
}

TEST(DarcyKernels, StencilFoldsAtBottomAndTop)
{
  const GridGeom g = test_grid();
  const double x = centre(g.xlo, g.dx, 1), y = centre(g.ylo, g.dy, 2);
  // below the first centre: all the z weight lands in layer 0 (mirrored grain)
  auto low = weights_by_cell(g, x, y, g.zlo + 0.2 * g.dz);
  EXPECT_NEAR(low.at(cell_index(g, 1, 2, 0)), 1.0, 1e-14);
  // above the last centre: all in the top layer
  auto high = weights_by_cell(g, x, y, g.zlo + (g.nz - 0.1) * g.dz);
  EXPECT_NEAR(high.at(cell_index(g, 1, 2, g.nz - 1)), 1.0, 1e-14);
  // folding = mirroring: that weight is the hat weight of the grain plus that of its
  // mirror image below the bottom face
  const double h = 0.3 * g.dz, zc0 = centre(g.zlo, g.dz, 0);
  const double direct = hat_weight(g.zlo + h - zc0, g.dz);
  const double mirrored = hat_weight(g.zlo - h - zc0, g.dz);
  EXPECT_NEAR(direct + mirrored, 1.0, 1e-14);
}

TEST(DarcyKernels, StencilAcrossPeriodicSeam)
{
  // a point just left of xlo and one just right of xlo + Lx are the same physical
  // point: same weights; a point on the seam splits between the first and last cell
  const GridGeom g = test_grid();
  const double lx = g.nx * g.dx, y = centre(g.ylo, g.dy, 0), z = centre(g.zlo, g.dz, 2);
  const auto a = weights_by_cell(g, g.xlo - 0.01, y, z);
  const auto b = weights_by_cell(g, g.xlo + lx - 0.01, y, z);
  ASSERT_EQ(a.size(), b.size());
  for (const auto &kv : a) EXPECT_NEAR(b.at(kv.first), kv.second, 1e-12);
  const auto seam = weights_by_cell(g, g.xlo, y, z);
  EXPECT_NEAR(seam.at(cell_index(g, 0, 0, 2)), 0.5, 1e-14);
  EXPECT_NEAR(seam.at(cell_index(g, g.nx - 1, 0, 2)), 0.5, 1e-14);
}

TEST(DarcyKernels, InterpolateLinearField)
{
  // trilinear interpolation reproduces a field linear in x inside the domain (away from
  // the seam): 1e-13 relative to O(1) values
  const GridGeom g = test_grid();
  std::vector<double> field(cell_count(g));
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        field[cell_index(g, i, j, k)] = 2.0 * centre(g.xlo, g.dx, i) - centre(g.zlo, g.dz, k);
  int idx[8];
  double w[8];
  const double x = -0.3 + 0.26, y = 1.1 + 0.2, z = 0.2 + 0.2;
  stencil(g, x, y, z, idx, w);
  EXPECT_NEAR(interpolate(field.data(), 1, idx, w), 2.0 * x - z, 1e-13);
}
