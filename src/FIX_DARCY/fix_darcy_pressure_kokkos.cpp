/* ----------------------------------------------------------------------
   fix darcy/pressure/kk (see doc/fix_darcy_pressure.rst)

   Per fluid step the grid crosses between device and host twice: the deposits
   (5 doubles per cell) up for the MPI sum and the solve, the pressure gradient (3 per
   cell) back down. At the grids this model uses (~1e2-1e4 cells) that is a few kB.
------------------------------------------------------------------------- */

#include "fix_darcy_pressure_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "error.h"
#include "memory_kokkos.h"

#include <Kokkos_ScatterView.hpp>
#include <type_traits>

using namespace LAMMPS_NS;

namespace {

// Every grain adds into the same few cells: per-thread copies on OpenMP (atomic additions
// made the fix 2.4x dearer there), atomics on GPUs, plain serially; LAMMPS' choice for
// pair forces shared between threads (HALFTHREAD).
template <class DeviceType>
using DepositScatter =
    Kokkos::Experimental::ScatterView<double *, Kokkos::LayoutRight, DeviceType,
                                      Kokkos::Experimental::ScatterSum,
                                      typename NeedDup<HALFTHREAD, DeviceType>::value>;
template <class DeviceType>
using DepositContribution = typename std::conditional<
    std::is_same<typename NeedDup<HALFTHREAD, DeviceType>::value,
                 Kokkos::Experimental::ScatterDuplicated>::value,
    Kokkos::Experimental::ScatterNonAtomic,
    typename AtomicDup<HALFTHREAD, DeviceType>::value>::type;

template <class Access> struct AddTo {
  const Access &sums;    // a ScatterAccess is not copyable
  KOKKOS_INLINE_FUNCTION void operator()(int slot, double value) const { sums(slot) += value; }
};

template <class DeviceType> struct DepositGrains {
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array_randomread x;
  typename AT::t_v_array_randomread v;
  typename AT::t_float_1d_randomread radius;
  typename AT::t_int_1d_randomread mask;
  DepositScatter<DeviceType> sums;
  porewater::GridGeom geom;
  porewater::DepositLayout layout;
  double interval;
  int groupbit;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    if (!(mask(i) & groupbit)) return;
    auto access = sums.template access<DepositContribution<DeviceType>>();
    porewater::deposit_grain(geom, layout, x(i, 0), x(i, 1), x(i, 2), v(i, 0), v(i, 1), v(i, 2),
                             porewater::sphere_volume(radius(i)), interval,
                             AddTo<decltype(access)>{access});
  }
};

template <class DeviceType> struct ApplyFluidForce {
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_x_array_randomread x;
  typename AT::t_float_1d_randomread radius;
  typename AT::t_int_1d_randomread mask;
  typename AT::t_f_array f;
  typename AT::t_ffloat_2d fluid_force;
  Kokkos::View<const double *, Kokkos::LayoutRight, DeviceType> gradient;
  porewater::GridGeom geom;
  double rho_g[3];
  int groupbit;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    double ff[3] = {0.0, 0.0, 0.0};
    if (mask(i) & groupbit) {
      porewater::fluid_force(geom, gradient.data(), rho_g, x(i, 0), x(i, 1), x(i, 2),
                             porewater::sphere_volume(radius(i)), ff);
      f(i, 0) += ff[0];
      f(i, 1) += ff[1];
      f(i, 2) += ff[2];
    }
    fluid_force(i, 0) = ff[0];
    fluid_force(i, 1) = ff[1];
    fluid_force(i, 2) = ff[2];
  }
};

template <class DeviceType> struct AddHeldForce {
  typedef ArrayTypes<DeviceType> AT;
  typename AT::t_f_array f;
  typename AT::t_ffloat_2d fluid_force;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    for (int d = 0; d < 3; ++d) f(i, d) += fluid_force(i, d);
  }
};

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixDarcyPressureKokkos<DeviceType>::FixDarcyPressureKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixDarcyPressure(lmp, narg, arg)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = X_MASK | V_MASK | F_MASK | RADIUS_MASK | MASK_MASK;
  datamask_modify = F_MASK;
  d_deposits = grid_view("darcy/pressure:deposits", layout.size());
  d_gradient = grid_view("darcy/pressure:gradient", 3 * solver->ncells());
}

template <class DeviceType> FixDarcyPressureKokkos<DeviceType>::~FixDarcyPressureKokkos()
{
  memoryKK->destroy_kokkos(k_fluid_force, fluid_force);
  fluid_force = nullptr;    // not the base class' to free
}

template <class DeviceType> void FixDarcyPressureKokkos<DeviceType>::sync_atoms_to_host()
{
  atomKK->sync(Host, ALL_MASK);    // equal-style variables read host data
}

template <class DeviceType>
void FixDarcyPressureKokkos<DeviceType>::deposit_grains(double interval)
{
  atomKK->sync(execution_space, X_MASK | V_MASK | RADIUS_MASK | MASK_MASK);
  Kokkos::deep_copy(d_deposits, 0.0);
  DepositScatter<DeviceType> sums(d_deposits);
  DepositGrains<DeviceType> deposit{atomKK->k_x.view<DeviceType>(),
                                    atomKK->k_v.view<DeviceType>(),
                                    atomKK->k_radius.view<DeviceType>(),
                                    atomKK->k_mask.view<DeviceType>(),
                                    sums,
                                    geom,
                                    layout,
                                    interval,
                                    groupbit};
  Kokkos::parallel_for("darcy/pressure:deposit", Kokkos::RangePolicy<DeviceType>(0, atom->nlocal),
                       deposit);
  Kokkos::Experimental::contribute(d_deposits, sums);
  Kokkos::View<double *, Kokkos::LayoutRight, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> host(
      deposits.data(), deposits.size());
  Kokkos::deep_copy(host, d_deposits);    // the MPI sum and the solve run on the host
}

template <class DeviceType> void FixDarcyPressureKokkos<DeviceType>::apply_fluid_force()
{
  if (atom->nmax > maxatom) grow_fluid_force(atom->nmax);
  if (gradient_changed) {
    Kokkos::View<const double *, Kokkos::LayoutRight, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>
        host(solver->pressure_gradient().data(), solver->pressure_gradient().size());
    Kokkos::deep_copy(d_gradient, host);
    gradient_changed = false;
  }
  atomKK->sync(execution_space, X_MASK | F_MASK | RADIUS_MASK | MASK_MASK);
  k_fluid_force.template sync<DeviceType>();
  ApplyFluidForce<DeviceType> apply{atomKK->k_x.view<DeviceType>(),
                                    atomKK->k_radius.view<DeviceType>(),
                                    atomKK->k_mask.view<DeviceType>(),
                                    atomKK->k_f.view<DeviceType>(),
                                    k_fluid_force.template view<DeviceType>(),
                                    d_gradient,
                                    geom,
                                    {rho_g[0], rho_g[1], rho_g[2]},
                                    groupbit};
  Kokkos::parallel_for("darcy/pressure:force", Kokkos::RangePolicy<DeviceType>(0, atom->nlocal),
                       apply);
  atomKK->modified(execution_space, F_MASK);
  // dumps and computes read the per-atom array on the host (no copy when they share memory)
  k_fluid_force.template modify<DeviceType>();
  k_fluid_force.template sync<LMPHostType>();
}

template <class DeviceType> void FixDarcyPressureKokkos<DeviceType>::add_held_fluid_force()
{
  atomKK->sync(execution_space, F_MASK);
  k_fluid_force.template sync<DeviceType>();
  AddHeldForce<DeviceType> add{atomKK->k_f.view<DeviceType>(),
                               k_fluid_force.template view<DeviceType>()};
  Kokkos::parallel_for("darcy/pressure:held force",
                       Kokkos::RangePolicy<DeviceType>(0, atom->nlocal), add);
  atomKK->modified(execution_space, F_MASK);
}

template <class DeviceType> void FixDarcyPressureKokkos<DeviceType>::grow_fluid_force(int nmax)
{
  maxatom = nmax;
  memoryKK->destroy_kokkos(k_fluid_force, fluid_force);
  memoryKK->create_kokkos(k_fluid_force, fluid_force, maxatom, 3, "darcy/pressure:fluid_force");
  array_atom = fluid_force;
}

namespace LAMMPS_NS {
template class FixDarcyPressureKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixDarcyPressureKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
