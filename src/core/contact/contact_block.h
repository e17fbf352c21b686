// pair linear/coulomb's pass over a block of grains, for hosts whose cores run SIMD lanes
// (the CPU style, /kk on OpenMP or Serial), in three steps over a buffer of closed contacts:
//   1. screen every neighbour pair of the block's grains: each one's distance is written to
//      the next row of the buffer, and the row kept only if the grains overlap, so that
//      whether a pair is in contact (about half of them in a dense bed, at random) is never
//      a branch; an open pair that was touched forgets its spring (open_pair);
//   2. the law on every buffered contact (linear_coulomb_block_law, contact_block.cpp):
//      independent contacts, one SIMD lane each;
//   3. each contact's force applied in the order of the screen (closed_contact), which is
//      the order of the one-grain sweep (contact_sweep.h), so that the forces, torques,
//      springs and virial are those of linear_coulomb_sweep to the bit.
// The policy P is that of linear_coulomb_sweep, plus:
//   p.grain(ii)              the ii-th grain of the neighbour list
//   p.uniform_coeffs(k)      true, with k set, if every type pair has the coefficients k
#ifndef PW_CONTACT_BLOCK_H
#define PW_CONTACT_BLOCK_H

#include "contact/contact_sweep.h"

namespace porewater {

// Closed contacts in columns (structure of arrays): what the law reads and writes, and where
// each contact came from. 64 rows, about 17 kB: the buffer stays in the L1 cache.
struct ContactBlock {
  static constexpr int capacity = 64;
  // the pair: grains i and j, and j's place jj in i's neighbour row
  int i[capacity], j[capacity], jj[capacity];
  // the law's inputs (ContactPair; rsq from del again) and the spring, updated in place
  double delx[capacity], dely[capacity], delz[capacity];
  double radi[capacity], radj[capacity];
  double vr[3][capacity], wi[3][capacity], wj[3][capacity], xi[3][capacity];
  // per contact coefficients, where the type pairs differ
  double kn[capacity], kt[capacity], mu[capacity];
  int frictional[capacity];
  // the law's outputs that the force's application needs (ContactForce)
  double f[3][capacity], tor_i[3][capacity], tor_j[3][capacity];
  double overlap[capacity], xisq_before[capacity];
};

// The law on row r of the block: what every SIMD copy of step 2 runs on each row
PW_FORCEINLINE void linear_coulomb_row(ContactBlock &b, const int r, const ContactCoeffs &k,
                                       const ContactStep &step)
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

// Step 2: the law on rows [0, n) of the block; k is the coefficients of every pair, or null
// where they differ (then each row's own, scalar). Run by the widest SIMD copy of the law
// this CPU has; every copy gives the scalar law's values to the bit.
void linear_coulomb_block_law(ContactBlock &b, int n, const ContactCoeffs *k,
                              const ContactStep &step);

// The law's copies for instruction sets (x86-64: AVX2, AVX-512; elsewhere the baseline only),
// named so that tests and benchmarks can run each one this CPU has (simd_copy_runs_here:
// another one would stop the program on an illegal instruction).
enum class SimdCopy { baseline, avx2, avx512 };
bool simd_copy_runs_here(SimdCopy copy);
SimdCopy widest_simd_copy();
void linear_coulomb_block_law(ContactBlock &b, int n, const ContactCoeffs *k,
                              const ContactStep &step, SimdCopy copy);

namespace detail {

// Step 2's inputs from the grains: velocities, spins and the stored spring of each row
template <class P> inline void gather_contacts(const P &p, ContactBlock &b, const int n, const bool uniform)
{
  int r = 0;
  while (r < n) {    // a grain's rows together
    const int i = b.i[r];
    const auto row = p.neighbors(i);
    const double radi = p.radius(i);
    double vi_scratch[3], wi_scratch[3];
    const double *vi = p.v(i, vi_scratch), *wi = p.omega(i, wi_scratch);
    for (; r < n && b.i[r] == i; r++) {
      const int j = b.j[r];
      double vj[3], wj[3], spring[3];
      const ContactPair pair = contact_pair(b.delx[r], b.dely[r], b.delz[r], 0.0, radi, b.radj[r],
                                            vi, p.v(j, vj), wi, p.omega(j, wj));
      const double *xi = row.history(b.jj[r], spring);
      b.radi[r] = radi;
      for (int d = 0; d < 3; d++) {
        b.vr[d][r] = pair.vr[d];
        b.wi[d][r] = pair.wi[d];
        b.wj[d][r] = pair.wj[d];
        b.xi[d][r] = xi[d];
      }
      if (!uniform) {
        const ContactCoeffs k = p.coeffs(p.type(i), p.type(j));
        b.kn[r] = k.kn;
        b.kt[r] = k.kt;
        b.mu[r] = k.mu;
        b.frictional[r] = k.frictional;
      }
    }
  }
}

// Step 3: each row's force applied, a grain's rows together (its accumulator opened once)
template <class P>
inline void apply_contacts(const P &p, const ContactBlock &b, const int n, const bool uniform,
                           const ContactCoeffs &k_all, typename P::Sums &sums)
{
  int r = 0;
  while (r < n) {
    const int i = b.i[r];
    const auto row = p.neighbors(i);
    auto force_i = p.force_on(i);
    for (; r < n && b.i[r] == i; r++) {
      const int j = b.j[r], jj = b.jj[r];
      row.touch(jj);
      const ContactCoeffs k =
          uniform ? k_all : ContactCoeffs{b.kn[r], b.kt[r], b.mu[r], b.frictional[r]};
      ContactForce c{};
      for (int d = 0; d < 3; d++) {
        c.f[d] = b.f[d][r];
        c.tor_i[d] = b.tor_i[d][r];
        c.tor_j[d] = b.tor_j[d][r];
      }
      c.overlap = b.overlap[r];
      c.xisq_before = b.xisq_before[r];
      double spring[3];
      double *xi = row.history(jj, spring);
      for (int d = 0; d < 3; d++) xi[d] = b.xi[d][r];
      closed_contact(p, row, force_i, sums, i, j, jj, k, c, xi, b.radi[r], b.radj[r],
                     b.delx[r], b.dely[r], b.delz[r]);
    }
    force_i.finish();
  }
}

template <class P>
PW_NOINLINE void flush_contacts(const P &p, ContactBlock &b, const int n, const bool uniform,
                           const ContactCoeffs &k, const ContactStep &step, typename P::Sums &sums)
{
  gather_contacts(p, b, n, uniform);
  linear_coulomb_block_law(b, n, uniform ? &k : nullptr, step);
  apply_contacts(p, b, n, uniform, k, sums);
}

template <class P, class Row>
PW_NOINLINE void forget_opened(const P &p, const Row &row, const int jj, const int itype,
                               const int j, typename P::Sums &sums)
{
  open_pair(p, row, jj, itype, j, sums);
}

}    // namespace detail

// The grains ii in [begin, end) of the neighbour list, through a buffer of closed contacts
// that is emptied whenever it is full and at the end.
template <class P>
inline void linear_coulomb_block_sweep(const P &p, const int begin, const int end,
                                       typename P::Sums &sums, ContactBlock &b)
{
  ContactCoeffs k{0.0, 0.0, 0.0, 0};
  const bool uniform = p.uniform_coeffs(k);
  const ContactStep step = p.step();
  int n = 0;
  for (int ii = begin; ii < end; ii++) {
    const int i = p.grain(ii);
    const SweptGrain gi = swept_grain(p, i);
    const auto row = p.neighbors(i);
    const int jnum = row.count();
    for (int jj = 0; jj < jnum; jj++) {
      const NeighbourPair pr = neighbour_pair(p, gi, row, jj);
      const int closed = pr.closed;
      b.i[n] = i;
      b.j[n] = pr.j;
      b.jj[n] = jj;
      b.delx[n] = pr.delx;
      b.dely[n] = pr.dely;
      b.delz[n] = pr.delz;
      b.radj[n] = pr.radj;
      n += closed;
      // a pair that opened since the last step: rare, so a predictable branch
      if (row.touched(jj) & !closed) detail::forget_opened(p, row, jj, gi.type, pr.j, sums);
      if (n == ContactBlock::capacity) {
        detail::flush_contacts(p, b, n, uniform, k, step, sums);
        n = 0;
      }
    }
  }
  if (n > 0) detail::flush_contacts(p, b, n, uniform, k, step, sums);
}

}    // namespace porewater

#endif
