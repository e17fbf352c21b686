/* -*- c++ -*- ----------------------------------------------------------
   fix shear/stress/kk: the KOKKOS variant of shear/stress: the sums over the plate's grains
   and the plate's forces as kernels over the atoms, the plate acceleration from
   porewater::plate_acceleration() on the host as in the CPU fix.
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
  void sum_forces_and_positions(double *sums) override;
  void sum_momentum(double *sums) override;
  void move_as_plate(double plate_acceleration) override;
  void set_velocity_x(double velocity) override;
};

}    // namespace LAMMPS_NS

#endif
