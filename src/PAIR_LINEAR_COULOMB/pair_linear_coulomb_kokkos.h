/* -*- c++ -*- ----------------------------------------------------------
   pair_style linear/coulomb/kk: the KOKKOS variant of linear/coulomb. Its kernel runs the
   core's porewater::linear_coulomb_sweep, the same as the CPU style, with a policy that
   reads Kokkos views and scatters forces per thread (OpenMP) or atomically (GPUs).
------------------------------------------------------------------------- */

#ifndef PW_PAIR_LINEAR_COULOMB_KOKKOS_H
#define PW_PAIR_LINEAR_COULOMB_KOKKOS_H

#include "kokkos_grains.h"
#include "kokkos_type.h"
#include "pair_kokkos.h"
#include "pair_linear_coulomb.h"

namespace porewater {
// the first contact found deeper than the overlap limit: its grains' tags (0: none) and step
struct BrokenContact {
  LAMMPS_NS::tagint i, j;
  LAMMPS_NS::bigint step;
};
}    // namespace porewater

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
  // found by the kernel on the device; read on the steps that wait for the device anyway
  porewater::DeviceState<porewater::BrokenContact, DeviceType> broken;
  bool checks_broken_now() const;
  FixNeighHistoryKokkos<DeviceType> *fix_historyKK;
};

}    // namespace LAMMPS_NS

#endif
