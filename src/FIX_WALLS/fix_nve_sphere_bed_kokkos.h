/* -*- c++ -*- ----------------------------------------------------------
   fix nve/sphere/bed/kk: the KOKKOS variant of nve/sphere/bed. The per-grain passes are
   porewater::BedInitial / BedForces / BedFinal, shared with the CPU fix: one kernel per hook.
------------------------------------------------------------------------- */

#ifndef PW_FIX_NVE_SPHERE_BED_KOKKOS_H
#define PW_FIX_NVE_SPHERE_BED_KOKKOS_H

#include "fix_nve_sphere_bed.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixNVESphereBedKokkos : public FixNVESphereBed {
 public:
  FixNVESphereBedKokkos(class LAMMPS *, int, char **);
  void initial_integrate(int) override;
  void post_force(int) override;
  void final_integrate() override;
};

}    // namespace LAMMPS_NS

#endif
