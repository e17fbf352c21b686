/* ----------------------------------------------------------------------
   fix shear/stress/kk (see doc/fix_shear_stress.rst)
------------------------------------------------------------------------- */

#include "fix_shear_stress_kokkos.h"

#include "kokkos_grains.h"

#include "atom_kokkos.h"
#include "atom_masks.h"

using namespace LAMMPS_NS;

template <class DeviceType>
FixShearStressKokkos<DeviceType>::FixShearStressKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixShearStress(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
}

template <class DeviceType> void FixShearStressKokkos<DeviceType>::plate_sums(double *sums)
{
  atomKK->sync(execution_space, X_MASK | F_MASK | RMASS_MASK | IMAGE_MASK | MASK_MASK);
  porewater::kokkos_sum_over_grains<DeviceType>(
      atom->nlocal,
      porewater::PlateSums<porewater::KokkosGrains<DeviceType>>{
          porewater::KokkosGrains<DeviceType>(atomKK), groupbit, image_unwrap()},
      sums);
}

template <class DeviceType> void FixShearStressKokkos<DeviceType>::momentum_sums(double *sums)
{
  atomKK->sync(execution_space, V_MASK | RMASS_MASK | MASK_MASK);
  porewater::kokkos_sum_over_grains<DeviceType>(
      atom->nlocal,
      porewater::PlateMomentum<porewater::KokkosGrains<DeviceType>>{
          porewater::KokkosGrains<DeviceType>(atomKK), groupbit},
      sums);
}

template <class DeviceType>
void FixShearStressKokkos<DeviceType>::move_as_plate(double force_per_mass)
{
  atomKK->sync(execution_space, V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | MASK_MASK);
  porewater::kokkos_for_each_grain<DeviceType>(
      atom->nlocal, porewater::PlateMotion<porewater::KokkosGrains<DeviceType>>{
                        porewater::KokkosGrains<DeviceType>(atomKK), groupbit, force_per_mass});
  atomKK->modified(execution_space, V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK);
}

template <class DeviceType> void FixShearStressKokkos<DeviceType>::set_velocity_x(double velocity)
{
  atomKK->sync(execution_space, V_MASK | MASK_MASK);
  porewater::kokkos_for_each_grain<DeviceType>(
      atom->nlocal, porewater::PlateVelocity<porewater::KokkosGrains<DeviceType>>{
                        porewater::KokkosGrains<DeviceType>(atomKK), groupbit, velocity});
  atomKK->modified(execution_space, V_MASK);
}

namespace LAMMPS_NS {
template class FixShearStressKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixShearStressKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
