// The contact law of pair linear/coulomb (doc/model.md §1), written once and called by the
// neighbour sweep (contact_sweep.h) of the CPU and KOKKOS styles and by the unit tests.
//
// Operation order deliberately follows LAMMPS 29Sep2021 gran/hooke/history with zero
// damping, so that `lever radius` reproduces it bit for bit (a chaotic granular flow
// amplifies any round-off difference).
#ifndef PW_CONTACT_LINEAR_COULOMB_H
#define PW_CONTACT_LINEAR_COULOMB_H

#include "pw_inline.h"

#include <cmath>

namespace porewater {

enum LeverArm { LEVER_CONTACT = 0, LEVER_RADIUS = 1 };

struct ContactForce {
  double f[3];      // force on i (−f acts on j)
  double ft[3];     // its tangential part f_t
  double ccel;      // normal part per unit |del|: f_n = ccel·del = k_n δ n
  double tor[3];    // n × f_t: torque on a grain is −ℓ·tor with its own lever arm ℓ
  double lever_i;   // ℓ_i
  double lever_j;   // ℓ_j
  double tor_i[3];  // ℓ_i tor: the torque on i is −tor_i
  double tor_j[3];  // ℓ_j tor: the torque on j is −tor_j
  double overlap;       // δ
  double xisq_before;   // |ξ|² after integration, before projection and cap
};

// Lever arm of a grain of radius `rad` in a contact of overlap `overlap`.
PW_INLINE double lever_arm(const int lever, const double rad, const double overlap)
{
  return lever == LEVER_RADIUS ? rad : rad - 0.5 * overlap;
}

// A pair with kt = 0 or mu = 0 never has a tangential force: its spring need not be kept.
PW_INLINE bool is_frictionless(const double kt, const double mu)
{
  return kt == 0.0 || mu == 0.0;
}

// Coefficients of one type pair; frictional = !is_frictionless(kt, mu), decided once per
// type pair rather than per contact.
struct ContactCoeffs {
  double kn, kt, mu;
  int frictional;
};

PW_INLINE ContactCoeffs contact_coeffs(const double kn, const double kt, const double mu)
{
  return ContactCoeffs{kn, kt, mu, is_frictionless(kt, mu) ? 0 : 1};
}

// How the law runs in this step: lever arm, whether the spring is integrated
// (update_history = 0 during setup: forces from the stored spring, as gran/hooke/history
// does), and the step length.
struct ContactStep {
  int lever;
  int update_history;
  double dt;
};

// |del|² of a pair, as the overlap test and the law take it
PW_INLINE double distance_squared(const double delx, const double dely, const double delz)
{
  return delx * delx + dely * dely + delz * delz;
}

// Whether two grains at |del|² = rsq with radii summing to radsum overlap; a distance that is
// not finite counts as an overlap (the law then reports the contact as broken, which stops a
// run that has blown up)
PW_INLINE bool pair_overlaps(const double rsq, const double radsum)
{
  return !(rsq >= radsum * radsum);
}

// Two grains i and j that overlap (rsq < (radi+radj)²): del = x_i − x_j, rsq = |del|², their
// relative velocity and their angular velocities, as values (a loop over a block of
// contacts keeps them in SIMD lanes: contact_block.h).
struct ContactPair {
  double delx, dely, delz, rsq;
  double radi, radj;
  double vr[3];    // v_i − v_j
  double wi[3], wj[3];
};

PW_INLINE ContactPair contact_pair(const double delx, const double dely, const double delz,
                                   const double rsq, const double radi, const double radj,
                                   const double *vi, const double *vj, const double *wi,
                                   const double *wj)
{
  return ContactPair{delx,          dely,          delz,          rsq,   radi,  radj,
                     {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]}, {wi[0], wi[1], wi[2]},
                     {wj[0], wj[1], wj[2]}};
}

// The force between them; xi[3] is the tangential spring history, updated in place. A
// frictionless pair skips the spring: f_t = 0 and tor = 0 as the full path gives, xi is
// cleared (a spring left by an earlier pair_coeff with friction is forgotten, its energy
// counted in xisq_before). No branch depends on the contact (the cap is a selection), so that
// a loop over independent contacts runs in SIMD lanes.
PW_INLINE ContactForce linear_coulomb_contact(const ContactPair &p, const ContactCoeffs &k,
                                              const ContactStep &step, double *xi)
{
  const double delx = p.delx, dely = p.dely, delz = p.delz, rsq = p.rsq;
  const double *wi = p.wi, *wj = p.wj;
  const double kn = k.kn, kt = k.kt, mu = k.mu, dt = step.dt;
  const int update_history = step.update_history;
  ContactForce c;
  const double radsum = p.radi + p.radj;
  const double r = sqrt(rsq);
  const double rinv = 1.0 / r;
  const double rsqinv = 1.0 / rsq;
  const double overlap = radsum - r;
  c.lever_i = lever_arm(step.lever, p.radi, overlap);
  c.lever_j = lever_arm(step.lever, p.radj, overlap);

  // normal force magnitude per unit |del|: k_n δ / r
  const double ccel = kn * overlap * rinv;
  c.ccel = ccel;
  c.overlap = overlap;

  if (!k.frictional) {
    c.xisq_before = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2];
    xi[0] = xi[1] = xi[2] = 0.0;
    for (int d = 0; d < 3; d++) c.ft[d] = c.tor[d] = c.tor_i[d] = c.tor_j[d] = 0.0;
    c.f[0] = delx * ccel;
    c.f[1] = dely * ccel;
    c.f[2] = delz * ccel;
    return c;
  }

  // relative velocity and its part tangential to n = del/r
  const double vr1 = p.vr[0];
  const double vr2 = p.vr[1];
  const double vr3 = p.vr[2];
  const double vnnr = vr1 * delx + vr2 * dely + vr3 * delz;
  const double vt1 = vr1 - delx * vnnr * rsqinv;
  const double vt2 = vr2 - dely * vnnr * rsqinv;
  const double vt3 = vr3 - delz * vnnr * rsqinv;

  // contact-point velocity: subtract (ℓ_i ω_i + ℓ_j ω_j) × n
  const double wr1 = (c.lever_i * wi[0] + c.lever_j * wj[0]) * rinv;
  const double wr2 = (c.lever_i * wi[1] + c.lever_j * wj[1]) * rinv;
  const double wr3 = (c.lever_i * wi[2] + c.lever_j * wj[2]) * rinv;
  const double vtr1 = vt1 - (delz * wr2 - dely * wr3);
  const double vtr2 = vt2 - (delx * wr3 - delz * wr1);
  const double vtr3 = vt3 - (dely * wr1 - delx * wr2);

  // tangential spring: integrate, then project onto the current tangent plane
  if (update_history) {
    xi[0] += vtr1 * dt;
    xi[1] += vtr2 * dt;
    xi[2] += vtr3 * dt;
  }
  const double xisq_before = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2];
  const double rsht = (xi[0] * delx + xi[1] * dely + xi[2] * delz) * rsqinv;
  if (update_history) {
    xi[0] -= rsht * delx;
    xi[1] -= rsht * dely;
    xi[2] -= rsht * delz;
  }

  // Coulomb cap: a spring beyond μ|f_n| is reset to the limit (one without length, |ξ| = 0
  // before the projection, exerts none); selections, not branches: the same values
  double fs1 = -(kt * xi[0]);
  double fs2 = -(kt * xi[1]);
  double fs3 = -(kt * xi[2]);
  const double fs = sqrt(fs1 * fs1 + fs2 * fs2 + fs3 * fs3);
  const double fn = mu * fabs(ccel * r);
  const bool capped = fs > fn;
  const bool has_length = xisq_before != 0.0;    // |ξ| != 0, without its square root
  const bool rescale = capped & has_length;    // & rather than &&: no branch
  // every candidate computed, then chosen: used only where capped
  const double scale = fn / fs;
  const double xi_capped[3] = {scale * xi[0], scale * xi[1], scale * xi[2]};
  const double fs_capped[3] = {fs1 * scale, fs2 * scale, fs3 * scale};
  xi[0] = rescale ? xi_capped[0] : xi[0];
  xi[1] = rescale ? xi_capped[1] : xi[1];
  xi[2] = rescale ? xi_capped[2] : xi[2];
  fs1 = rescale ? fs_capped[0] : (capped ? 0.0 : fs1);
  fs2 = rescale ? fs_capped[1] : (capped ? 0.0 : fs2);
  fs3 = rescale ? fs_capped[2] : (capped ? 0.0 : fs3);

  c.ft[0] = fs1;
  c.ft[1] = fs2;
  c.ft[2] = fs3;
  c.f[0] = delx * ccel + fs1;
  c.f[1] = dely * ccel + fs2;
  c.f[2] = delz * ccel + fs3;
  c.tor[0] = rinv * (dely * fs3 - delz * fs2);
  c.tor[1] = rinv * (delz * fs1 - delx * fs3);
  c.tor[2] = rinv * (delx * fs2 - dely * fs1);
  for (int d = 0; d < 3; d++) {
    c.tor_i[d] = c.lever_i * c.tor[d];
    c.tor_j[d] = c.lever_j * c.tor[d];
  }
  c.xisq_before = xisq_before;
  return c;
}

// Elastic energy stored in a contact: ½k_n δ² + ½k_t|ξ|² (ξ as the contact left it).
PW_INLINE double contact_energy(const double kn, const double kt, const ContactForce &c,
                                const double *xi)
{
  return 0.5 * kn * c.overlap * c.overlap + 0.5 * kt * (xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]);
}

// Energy the tangential spring lost to projection and the Coulomb cap in this contact.
PW_INLINE double spring_loss(const double kt, const ContactForce &c, const double *xi)
{
  return 0.5 * kt * (c.xisq_before - (xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]));
}

// Energy a spring of history xi loses when its contact opens (doc/model.md §1: it is forgotten).
PW_INLINE double opening_loss(const double kt, const double *xi)
{
  return 0.5 * kt * (xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]);
}

// A contact deeper than `limit` times the smaller radius, or a non-finite one, means the run
// has blown up (a time step too large for k_n, or NaN positions): never a state to go on from.
PW_INLINE bool contact_is_broken(const double overlap, const double radi, const double radj,
                                 const double limit)
{
  return !(overlap <= limit * (radi < radj ? radi : radj));    // true for NaN too
}

// Share of a pair's energy owned here: a pair with a ghost j is computed on both ranks
// when newton is off.
PW_INLINE double pair_share(const int j, const int nlocal, const int newton_pair)
{
  return (newton_pair || j < nlocal) ? 1.0 : 0.5;
}

// Mixing of per-type coefficients for I != J: geometric mean, as pair granular does.
PW_INLINE double mix_geometric(const double a, const double b)
{
  return sqrt(a * b);
}

}    // namespace porewater

#endif
