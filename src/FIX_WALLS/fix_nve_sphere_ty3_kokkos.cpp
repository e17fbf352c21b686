/* ----------------------------------------------------------------------
   fix nve/sphere/ty3/kk (see doc/fix_nve_sphere_ty3.rst)
------------------------------------------------------------------------- */

#include "fix_nve_sphere_ty3_kokkos.h"

#include "integrate/taylor3.h"
#include "kokkos_grains.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "force.h"
#include "memory_kokkos.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
template <class DeviceType> struct HistoryRows {    // grain i's row of the per-atom history
  typename ArrayTypes<DeviceType>::t_float_2d rows;
  KOKKOS_INLINE_FUNCTION double *operator()(int i) const { return &rows(i, 0); }
};
}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixNVESphereTY3Kokkos<DeviceType>::FixNVESphereTY3Kokkos(LAMMPS *lmp, int narg, char **arg) :
    FixNVESphereTY3(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;    // synced in the hooks themselves
  datamask_modify = EMPTY_MASK;

  // the base constructor allocated a plain array: replace it by the DualView
  memory->destroy(history);
  history = nullptr;
  grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nlocal; i++) FixNVESphereTY3::set_arrays(i);
  k_history.template modify<LMPHostType>();
}

template <class DeviceType> FixNVESphereTY3Kokkos<DeviceType>::~FixNVESphereTY3Kokkos()
{
  if (copymode) return;
  memoryKK->destroy_kokkos(k_history, history);
  history = nullptr;    // nothing left for the base destructor
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void FixNVESphereTY3Kokkos<DeviceType>::initial_integrate(int)
{
  atomKK->sync(execution_space,
               X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | RADIUS_MASK |
                   MASK_MASK);
  k_history.template sync<DeviceType>();
  porewater::kokkos_for_each_grain<DeviceType>(
      "nve/sphere/ty3:predict", integrated_count(),
      porewater::Ty3Predict<porewater::KokkosGrains<DeviceType>, HistoryRows<DeviceType>>{
          porewater::KokkosGrains<DeviceType>(atomKK),
          HistoryRows<DeviceType>{k_history.template view<DeviceType>()}, groupbit, corrector,
          update->dt, force->ftm2v});
  atomKK->modified(execution_space, X_MASK | V_MASK | OMEGA_MASK);
  k_history.template modify<DeviceType>();
  dt_of_history = update->dt;
}

template <class DeviceType> void FixNVESphereTY3Kokkos<DeviceType>::final_integrate()
{
  atomKK->sync(execution_space,
               V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | RADIUS_MASK | MASK_MASK);
  k_history.template sync<DeviceType>();
  porewater::kokkos_for_each_grain<DeviceType>(
      "nve/sphere/ty3:correct", integrated_count(),
      porewater::Ty3Correct<porewater::KokkosGrains<DeviceType>, HistoryRows<DeviceType>>{
          porewater::KokkosGrains<DeviceType>(atomKK),
          HistoryRows<DeviceType>{k_history.template view<DeviceType>()}, groupbit, update->dt,
          force->ftm2v});
  atomKK->modified(execution_space, V_MASK | OMEGA_MASK);
}

/* ----------------------------------------------------------------------
   the history on the host: sync before the CPU code reads it, flag it after it writes
------------------------------------------------------------------------- */

template <class DeviceType> void FixNVESphereTY3Kokkos<DeviceType>::grow_arrays(int nmax)
{
  k_history.template sync<LMPHostType>();    // resize keeps the newest copy
  memoryKK->grow_kokkos(k_history, history, nmax, ncols, "nve/sphere/ty3:history");
  k_history.template modify<LMPHostType>();
}

template <class DeviceType>
void FixNVESphereTY3Kokkos<DeviceType>::copy_arrays(int i, int j, int delflag)
{
  k_history.template sync<LMPHostType>();
  FixNVESphereTY3::copy_arrays(i, j, delflag);
  k_history.template modify<LMPHostType>();
}

template <class DeviceType> void FixNVESphereTY3Kokkos<DeviceType>::set_arrays(int i)
{
  k_history.template sync<LMPHostType>();
  FixNVESphereTY3::set_arrays(i);
  k_history.template modify<LMPHostType>();
}

template <class DeviceType> int FixNVESphereTY3Kokkos<DeviceType>::pack_exchange(int i, double *buf)
{
  k_history.template sync<LMPHostType>();
  return FixNVESphereTY3::pack_exchange(i, buf);
}

template <class DeviceType>
int FixNVESphereTY3Kokkos<DeviceType>::unpack_exchange(int nlocal, double *buf)
{
  k_history.template sync<LMPHostType>();
  const int n = FixNVESphereTY3::unpack_exchange(nlocal, buf);
  k_history.template modify<LMPHostType>();
  return n;
}

template <class DeviceType> int FixNVESphereTY3Kokkos<DeviceType>::pack_restart(int i, double *buf)
{
  k_history.template sync<LMPHostType>();
  return FixNVESphereTY3::pack_restart(i, buf);
}

template <class DeviceType>
void FixNVESphereTY3Kokkos<DeviceType>::unpack_restart(int nlocal, int nth)
{
  k_history.template sync<LMPHostType>();
  FixNVESphereTY3::unpack_restart(nlocal, nth);
  k_history.template modify<LMPHostType>();
}

template <class DeviceType> void FixNVESphereTY3Kokkos<DeviceType>::forget_history()
{
  k_history.template sync<LMPHostType>();
  FixNVESphereTY3::forget_history();
  k_history.template modify<LMPHostType>();
}

namespace LAMMPS_NS {
template class FixNVESphereTY3Kokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixNVESphereTY3Kokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
