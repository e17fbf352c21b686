// PW_INLINE marks the header-only physics shared by the CPU and the KOKKOS styles:
// KOKKOS_INLINE_FUNCTION (host + device) when built against Kokkos, plain inline otherwise,
// so the same functions are unit-tested without LAMMPS or Kokkos.
#ifndef PW_INLINE_H
#define PW_INLINE_H

#if defined(LMP_KOKKOS) || defined(PW_WITH_KOKKOS)
#include <Kokkos_Macros.hpp>
#define PW_INLINE KOKKOS_INLINE_FUNCTION
#else
#define PW_INLINE inline
#endif

#endif
