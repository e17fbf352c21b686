// The block pass of pair linear/coulomb (contact/contact_block.h: screen, the law on a buffer
// in SIMD lanes, forces applied in order) against the one-grain sweep it replaces on SIMD
// hosts (contact/contact_sweep.h), on a random dense packing with ghosts, springs at the
// Coulomb cap, pairs that just opened, more contacts than one buffer holds, and two grain
// types: forces, torques, springs, touch flags, the broken contacts named and the pairs
// tallied must be the same to the bit (the same operations in the same order); the
// dissipation, summed in another order, to round-off.
#include "sweep_policy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace porewater;
using pwtest::Grains;
using pwtest::Policy;

namespace {

// `n` grains of radius ~0.5 in a box packed densely enough for ~2-3 contacts a grain in the
// half list, the last `ghosts` of them ghosts (no row of their own); springs stored on most
// touching pairs, some long enough to be capped, some on pairs that have since opened
Grains packing(const int n, const int ghosts, const unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Grains g;
  const double side = std::cbrt(n * 0.75);
  for (int i = 0; i < n; i++) {
    g.x.push_back({side * u(rng), side * u(rng), side * u(rng)});
    g.v.push_back({u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5});
    g.omega.push_back({u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5});
    g.f.push_back({0.0, 0.0, 0.0});
    g.torque.push_back({0.0, 0.0, 0.0});
    g.radius.push_back(0.45 + 0.1 * u(rng));
    g.type.push_back(u(rng) < 0.3 ? 2 : 1);
  }
  g.nlocal = n - ghosts;
  for (int i = 0; i < g.nlocal; i++) {
    g.neighbors.emplace_back();
    g.touch.emplace_back();
    g.springs.emplace_back();
    for (int j = i + 1; j < n; j++) {
      double rsq = 0.0;
      for (int d = 0; d < 3; d++) rsq += (g.x[i][d] - g.x[j][d]) * (g.x[i][d] - g.x[j][d]);
      const double cut = g.radius[i] + g.radius[j] + 0.2;
      if (rsq >= cut * cut) continue;
      g.neighbors[i].push_back(j);
      const bool stored = u(rng) < 0.7;
      g.touch[i].push_back(stored);
      for (int d = 0; d < 3; d++) g.springs[i].push_back(stored ? 0.2 * (u(rng) - 0.5) : 0.0);
    }
  }
  return g;
}

struct Outcome {
  Grains g;
  double lost;
};

// the policy p on another set of grains
Policy rebind(const Policy &p, Grains &g)
{
  Policy r{g, {}, p.uniform, p.contact, p.limit};
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) r.k[a][b] = p.k[a][b];
  return r;
}

Outcome grain_sweep(Grains g, const Policy &p)
{
  const Policy r = rebind(p, g);
  Policy::Sums sums;
  for (int i = 0; i < g.nlocal; i++) linear_coulomb_sweep(r, i, sums);
  return Outcome{g, sums.lost};
}

Outcome block_sweep(Grains g, const Policy &p)
{
  const Policy r = rebind(p, g);
  Policy::Sums sums;
  ContactBlock block;
  // in two calls, as a host splits its grains into chunks
  linear_coulomb_block_sweep(r, 0, g.nlocal / 3, sums, block);
  linear_coulomb_block_sweep(r, g.nlocal / 3, g.nlocal, sums, block);
  return Outcome{g, sums.lost};
}

Policy policy(Grains &g, const ContactCoeffs &k11, const ContactCoeffs &k22, bool uniform,
              int lever, int update)
{
  Policy p{g, {}, uniform, ContactStep{lever, update, 1e-3}, 0.05};
  const ContactCoeffs k12 =
      contact_coeffs(std::sqrt(k11.kn * k22.kn), std::sqrt(k11.kt * k22.kt), std::sqrt(k11.mu * k22.mu));
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) p.k[a][b] = (a == 2 && b == 2) ? k22 : (a == 2 || b == 2) ? k12 : k11;
  return p;
}

int closed_contacts(const Grains &g)
{
  int n = 0;
  for (int i = 0; i < g.nlocal; i++)
    for (int jj = 0; jj < (int) g.neighbors[i].size(); jj++) {
      const int j = g.neighbors[i][jj];
      double rsq = 0.0;
      for (int d = 0; d < 3; d++) rsq += (g.x[i][d] - g.x[j][d]) * (g.x[i][d] - g.x[j][d]);
      n += rsq < (g.radius[i] + g.radius[j]) * (g.radius[i] + g.radius[j]);
    }
  return n;
}

void expect_same(const Outcome &a, const Outcome &b)
{
  const int n = (int) a.g.x.size();
  for (int i = 0; i < n; i++)
    for (int d = 0; d < 3; d++) {
      ASSERT_EQ(a.g.f[i][d], b.g.f[i][d]) << "f of grain " << i;
      ASSERT_EQ(a.g.torque[i][d], b.g.torque[i][d]) << "torque of grain " << i;
    }
  EXPECT_EQ(a.g.springs, b.g.springs);
  EXPECT_EQ(a.g.touch, b.g.touch);
  EXPECT_EQ(a.g.broken, b.g.broken);
  EXPECT_EQ(a.g.tallied, b.g.tallied);
  EXPECT_NEAR(a.lost, b.lost, 1e-12 * std::fabs(a.lost));
}

}    // namespace

TEST(ContactBlock, EqualsTheOneGrainSweepToTheBit)
{
  Grains g = packing(600, 60, 7);
  const int closed = closed_contacts(g);
  ASSERT_GT(closed, 3 * ContactBlock::capacity);    // the buffer fills and flushes mid-grain
  std::printf("[ report ] %d grains, %d closed contacts\n", (int) g.x.size(), closed);
  const ContactCoeffs frictional = contact_coeffs(1e3, 1e3, 0.5);
  const ContactCoeffs frictionless = contact_coeffs(1e3, 1e3, 0.0);
  const ContactCoeffs other = contact_coeffs(2e3, 5e2, 0.3);
  struct Case {
    const char *name;
    ContactCoeffs k22;
    bool uniform;
  } cases[] = {{"uniform frictional", frictional, true},
               {"uniform frictionless", frictionless, true},
               {"two types", other, false},
               {"two types, one frictionless", frictionless, false}};
  for (const Case &c : cases)
    for (int lever : {LEVER_CONTACT, LEVER_RADIUS})
      for (int update : {0, 1}) {
        SCOPED_TRACE(std::string(c.name) + (lever == LEVER_RADIUS ? ", lever radius" : ", lever contact") +
                     (update ? ", spring integrated" : ", setup step"));
        const ContactCoeffs k11 = c.uniform ? c.k22 : frictional;
        const Outcome one = grain_sweep(g, policy(g, k11, c.k22, c.uniform, lever, update));
        const Outcome block = block_sweep(g, policy(g, k11, c.k22, c.uniform, lever, update));
        expect_same(one, block);
      }
}

TEST(ContactBlock, CappedSpringsAndBrokenContactsAreThoseOfTheOneGrainSweep)
{
  // springs far beyond the cap on every touching pair, and grains pushed together until some
  // overlaps pass the limit: the same springs rescaled, the same pairs named, in order
  Grains g = packing(300, 30, 11);
  for (auto &row : g.springs)
    for (double &s : row) s *= 50.0;
  for (auto &x : g.x)
    for (double &c : x) c *= 0.97;
  const Outcome one = grain_sweep(g, policy(g, contact_coeffs(1e3, 1e3, 0.5), contact_coeffs(1e3, 1e3, 0.5),
                                            true, LEVER_CONTACT, 1));
  ASSERT_FALSE(one.g.broken.empty());
  const Outcome block = block_sweep(g, policy(g, contact_coeffs(1e3, 1e3, 0.5),
                                              contact_coeffs(1e3, 1e3, 0.5), true, LEVER_CONTACT, 1));
  expect_same(one, block);
}

TEST(ContactBlock, ANonFiniteDistanceIsABrokenContactAsInTheOneGrainSweep)
{
  // a grain at NaN (a run that has blown up): its pairs count as overlapping, and the law
  // reports them as broken, in both passes
  Grains g = packing(200, 20, 13);
  int lost = 0;
  while (g.neighbors[lost].empty()) lost++;
  g.x[lost][0] = std::nan("");
  const Policy p = policy(g, contact_coeffs(1e3, 1e3, 0.5), contact_coeffs(1e3, 1e3, 0.5), true,
                          LEVER_CONTACT, 1);
  const Outcome one = grain_sweep(g, p);
  const Outcome block = block_sweep(g, p);
  bool names_it = false;
  for (const auto &b : block.g.broken) names_it |= b.first == lost || b.second == lost;
  EXPECT_TRUE(names_it);
  EXPECT_EQ(one.g.broken, block.g.broken);
}
