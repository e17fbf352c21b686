/* -*- c++ -*- ----------------------------------------------------------
   pair_style linear/coulomb/kk: the KOKKOS variant of linear/coulomb. Its kernel runs the
   core's porewater::linear_coulomb_sweep, the same as the CPU style, with a policy that
   reads Kokkos views and scatters forces per thread (OpenMP) or atomically (GPUs).
------------------------------------------------------------------------- */

#ifndef PW_PAIR_LINEAR_COULOMB_KOKKOS_H
#define PW_PAIR_LINEAR_COULOMB_KOKKOS_H

#include "kokkos_type.h"
#include "pair_kokkos.h"
#include "pair_linear_coulomb.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixNeighHistoryKokkos;

template <class DeviceType> class PairLinearCoulombKokkos : public PairLinearCoulomb {
 public:
  typedef DeviceType device_type;
  typedef ArrayTypes<DeviceType> AT;
  typedef Kokkos::DualView<porewater::ContactCoeffs **, Kokkos::LayoutRight, DeviceType> tdual_coeffs;

  PairLinearCoulombKokkos(class LAMMPS *);
  ~PairLinearCoulombKokkos() override;
  void compute(int, int) override;
  void init_style() override;
  double init_one(int, int) override;

 protected:
  template <int NEIGHFLAG, int EVFLAG, int UPDATE_HISTORY> void launch();

  tdual_coeffs k_coeffs;    // per type pair, decided in init_one()
  DAT::tdual_efloat_1d k_eatom;
  DAT::tdual_virial_array k_vatom;
  Kokkos::DualView<tagint[2], DeviceType> k_broken;    // tags of a broken contact, 0 if none
  FixNeighHistoryKokkos<DeviceType> *fix_historyKK;
};

}    // namespace LAMMPS_NS

#endif
