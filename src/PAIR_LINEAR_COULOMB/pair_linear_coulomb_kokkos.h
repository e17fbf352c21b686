/* -*- c++ -*- ----------------------------------------------------------
   pair_style linear/coulomb/kk: the KOKKOS variant of linear/coulomb. The force law is
   porewater::linear_coulomb_contact(), shared with the CPU style.
------------------------------------------------------------------------- */

#ifndef PW_PAIR_LINEAR_COULOMB_KOKKOS_H
#define PW_PAIR_LINEAR_COULOMB_KOKKOS_H

#include "kokkos_type.h"
#include "pair_kokkos.h"
#include "pair_linear_coulomb.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixNeighHistoryKokkos;

// LAMMPS' ScatterViewHelper::get returns a copy, made once per grain in the kernel (a view
// copy and its reference-tracking check); this returns a reference
template <class Dup> struct ScatterPick;
template <> struct ScatterPick<Kokkos::Experimental::ScatterDuplicated> {
  template <class D, class N> KOKKOS_INLINE_FUNCTION static const D &get(const D &dup, const N &)
  {
    return dup;
  }
};
template <> struct ScatterPick<Kokkos::Experimental::ScatterNonDuplicated> {
  template <class D, class N> KOKKOS_INLINE_FUNCTION static const N &get(const D &, const N &nondup)
  {
    return nondup;
  }
};

template <int NEIGHFLAG, int NEWTON_PAIR, int EVFLAG, int UPDATE_HISTORY>
struct TagPairLinearCoulombCompute {};

template <class DeviceType> class PairLinearCoulombKokkos : public PairLinearCoulomb {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef EV_FLOAT value_type;

  PairLinearCoulombKokkos(class LAMMPS *);
  ~PairLinearCoulombKokkos() override;
  void compute(int, int) override;
  void init_style() override;
  double init_one(int, int) override;

  // one pass per owned grain: open contacts are cleared, closed ones computed; force-inlined
  // into the Kokkos loop, so that the per-grain setup is hoisted out of it
  template <int NEIGHFLAG, int NEWTON_PAIR, int EVFLAG, int UPDATE_HISTORY>
  KOKKOS_FORCEINLINE_FUNCTION void
  operator()(TagPairLinearCoulombCompute<NEIGHFLAG, NEWTON_PAIR, EVFLAG, UPDATE_HISTORY>, const int,
             EV_FLOAT &) const;
  template <int NEIGHFLAG, int NEWTON_PAIR, int EVFLAG, int UPDATE_HISTORY>
  KOKKOS_FORCEINLINE_FUNCTION void
  operator()(TagPairLinearCoulombCompute<NEIGHFLAG, NEWTON_PAIR, EVFLAG, UPDATE_HISTORY>,
             const int) const;

  struct ContactParams {
    KOKKOS_INLINE_FUNCTION ContactParams() : kn(0.0), kt(0.0), mu(0.0), frictional(0) {}
    double kn, kt, mu;
    int frictional;    // !porewater::is_frictionless(kt, mu), decided once in init_one()
  };

 protected:
  template <int NEIGHFLAG, int NEWTON_PAIR, int EVFLAG, int UPDATE_HISTORY>
  void launch(int inum, EV_FLOAT &ev);
  template <int NEIGHFLAG, int NEWTON_PAIR>
  KOKKOS_INLINE_FUNCTION void tally(EV_FLOAT &ev, int i, int j, double energy, const double *fij,
                                    double delx, double dely, double delz) const;

  typename AT::t_x_array_randomread x;
  typename AT::t_v_array_randomread v;
  typename AT::t_v_array_randomread omega;
  typename AT::t_f_array f;
  typename AT::t_f_array torque;
  typename AT::t_int_1d_randomread type;
  typename AT::t_float_1d_randomread radius;

  // force and torque scatter: duplicated per thread on OpenMP, atomic on GPUs, plain serially
  typedef Kokkos::Experimental::ScatterView<F_FLOAT *[3], typename DAT::t_f_array::array_layout,
                                            typename KKDevice<DeviceType>::value,
                                            Kokkos::Experimental::ScatterSum,
                                            Kokkos::Experimental::ScatterDuplicated>
      DupForce;
  typedef Kokkos::Experimental::ScatterView<F_FLOAT *[3], typename DAT::t_f_array::array_layout,
                                            typename KKDevice<DeviceType>::value,
                                            Kokkos::Experimental::ScatterSum,
                                            Kokkos::Experimental::ScatterNonDuplicated>
      NonDupForce;
  DupForce dup_f, dup_torque;
  NonDupForce ndup_f, ndup_torque;
  int need_dup;

  DAT::tdual_efloat_1d k_eatom;
  DAT::tdual_virial_array k_vatom;
  typename AT::t_efloat_1d d_eatom;
  typename AT::t_virial_array d_vatom;

  typename AT::t_neighbors_2d d_neighbors;
  typename AT::t_int_1d_randomread d_ilist;
  typename AT::t_int_1d_randomread d_numneigh;
  typename AT::t_int_2d d_firsttouch;
  typename AT::t_float_2d d_firstxi;

  Kokkos::DualView<ContactParams **, Kokkos::LayoutRight, DeviceType> k_params;
  typename Kokkos::DualView<ContactParams **, Kokkos::LayoutRight, DeviceType>::t_dev_const_um
      params;

  int neighflag, newton_pair, nlocal, eflag, vflag;
  typename AT::t_tagint_1d_randomread tag;
  Kokkos::DualView<tagint[2], DeviceType> k_broken;    // tags of a broken contact, 0 if none
  typename Kokkos::DualView<tagint[2], DeviceType>::t_dev d_broken;
  FixNeighHistoryKokkos<DeviceType> *fix_historyKK;
};

}    // namespace LAMMPS_NS

#endif
