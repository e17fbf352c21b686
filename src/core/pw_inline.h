// PW_INLINE marks the header-only physics shared by the CPU and the KOKKOS styles:
// KOKKOS_INLINE_FUNCTION (host + device) when a host's KOKKOS styles include it (LMP_KOKKOS),
// plain inline otherwise: the core library itself and its unit tests need no Kokkos.
#ifndef PW_INLINE_H
#define PW_INLINE_H

#if defined(LMP_KOKKOS)
#include <Kokkos_Macros.hpp>
#define PW_INLINE KOKKOS_INLINE_FUNCTION
#else
#define PW_INLINE inline
#endif

#endif
