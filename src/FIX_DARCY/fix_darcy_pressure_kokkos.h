/* -*- c++ -*- ----------------------------------------------------------
   fix darcy/pressure/kk: the KOKKOS variant of darcy/pressure. Deposition and the force
   on the grains run as kernels of the core's per-grain coupling (darcy/coupling.h), the
   same as the CPU fix runs in loops; the grid solve stays on the host.
------------------------------------------------------------------------- */

#ifndef PW_FIX_DARCY_PRESSURE_KOKKOS_H
#define PW_FIX_DARCY_PRESSURE_KOKKOS_H

#include "fix_darcy_pressure.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixDarcyPressureKokkos : public FixDarcyPressure {
 public:
  FixDarcyPressureKokkos(class LAMMPS *, int, char **);
  ~FixDarcyPressureKokkos() override;
  void setup(int) override;
  void post_force(int) override;
  class Grains;    // the GrainBackend of the kernels

 protected:
  porewater::GrainBackend &grains() override;
  void grow_fluid_force(int nmax) override;
  void sync_for_variables() override;
  void sync_for_nonfinite_check() override;

 private:
  Grains *kernels;
  DAT::tdual_ffloat_2d k_fluid_force;    // `fluid_force` is its host view
};

}    // namespace LAMMPS_NS

#endif
