// The contact law of pair linear/coulomb on its own (doc/model.md §1), without LAMMPS.
#include "contact/linear_coulomb.h"

#include <gtest/gtest.h>

#include <cmath>

using porewater::ContactForce;
using porewater::LEVER_CONTACT;
using porewater::LEVER_RADIUS;

namespace {
const double zero3[3] = {0.0, 0.0, 0.0};

// grain i at distance r above a grain j at rest along +z (n = +z)
ContactForce linear_coulomb_contact(double r, double radi, double radj, const double *vi,
                                    const double *wi, double kn, double kt, double mu, int lever,
                                    int update_history, double dt, double *xi)
{
  const porewater::ContactPair pair =
      porewater::contact_pair(0.0, 0.0, r, r * r, radi, radj, vi, zero3, wi, zero3);
  return porewater::linear_coulomb_contact(pair, porewater::contact_coeffs(kn, kt, mu),
                                           porewater::ContactStep{lever, update_history, dt}, xi);
}

double norm(const double *a)
{
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}
}    // namespace

TEST(LinearCoulombContact, NormalSpringIsKnTimesOverlapAlongN)
{
  // i above j along z, overlap 0.01
  const double r = 0.99, kn = 1000.0;
  double xi[3] = {0, 0, 0};
  const ContactForce c = linear_coulomb_contact(r, 0.5, 0.5, zero3, zero3, kn, kn, 0.5, LEVER_CONTACT, 1, 1e-3, xi);
  EXPECT_NEAR(c.f[2], kn * 0.01, 1e-12);    // pushes i away from j (+z)
  EXPECT_EQ(c.f[0], 0.0);
  EXPECT_EQ(c.f[1], 0.0);
  EXPECT_NEAR(porewater::contact_energy(kn, kn, c, xi), 0.5 * kn * 1e-4, 1e-15);
}

TEST(LinearCoulombContact, RollingWithoutSlipBuildsNoTangentialSpring)
{
  // grain i (radius 0.5) on a fixed grain j, n = +z, overlap δ; i moves along +x and
  // rolls: contact-point velocity v_i − ℓ_i ω_i × n must vanish, i.e. ω_y = v_x/ℓ_i
  for (int lever : {LEVER_CONTACT, LEVER_RADIUS}) {
    const double rad = 0.5, overlap = 0.02, r = 2 * rad - overlap;
    const double ell = porewater::lever_arm(lever, rad, overlap);
    const double vi[3] = {0.3, 0.0, 0.0};
    const double wi_roll[3] = {0.0, vi[0] / ell, 0.0};
    double xi[3] = {0, 0, 0};
    for (int step = 0; step < 10; step++)
      linear_coulomb_contact(r, rad, rad, vi, wi_roll, 1e3, 1e3, 0.5, lever, 1, 1e-3, xi);
    EXPECT_LT(norm(xi), 1e-15) << "lever " << lever;

    // spinning the other way slips at twice the speed: the spring must load
    const double wi_skid[3] = {0.0, -vi[0] / ell, 0.0};
    double xi2[3] = {0, 0, 0};
    linear_coulomb_contact(r, rad, rad, vi, wi_skid, 1e3, 1e3, 0.5, lever, 1, 1e-3, xi2);
    EXPECT_NEAR(xi2[0], 2 * vi[0] * 1e-3, 1e-15);
  }
}

TEST(LinearCoulombContact, CoulombCapResetsTheSpringToTheLimit)
{
  const double r = 0.99, kn = 1000.0, kt = 1000.0, mu = 0.5;
  const double vi[3] = {5.0, 0.0, 0.0};    // large sliding speed
  double xi[3] = {0, 0, 0};
  const ContactForce c = linear_coulomb_contact(r, 0.5, 0.5, vi, zero3, kn, kt, mu, LEVER_CONTACT, 1, 1e-3, xi);
  const double fn = kn * 0.01;
  EXPECT_NEAR(norm(c.ft), mu * fn, 1e-12);
  EXPECT_LT(c.ft[0], 0.0);    // friction opposes the sliding
  EXPECT_NEAR(xi[0], -c.ft[0] / kt, 1e-15);    // ξ ← −f_t/k_t
}

TEST(LinearCoulombContact, HistoryIsProjectedOntoTheNewTangentPlane)
{
  // a stored spring with a normal component loses it, without rescaling
  const double r = 0.99;
  double xi[3] = {1e-4, 0.0, 2e-4};
  linear_coulomb_contact(r, 0.5, 0.5, zero3, zero3, 1e3, 1e3, 10.0, LEVER_CONTACT, 1, 1e-3, xi);
  EXPECT_DOUBLE_EQ(xi[0], 1e-4);
  EXPECT_NEAR(xi[2], 0.0, 1e-20);
}

TEST(LinearCoulombContact, TorquesUseEachGrainsLeverArm)
{
  // unequal radii: T_i = −ℓ_i n × f_t, T_j = −ℓ_j n × f_t
  const double radi = 0.6, radj = 0.3, overlap = 0.03, r = radi + radj - overlap;
  const double vi[3] = {0.1, 0.0, 0.0};
  double xi[3] = {0, 0, 0};
  const ContactForce c = linear_coulomb_contact(r, radi, radj, vi, zero3, 1e3, 1e3, 0.5, LEVER_CONTACT, 1, 1e-2, xi);
  EXPECT_DOUBLE_EQ(c.lever_i, radi - overlap / 2);
  EXPECT_DOUBLE_EQ(c.lever_j, radj - overlap / 2);
  // n = +z, f_t along −x: n × f_t along −y, so T_i along +y: i spins to roll along +x
  EXPECT_LT(c.ft[0], 0.0);
  EXPECT_GT(-c.lever_i * c.tor[1], 0.0);
}

TEST(LinearCoulombContact, SetupDoesNotIntegrateTheSpring)
{
  const double r = 0.99;
  const double vi[3] = {0.1, 0.0, 0.0};
  double xi[3] = {0, 0, 0};
  linear_coulomb_contact(r, 0.5, 0.5, vi, zero3, 1e3, 1e3, 0.5, LEVER_CONTACT, 0, 1e-3, xi);
  EXPECT_EQ(norm(xi), 0.0);
}
