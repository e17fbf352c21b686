// The grain accessor of the core's per-grain kernels (grains/host_grains.h) over the
// KOKKOS atom views, and the loops that run those kernels as Kokkos kernels. Every /kk fix
// of the package syncs, in the hook itself, exactly the atom data it reads and flags what
// it writes (datamask_read/modify stay EMPTY_MASK, so LAMMPS' own syncs around the hook do
// nothing): one sync policy.
#ifndef PW_LAMMPS_KOKKOS_GRAINS_H
#define PW_LAMMPS_KOKKOS_GRAINS_H

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "kokkos_type.h"

#include <string>

namespace porewater {

template <class DeviceType> struct KokkosGrains {
  typedef ::ArrayTypes<DeviceType> AT;
  typename AT::t_x_array xs;
  typename AT::t_v_array vs, omegas;
  typename AT::t_f_array fs, torques;
  typename AT::t_float_1d radii, rmasses;
  typename AT::t_int_1d masks;
  typename AT::t_imageint_1d images;

  KokkosGrains() = default;    // no grains: a kernel's part that does not run
  explicit KokkosGrains(LAMMPS_NS::AtomKokkos *atomKK) :
      xs(atomKK->k_x.view<DeviceType>()), vs(atomKK->k_v.view<DeviceType>()),
      omegas(atomKK->k_omega.view<DeviceType>()), fs(atomKK->k_f.view<DeviceType>()),
      torques(atomKK->k_torque.view<DeviceType>()), radii(atomKK->k_radius.view<DeviceType>()),
      rmasses(atomKK->k_rmass.view<DeviceType>()), masks(atomKK->k_mask.view<DeviceType>()),
      images(atomKK->k_image.view<DeviceType>())
  {
  }

  KOKKOS_INLINE_FUNCTION double &x(int i, int d) const { return xs(i, d); }
  KOKKOS_INLINE_FUNCTION double &v(int i, int d) const { return vs(i, d); }
  KOKKOS_INLINE_FUNCTION double &f(int i, int d) const { return fs(i, d); }
  KOKKOS_INLINE_FUNCTION double &omega(int i, int d) const { return omegas(i, d); }
  KOKKOS_INLINE_FUNCTION double &torque(int i, int d) const { return torques(i, d); }
  KOKKOS_INLINE_FUNCTION double radius(int i) const { return radii(i); }
  KOKKOS_INLINE_FUNCTION double rmass(int i) const { return rmasses(i); }
  KOKKOS_INLINE_FUNCTION int mask(int i) const { return masks(i); }
  KOKKOS_INLINE_FUNCTION LAMMPS_NS::imageint image(int i) const { return images(i); }
};

template <class Body> struct ForEachGrain {
  Body body;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { body(i); }
};

template <class Body> struct SumOverGrains {
  typedef double value_type[];
  const unsigned value_count = Body::count;
  Body body;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type sums) const { body(i, sums); }
};

// The range of every kernel of the package. Light weight: on CUDA, Kokkos 3.4 then passes
// the kernel's launch object (functor and policy) as a kernel argument up to 4 kB, where it
// would otherwise copy one of 512 B or more to constant memory and wait for the last kernel
// that used it (Kokkos_Cuda_KernelLaunch.hpp, DeduceCudaLaunchMechanism); other backends
// ignore the hint. The CUDA check asserts the argument path (assert_launch_by_argument).
template <class DeviceType, class Tag = void> auto grain_range(int begin, int end)
    -> decltype(Kokkos::Experimental::require(
        Kokkos::RangePolicy<DeviceType, Tag>(begin, end),
        Kokkos::Experimental::WorkItemProperty::HintLightWeight))
{
  return Kokkos::Experimental::require(Kokkos::RangePolicy<DeviceType, Tag>(begin, end),
                                       Kokkos::Experimental::WorkItemProperty::HintLightWeight);
}

// On CUDA, a kernel of `Driver` (Kokkos::Impl::ParallelFor/ParallelReduce) has its launch
// object passed as a kernel argument: no copy to constant memory, no wait for the host.
// Other execution spaces launch no such object.
template <class Space, class Driver> struct LaunchedByArgument {
  static constexpr bool value = true;
};
#ifdef KOKKOS_ENABLE_CUDA
template <class Driver> struct LaunchedByArgument<Kokkos::Cuda, Driver> {
  static constexpr bool value = Kokkos::Impl::DeduceCudaLaunchMechanism<Driver>::launch_mechanism ==
      Kokkos::Impl::Experimental::CudaLaunchMechanism::LocalMemory;
};
#endif
#define PW_ASSERT_LAUNCH_BY_ARGUMENT(Space, ...)                                               \
  static_assert(porewater::LaunchedByArgument<Space, __VA_ARGS__>::value,                       \
                "this kernel's launch object would go through CUDA constant memory (a host "  \
                "wait): launch it on grain_range (light weight) and keep it under 4 kB")

// body(i) for the grains [0, n) as a kernel `name` in DeviceType's execution space
template <class DeviceType, class Body>
void kokkos_for_each_grain(const char *name, int n, const Body &body)
{
  using Policy = decltype(grain_range<DeviceType>(0, n));
  using Space = typename DeviceType::execution_space;
  PW_ASSERT_LAUNCH_BY_ARGUMENT(Space, Kokkos::Impl::ParallelFor<ForEachGrain<Body>, Policy, Space>);
  Kokkos::parallel_for(name, grain_range<DeviceType>(0, n), ForEachGrain<Body>{body});
}

// body(i, sums) for the grains [0, n), summing Body::count values into the host's sums
template <class DeviceType, class Body>
void kokkos_sum_over_grains(const char *name, int n, const Body &body, double *sums)
{
  for (int k = 0; k < Body::count; ++k) sums[k] = 0.0;
  Kokkos::parallel_reduce(name, grain_range<DeviceType>(0, n),
                          SumOverGrains<Body>{Body::count, body}, sums);
}

// body(i, sums) for the grains [0, n), summing Body::count values, then body.final(sums)
// once with their totals, on the device (a kernel named `name`): nothing comes back to the host and the host does
// not wait (Kokkos' reduction into a device view). The range holds one item at least, so
// that every backend calls final, also with no grains.
template <class Body> struct SumOverGrainsOnDevice {
  typedef double value_type[];
  const unsigned value_count = Body::count;
  Body body;
  int n;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type sums) const
  {
    if (i < n) body(i, sums);
  }
  KOKKOS_INLINE_FUNCTION void final(value_type sums) const { body.final(sums); }
};

template <class DeviceType, class Body>
void kokkos_sum_over_grains_on_device(const char *name, int n, const Body &body,
                                      const Kokkos::View<double *, DeviceType> &totals)
{
  using Policy = decltype(grain_range<DeviceType>(0, 1));
  using Space = typename DeviceType::execution_space;
  PW_ASSERT_LAUNCH_BY_ARGUMENT(
      Space, Kokkos::Impl::ParallelReduce<SumOverGrainsOnDevice<Body>, Policy, Kokkos::InvalidType, Space>);
  Kokkos::parallel_reduce(name, grain_range<DeviceType>(0, n > 0 ? n : 1),
                          SumOverGrainsOnDevice<Body>{Body::count, body, n}, totals);
}

// The atom data an equal-style variable evaluated on the host may read (per-atom values,
// group functions, thermo keywords), brought there from the device, as LAMMPS' own KOKKOS
// fixes do before they evaluate one (fix setforce/kk)
inline void sync_for_host_variables(LAMMPS_NS::AtomKokkos *atomKK)
{
  atomKK->sync(LAMMPS_NS::Host, X_MASK | V_MASK | F_MASK | TAG_MASK | TYPE_MASK | MASK_MASK |
                                    IMAGE_MASK | RMASS_MASK | RADIUS_MASK);
}

// A small state of a /kk fix kept on the device between steps, with its host copy: the
// device's kernels read and write it, the host reads it back where it needs it (outputs,
// restart, the end of a run, its checks) and writes it at a run's setup.
template <class State, class DeviceType> struct DeviceState {
  Kokkos::View<State, DeviceType> device;
  typename Kokkos::View<State, DeviceType>::HostMirror host;
  explicit DeviceState(const char *label) :
      device(std::string(label)), host(Kokkos::create_mirror_view(device))
  {
  }
  State &pull()
  {
    Kokkos::deep_copy(host, device);
    return host();
  }
  void push(const State &state)
  {
    host() = state;
    Kokkos::deep_copy(device, host);
  }
};

}    // namespace porewater

#endif
