/* ----------------------------------------------------------------------
   fix wall/stress/kk (see doc/fix_wall_stress.rst)
------------------------------------------------------------------------- */

#include "fix_wall_stress_kokkos.h"

#include "wall_stress_contact.h"

#include "atom_kokkos.h"
#include "atom_masks.h"

using namespace LAMMPS_NS;

namespace {

// contact forces on the grains; sums {force on the wall, spring energy, zz virial}
template <class DeviceType> struct WallContacts {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef double value_type[];
  const unsigned value_count = 3;

  typename AT::t_x_array_randomread x;
  typename AT::t_v_array_randomread v;
  typename AT::t_f_array f;
  typename AT::t_float_1d_randomread radius;
  typename AT::t_int_1d_randomread mask;
  int groupbit;
  double z_wall, v_wall, kn, gamma;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type sums) const
  {
    if (!(mask(i) & groupbit)) return;
    const porewater::WallContact c =
        porewater::wall_contact(x(i, 2), radius(i), v(i, 2), z_wall, v_wall, kn, gamma);
    f(i, 2) += c.force_z;
    sums[0] -= c.force_z;
    sums[1] += c.energy;
    sums[2] += (x(i, 2) - z_wall) * c.force_z;
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixWallStressKokkos<DeviceType>::FixWallStressKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixWallStress(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;    // synced in the hooks themselves
  datamask_modify = EMPTY_MASK;
  virial_peratom_flag = 0;    // the global virial only
}

// once, at the first setup with `z auto`: on the host
template <class DeviceType> double FixWallStressKokkos<DeviceType>::highest_grain_top()
{
  atomKK->sync(Host, X_MASK | RADIUS_MASK | MASK_MASK);
  return FixWallStress::highest_grain_top();
}

template <class DeviceType> void FixWallStressKokkos<DeviceType>::add_contact_forces(double *sums)
{
  atomKK->sync(execution_space, X_MASK | V_MASK | F_MASK | RADIUS_MASK | MASK_MASK);
  WallContacts<DeviceType> contacts;
  contacts.x = atomKK->k_x.view<DeviceType>();
  contacts.v = atomKK->k_v.view<DeviceType>();
  contacts.f = atomKK->k_f.view<DeviceType>();
  contacts.radius = atomKK->k_radius.view<DeviceType>();
  contacts.mask = atomKK->k_mask.view<DeviceType>();
  contacts.groupbit = groupbit;
  contacts.z_wall = z_wall;
  contacts.v_wall = v_wall;
  contacts.kn = kn;
  contacts.gamma = gamma;
  double local[3] = {0.0, 0.0, 0.0};
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), contacts, local);
  atomKK->modified(execution_space, F_MASK);
  sums[0] += local[0];
  sums[1] += local[1];
  if (evflag && vflag_global) virial[2] += local[2];
}

namespace LAMMPS_NS {
template class FixWallStressKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixWallStressKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
