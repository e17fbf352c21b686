// The block pass of pair linear/coulomb (contact/contact_block.h: screen, the law on a buffer
// in SIMD lanes, forces applied in order) against the one-grain sweep it replaces on SIMD
// hosts (contact/contact_sweep.h), on a random dense packing with ghosts, springs at the
// Coulomb cap, pairs that just opened, more contacts than one buffer holds, and two grain
// types: forces, torques, springs, touch flags, the broken contacts named and the pairs
// tallied must be the same to the bit (the same operations in the same order); the
// dissipation, summed in another order, to round-off. Each SIMD copy of the law (AVX2,
// AVX-512) that this CPU runs gives the scalar law's values to the bit.
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

namespace {

// n rows of closed contacts: overlaps up to 5 % of the radii, springs of every length (none,
// inside the cap, far beyond it), velocities and spins of either sign
void random_rows(ContactBlock &b, const int n, std::mt19937 &rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int r = 0; r < n; r++) {
    b.radi[r] = 0.5 + 0.05 * u(rng);
    b.radj[r] = 0.5 + 0.05 * u(rng);
    const double dist = (b.radi[r] + b.radj[r]) * (0.975 + 0.025 * u(rng));
    double n3[3] = {u(rng), u(rng), u(rng)};
    const double len = std::sqrt(n3[0] * n3[0] + n3[1] * n3[1] + n3[2] * n3[2]) + 1e-3;
    b.delx[r] = dist * n3[0] / len;
    b.dely[r] = dist * n3[1] / len;
    b.delz[r] = dist * n3[2] / len;
    const double spring = r % 5 == 0 ? 0.0 : r % 5 == 1 ? 10.0 : 1e-3;
    for (int d = 0; d < 3; d++) {
      b.vr[d][r] = u(rng);
      b.wi[d][r] = u(rng);
      b.wj[d][r] = u(rng);
      b.xi[d][r] = spring * u(rng);
    }
    b.kn[r] = 1e3 * (1.5 + u(rng));
    b.kt[r] = 1e3 * (1.5 + u(rng));
    b.mu[r] = r % 7 == 0 ? 0.0 : 0.3 + 0.2 * u(rng);
    b.frictional[r] = is_frictionless(b.kt[r], b.mu[r]) ? 0 : 1;
  }
}

void expect_same_rows(const ContactBlock &a, const ContactBlock &b, const int n)
{
  for (int r = 0; r < n; r++) {
    for (int d = 0; d < 3; d++) {
      ASSERT_EQ(a.f[d][r], b.f[d][r]) << "force, row " << r;
      ASSERT_EQ(a.tor_i[d][r], b.tor_i[d][r]) << "torque on i, row " << r;
      ASSERT_EQ(a.tor_j[d][r], b.tor_j[d][r]) << "torque on j, row " << r;
      ASSERT_EQ(a.xi[d][r], b.xi[d][r]) << "spring, row " << r;
    }
    ASSERT_EQ(a.overlap[r], b.overlap[r]) << "overlap, row " << r;
    ASSERT_EQ(a.xisq_before[r], b.xisq_before[r]) << "spring before the cap, row " << r;
  }
}

}    // namespace

TEST(ContactBlock, EverySimdCopyOfTheLawGivesTheScalarLawsValues)
{
  // 61 rows: the vector loops' remainders too; uniform coefficients (the SIMD loop) in every
  // switch of the step, and per-row ones (each row's own friction)
  std::mt19937 rng(17);
  const char *names[] = {"baseline", "AVX2", "AVX-512"};
  int copies_run = 0;
  for (SimdCopy copy : {SimdCopy::baseline, SimdCopy::avx2, SimdCopy::avx512}) {
    if (!simd_copy_runs_here(copy)) continue;
    copies_run++;
    std::printf("[ report ] the law's %s copy runs here%s\n", names[int(copy)],
                copy == widest_simd_copy() ? " (the one pair linear/coulomb uses)" : "");
    for (int trial = 0; trial < 20; trial++) {
      const int n = 61;
      ContactBlock rows;
      random_rows(rows, n, rng);
      for (int lever : {LEVER_CONTACT, LEVER_RADIUS})
        for (int update : {0, 1})
          for (int uniform : {0, 1})
            for (double mu : {0.4, 0.0}) {
              SCOPED_TRACE(std::string(names[int(copy)]) + (uniform ? ", uniform" : ", per row") +
                           ", lever " + std::to_string(lever) + ", update " + std::to_string(update) +
                           ", mu " + std::to_string(mu));
              const ContactStep step{lever, update, 1e-3};
              const ContactCoeffs k = contact_coeffs(1.2e3, 0.8e3, mu);
              // the law row by row, as this file compiles it (no SIMD copy)
              ContactBlock scalar = rows, simd = rows;
              for (int r = 0; r < n; r++)
                linear_coulomb_row(scalar, r, uniform ? k : ContactCoeffs{rows.kn[r], rows.kt[r], rows.mu[r],
                                                                    rows.frictional[r]}, step);
              linear_coulomb_block_law(simd, n, uniform ? &k : nullptr, step, copy);
              expect_same_rows(scalar, simd, n);
            }
    }
  }
  EXPECT_GE(copies_run, 1);
}
