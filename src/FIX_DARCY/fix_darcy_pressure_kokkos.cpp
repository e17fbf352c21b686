/* ----------------------------------------------------------------------
   fix darcy/pressure/kk (see doc/fix_darcy_pressure.rst)

   Per fluid step the grid crosses between device and host twice: the deposits (40 values
   per stencil block, 5 per cell) up for the MPI sum and the solve, the force field (32 per
   block, 4 per cell) back down. At the grids this model uses (~1e2-1e4 cells) that is a
   few hundred kB at most.
------------------------------------------------------------------------- */

#include "fix_darcy_pressure_kokkos.h"

#include "kokkos_grains.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "error.h"
#include "memory_kokkos.h"
#include "modify.h"
#include "output.h"
#include "update.h"

#include <Kokkos_ScatterView.hpp>
#include <type_traits>

using namespace LAMMPS_NS;

namespace {

// Every grain adds into the same few blocks: per-thread copies on OpenMP (atomic additions
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

template <class DeviceType> struct Stencils {
  Kokkos::View<int *, DeviceType> blocks;
  Kokkos::View<double *[porewater::CORNERS], Kokkos::LayoutRight, DeviceType> weight_rows;
  KOKKOS_INLINE_FUNCTION int &block(int i) const { return blocks(i); }
  KOKKOS_INLINE_FUNCTION double *weights(int i) const { return &weight_rows(i, 0); }
};

template <class DeviceType> using Held = porewater::KokkosHeldRows<DeviceType>;

// the `add` of porewater::deposit_grain over a ScatterView access
template <class Access> struct ScatterAdd {
  const Access &sums;    // a ScatterAccess is not copyable
  struct Row {
    const Access &sums;
    int offset;
    KOKKOS_INLINE_FUNCTION void operator()(int k, double value) const { sums(offset + k) += value; }
  };
  KOKKOS_INLINE_FUNCTION void operator()(int slot, double value) const { sums(slot) += value; }
  KOKKOS_INLINE_FUNCTION Row row(int offset) const { return Row{sums, offset}; }
};

template <class DeviceType> struct DepositKernel {
  porewater::CouplingGrid grid;
  porewater::KokkosGrains<DeviceType> grains;
  Stencils<DeviceType> stencils;
  DepositScatter<DeviceType> sums;
  int groupbit;
  double interval;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    const auto access = sums.template access<DepositContribution<DeviceType>>();
    porewater::deposit_grain(grid, grains, stencils, groupbit, interval, i,
                             ScatterAdd<decltype(access)>{access});
  }
};

template <class DeviceType> struct ForceKernel {
  porewater::CouplingGrid grid;
  porewater::FluidForceField field;    // device pointers
  porewater::KokkosGrains<DeviceType> grains;
  Stencils<DeviceType> stencils;
  Held<DeviceType> held;
  int groupbit;
  bool kept;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    porewater::apply_fluid_force(grid, field, grains, stencils, held, groupbit, kept, i);
  }
};

}    // namespace

/* ----------------------------------------------------------------------
   the grains' side of the coupling as kernels
------------------------------------------------------------------------- */

template <class DeviceType>
class FixDarcyPressureKokkos<DeviceType>::Grains final : public porewater::GrainBackend {
 public:
  typedef Kokkos::View<double *, Kokkos::LayoutRight, DeviceType> grid_view;

  Grains(FixDarcyPressureKokkos *fix, const porewater::CouplingGrid &grid) :
      fix(fix), atomKK((AtomKokkos *) fix->atom),
      d_sums("darcy/pressure:deposits", grid.sums_size()),
      d_table("darcy/pressure:gradient table", grid.gradient_table_size()),
      d_cell_gradient("darcy/pressure:cell gradient", 3 * grid.cells.ncells),
      d_cell_porosity("darcy/pressure:cell porosity", grid.cells.ncells)
  {
  }

  void deposit(const porewater::CouplingGrid &grid, double interval, double *sums) override
  {
    const int nlocal = fix->atom->nlocal;
    grow_stencils(nlocal);
    atomKK->sync(execution(), X_MASK | V_MASK | RADIUS_MASK | MASK_MASK);
    Kokkos::deep_copy(d_sums, 0.0);
    DepositScatter<DeviceType> scatter(d_sums);
    porewater::kokkos_for_each_grain<DeviceType>(
        "darcy/pressure:deposit", nlocal,
        DepositKernel<DeviceType>{grid, porewater::KokkosGrains<DeviceType>(atomKK), stencils,
                                  scatter, fix->groupbit, interval});
    Kokkos::Experimental::contribute(d_sums, scatter);
    // the fold, the MPI sum and the solve run on the host
    Kokkos::View<double *, Kokkos::LayoutRight, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> host(
        sums, grid.sums_size());
    Kokkos::deep_copy(host, d_sums);
  }

  void apply_force(const porewater::CouplingGrid &grid, const porewater::FluidForceField &field,
                   bool kept, bool field_changed) override
  {
    if (field_changed) {
      copy_to_device(d_table, field.gradient_table);
      copy_to_device(d_cell_gradient, field.cell_gradient);
      copy_to_device(d_cell_porosity, field.cell_porosity);
    }
    const porewater::FluidForceField device_field{
        d_table.data(), d_cell_gradient.data(), d_cell_porosity.data(),
        {field.rho_g[0], field.rho_g[1], field.rho_g[2]}, field.horizontal_only_bit};
    const int nlocal = fix->atom->nlocal;
    atomKK->sync(execution(), X_MASK | F_MASK | RADIUS_MASK | MASK_MASK);
    fix->k_fluid_force.template sync<DeviceType>();
    porewater::kokkos_for_each_grain<DeviceType>(
        "darcy/pressure:force", nlocal,
        ForceKernel<DeviceType>{grid, device_field, porewater::KokkosGrains<DeviceType>(atomKK),
                                stencils, held(), fix->groupbit, kept});
    atomKK->modified(execution(), F_MASK);
    fix->k_fluid_force.template modify<DeviceType>();
  }

  void add_held_force() override
  {
    if (fix->held_in_pass.done_at(fix->update->ntimestep)) return;    // the fused pass did
    atomKK->sync(execution(), F_MASK);
    porewater::kokkos_for_each_grain<DeviceType>("darcy/pressure:held force", fix->atom->nlocal,
                                                 fix->held_kernel());
    atomKK->modified(execution(), F_MASK);
  }

 private:
  ExecutionSpace execution() const { return fix->execution_space; }
  Held<DeviceType> held() const
  {
    return Held<DeviceType>{fix->k_fluid_force.template view<DeviceType>()};
  }
  void grow_stencils(int nlocal)
  {
    if ((int) stencils.blocks.extent(0) >= nlocal) return;
    stencils.blocks = Kokkos::View<int *, DeviceType>("darcy/pressure:stencil blocks", nlocal);
    stencils.weight_rows = decltype(stencils.weight_rows)("darcy/pressure:stencil weights", nlocal);
  }
  static void copy_to_device(const grid_view &to, const double *from)
  {
    Kokkos::View<const double *, Kokkos::LayoutRight, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>
        host(from, to.extent(0));
    Kokkos::deep_copy(to, host);
  }

  FixDarcyPressureKokkos *fix;
  AtomKokkos *atomKK;
  grid_view d_sums, d_table, d_cell_gradient, d_cell_porosity;
  Stencils<DeviceType> stencils;
};

/* ---------------------------------------------------------------------- */

template <class DeviceType>
FixDarcyPressureKokkos<DeviceType>::FixDarcyPressureKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixDarcyPressure(lmp, narg, arg), kernels(nullptr)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
  kernels = new Grains(this, fluid->grid());
}

template <class DeviceType> FixDarcyPressureKokkos<DeviceType>::~FixDarcyPressureKokkos()
{
  delete kernels;
  memoryKK->destroy_kokkos(k_fluid_force, fluid_force);
  fluid_force = nullptr;    // not the base class' to free
}

// The per-atom fluid force (f_ID) is copied to the host on the steps when another style may
// read it, LAMMPS' own styles all being host ones: outputs (dump, thermo, restart) and the
// steps of the end_of_step fixes (fix ave/atom, ave/time of a compute reduce, print, ...);
// and after each run, for the commands between runs. A copy is made only when the device's
// values changed since the last (a no-op where host and device share memory).
template <class DeviceType> void FixDarcyPressureKokkos<DeviceType>::setup(int vflag)
{
  held_in_pass.reset();
  reader_every.clear();    // the fix list LAMMPS calls during this run is the one now
  for (int k = 0; k < modify->nfix; ++k)
    if ((modify->fmask[k] & FixConst::END_OF_STEP) && modify->fix[k]->nevery > 0)
      reader_every.push_back(modify->fix[k]->nevery);
  FixDarcyPressure::setup(vflag);
  k_fluid_force.template sync<LMPHostType>();
}

template <class DeviceType> void FixDarcyPressureKokkos<DeviceType>::post_force(int vflag)
{
  FixDarcyPressure::post_force(vflag);
  if (per_grain_output_read_now()) k_fluid_force.template sync<LMPHostType>();
}

template <class DeviceType> void FixDarcyPressureKokkos<DeviceType>::post_run()
{
  FixDarcyPressure::post_run();
  k_fluid_force.template sync<LMPHostType>();
}

template <class DeviceType> bool FixDarcyPressureKokkos<DeviceType>::per_grain_output_read_now() const
{
  const bigint step = update->ntimestep;
  if (step == output->next) return true;
  for (const int every : reader_every)
    if (step % every == 0) return true;
  return false;
}

template <class DeviceType> bool FixDarcyPressureKokkos<DeviceType>::only_holds_force_now()
{
  return fluid->only_holds_force(*this, update->ntimestep);
}

template <class DeviceType>
porewater::KokkosHeldForce<DeviceType> FixDarcyPressureKokkos<DeviceType>::held_kernel()
{
  if (atom->nmax > maxatom) grow_fluid_force(atom->nmax);
  k_fluid_force.template sync<DeviceType>();
  return porewater::KokkosHeldForce<DeviceType>{porewater::KokkosGrains<DeviceType>(atomKK),
                                                {k_fluid_force.template view<DeviceType>()}};
}

template <class DeviceType> porewater::GrainBackend &FixDarcyPressureKokkos<DeviceType>::grains()
{
  if (atom->nmax > maxatom) grow_fluid_force(atom->nmax);
  return *kernels;
}

template <class DeviceType> void FixDarcyPressureKokkos<DeviceType>::grow_fluid_force(int nmax)
{
  maxatom = nmax;
  memoryKK->destroy_kokkos(k_fluid_force, fluid_force);
  memoryKK->create_kokkos(k_fluid_force, fluid_force, maxatom, 3, "darcy/pressure:fluid_force");
  array_atom = fluid_force;
}

// equal-style variables read atom data on the host (unless `variables global`)
template <class DeviceType> void FixDarcyPressureKokkos<DeviceType>::sync_for_variables()
{
  porewater::sync_for_host_variables(atomKK);
}

template <class DeviceType> void FixDarcyPressureKokkos<DeviceType>::sync_for_nonfinite_check()
{
  atomKK->sync(Host, X_MASK | V_MASK | TAG_MASK | MASK_MASK);
}

namespace LAMMPS_NS {
template class FixDarcyPressureKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixDarcyPressureKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
