// The bookkeeping of pair linear/coulomb around its law (contact/contact_sweep.h) with a
// policy over plain arrays, as a host would give it: history kept or forgotten, forces on
// owned partners only, the ghost's half of the dissipation, the broken-contact check.
#include "contact/contact_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

using namespace porewater;

namespace {

struct Grains {
  std::vector<std::vector<double>> x, v, omega, f, torque;
  std::vector<double> radius;
  std::vector<int> neighbors, touch;    // of grain 0 only
  std::vector<double> springs;          // 3 per neighbour
  int nlocal;
  std::vector<std::pair<int, int>> broken, tallied;
};

struct Policy {
  Grains &g;
  ContactCoeffs k;
  struct Sums {
    double lost = 0.0;
  };
  struct Row {
    Grains &g;
    int count() const { return (int) g.neighbors.size(); }
    int neighbor(int jj) const { return g.neighbors[jj]; }
    int touched(int jj) const { return g.touch[jj]; }
    void touch(int jj) const { g.touch[jj] = 1; }
    void forget(int jj) const
    {
      g.touch[jj] = 0;
      for (int d = 0; d < 3; d++) g.springs[3 * jj + d] = 0.0;
    }
    double *history(int jj, double *) const { return &g.springs[3 * jj]; }
    void keep_history(int, const double *) const {}
  };
  struct GrainForce {
    Grains &g;
    int i;
    void add(const ContactForce &c, int frictional) const
    {
      for (int d = 0; d < 3; d++) {
        g.f[i][d] += c.f[d];
        if (frictional) g.torque[i][d] -= c.lever_i * c.tor[d];
      }
    }
    void finish() const {}
  };
  double x(int i, int d) const { return g.x[i][d]; }
  double radius(int i) const { return g.radius[i]; }
  int type(int) const { return 1; }
  Row neighbors(int) const { return Row{g}; }
  const double *v(int i, double *) const { return g.v[i].data(); }
  const double *omega(int i, double *) const { return g.omega[i].data(); }
  ContactCoeffs coeffs(int, int) const { return k; }
  ContactStep step() const { return ContactStep{LEVER_CONTACT, 1, 1e-3}; }
  bool owns(int j) const { return j < g.nlocal; }
  double share(int j) const { return pair_share(j, g.nlocal, 0); }
  GrainForce force_on(int i) const { return GrainForce{g, i}; }
  void add_reaction(int j, const ContactForce &c, int frictional) const
  {
    for (int d = 0; d < 3; d++) {
      g.f[j][d] -= c.f[d];
      if (frictional) g.torque[j][d] -= c.lever_j * c.tor[d];
    }
  }
  double overlap_limit() const { return 0.5; }
  void broken(int i, int j, double) const { g.broken.push_back({i, j}); }
  bool tracks_dissipation() const { return true; }
  void add_loss(Sums &sums, double energy) const { sums.lost += energy; }
  void tally(Sums &, int i, int j, const ContactForce &, const ContactCoeffs &, const double *,
             double, double, double) const
  {
    g.tallied.push_back({i, j});
  }
};

// grain 0 at the origin; 1 above it, overlapping by `overlap`; 2 far away, but its spring
// with 0 still stored from an earlier contact
Grains scene(double overlap, int nlocal)
{
  Grains g;
  g.x = {{0, 0, 0}, {0, 0, 1.0 - overlap}, {2, 0, 0}};
  g.v = {{0.2, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  g.omega = g.f = g.torque = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  g.radius = {0.5, 0.5, 0.5};
  g.neighbors = {1, 2};
  g.touch = {0, 1};
  g.springs = {0, 0, 0, 1e-3, 2e-3, 0};
  g.nlocal = nlocal;
  return g;
}

}    // namespace

TEST(ContactSweep, ClosedContactsKeepASpringOpenOnesForgetItAndCountItsLoss)
{
  Grains g = scene(0.01, 3);
  const Policy p{g, contact_coeffs(1e3, 1e3, 0.5)};
  Policy::Sums sums;
  linear_coulomb_sweep(p, 0, sums);
  EXPECT_EQ(g.touch, (std::vector<int>{1, 0}));
  EXPECT_GT(std::fabs(g.springs[0]), 0.0);    // sliding along x loads the new spring
  for (int d = 3; d < 6; d++) EXPECT_EQ(g.springs[d], 0.0);
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
  linear_coulomb_sweep(Policy{owned, frictionless}, 0, lost_owned);
  linear_coulomb_sweep(Policy{ghost, frictionless}, 0, lost_ghost);
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
  linear_coulomb_sweep(Policy{g, contact_coeffs(1e3, 1e3, 0.5)}, 0, sums);
  EXPECT_EQ(g.broken, (std::vector<std::pair<int, int>>{{0, 1}}));
}
