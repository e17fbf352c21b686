// Step 2 of the block pass (contact_block.h): linear_coulomb_contact on every row of the
// buffer. With one set of coefficients the rows are independent and branch-free, so the
// loop runs in SIMD lanes; the x86-64 build carries AVX2 and AVX-512 copies, the widest the
// CPU runs picked at the first call (without FMA: the same operations, rounded as the
// scalar law rounds them; tests/unit/test_contact_block.cpp runs every copy).
#include "contact/contact_block.h"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__CUDACC__)
#define PW_X86_COPIES 1    // the AVX2 and AVX-512 copies, chosen with __builtin_cpu_supports
#endif

namespace porewater {

namespace {

template <int LEVER, int UPDATE_HISTORY, int FRICTIONAL>
inline __attribute__((always_inline)) void uniform_law(ContactBlock &b, const int n,
                                                       const ContactCoeffs &k_all,
                                                       const double dt)
{
  const ContactCoeffs k{k_all.kn, k_all.kt, k_all.mu, FRICTIONAL};
  const ContactStep step{LEVER, UPDATE_HISTORY, dt};
#pragma omp simd
  for (int r = 0; r < n; r++) linear_coulomb_row(b, r, k, step);
}

// type pairs with their own coefficients (and so their own branch for frictionless pairs)
void mixed_law(ContactBlock &b, const int n, const ContactStep &step)
{
  for (int r = 0; r < n; r++)
    linear_coulomb_row(b, r, ContactCoeffs{b.kn[r], b.kt[r], b.mu[r], b.frictional[r]}, step);
}

// the law over the block: the rows' switches and the pairs' friction as constants of the loop
inline __attribute__((always_inline)) void block_law(ContactBlock &b, const int n,
                                                     const ContactCoeffs *k, const ContactStep &step)
{
  if (!k) return mixed_law(b, n, step);
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

using BlockLaw = void (*)(ContactBlock &, int, const ContactCoeffs *, const ContactStep &);

void law_baseline(ContactBlock &b, const int n, const ContactCoeffs *k, const ContactStep &step)
{
  block_law(b, n, k, step);
}

#ifdef PW_X86_COPIES
__attribute__((target("avx2"))) void law_avx2(ContactBlock &b, const int n,
                                              const ContactCoeffs *k, const ContactStep &step)
{
  block_law(b, n, k, step);
}

// 8 lanes a vector: on cores with full-width AVX-512 the law takes 0.6x its AVX2 time
__attribute__((target("avx512f"))) void law_avx512(ContactBlock &b, const int n,
                                                  const ContactCoeffs *k, const ContactStep &step)
{
  block_law(b, n, k, step);
}
#endif

BlockLaw law_of(const SimdCopy copy)
{
#ifdef PW_X86_COPIES
  if (copy == SimdCopy::avx512) return law_avx512;
  if (copy == SimdCopy::avx2) return law_avx2;
#endif
  return copy == SimdCopy::baseline ? law_baseline : nullptr;
}

}    // namespace

bool simd_copy_runs_here(const SimdCopy copy)
{
#ifdef PW_X86_COPIES
  __builtin_cpu_init();
  if (copy == SimdCopy::avx512) return __builtin_cpu_supports("avx512f");
  if (copy == SimdCopy::avx2) return __builtin_cpu_supports("avx2");
#endif
  return copy == SimdCopy::baseline;
}

SimdCopy widest_simd_copy()
{
  if (simd_copy_runs_here(SimdCopy::avx512)) return SimdCopy::avx512;
  return simd_copy_runs_here(SimdCopy::avx2) ? SimdCopy::avx2 : SimdCopy::baseline;
}

void linear_coulomb_block_law(ContactBlock &b, const int n, const ContactCoeffs *k,
                              const ContactStep &step, const SimdCopy copy)
{
  law_of(copy)(b, n, k, step);
}

void linear_coulomb_block_law(ContactBlock &b, const int n, const ContactCoeffs *k,
                              const ContactStep &step)
{
  static const BlockLaw widest = law_of(widest_simd_copy());
  widest(b, n, k, step);
}

}    // namespace porewater
