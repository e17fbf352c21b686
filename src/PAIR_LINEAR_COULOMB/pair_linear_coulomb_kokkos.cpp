/* ----------------------------------------------------------------------
   pair_style linear/coulomb/kk (see doc/pair_linear_coulomb.rst)

   Compared with gran/hooke/history/kk of this LAMMPS version: one pass over the
   neighbor list instead of two (no separate "touch" list), per-type coefficients, and the
   virial tallied from each pair's own force (the native style tallies a running sum).
   Few neighbors touch in a granular flow, so velocities are read, histories and forces
   written only for closed contacts (bench/pair/RESULTS.md).
------------------------------------------------------------------------- */

#include "pair_linear_coulomb_kokkos.h"

#include "contact/contact_block.h"
#include "kokkos_grains.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "error.h"
#include "fix_neigh_history_kokkos.h"
#include "force.h"
#include "kokkos.h"
#include "memory_kokkos.h"
#include "modify.h"
#include "neigh_list_kokkos.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "output.h"
#include "update.h"

#include <type_traits>

using namespace LAMMPS_NS;
using porewater::ContactCoeffs;
using porewater::ContactForce;

namespace {

// What the kernel sums over the grains: energy, virial and frictional dissipation.
struct PairTally {
  double energy, virial[6], dissipated;
  KOKKOS_INLINE_FUNCTION PairTally() : energy(0.0), virial{0, 0, 0, 0, 0, 0}, dissipated(0.0) {}
  KOKKOS_INLINE_FUNCTION void operator+=(const PairTally &r)
  {
    energy += r.energy;
    for (int n = 0; n < 6; n++) virial[n] += r.virial[n];
    dissipated += r.dissipated;
  }
  KOKKOS_INLINE_FUNCTION void operator+=(const volatile PairTally &r) volatile
  {
    energy += r.energy;
    for (int n = 0; n < 6; n++) virial[n] += r.virial[n];
    dissipated += r.dissipated;
  }
};

// Row i of a 2-D view as a pointer: element jj is base[jj * stride], with the stride 1 known
// at compile time for LayoutRight (the host's), so that the sweep's walk along a row of the
// neighbour list and of its history is pointer increments.
template <class T, class Layout> struct ViewRow {
  T *base;
  size_t stride;
  KOKKOS_INLINE_FUNCTION T &operator[](int jj) const { return base[jj * stride]; }
};
template <class T> struct ViewRow<T, Kokkos::LayoutRight> {
  T *base;
  KOKKOS_INLINE_FUNCTION T &operator[](int jj) const { return base[jj]; }
};
template <class View>
KOKKOS_INLINE_FUNCTION ViewRow<typename View::value_type, typename View::array_layout>
view_row(const View &v, int i, std::true_type /*LayoutRight*/)
{
  return {&v(i, 0)};
}
template <class View>
KOKKOS_INLINE_FUNCTION ViewRow<typename View::value_type, typename View::array_layout>
view_row(const View &v, int i, std::false_type)
{
  return {&v(i, 0), v.stride(1)};
}
template <class View>
KOKKOS_INLINE_FUNCTION ViewRow<typename View::value_type, typename View::array_layout>
view_row(const View &v, int i)
{
  return view_row(v, i, std::is_same<typename View::array_layout, Kokkos::LayoutRight>());
}

// work tag: a chunk of grains through the block pass (contact_block.h), on host backends
struct TagBlock {};
constexpr int GRAINS_PER_CHUNK = 64;

// The sweep over each grain's half list (newton off: pairs with a ghost j are computed on
// both ranks): on a GPU a thread per grain (linear_coulomb_sweep), on the host a chunk of
// grains per call (linear_coulomb_block_sweep). NEIGHFLAG HALF: one thread; HALFTHREAD:
// threads share j, whose forces go to per-thread copies on OpenMP and atomically on GPUs.
template <class DeviceType, int NEIGHFLAG, int EVFLAG, int UPDATE_HISTORY> struct SweepKernel {
  typedef ArrayTypes<DeviceType> AT;
  typedef PairTally value_type;    // of the parallel_reduce (EVFLAG)
  typedef typename NeedDup<NEIGHFLAG, DeviceType>::value Dup;
  typedef Kokkos::Experimental::ScatterView<F_FLOAT *[3], typename DAT::t_f_array::array_layout,
                                            typename KKDevice<DeviceType>::value,
                                            Kokkos::Experimental::ScatterSum, Dup>
      Scatter;
  typedef typename AtomicDup<NEIGHFLAG, DeviceType>::value Contribution;
  typedef Kokkos::View<E_FLOAT *, typename DAT::t_efloat_1d::array_layout,
                       typename KKDevice<DeviceType>::value,
                       Kokkos::MemoryTraits<AtomicF<NEIGHFLAG>::value>>
      AtomEnergy;
  typedef Kokkos::View<F_FLOAT *[6], typename DAT::t_virial_array::array_layout,
                       typename KKDevice<DeviceType>::value,
                       Kokkos::MemoryTraits<AtomicF<NEIGHFLAG>::value>>
      AtomVirial;

  typename AT::t_x_array_randomread x;
  typename AT::t_v_array_randomread v, omega;
  typename AT::t_int_1d_randomread type;
  typename AT::t_float_1d_randomread radius;
  typename AT::t_tagint_1d_randomread tag;
  typename AT::t_int_1d_randomread ilist, numneigh;
  typename AT::t_neighbors_2d neighbors;
  typename AT::t_int_2d touch;
  typename AT::t_float_2d springs;
  typename PairLinearCoulombKokkos<DeviceType>::tdual_coeffs::t_dev_const_um coeffs;
  Scatter f, torque;
  typename AT::t_efloat_1d eatom;
  typename AT::t_virial_array vatom;
  Kokkos::View<porewater::BrokenContact, DeviceType> broken;
  bigint step;
  porewater::ContactStep contact;
  ContactCoeffs uniform;    // the coefficients of every type pair, if is_uniform
  double limit;
  int inum, nlocal, tracking, is_uniform, eflag_global, vflag_global, eflag_atom, vflag_atom;

  // porewater::linear_coulomb_sweep's view of this kernel, for one grain's thread
  template <class Access> struct Policy {
    const SweepKernel &k;
    const Access &f, &torque;
    typedef PairTally Sums;

    struct Row {
      ViewRow<int, typename AT::t_neighbors_2d::array_layout> neighbors;
      ViewRow<int, typename AT::t_int_2d::array_layout> flags;
      ViewRow<double, typename AT::t_float_2d::array_layout> springs;
      int jnum;
      KOKKOS_INLINE_FUNCTION int count() const { return jnum; }
      KOKKOS_INLINE_FUNCTION int neighbor(int jj) const { return neighbors[jj] & NEIGHMASK; }
      KOKKOS_INLINE_FUNCTION int touched(int jj) const { return flags[jj]; }
      KOKKOS_INLINE_FUNCTION void touch(int jj) const { flags[jj] = 1; }
      KOKKOS_INLINE_FUNCTION void forget(int jj) const
      {
        flags[jj] = 0;
        for (int d = 0; d < 3; d++) springs[3 * jj + d] = 0.0;
      }
      KOKKOS_INLINE_FUNCTION double *history(int jj, double *scratch) const
      {
        for (int d = 0; d < 3; d++) scratch[d] = springs[3 * jj + d];
        return scratch;
      }
      KOKKOS_INLINE_FUNCTION void keep_history(int jj, const double *xi) const
      {
        for (int d = 0; d < 3; d++) springs[3 * jj + d] = xi[d];
      }
    };
    // scalars, not arrays: kept in registers; written once, if any contact closed
    struct GrainForce {
      const Access &f, &torque;
      int i;
      double fx = 0.0, fy = 0.0, fz = 0.0, tx = 0.0, ty = 0.0, tz = 0.0;
      bool closed_any = false;    // most grains have no closed contact in their half list
      KOKKOS_INLINE_FUNCTION void add(const ContactForce &c, int frictional)
      {
        closed_any = true;
        fx += c.f[0];
        fy += c.f[1];
        fz += c.f[2];
        if (frictional) {
          tx -= c.tor_i[0];
          ty -= c.tor_i[1];
          tz -= c.tor_i[2];
        }
      }
      KOKKOS_INLINE_FUNCTION void finish() const
      {
        if (!closed_any) return;
        f(i, 0) += fx;
        f(i, 1) += fy;
        f(i, 2) += fz;
        torque(i, 0) += tx;
        torque(i, 1) += ty;
        torque(i, 2) += tz;
      }
    };

    KOKKOS_INLINE_FUNCTION int grain(int ii) const { return k.ilist[ii]; }
    KOKKOS_INLINE_FUNCTION bool uniform_coeffs(ContactCoeffs &c) const
    {
      c = k.uniform;
      return k.is_uniform;
    }
    KOKKOS_INLINE_FUNCTION double x(int i, int d) const { return k.x(i, d); }
    KOKKOS_INLINE_FUNCTION double radius(int i) const { return k.radius[i]; }
    KOKKOS_INLINE_FUNCTION int type(int i) const { return k.type[i]; }
    KOKKOS_INLINE_FUNCTION Row neighbors(int i) const
    {
      return Row{view_row(k.neighbors, i), view_row(k.touch, i), view_row(k.springs, i),
                 k.numneigh[i]};
    }
    KOKKOS_INLINE_FUNCTION const double *v(int i, double *scratch) const
    {
      for (int d = 0; d < 3; d++) scratch[d] = k.v(i, d);
      return scratch;
    }
    KOKKOS_INLINE_FUNCTION const double *omega(int i, double *scratch) const
    {
      for (int d = 0; d < 3; d++) scratch[d] = k.omega(i, d);
      return scratch;
    }
    KOKKOS_INLINE_FUNCTION ContactCoeffs coeffs(int itype, int jtype) const
    {
      return k.coeffs(itype, jtype);
    }
    KOKKOS_INLINE_FUNCTION porewater::ContactStep step() const
    {
      return porewater::ContactStep{k.contact.lever, UPDATE_HISTORY, k.contact.dt};
    }
    KOKKOS_INLINE_FUNCTION bool owns(int j) const { return j < k.nlocal; }
    KOKKOS_INLINE_FUNCTION double share(int j) const { return porewater::pair_share(j, k.nlocal, 0); }
    KOKKOS_INLINE_FUNCTION GrainForce force_on(int i) const { return GrainForce{f, torque, i}; }
    KOKKOS_INLINE_FUNCTION void add_reaction(int j, const ContactForce &c, int frictional) const
    {
      f(j, 0) -= c.f[0];
      f(j, 1) -= c.f[1];
      f(j, 2) -= c.f[2];
      if (frictional) {
        torque(j, 0) -= c.tor_j[0];
        torque(j, 1) -= c.tor_j[1];
        torque(j, 2) -= c.tor_j[2];
      }
    }
    KOKKOS_INLINE_FUNCTION double overlap_limit() const { return k.limit; }
    // the first broken contact found is the one the message names
    KOKKOS_INLINE_FUNCTION void broken(int i, int j, double) const
    {
      if (Kokkos::atomic_compare_exchange(&k.broken().i, tagint(0), k.tag[i]) == 0) {
        k.broken().j = k.tag[j];
        k.broken().step = k.step;
      }
    }
    KOKKOS_INLINE_FUNCTION bool tracks_dissipation() const { return EVFLAG && k.tracking; }
    KOKKOS_INLINE_FUNCTION void add_loss(PairTally &sums, double energy) const
    {
      sums.dissipated += energy;
    }
    // energy and virial of one pair, split as Pair::ev_tally_xyz does with newton off
    KOKKOS_INLINE_FUNCTION void tally(PairTally &sums, int i, int j, const ContactForce &c,
                                      const ContactCoeffs &kc, const double *xi, double delx,
                                      double dely, double delz) const
    {
      if (!EVFLAG) return;
      const double energy = porewater::contact_energy(kc.kn, kc.kt, c, xi);
      const double vir[6] = {delx * c.f[0], dely * c.f[1], delz * c.f[2],
                             delx * c.f[1], delx * c.f[2], dely * c.f[2]};
      const double owned = 0.5 * ((i < k.nlocal) + (j < k.nlocal));
      if (k.eflag_global) sums.energy += owned * energy;
      if (k.vflag_global)
        for (int n = 0; n < 6; n++) sums.virial[n] += owned * vir[n];
      if (k.eflag_atom) {
        const AtomEnergy a_eatom = k.eatom;
        if (i < k.nlocal) a_eatom[i] += 0.5 * energy;
        if (j < k.nlocal) a_eatom[j] += 0.5 * energy;
      }
      if (k.vflag_atom) {
        const AtomVirial a_vatom = k.vatom;
        for (int n = 0; n < 6; n++) {
          if (i < k.nlocal) a_vatom(i, n) += 0.5 * vir[n];
          if (j < k.nlocal) a_vatom(j, n) += 0.5 * vir[n];
        }
      }
    }
  };

  KOKKOS_FORCEINLINE_FUNCTION void operator()(const int ii, PairTally &sums) const
  {
    const auto a_f = f.template access<Contribution>();
    const auto a_torque = torque.template access<Contribution>();
    const Policy<decltype(a_f)> policy{*this, a_f, a_torque};
    porewater::linear_coulomb_sweep(policy, ilist[ii], sums);
  }
  KOKKOS_FORCEINLINE_FUNCTION void operator()(const int ii) const
  {
    PairTally unused;
    this->operator()(ii, unused);
  }

  // host backends only (SIMD lanes, no device code): a chunk of grains
  void operator()(TagBlock, const int chunk, PairTally &sums) const
  {
    const auto a_f = f.template access<Contribution>();
    const auto a_torque = torque.template access<Contribution>();
    const Policy<decltype(a_f)> policy{*this, a_f, a_torque};
    porewater::ContactBlock block;
    const int begin = chunk * GRAINS_PER_CHUNK;
    porewater::linear_coulomb_block_sweep(policy, begin, std::min(begin + GRAINS_PER_CHUNK, inum),
                                          sums, block);
  }
  void operator()(TagBlock, const int chunk) const
  {
    PairTally unused;
    this->operator()(TagBlock(), chunk, unused);
  }
};

// the kernel over every grain: a chunk a call on the host, a grain a thread on a GPU
template <class Kernel, class DeviceType>
void run_sweep(const Kernel &kernel, const int inum, PairTally &sums, const bool reduce,
               std::true_type /*host*/)
{
  const auto chunks =
      porewater::grain_range<DeviceType, TagBlock>(0, (inum + GRAINS_PER_CHUNK - 1) / GRAINS_PER_CHUNK);
  if (reduce)
    Kokkos::parallel_reduce("pair linear/coulomb", chunks, kernel, sums);
  else
    Kokkos::parallel_for("pair linear/coulomb", chunks, kernel);
}
template <class Kernel, class DeviceType>
void run_sweep(const Kernel &kernel, const int inum, PairTally &sums, const bool reduce,
               std::false_type /*device*/)
{
  const auto grains = porewater::grain_range<DeviceType>(0, inum);
  using Space = typename DeviceType::execution_space;
  PW_ASSERT_LAUNCH_BY_ARGUMENT(
      Space, Kokkos::Impl::ParallelFor<Kernel, typename std::decay<decltype(grains)>::type, Space>);
  if (reduce)
    Kokkos::parallel_reduce("pair linear/coulomb", grains, kernel, sums);
  else
    Kokkos::parallel_for("pair linear/coulomb", grains, kernel);
}

}    // namespace

/* ---------------------------------------------------------------------- */

template <class DeviceType>
PairLinearCoulombKokkos<DeviceType>::PairLinearCoulombKokkos(LAMMPS *lmp) :
    PairLinearCoulomb(lmp), broken("pair:broken"), fix_historyKK(nullptr)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  // synced in compute() itself, as every /kk style of the package does
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
}

template <class DeviceType> PairLinearCoulombKokkos<DeviceType>::~PairLinearCoulombKokkos()
{
  if (copymode) return;
  if (allocated) {
    memoryKK->destroy_kokkos(k_eatom, eatom);
    memoryKK->destroy_kokkos(k_vatom, vatom);
    eatom = nullptr;
    vatom = nullptr;
  }
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairLinearCoulombKokkos<DeviceType>::init_style()
{
  // the history fix must be the KOKKOS one; it replaces the dummy made by the constructor
  if (history && fix_history == nullptr) {
    auto cmd = std::string("NEIGH_HISTORY_HH") + std::to_string(instance_me) + " all ";
    cmd += (execution_space == Device) ? "NEIGH_HISTORY/KK/DEVICE 3" : "NEIGH_HISTORY/KK/HOST 3";
    fix_history = (FixNeighHistory *) modify->replace_fix(
        "NEIGH_HISTORY_HH_DUMMY" + std::to_string(instance_me), cmd, 1);
    fix_history->pair = this;
    fix_historyKK = (FixNeighHistoryKokkos<DeviceType> *) fix_history;
  }
  PairLinearCoulomb::init_style();

  const int neighflag = lmp->kokkos->neighflag;
  int irequest = neighbor->nrequest - 1;
  neighbor->requests[irequest]->kokkos_host =
      std::is_same<DeviceType, LMPHostType>::value && !std::is_same<DeviceType, LMPDeviceType>::value;
  neighbor->requests[irequest]->kokkos_device = std::is_same<DeviceType, LMPDeviceType>::value;
  if (neighflag == HALF || neighflag == HALFTHREAD) {
    neighbor->requests[irequest]->full = 0;
    neighbor->requests[irequest]->half = 1;
  } else {
    error->all(FLERR, "Pair linear/coulomb/kk needs a half neighbor list (package kokkos neigh half)");
  }
  // this LAMMPS' FixNeighHistoryKokkos has no reverse communication of ghost partners, so
  // under newton on a pair whose history sits on a ghost's owner loses it at reneighboring
  if (force->newton_pair)
    error->all(FLERR, "Pair linear/coulomb/kk requires newton off (add 'newton off' to the input "
                      "or run with -pk kokkos newton off): KOKKOS neighbor history of this LAMMPS "
                      "version loses ghost-pair histories under newton on");

  const int n = atom->ntypes;
  if ((int) k_coeffs.extent(0) != n + 1) k_coeffs = tdual_coeffs("PairLinearCoulomb::coeffs", n + 1, n + 1);
}

template <class DeviceType> double PairLinearCoulombKokkos<DeviceType>::init_one(int i, int j)
{
  const double cut = PairLinearCoulomb::init_one(i, j);
  k_coeffs.h_view(i, j) = porewater::contact_coeffs(kn_ij[i][j], kt_ij[i][j], mu_ij[i][j]);
  k_coeffs.h_view(j, i) = k_coeffs.h_view(i, j);
  k_coeffs.template modify<LMPHostType>();
  return cut;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairLinearCoulombKokkos<DeviceType>::compute(int eflag_in, int vflag_in)
{
  ev_init(eflag_in, vflag_in, 0);
  if (eflag_atom) {
    memoryKK->destroy_kokkos(k_eatom, eatom);
    memoryKK->create_kokkos(k_eatom, eatom, maxeatom, "pair:eatom");
  }
  if (vflag_atom) {
    memoryKK->destroy_kokkos(k_vatom, vatom);
    memoryKK->create_kokkos(k_vatom, vatom, maxvatom, "pair:vatom");
  }
  atomKK->sync(execution_space,
               X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | TYPE_MASK | RADIUS_MASK | TAG_MASK);
  k_coeffs.template sync<DeviceType>();
  fix_historyKK->k_firstflag.template sync<DeviceType>();
  fix_historyKK->k_firstvalue.template sync<DeviceType>();

  const bool tally = eflag_in || vflag_in || style.dissipation;
  const bool update_history = !update->setupflag;
#define PW_LAUNCH(NF)                                    \
  if (tally) {                                           \
    if (update_history) launch<NF, 1, 1>();              \
    else launch<NF, 1, 0>();                             \
  } else {                                               \
    if (update_history) launch<NF, 0, 1>();              \
    else launch<NF, 0, 0>();                             \
  }
  // newton off only (see init_style)
  if (lmp->kokkos->neighflag == HALF) {
    PW_LAUNCH(HALF)
  } else {
    PW_LAUNCH(HALFTHREAD)
  }
#undef PW_LAUNCH
  atomKK->modified(execution_space, F_MASK | TORQUE_MASK);
  fix_historyKK->k_firstflag.template modify<DeviceType>();
  fix_historyKK->k_firstvalue.template modify<DeviceType>();

  // a broken contact found in the kernel stops the run at the next check, naming the
  // grains and the step it was found at
  if (checks_broken_now()) {
    const porewater::BrokenContact &b = broken.pull();
    if (b.i != 0)
      error->one(FLERR,
                 "Pair linear/coulomb/kk: at step {} grains {} and {} overlap by more than "
                 "overlap_limit {} of the smaller radius (or not finite): the time step is too "
                 "large for kn, or the run has blown up",
                 b.step, b.i, b.j, style.overlap_limit);
  }

  pvector[0] = dissipated;
  if (eflag_atom) {
    k_eatom.template modify<DeviceType>();
    k_eatom.template sync<LMPHostType>();
  }
  if (vflag_atom) {
    k_vatom.template modify<DeviceType>();
    k_vatom.template sync<LMPHostType>();
  }
}

template <class DeviceType>
template <int NEIGHFLAG, int EVFLAG, int UPDATE_HISTORY>
void PairLinearCoulombKokkos<DeviceType>::launch()
{
  typedef SweepKernel<DeviceType, NEIGHFLAG, EVFLAG, UPDATE_HISTORY> Kernel;
  NeighListKokkos<DeviceType> *k_list = static_cast<NeighListKokkos<DeviceType> *>(list);
  Kernel kernel;
  kernel.x = atomKK->k_x.view<DeviceType>();
  kernel.v = atomKK->k_v.view<DeviceType>();
  kernel.omega = atomKK->k_omega.view<DeviceType>();
  kernel.type = atomKK->k_type.view<DeviceType>();
  kernel.radius = atomKK->k_radius.view<DeviceType>();
  kernel.tag = atomKK->k_tag.view<DeviceType>();
  kernel.ilist = k_list->d_ilist;
  kernel.numneigh = k_list->d_numneigh;
  kernel.neighbors = k_list->d_neighbors;
  kernel.touch = fix_historyKK->k_firstflag.template view<DeviceType>();
  kernel.springs = fix_historyKK->k_firstvalue.template view<DeviceType>();
  kernel.coeffs = k_coeffs.template view<DeviceType>();
  kernel.f = Kokkos::Experimental::create_scatter_view<Kokkos::Experimental::ScatterSum,
                                                       typename Kernel::Dup>(atomKK->k_f.view<DeviceType>());
  kernel.torque = Kokkos::Experimental::create_scatter_view<Kokkos::Experimental::ScatterSum,
                                                            typename Kernel::Dup>(
      atomKK->k_torque.view<DeviceType>());
  if (eflag_atom) kernel.eatom = k_eatom.template view<DeviceType>();
  if (vflag_atom) kernel.vatom = k_vatom.template view<DeviceType>();
  kernel.broken = broken.device;
  kernel.step = update->ntimestep;
  kernel.contact = contact_step();
  kernel.is_uniform = coefficients_are_uniform() ? 1 : 0;
  kernel.uniform = porewater::contact_coeffs(kn_ij[1][1], kt_ij[1][1], mu_ij[1][1]);
  kernel.limit = style.overlap_limit;
  kernel.inum = list->inum;
  kernel.nlocal = atom->nlocal;
  kernel.tracking = style.dissipation ? 1 : 0;
  kernel.eflag_global = eflag_global;
  kernel.vflag_global = vflag_global;
  kernel.eflag_atom = eflag_atom;
  kernel.vflag_atom = vflag_atom;

  PairTally sums;
  run_sweep<Kernel, DeviceType>(
      kernel, list->inum, sums, EVFLAG,
      std::integral_constant<bool, ExecutionSpaceFromDevice<DeviceType>::space == Host>());
  typename ArrayTypes<DeviceType>::t_f_array f = atomKK->k_f.view<DeviceType>();
  typename ArrayTypes<DeviceType>::t_f_array torque = atomKK->k_torque.view<DeviceType>();
  Kokkos::Experimental::contribute(f, kernel.f);
  Kokkos::Experimental::contribute(torque, kernel.torque);

  if (eflag_global) eng_vdwl += sums.energy;
  if (vflag_global)
    for (int n = 0; n < 6; n++) virial[n] += sums.virial[n];
  dissipated += sums.dissipated;
}

// The steps that wait for the device anyway, so that reading the flag costs no wait of its
// own: a run's setup, re-neighboring, output and the run's last step
template <class DeviceType> bool PairLinearCoulombKokkos<DeviceType>::checks_broken_now() const
{
  const bigint step = update->ntimestep;
  return update->setupflag || neighbor->ago == 0 || step == output->next || step == update->laststep;
}

namespace LAMMPS_NS {
template class PairLinearCoulombKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairLinearCoulombKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
