/* ----------------------------------------------------------------------
   fix wall/stress/kk (see doc/fix_wall_stress.rst)
------------------------------------------------------------------------- */

#include "fix_wall_stress_kokkos.h"

#include "kokkos_grains.h"
#include "walls/wall_contact.h"

#include "atom_kokkos.h"
#include "atom_masks.h"

using namespace LAMMPS_NS;

namespace {
struct NoPerAtomVirial {    // the KOKKOS fix keeps the global virial only
  KOKKOS_INLINE_FUNCTION void operator()(int, double) const {}
};
}    // namespace

template <class DeviceType>
FixWallStressKokkos<DeviceType>::FixWallStressKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixWallStress(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
  virial_peratom_flag = 0;
}

// `z auto` reads the grains once, at the first setup, on the host
template <class DeviceType> void FixWallStressKokkos<DeviceType>::setup(int vflag)
{
  if (wall->placement_pending()) atomKK->sync(Host, X_MASK | RADIUS_MASK | MASK_MASK);
  FixWallStress::setup(vflag);
}

template <class DeviceType> void FixWallStressKokkos<DeviceType>::grain_contacts(double *sums)
{
  atomKK->sync(execution_space, X_MASK | V_MASK | F_MASK | RADIUS_MASK | MASK_MASK);
  porewater::kokkos_sum_over_grains<DeviceType>(
      atom->nlocal,
      wall->contacts(porewater::KokkosGrains<DeviceType>(atomKK), NoPerAtomVirial(), groupbit),
      sums);
  atomKK->modified(execution_space, F_MASK);
}

namespace LAMMPS_NS {
template class FixWallStressKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixWallStressKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
