// The rigid shear plate of fix shear/stress (MODEL.md §4), shared by the CPU and KOKKOS
// fixes and the unit tests.
#ifndef PW_SHEAR_PLATE_H
#define PW_SHEAR_PLATE_H

#include "pw_inline.h"

namespace porewater {

// x-acceleration every grain of the plate shares: applied shear force τ·L_x·L_y plus the
// x-forces of all other interactions on the plate's grains, over the plate mass M.
PW_INLINE double plate_acceleration(const double tau, const double area, const double sum_fx,
                                    const double plate_mass)
{
  return (tau * area + sum_fx) / plate_mass;
}

}    // namespace porewater

#endif
