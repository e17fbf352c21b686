/* -*- c++ -*- ----------------------------------------------------------
   The fused pass of fix nve/sphere/bed/kk (keyword `fuse`, doc/fix_nve_sphere_bed.rst): on
   one rank, the per-grain post_force work of the package's /kk fixes right after it among
   the post_force fixes, in this order, each optional,
     fix wall/stress/kk     the wall's step (its motion, the contacts, its force)
     fix darcy/pressure/kk  on a step between fluid steps, its held force
     fix shear/stress/kk    its sums of the layer's forces and the plate's step
   runs in the kernel of the bed's own post_force, each grain's forces added in the order of
   the fixes; and when shear/stress/kk is the last post_force fix and nve/sphere/bed/kk the
   first final_integrate one, the layer's motion runs in the bed's final kernel. Any other
   post_force fix ends the list: its forces must come in their place.

   The handshake is by step (lammps/kokkos_fused_pass.h): each step the pass stamps every
   member whose work it did, and a member does its own work unless stamped for this step.
   Which fixes join is decided at each run's setup, logged in one line, and again whenever
   the fix list changes between runs that skip the setup (`run N pre no`).
------------------------------------------------------------------------- */

#ifndef PW_FIX_NVE_SPHERE_BED_PASS_KOKKOS_H
#define PW_FIX_NVE_SPHERE_BED_PASS_KOKKOS_H

#include "integrate/bed_pass.h"
#include "kokkos_grains.h"
#include "kokkos_type.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

template <class> class FixWallStressKokkos;
template <class> class FixDarcyPressureKokkos;
template <class> class FixShearStressKokkos;

template <class DeviceType> class BedPassKokkos {
 public:
  using Grains = porewater::KokkosGrains<DeviceType>;
  explicit BedPassKokkos(class LAMMPS *lmp);

  // which fixes join the pass of `bed`, from the fix list now; returns the log line
  std::string compose(class Fix *bed, bool fuse);
  // the fix list has changed since the last compose
  bool stale() const;
  // this step's post_force: the bed's forces and the work of the members that join on this
  // step, stamped; false when none joins (the bed then adds its forces alone)
  bool post_force(const porewater::BedForces<Grains> &bed);
  // this step's final kick, after the plate's layer motion if this step's pass deferred it
  // to here; false when it did not (the bed then kicks alone)
  bool final_integrate(const porewater::BedFinal<Grains> &kick);

 private:
  class LAMMPS *lmp;
  FixWallStressKokkos<DeviceType> *wall;
  FixDarcyPressureKokkos<DeviceType> *darcy;
  FixShearStressKokkos<DeviceType> *plate;
  bool moves_plate;                  // the layer's motion runs in the bed's final kernel
  long long motion_step;             // ... and the step it was deferred for
  std::vector<class Fix *> fixes;    // the fix list compose saw
  Kokkos::View<double *, DeviceType> d_totals;    // the pass' sums (read by its final)
};

}    // namespace LAMMPS_NS

#endif
