/* ----------------------------------------------------------------------
   fix nve/sphere/bed/kk (see doc/fix_nve_sphere_bed.rst)
------------------------------------------------------------------------- */

#include "fix_nve_sphere_bed_kokkos.h"

#include "integrate/bed_pass.h"
#include "kokkos_grains.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "force.h"
#include "update.h"

using namespace LAMMPS_NS;

template <class DeviceType>
FixNVESphereBedKokkos<DeviceType>::FixNVESphereBedKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixNVESphereBed(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;    // synced in the hooks themselves
  datamask_modify = EMPTY_MASK;
}

template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::initial_integrate(int)
{
  atomKK->sync(execution_space, X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK |
                                    RMASS_MASK | RADIUS_MASK | MASK_MASK);
  using G = porewater::KokkosGrains<DeviceType>;
  porewater::kokkos_for_each_grain<DeviceType>(
      atom->nlocal, porewater::BedInitial<G>{G(atomKK), groupbit, heldbit,
                                             porewater::verlet_steps(update->dt, force->ftm2v)});
  atomKK->modified(execution_space, X_MASK | V_MASK | OMEGA_MASK);
}

template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::post_force(int)
{
  atomKK->sync(execution_space, X_MASK | F_MASK | RMASS_MASK | RADIUS_MASK | MASK_MASK);
  using G = porewater::KokkosGrains<DeviceType>;
  porewater::kokkos_for_each_grain<DeviceType>(
      atom->nlocal, porewater::BedForces<G>{G(atomKK), groupbit, gravitybit,
                                            settings.floor ? 1 : 0, settings.z_floor,
                                            settings.kn, -settings.gravity});
  atomKK->modified(execution_space, F_MASK);
}

template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::final_integrate()
{
  atomKK->sync(execution_space,
               V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | RADIUS_MASK | MASK_MASK);
  using G = porewater::KokkosGrains<DeviceType>;
  porewater::kokkos_for_each_grain<DeviceType>(
      atom->nlocal, porewater::BedFinal<G>{G(atomKK), groupbit, heldbit,
                                           porewater::verlet_steps(update->dt, force->ftm2v)});
  atomKK->modified(execution_space, V_MASK | OMEGA_MASK);
}

namespace LAMMPS_NS {
template class FixNVESphereBedKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixNVESphereBedKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
