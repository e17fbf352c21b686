/* ----------------------------------------------------------------------
   fix nve/sphere/bed/kk (see doc/fix_nve_sphere_bed.rst)
------------------------------------------------------------------------- */

#include "fix_nve_sphere_bed_kokkos.h"

#include "integrate/bed_pass.h"
#include "kokkos_grains.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "force.h"
#include "update.h"

using namespace LAMMPS_NS;

template <class DeviceType>
FixNVESphereBedKokkos<DeviceType>::FixNVESphereBedKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixNVESphereBed(lmp, narg, arg), pass(lmp)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;    // synced in the hooks themselves
  datamask_modify = EMPTY_MASK;
}

template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::compose_pass()
{
  const std::string line = pass.compose(this, settings.fuse);
  if (comm->me == 0) utils::logmesg(lmp, line);
}

// the fixes may have changed between runs: which join is decided again at every setup (the
// setup's own forces each fix adds itself)
template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::setup(int vflag)
{
  compose_pass();
  FixNVESphereBed::setup(vflag);
}

template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::initial_integrate(int)
{
  atomKK->sync(execution_space, X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK |
                                    RMASS_MASK | RADIUS_MASK | MASK_MASK);
  using G = porewater::KokkosGrains<DeviceType>;
  porewater::kokkos_for_each_grain<DeviceType>(
      "nve/sphere/bed:initial_integrate", atom->nlocal,
      porewater::BedInitial<G>{G(atomKK), groupbit, heldbit,
                               porewater::verlet_steps(update->dt, force->ftm2v)});
  atomKK->modified(execution_space, X_MASK | V_MASK | OMEGA_MASK);
}

template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::post_force(int)
{
  using G = porewater::KokkosGrains<DeviceType>;
  const porewater::BedForces<G> bed{G(atomKK), groupbit, gravitybit, settings.floor ? 1 : 0,
                                    settings.z_floor, settings.kn, -settings.gravity};
  if (!update->setupflag) {    // the setup's forces each fix adds itself
    if (pass.stale()) compose_pass();    // fixes changed before a run without its setup
    if (pass.post_force(bed)) return;
  }
  atomKK->sync(execution_space, X_MASK | F_MASK | RMASS_MASK | RADIUS_MASK | MASK_MASK);
  porewater::kokkos_for_each_grain<DeviceType>("nve/sphere/bed:post_force", atom->nlocal, bed);
  atomKK->modified(execution_space, F_MASK);
}

template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::final_integrate()
{
  using G = porewater::KokkosGrains<DeviceType>;
  const porewater::BedFinal<G> kick{G(atomKK), groupbit, heldbit,
                                    porewater::verlet_steps(update->dt, force->ftm2v)};
  if (pass.final_integrate(kick)) return;
  atomKK->sync(execution_space,
               V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | RADIUS_MASK | MASK_MASK);
  porewater::kokkos_for_each_grain<DeviceType>("nve/sphere/bed:final_integrate", atom->nlocal, kick);
  atomKK->modified(execution_space, V_MASK | OMEGA_MASK);
}

namespace LAMMPS_NS {
template class FixNVESphereBedKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixNVESphereBedKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
