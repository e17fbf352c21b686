/* ----------------------------------------------------------------------
   pair_style linear/coulomb/kk (see doc/pair_linear_coulomb.rst)

   Compared with gran/hooke/history/kk of this LAMMPS version: one pass over the
   neighbor list instead of two (no separate "touch" list), per-type coefficients, and the
   virial tallied from each pair's own force (the native style tallies a running sum).
   Few neighbors touch in a granular flow, so velocities are read, histories and forces
   written only for closed contacts (bench/RESULTS.md).
------------------------------------------------------------------------- */

#include "pair_linear_coulomb_kokkos.h"

#include "linear_coulomb_contact.h"

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
#include "update.h"

using namespace LAMMPS_NS;
using porewater::ContactForce;

/* ---------------------------------------------------------------------- */

template <class DeviceType>
PairLinearCoulombKokkos<DeviceType>::PairLinearCoulombKokkos(LAMMPS *lmp) :
    PairLinearCoulomb(lmp), fix_historyKK(nullptr)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | TYPE_MASK | ENERGY_MASK |
      VIRIAL_MASK | RADIUS_MASK | TAG_MASK;
  datamask_modify = F_MASK | TORQUE_MASK | ENERGY_MASK | VIRIAL_MASK;
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

  neighflag = lmp->kokkos->neighflag;
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
  if ((int) k_params.extent(0) != n + 1)
    k_params = Kokkos::DualView<ContactParams **, Kokkos::LayoutRight, DeviceType>(
        "PairLinearCoulomb::params", n + 1, n + 1);
}

template <class DeviceType> double PairLinearCoulombKokkos<DeviceType>::init_one(int i, int j)
{
  const double cut = PairLinearCoulomb::init_one(i, j);
  k_params.h_view(i, j).kn = kn_ij[i][j];
  k_params.h_view(i, j).kt = kt_ij[i][j];
  k_params.h_view(i, j).mu = mu_ij[i][j];
  k_params.h_view(i, j).frictional = porewater::is_frictionless(kt_ij[i][j], mu_ij[i][j]) ? 0 : 1;
  k_params.h_view(j, i) = k_params.h_view(i, j);
  k_params.template modify<LMPHostType>();
  return cut;
}

/* ---------------------------------------------------------------------- */

template <class DeviceType> void PairLinearCoulombKokkos<DeviceType>::compute(int eflag_in, int vflag_in)
{
  copymode = 1;
  eflag = eflag_in;
  vflag = vflag_in;
  ev_init(eflag, vflag, 0);
  const int update_history = update->setupflag ? 0 : 1;

  if (eflag_atom) {
    memoryKK->destroy_kokkos(k_eatom, eatom);
    memoryKK->create_kokkos(k_eatom, eatom, maxeatom, "pair:eatom");
    d_eatom = k_eatom.view<DeviceType>();
  }
  if (vflag_atom) {
    memoryKK->destroy_kokkos(k_vatom, vatom);
    memoryKK->create_kokkos(k_vatom, vatom, maxvatom, "pair:vatom");
    d_vatom = k_vatom.view<DeviceType>();
  }

  atomKK->sync(execution_space, datamask_read);
  if (eflag || vflag)
    atomKK->modified(execution_space, datamask_modify);
  else
    atomKK->modified(execution_space, F_MASK | TORQUE_MASK);

  x = atomKK->k_x.view<DeviceType>();
  v = atomKK->k_v.view<DeviceType>();
  omega = atomKK->k_omega.view<DeviceType>();
  f = atomKK->k_f.view<DeviceType>();
  torque = atomKK->k_torque.view<DeviceType>();
  type = atomKK->k_type.view<DeviceType>();
  radius = atomKK->k_radius.view<DeviceType>();
  tag = atomKK->k_tag.view<DeviceType>();
  nlocal = atom->nlocal;
  if (!k_broken.d_view.data()) k_broken = Kokkos::DualView<tagint[2], DeviceType>("pair:broken");
  d_broken = k_broken.template view<DeviceType>();
  newton_pair = force->newton_pair;

  k_params.template sync<DeviceType>();
  params = k_params.template view<DeviceType>();

  NeighListKokkos<DeviceType> *k_list = static_cast<NeighListKokkos<DeviceType> *>(list);
  d_numneigh = k_list->d_numneigh;
  d_neighbors = k_list->d_neighbors;
  d_ilist = k_list->d_ilist;
  fix_historyKK->k_firstflag.template sync<DeviceType>();
  fix_historyKK->k_firstvalue.template sync<DeviceType>();
  d_firsttouch = fix_historyKK->k_firstflag.template view<DeviceType>();
  d_firstxi = fix_historyKK->k_firstvalue.template view<DeviceType>();

  need_dup = lmp->kokkos->need_dup<DeviceType>();
  if (need_dup) {
    dup_f = Kokkos::Experimental::create_scatter_view<Kokkos::Experimental::ScatterSum,
                                                      Kokkos::Experimental::ScatterDuplicated>(f);
    dup_torque = Kokkos::Experimental::create_scatter_view<
        Kokkos::Experimental::ScatterSum, Kokkos::Experimental::ScatterDuplicated>(torque);
  } else {
    ndup_f = Kokkos::Experimental::create_scatter_view<
        Kokkos::Experimental::ScatterSum, Kokkos::Experimental::ScatterNonDuplicated>(f);
    ndup_torque = Kokkos::Experimental::create_scatter_view<
        Kokkos::Experimental::ScatterSum, Kokkos::Experimental::ScatterNonDuplicated>(torque);
  }

  const int inum = list->inum;
  const int evf = (eflag || vflag || track_dissipation) ? 1 : 0;
  EV_FLOAT ev;
#define PW_LAUNCH(NF, NP)                                                 \
  if (evf) {                                                              \
    if (update_history) launch<NF, NP, 1, 1>(inum, ev);                   \
    else launch<NF, NP, 1, 0>(inum, ev);                                  \
  } else {                                                                \
    if (update_history) launch<NF, NP, 0, 1>(inum, ev);                   \
    else launch<NF, NP, 0, 0>(inum, ev);                                  \
  }
  // newton off only (see init_style)
  if (neighflag == HALF) {
    PW_LAUNCH(HALF, 0)
  } else {
    PW_LAUNCH(HALFTHREAD, 0)
  }
#undef PW_LAUNCH

  // a broken contact found in the kernel stops the run here, naming the grains
  k_broken.template modify<DeviceType>();
  k_broken.template sync<LMPHostType>();
  if (k_broken.h_view(0) != 0)
    error->one(FLERR,
               "Pair linear/coulomb/kk: at step {} grains {} and {} overlap by more than "
               "overlap_limit {} of the smaller radius (or not finite): the time step is too "
               "large for kn, or the run has blown up",
               update->ntimestep, k_broken.h_view(0), k_broken.h_view(1), overlap_limit);

  if (need_dup) {
    Kokkos::Experimental::contribute(f, dup_f);
    Kokkos::Experimental::contribute(torque, dup_torque);
    dup_f = DupForce();    // free the per-thread copies between steps
    dup_torque = DupForce();
  }

  if (eflag_global) eng_vdwl += ev.evdwl;
  if (track_dissipation) dissipated += ev.ecoul;
  pvector[0] = dissipated;
  if (vflag_global)
    for (int n = 0; n < 6; n++) virial[n] += ev.v[n];
  if (eflag_atom) {
    k_eatom.template modify<DeviceType>();
    k_eatom.template sync<LMPHostType>();
  }
  if (vflag_atom) {
    k_vatom.template modify<DeviceType>();
    k_vatom.template sync<LMPHostType>();
  }
  copymode = 0;
}

template <class DeviceType>
template <int NEIGHFLAG, int NEWTON_PAIR, int EVFLAG, int UPDATE_HISTORY>
void PairLinearCoulombKokkos<DeviceType>::launch(int inum, EV_FLOAT &ev)
{
  typedef TagPairLinearCoulombCompute<NEIGHFLAG, NEWTON_PAIR, EVFLAG, UPDATE_HISTORY> Tag;
  if (EVFLAG)
    Kokkos::parallel_reduce(Kokkos::RangePolicy<DeviceType, Tag>(0, inum), *this, ev);
  else
    Kokkos::parallel_for(Kokkos::RangePolicy<DeviceType, Tag>(0, inum), *this);
}

/* ---------------------------------------------------------------------- */

template <class DeviceType>
template <int NEIGHFLAG, int NEWTON_PAIR, int EVFLAG, int UPDATE_HISTORY>
KOKKOS_FORCEINLINE_FUNCTION void PairLinearCoulombKokkos<DeviceType>::operator()(
    TagPairLinearCoulombCompute<NEIGHFLAG, NEWTON_PAIR, EVFLAG, UPDATE_HISTORY>, const int ii,
    EV_FLOAT &ev) const
{
  // threads sharing j (HALFTHREAD) write per-thread copies on OpenMP, atomically on GPUs
  typedef ScatterPick<typename NeedDup<NEIGHFLAG, DeviceType>::value> Pick;
  const auto &v_f = Pick::get(dup_f, ndup_f);
  const auto &v_torque = Pick::get(dup_torque, ndup_torque);
  auto a_f = v_f.template access<typename AtomicDup<NEIGHFLAG, DeviceType>::value>();
  auto a_torque = v_torque.template access<typename AtomicDup<NEIGHFLAG, DeviceType>::value>();

  const int i = d_ilist[ii];
  const double xtmp = x(i, 0), ytmp = x(i, 1), ztmp = x(i, 2);
  const double radi = radius[i];
  const int itype = type[i];
  double fx_i = 0.0, fy_i = 0.0, fz_i = 0.0;    // scalars, not arrays: kept in registers
  double tx_i = 0.0, ty_i = 0.0, tz_i = 0.0;
  bool closed_any = false;    // most grains have no closed contact in their half list

  const int jnum = d_numneigh[i];
  for (int jj = 0; jj < jnum; jj++) {
    const int j = d_neighbors(i, jj) & NEIGHMASK;
    const double delx = xtmp - x(j, 0);
    const double dely = ytmp - x(j, 1);
    const double delz = ztmp - x(j, 2);
    const double rsq = delx * delx + dely * dely + delz * delz;
    const double radj = radius[j];
    const double radsum = radi + radj;
    // dissipation is tallied on the EV path; ev.ecoul carries it
    const bool tally_loss = EVFLAG && track_dissipation;
    if (rsq >= radsum * radsum) {    // an open contact forgets its history
      if (tally_loss && d_firsttouch(i, jj)) {
        const double xi_open[3] = {d_firstxi(i, 3 * jj), d_firstxi(i, 3 * jj + 1),
                                   d_firstxi(i, 3 * jj + 2)};
        ev.ecoul += porewater::pair_share(j, nlocal, NEWTON_PAIR) *
            porewater::opening_loss(params(itype, type[j]).kt, xi_open);
      }
      if (d_firsttouch(i, jj)) {    // most stay apart: no stores (flag 0 means history 0)
        d_firsttouch(i, jj) = 0;
        d_firstxi(i, 3 * jj) = 0.0;
        d_firstxi(i, 3 * jj + 1) = 0.0;
        d_firstxi(i, 3 * jj + 2) = 0.0;
      }
      continue;
    }
    d_firsttouch(i, jj) = 1;
    const ContactParams &p = params(itype, type[j]);
    // velocities are read only for closed contacts (few of the neighbors in a granular flow)
    const double vi[3] = {v(i, 0), v(i, 1), v(i, 2)};
    const double wi[3] = {omega(i, 0), omega(i, 1), omega(i, 2)};
    const double vj[3] = {v(j, 0), v(j, 1), v(j, 2)};
    const double wj[3] = {omega(j, 0), omega(j, 1), omega(j, 2)};
    double xi[3] = {d_firstxi(i, 3 * jj), d_firstxi(i, 3 * jj + 1), d_firstxi(i, 3 * jj + 2)};
    const ContactForce c = porewater::linear_coulomb_contact(
        delx, dely, delz, rsq, radi, radj, vi, vj, wi, wj, p.kn, p.kt, p.mu, lever, UPDATE_HISTORY,
        dt, xi, p.frictional);
    if (porewater::contact_is_broken(c.overlap, radi, radj, overlap_limit)) {
      d_broken(0) = tag[i];    // any one broken contact will do for the message
      d_broken(1) = tag[j];
    }
    d_firstxi(i, 3 * jj) = xi[0];
    d_firstxi(i, 3 * jj + 1) = xi[1];
    d_firstxi(i, 3 * jj + 2) = xi[2];
    if (tally_loss)
      ev.ecoul += porewater::pair_share(j, nlocal, NEWTON_PAIR) * porewater::spring_loss(p.kt, c, xi);

    closed_any = true;
    fx_i += c.f[0];
    fy_i += c.f[1];
    fz_i += c.f[2];
    if (p.frictional) {    // a frictionless pair has no torque
      tx_i -= c.lever_i * c.tor[0];
      ty_i -= c.lever_i * c.tor[1];
      tz_i -= c.lever_i * c.tor[2];
    }
    if (NEWTON_PAIR || j < nlocal) {
      a_f(j, 0) -= c.f[0];
      a_f(j, 1) -= c.f[1];
      a_f(j, 2) -= c.f[2];
      if (p.frictional) {
        a_torque(j, 0) -= c.lever_j * c.tor[0];
        a_torque(j, 1) -= c.lever_j * c.tor[1];
        a_torque(j, 2) -= c.lever_j * c.tor[2];
      }
    }
    if (EVFLAG)
      tally<NEIGHFLAG, NEWTON_PAIR>(ev, i, j, porewater::contact_energy(p.kn, p.kt, c, xi), c.f,
                                    delx, dely, delz);
  }
  if (!closed_any) return;
  a_f(i, 0) += fx_i;
  a_f(i, 1) += fy_i;
  a_f(i, 2) += fz_i;
  a_torque(i, 0) += tx_i;
  a_torque(i, 1) += ty_i;
  a_torque(i, 2) += tz_i;
}

template <class DeviceType>
template <int NEIGHFLAG, int NEWTON_PAIR, int EVFLAG, int UPDATE_HISTORY>
KOKKOS_FORCEINLINE_FUNCTION void PairLinearCoulombKokkos<DeviceType>::operator()(
    TagPairLinearCoulombCompute<NEIGHFLAG, NEWTON_PAIR, EVFLAG, UPDATE_HISTORY> tag,
    const int ii) const
{
  EV_FLOAT ev;
  this->operator()(tag, ii, ev);
}

/* ----------------------------------------------------------------------
   energy and virial of one pair, split as Pair::ev_tally_xyz does
------------------------------------------------------------------------- */

template <class DeviceType>
template <int NEIGHFLAG, int NEWTON_PAIR>
KOKKOS_INLINE_FUNCTION void PairLinearCoulombKokkos<DeviceType>::tally(
    EV_FLOAT &ev, int i, int j, double energy, const double *fij, double delx, double dely,
    double delz) const
{
  const double vir[6] = {delx * fij[0], dely * fij[1], delz * fij[2],
                         delx * fij[1], delx * fij[2], dely * fij[2]};
  // share of this pair owned here: all of it with newton, else half per owned grain
  const double share = NEWTON_PAIR ? 1.0 : 0.5 * ((i < nlocal) + (j < nlocal));
  if (eflag_global) ev.evdwl += share * energy;
  if (vflag_global)
    for (int n = 0; n < 6; n++) ev.v[n] += share * vir[n];

  if (eflag_atom) {
    Kokkos::View<E_FLOAT *, typename DAT::t_efloat_1d::array_layout,
                 typename KKDevice<DeviceType>::value, Kokkos::MemoryTraits<AtomicF<NEIGHFLAG>::value>>
        a_eatom = d_eatom;
    if (NEWTON_PAIR || i < nlocal) a_eatom[i] += 0.5 * energy;
    if (NEWTON_PAIR || j < nlocal) a_eatom[j] += 0.5 * energy;
  }
  if (vflag_atom) {
    Kokkos::View<F_FLOAT *[6], typename DAT::t_virial_array::array_layout,
                 typename KKDevice<DeviceType>::value, Kokkos::MemoryTraits<AtomicF<NEIGHFLAG>::value>>
        a_vatom = d_vatom;
    for (int n = 0; n < 6; n++) {
      if (NEWTON_PAIR || i < nlocal) a_vatom(i, n) += 0.5 * vir[n];
      if (NEWTON_PAIR || j < nlocal) a_vatom(j, n) += 0.5 * vir[n];
    }
  }
}

namespace LAMMPS_NS {
template class PairLinearCoulombKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class PairLinearCoulombKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
