/* -*- c++ -*- ----------------------------------------------------------
   fix nve/sphere/bed/kk: the KOKKOS variant of nve/sphere/bed. The per-grain passes are
   porewater::BedInitial / BedForces / BedFinal, shared with the CPU fix: one kernel per hook.
   On one rank its post_force kernel also runs the per-grain work of the package's /kk fixes
   that follow it in post_force (wall/stress, darcy/pressure between fluid steps,
   shear/stress's sums): one kernel where there were four, each grain's forces added in the
   same order; and when shear/stress/kk is the last post_force fix and this the first
   final_integrate one, its final kernel moves the layer before the kick.
------------------------------------------------------------------------- */

#ifndef PW_FIX_NVE_SPHERE_BED_KOKKOS_H
#define PW_FIX_NVE_SPHERE_BED_KOKKOS_H

#include "fix_nve_sphere_bed.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class> class FixWallStressKokkos;
template <class> class FixDarcyPressureKokkos;
template <class> class FixShearStressKokkos;

template <class DeviceType> class FixNVESphereBedKokkos : public FixNVESphereBed {
 public:
  FixNVESphereBedKokkos(class LAMMPS *, int, char **);
  void setup(int) override;
  void initial_integrate(int) override;
  void post_force(int) override;
  void final_integrate() override;

 private:
  // the fixes whose work joins this one's post_force pass: those right after it among the
  // post_force fixes, in this order, each optional (found at the first step of a run)
  FixWallStressKokkos<DeviceType> *pass_wall;
  FixDarcyPressureKokkos<DeviceType> *pass_darcy;
  FixShearStressKokkos<DeviceType> *pass_plate;
  bool pass_found;
  bool moves_plate;    // pass_plate's layer moves in this fix's final_integrate kernel
  Kokkos::View<double *, DeviceType> d_totals;    // the pass' sums (read by its final)
  void find_pass();
  bool run_pass();    // false: nothing joins this step
};

}    // namespace LAMMPS_NS

#endif
