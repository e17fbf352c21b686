/* -*- c++ -*- ----------------------------------------------------------
   fix shear/stress/kk: the KOKKOS variant of shear/stress: the core's plate kernels
   (walls/shear_plate.h) as Kokkos kernels over the atoms, the plate itself on the host as
   in the CPU fix.
------------------------------------------------------------------------- */

#ifndef PW_FIX_SHEAR_STRESS_KOKKOS_H
#define PW_FIX_SHEAR_STRESS_KOKKOS_H

#include "fix_shear_stress.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixShearStressKokkos : public FixShearStress {
 public:
  FixShearStressKokkos(class LAMMPS *, int, char **);

 protected:
  void plate_sums(double *sums) override;
  void momentum_sums(double *sums) override;
  void move_as_plate(double force_per_mass) override;
  void set_velocity_x(double velocity) override;
};

}    // namespace LAMMPS_NS

#endif
