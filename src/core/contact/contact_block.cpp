// Step 2 of the block pass (contact_block.h): linear_coulomb_contact on every row of the
// buffer. With one set of coefficients the rows are independent and branch-free, so the
// loop runs in SIMD lanes; the x86-64 build carries an AVX2 copy picked at load time
// (without FMA: the same operations, rounded as the scalar law rounds them).
#include "contact/contact_block.h"

namespace porewater {

namespace {

// the law on row r of the block
inline __attribute__((always_inline)) void law_row(ContactBlock &b, const int r,
                                                   const ContactCoeffs &k, const ContactStep &step)
{
  const ContactPair pair{b.delx[r],
                         b.dely[r],
                         b.delz[r],
                         distance_squared(b.delx[r], b.dely[r], b.delz[r]),
                         b.radi[r],
                         b.radj[r],
                         {b.vr[0][r], b.vr[1][r], b.vr[2][r]},
                         {b.wi[0][r], b.wi[1][r], b.wi[2][r]},
                         {b.wj[0][r], b.wj[1][r], b.wj[2][r]}};
  double xi[3] = {b.xi[0][r], b.xi[1][r], b.xi[2][r]};
  const ContactForce c = linear_coulomb_contact(pair, k, step, xi);
  for (int d = 0; d < 3; d++) {
    b.xi[d][r] = xi[d];
    b.f[d][r] = c.f[d];
    b.tor_i[d][r] = c.tor_i[d];
    b.tor_j[d][r] = c.tor_j[d];
  }
  b.overlap[r] = c.overlap;
  b.xisq_before[r] = c.xisq_before;
}

template <int LEVER, int UPDATE_HISTORY, int FRICTIONAL>
inline __attribute__((always_inline)) void uniform_law(ContactBlock &b, const int n,
                                                       const ContactCoeffs &k_all,
                                                       const double dt)
{
  const ContactCoeffs k{k_all.kn, k_all.kt, k_all.mu, FRICTIONAL};
  const ContactStep step{LEVER, UPDATE_HISTORY, dt};
#pragma omp simd
  for (int r = 0; r < n; r++) law_row(b, r, k, step);
}

// type pairs with their own coefficients (and so their own branch for frictionless pairs)
void mixed_law(ContactBlock &b, const int n, const ContactStep &step)
{
  for (int r = 0; r < n; r++)
    law_row(b, r, ContactCoeffs{b.kn[r], b.kt[r], b.mu[r], b.frictional[r]}, step);
}

}    // namespace

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__)
__attribute__((target_clones("avx2", "default")))
#endif
void linear_coulomb_block_law(ContactBlock &b, const int n, const ContactCoeffs *k,
                              const ContactStep &step)
{
  if (!k) return mixed_law(b, n, step);
  // the step's switches and the pairs' friction as constants of the loop
  const int lever = step.lever == LEVER_RADIUS, update = step.update_history != 0,
            frictional = k->frictional != 0;
  switch (lever * 4 + update * 2 + frictional) {
  case 0: return uniform_law<LEVER_CONTACT, 0, 0>(b, n, *k, step.dt);
  case 1: return uniform_law<LEVER_CONTACT, 0, 1>(b, n, *k, step.dt);
  case 2: return uniform_law<LEVER_CONTACT, 1, 0>(b, n, *k, step.dt);
  case 3: return uniform_law<LEVER_CONTACT, 1, 1>(b, n, *k, step.dt);
  case 4: return uniform_law<LEVER_RADIUS, 0, 0>(b, n, *k, step.dt);
  case 5: return uniform_law<LEVER_RADIUS, 0, 1>(b, n, *k, step.dt);
  case 6: return uniform_law<LEVER_RADIUS, 1, 0>(b, n, *k, step.dt);
  default: return uniform_law<LEVER_RADIUS, 1, 1>(b, n, *k, step.dt);
  }
}

}    // namespace porewater
