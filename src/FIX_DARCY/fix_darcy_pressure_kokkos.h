/* -*- c++ -*- ----------------------------------------------------------
   fix darcy/pressure/kk: the KOKKOS variant of darcy/pressure. Deposition and the force
   on the grains run as kernels calling the same porewater:: inline functions as the CPU
   fix (darcy_grains.h); the grid solve stays on the host DarcySolver.
------------------------------------------------------------------------- */

#ifndef PW_FIX_DARCY_PRESSURE_KOKKOS_H
#define PW_FIX_DARCY_PRESSURE_KOKKOS_H

#include "fix_darcy_pressure.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixDarcyPressureKokkos : public FixDarcyPressure {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef Kokkos::View<double *, Kokkos::LayoutRight, DeviceType> grid_view;

  FixDarcyPressureKokkos(class LAMMPS *, int, char **);
  ~FixDarcyPressureKokkos() override;

 protected:
  void deposit_grains(double interval) override;
  void apply_fluid_force() override;
  void add_held_fluid_force() override;
  void grow_fluid_force(int nmax) override;
  void sync_atoms_to_host() override;

 private:
  grid_view d_deposits;    // DepositLayout, summed with atomics
  grid_view d_gradient;    // the solver's cell-centre grad p, copied after each solve
  DAT::tdual_ffloat_2d k_fluid_force;
};

}    // namespace LAMMPS_NS

#endif
