/* -*- c++ -*- ----------------------------------------------------------
   fix nve/sphere/bed/kk: the KOKKOS variant of nve/sphere/bed. The per-grain passes are
   porewater::BedInitial / BedForces / BedFinal, shared with the CPU fix: one kernel per hook.
   On one rank, unless `fuse no`, its post_force kernel also runs the per-grain work of the
   package's /kk fixes that follow it, and its final kernel the plate's layer motion: the
   fused pass, fix_nve_sphere_bed_pass_kokkos.h, which says which fixes join and how.
------------------------------------------------------------------------- */

#ifndef PW_FIX_NVE_SPHERE_BED_KOKKOS_H
#define PW_FIX_NVE_SPHERE_BED_KOKKOS_H

#include "fix_nve_sphere_bed.h"
#include "fix_nve_sphere_bed_pass_kokkos.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixNVESphereBedKokkos : public FixNVESphereBed {
 public:
  FixNVESphereBedKokkos(class LAMMPS *, int, char **);
  void setup(int) override;
  void initial_integrate(int) override;
  void post_force(int) override;
  void final_integrate() override;

 private:
  BedPassKokkos<DeviceType> pass;
  void compose_pass();    // which fixes join the pass, logged
};

}    // namespace LAMMPS_NS

#endif
