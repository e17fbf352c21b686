// The original program's contact rule (src/core/analysis/original_contacts.h): a pair
// counts only if it overlaps strictly, neither grain is fixed, and both lie in the same copy
// of the box along every periodic axis (the original's raw difference of wrapped positions).
#include "analysis/original_contacts.h"

#include <gtest/gtest.h>

using porewater::PeriodicBox;
using porewater::counted_by_original;

namespace {
const PeriodicBox box{{0.0, 0.0, 0.0}, {1.0, 0.5, 2.0}, {true, true, false}};
}

TEST(OriginalContacts, FreeOverlappingPairInsideTheBoxCounts)
{
  const double xi[3] = {0.5, 0.25, 1.0}, xj[3] = {0.515, 0.25, 1.0};
  EXPECT_TRUE(counted_by_original(xi, xj, 0.02, false, false, box));
}

TEST(OriginalContacts, TouchingOrApartDoesNotCount)
{
  const double xi[3] = {0.5, 0.25, 1.0}, touching[3] = {0.52, 0.25, 1.0}, apart[3] = {0.53, 0.25, 1.0};
  EXPECT_FALSE(counted_by_original(xi, touching, 0.02, false, false, box));    // delta_n = 0
  EXPECT_FALSE(counted_by_original(xi, apart, 0.02, false, false, box));
}

TEST(OriginalContacts, AFixedGrainLeavesThePairOut)
{
  const double xi[3] = {0.5, 0.25, 1.0}, xj[3] = {0.515, 0.25, 1.0};
  EXPECT_FALSE(counted_by_original(xi, xj, 0.02, true, false, box));
  EXPECT_FALSE(counted_by_original(xi, xj, 0.02, false, true, box));
}

// the neighbour is the periodic image of a grain at x = 0.99 (y = 0.49): 15 mm apart as images
TEST(OriginalContacts, APairAcrossAPeriodicBoundaryDoesNotCount)
{
  const double xi[3] = {0.005, 0.25, 1.0}, image_x[3] = {-0.01, 0.25, 1.0};
  const double yi[3] = {0.5, 0.005, 1.0}, image_y[3] = {0.5, -0.01, 1.0};
  EXPECT_FALSE(counted_by_original(xi, image_x, 0.02, false, false, box));
  EXPECT_FALSE(counted_by_original(yi, image_y, 0.02, false, false, box));
  // z is not periodic: the same pair shifted below z = 0 counts
  const double zi[3] = {0.5, 0.25, 0.005}, zj[3] = {0.5, 0.25, -0.01};
  EXPECT_TRUE(counted_by_original(zi, zj, 0.02, false, false, box));
}
