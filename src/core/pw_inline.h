// PW_INLINE marks the header-only physics shared by the CPU and the KOKKOS styles:
// KOKKOS_INLINE_FUNCTION (host + device) when a host's KOKKOS styles include it (LMP_KOKKOS),
// plain inline otherwise: the core library itself and its unit tests need no Kokkos.
#ifndef PW_INLINE_H
#define PW_INLINE_H

// PW_FORCEINLINE: the per-grain bodies of the loops, whose per-grain setup the compiler
// must hoist out of the caller's loop (a call per grain costs more than the body saves).
#if defined(LMP_KOKKOS)
#include <Kokkos_Macros.hpp>
#define PW_INLINE KOKKOS_INLINE_FUNCTION
#define PW_FORCEINLINE KOKKOS_FORCEINLINE_FUNCTION
#elif defined(__GNUC__)
#define PW_INLINE inline
#define PW_FORCEINLINE inline __attribute__((always_inline))
#else
#define PW_INLINE inline
#define PW_FORCEINLINE inline
#endif

// PW_NOINLINE: host code called rarely from a hot loop (a buffer's flush, a contact that
// opened), kept out of it so that the loop keeps its values in registers.
#if defined(__GNUC__)
#define PW_NOINLINE __attribute__((noinline))
#else
#define PW_NOINLINE
#endif

#endif
