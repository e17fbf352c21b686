/* ----------------------------------------------------------------------
   fix shear/stress/kk (see doc/fix_shear_stress.rst)
------------------------------------------------------------------------- */

#include "fix_shear_stress_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "domain.h"
#include "force.h"

using namespace LAMMPS_NS;

namespace {

// {ΣF_x, Σ m x_unwrapped, Σ m} over the plate's grains
template <class DeviceType> struct PlateSums {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef double value_type[];
  const unsigned value_count = 3;

  typename AT::t_x_array_randomread x;
  typename AT::t_f_array_const f;
  typename AT::t_float_1d_randomread rmass;
  typename AT::t_imageint_1d_randomread image;
  typename AT::t_int_1d_randomread mask;
  int groupbit;
  double h0, h4, h5;    // Domain::h: x unwraps by image_x h0 + image_y h5 + image_z h4

  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type sums) const
  {
    if (!(mask(i) & groupbit)) return;
    const int xbox = (image(i) & IMGMASK) - IMGMAX;
    const int ybox = (image(i) >> IMGBITS & IMGMASK) - IMGMAX;
    const int zbox = (image(i) >> IMG2BITS) - IMGMAX;
    const double unwrapped = x(i, 0) + h0 * xbox + h5 * ybox + h4 * zbox;
    sums[0] += f(i, 0);
    sums[1] += rmass(i) * unwrapped;
    sums[2] += rmass(i);
  }
};

// {Σ m v_x, Σ m}
template <class DeviceType> struct PlateMomentum {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef double value_type[];
  const unsigned value_count = 2;

  typename AT::t_v_array_randomread v;
  typename AT::t_float_1d_randomread rmass;
  typename AT::t_int_1d_randomread mask;
  int groupbit;

  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type sums) const
  {
    if (!(mask(i) & groupbit)) return;
    sums[0] += rmass(i) * v(i, 0);
    sums[1] += rmass(i);
  }
};

// every grain the plate's x-acceleration; y and rotation locked
template <class DeviceType> struct PlateMotion {
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_v_array v, omega;
  typename AT::t_f_array f, torque;
  typename AT::t_float_1d_randomread rmass;
  typename AT::t_int_1d_randomread mask;
  int groupbit;
  double force_per_mass;    // a_plate / ftm2v

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    if (!(mask(i) & groupbit)) return;
    f(i, 0) = rmass(i) * force_per_mass;
    f(i, 1) = 0.0;
    v(i, 1) = 0.0;
    for (int k = 0; k < 3; k++) torque(i, k) = omega(i, k) = 0.0;
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixShearStressKokkos<DeviceType>::FixShearStressKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixShearStress(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;    // synced in the hooks themselves
  datamask_modify = EMPTY_MASK;
}

template <class DeviceType>
void FixShearStressKokkos<DeviceType>::sum_forces_and_positions(double *sums)
{
  atomKK->sync(execution_space, X_MASK | F_MASK | RMASS_MASK | IMAGE_MASK | MASK_MASK);
  PlateSums<DeviceType> plate;
  plate.x = atomKK->k_x.view<DeviceType>();
  plate.f = atomKK->k_f.view<DeviceType>();
  plate.rmass = atomKK->k_rmass.view<DeviceType>();
  plate.image = atomKK->k_image.view<DeviceType>();
  plate.mask = atomKK->k_mask.view<DeviceType>();
  plate.groupbit = groupbit;
  plate.h0 = domain->h[0];
  plate.h4 = domain->h[4];
  plate.h5 = domain->h[5];
  double local[3] = {0.0, 0.0, 0.0};
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), plate, local);
  for (int k = 0; k < 3; k++) sums[k] += local[k];
}

template <class DeviceType> void FixShearStressKokkos<DeviceType>::sum_momentum(double *sums)
{
  atomKK->sync(execution_space, V_MASK | RMASS_MASK | MASK_MASK);
  PlateMomentum<DeviceType> plate;
  plate.v = atomKK->k_v.view<DeviceType>();
  plate.rmass = atomKK->k_rmass.view<DeviceType>();
  plate.mask = atomKK->k_mask.view<DeviceType>();
  plate.groupbit = groupbit;
  double local[2] = {0.0, 0.0};
  Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), plate, local);
  sums[0] += local[0];
  sums[1] += local[1];
}

template <class DeviceType>
void FixShearStressKokkos<DeviceType>::move_as_plate(double plate_acceleration)
{
  atomKK->sync(execution_space,
               V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | MASK_MASK);
  PlateMotion<DeviceType> plate;
  plate.v = atomKK->k_v.view<DeviceType>();
  plate.omega = atomKK->k_omega.view<DeviceType>();
  plate.f = atomKK->k_f.view<DeviceType>();
  plate.torque = atomKK->k_torque.view<DeviceType>();
  plate.rmass = atomKK->k_rmass.view<DeviceType>();
  plate.mask = atomKK->k_mask.view<DeviceType>();
  plate.groupbit = groupbit;
  plate.force_per_mass = plate_acceleration / force->ftm2v;
  Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), plate);
  atomKK->modified(execution_space, V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK);
}

// once per run, at setup: on the host
template <class DeviceType> void FixShearStressKokkos<DeviceType>::set_velocity_x(double velocity)
{
  atomKK->sync(Host, V_MASK | MASK_MASK);
  FixShearStress::set_velocity_x(velocity);
  atomKK->modified(Host, V_MASK);
}

namespace LAMMPS_NS {
template class FixShearStressKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixShearStressKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
