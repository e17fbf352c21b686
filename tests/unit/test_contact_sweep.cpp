// The bookkeeping of pair linear/coulomb around its law (contact/contact_sweep.h) with a
// policy over plain arrays (sweep_policy.h): history kept or forgotten, forces on owned
// partners only, the ghost's half of the dissipation, the broken-contact check.
#include "sweep_policy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

using namespace porewater;

using pwtest::Grains;
using pwtest::Policy;
using pwtest::uniform_policy;

namespace {

// grain 0 at the origin; 1 above it, overlapping by `overlap`; 2 far away, but its spring
// with 0 still stored from an earlier contact
Grains scene(double overlap, int nlocal)
{
  Grains g;
  g.x = {{0, 0, 0}, {0, 0, 1.0 - overlap}, {2, 0, 0}};
  g.v = {{0.2, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  g.omega = g.f = g.torque = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  g.radius = {0.5, 0.5, 0.5};
  g.type = {1, 1, 1};
  g.nlocal = nlocal;
  g.neighbors.assign(nlocal, {});    // the owned grains' rows: only grain 0 has neighbours
  g.touch.assign(nlocal, {});
  g.springs.assign(nlocal, {});
  g.neighbors[0] = {1, 2};
  g.touch[0] = {0, 1};
  g.springs[0] = {0, 0, 0, 1e-3, 2e-3, 0};
  return g;
}

}    // namespace

TEST(ContactSweep, ClosedContactsKeepASpringOpenOnesForgetItAndCountItsLoss)
{
  Grains g = scene(0.01, 3);
  const Policy p = uniform_policy(g, contact_coeffs(1e3, 1e3, 0.5));
  Policy::Sums sums;
  linear_coulomb_sweep(p, 0, sums);
  EXPECT_EQ(g.touch[0], (std::vector<int>{1, 0}));
  EXPECT_GT(std::fabs(g.springs[0][0]), 0.0);    // sliding along x loads the new spring
  for (int d = 3; d < 6; d++) EXPECT_EQ(g.springs[0][d], 0.0);
  // the opened spring's ½ k_t |ξ|², and what the cap and projection took from the new one
  EXPECT_GE(sums.lost, 0.5 * 1e3 * (1e-6 + 4e-6) - 1e-18);
  for (int d = 0; d < 3; d++) EXPECT_EQ(g.f[0][d], -g.f[1][d]);    // Newton's third law
  EXPECT_NEAR(g.f[0][2], -1e3 * 0.01, 1e-9);    // 1 pushes 0 down
  EXPECT_EQ(g.tallied, (std::vector<std::pair<int, int>>{{0, 1}}));
  EXPECT_TRUE(g.broken.empty());
}

TEST(ContactSweep, AGhostPartnerGetsNoForceAndHalfTheLoss)
{
  Grains owned = scene(0.01, 3), ghost = scene(0.01, 1);    // 1 and 2 ghosts of this rank
  const ContactCoeffs frictionless = contact_coeffs(1e3, 1e3, 0.0);
  Policy::Sums lost_owned, lost_ghost;
  linear_coulomb_sweep(uniform_policy(owned, frictionless), 0, lost_owned);
  linear_coulomb_sweep(uniform_policy(ghost, frictionless), 0, lost_ghost);
  for (int d = 0; d < 3; d++) {
    EXPECT_EQ(ghost.f[1][d], 0.0);
    EXPECT_EQ(ghost.f[0][d], owned.f[0][d]);
  }
  // a frictionless pair has no new spring: only the opened one is lost
  EXPECT_DOUBLE_EQ(lost_owned.lost, 0.5 * 1e3 * 5e-6);
  EXPECT_DOUBLE_EQ(lost_ghost.lost, 0.5 * lost_owned.lost);
}

TEST(ContactSweep, AnOverlapBeyondTheLimitIsReportedNamingBothGrains)
{
  Grains g = scene(0.6, 3);    // 0.6 > 0.5 of the smaller radius 0.5
  Policy::Sums sums;
  linear_coulomb_sweep(uniform_policy(g, contact_coeffs(1e3, 1e3, 0.5)), 0, sums);
  EXPECT_EQ(g.broken, (std::vector<std::pair<int, int>>{{0, 1}}));
}
