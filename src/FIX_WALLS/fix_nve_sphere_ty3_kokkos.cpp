/* ----------------------------------------------------------------------
   fix nve/sphere/ty3/kk (see doc/fix_nve_sphere_ty3.rst)
------------------------------------------------------------------------- */

#include "fix_nve_sphere_ty3_kokkos.h"

#include "taylor3.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "force.h"
#include "memory_kokkos.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {

// what one grain's step reads and writes, in the execution space of DeviceType
template <class DeviceType> struct TY3Grains {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array x;
  typename AT::t_v_array v, omega;
  typename AT::t_f_array_const f, torque;
  typename AT::t_float_1d_randomread rmass, radius;
  typename AT::t_int_1d_randomread mask;
  typename AT::t_float_2d history;
  int groupbit, corrector;
  double dt, ftm2v;

  KOKKOS_INLINE_FUNCTION void accelerations(const int i, double *a, double *alpha) const
  {
    const double fi[3] = {f(i, 0), f(i, 1), f(i, 2)};
    const double ti[3] = {torque(i, 0), torque(i, 1), torque(i, 2)};
    porewater::sphere_accelerations(ftm2v, rmass(i), radius(i), fi, ti, a, alpha);
  }
};

template <class DeviceType> struct TY3Predict : TY3Grains<DeviceType> {
  explicit TY3Predict(const TY3Grains<DeviceType> &grains) : TY3Grains<DeviceType>(grains) {}
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    if (!(this->mask(i) & this->groupbit)) return;
    double a[3], alpha[3], xi[3], vi[3], wi[3];
    this->accelerations(i, a, alpha);
    for (int k = 0; k < 3; k++) {
      xi[k] = this->x(i, k);
      vi[k] = this->v(i, k);
      wi[k] = this->omega(i, k);
    }
    porewater::ty3_predict_grain(xi, vi, wi, a, alpha, this->dt, this->corrector,
                                 &this->history(i, 0));
    for (int k = 0; k < 3; k++) {
      this->x(i, k) = xi[k];
      this->v(i, k) = vi[k];
      this->omega(i, k) = wi[k];
    }
  }
};

template <class DeviceType> struct TY3Correct : TY3Grains<DeviceType> {
  explicit TY3Correct(const TY3Grains<DeviceType> &grains) : TY3Grains<DeviceType>(grains) {}
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    if (!(this->mask(i) & this->groupbit)) return;
    double a[3], alpha[3], vi[3], wi[3];
    this->accelerations(i, a, alpha);
    for (int k = 0; k < 3; k++) {
      vi[k] = this->v(i, k);
      wi[k] = this->omega(i, k);
    }
    porewater::ty3_correct_grain(vi, wi, a, alpha, this->dt, &this->history(i, 0));
    for (int k = 0; k < 3; k++) {
      this->v(i, k) = vi[k];
      this->omega(i, k) = wi[k];
    }
  }
};

// the grain views and step constants both hooks hand to their kernel
template <class DeviceType>
TY3Grains<DeviceType> grain_data(AtomKokkos *atomKK, const DAT::tdual_float_2d &k_history,
                                 int groupbit, int corrector, double dt, double ftm2v)
{
  TY3Grains<DeviceType> g;
  g.x = atomKK->k_x.view<DeviceType>();
  g.v = atomKK->k_v.view<DeviceType>();
  g.omega = atomKK->k_omega.view<DeviceType>();
  g.f = atomKK->k_f.view<DeviceType>();
  g.torque = atomKK->k_torque.view<DeviceType>();
  g.rmass = atomKK->k_rmass.view<DeviceType>();
  g.radius = atomKK->k_radius.view<DeviceType>();
  g.mask = atomKK->k_mask.view<DeviceType>();
  g.history = k_history.template view<DeviceType>();
  g.groupbit = groupbit;
  g.corrector = corrector;
  g.dt = dt;
  g.ftm2v = ftm2v;
  return g;
}

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
  const TY3Predict<DeviceType> step(grain_data<DeviceType>(atomKK, k_history, groupbit, corrector,
                                                          update->dt, force->ftm2v));
  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), step);
  atomKK->modified(execution_space, X_MASK | V_MASK | OMEGA_MASK);
  k_history.template modify<DeviceType>();
  dt_of_history = update->dt;
}

template <class DeviceType> void FixNVESphereTY3Kokkos<DeviceType>::final_integrate()
{
  atomKK->sync(execution_space,
               V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | RADIUS_MASK | MASK_MASK);
  k_history.template sync<DeviceType>();
  const TY3Correct<DeviceType> step(grain_data<DeviceType>(atomKK, k_history, groupbit, corrector,
                                                          update->dt, force->ftm2v));
  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, nlocal), step);
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
