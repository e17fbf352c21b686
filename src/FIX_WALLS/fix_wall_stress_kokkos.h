/* -*- c++ -*- ----------------------------------------------------------
   fix wall/stress/kk: the KOKKOS variant of wall/stress. The grain–wall contacts run as a
   kernel over the atoms: the core's porewater::WallContacts, as in the CPU fix; the wall
   itself (a few scalars) moves on the host.
------------------------------------------------------------------------- */

#ifndef PW_FIX_WALL_STRESS_KOKKOS_H
#define PW_FIX_WALL_STRESS_KOKKOS_H

#include "fix_wall_stress.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixWallStressKokkos : public FixWallStress {
 public:
  FixWallStressKokkos(class LAMMPS *, int, char **);
  void setup(int) override;

 protected:
  void grain_contacts(double *sums) override;
};

}    // namespace LAMMPS_NS

#endif
