/* -*- c++ -*- ----------------------------------------------------------
   fix darcy/pressure/kk: the KOKKOS variant of darcy/pressure. Deposition and the force
   on the grains run as kernels of the core's per-grain coupling (darcy/coupling.h), the
   same as the CPU fix runs in loops; the grid solve stays on the host. Between fluid steps
   its held force may be added in fix nve/sphere/bed/kk's fused pass instead
   (fix_nve_sphere_bed_pass_kokkos.h), which stamps the step it did so.
------------------------------------------------------------------------- */

#ifndef PW_FIX_DARCY_PRESSURE_KOKKOS_H
#define PW_FIX_DARCY_PRESSURE_KOKKOS_H

#include "darcy/coupling.h"
#include "fix_darcy_pressure.h"
#include "kokkos_fused_pass.h"
#include "kokkos_grains.h"
#include "kokkos_type.h"

#include <vector>

namespace porewater {
// the per-atom held fluid force, rows of 3
template <class DeviceType> struct KokkosHeldRows {
  typename ArrayTypes<DeviceType>::t_ffloat_2d rows;
  KOKKOS_INLINE_FUNCTION double &operator()(int i, int d) const { return rows(i, d); }
};
// every grain its held fluid force (between fluid steps, `interpolate fluid`)
template <class DeviceType> struct KokkosHeldForce {
  KokkosGrains<DeviceType> grains;
  KokkosHeldRows<DeviceType> held;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { add_held_fluid_force(grains, held, i); }
};
}    // namespace porewater

namespace LAMMPS_NS {

template <class DeviceType> class FixDarcyPressureKokkos : public FixDarcyPressure {
 public:
  FixDarcyPressureKokkos(class LAMMPS *, int, char **);
  ~FixDarcyPressureKokkos() override;
  void setup(int) override;
  void post_force(int) override;
  void post_run() override;
  class Grains;    // the GrainBackend of the kernels

  // fix nve/sphere/bed/kk's fused pass: on a step whose post_force only adds the held
  // fluid force, that per-grain work may run in the pass, which stamps the step
  bool only_holds_force_now();
  porewater::KokkosHeldForce<DeviceType> held_kernel();
  porewater::PassStamp &pass_stamp() { return held_in_pass; }

 protected:
  porewater::GrainBackend &grains() override;
  void grow_fluid_force(int nmax) override;
  void sync_for_variables() override;
  void sync_for_nonfinite_check() override;

 private:
  bool per_grain_output_read_now() const;    // another style may read f_ID this step
  std::vector<int> reader_every;             // the end_of_step fixes' intervals (setup)
  porewater::PassStamp held_in_pass;    // the step whose held force the fused pass added
  Grains *kernels;
  DAT::tdual_ffloat_2d k_fluid_force;    // `fluid_force` is its host view
};

}    // namespace LAMMPS_NS

#endif
