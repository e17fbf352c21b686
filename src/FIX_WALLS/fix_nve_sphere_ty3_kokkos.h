/* -*- c++ -*- ----------------------------------------------------------
   fix nve/sphere/ty3/kk: the KOKKOS variant of nve/sphere/ty3. The step of one grain is
   porewater::ty3_predict_grain / ty3_correct_grain, shared with the CPU fix; the per-atom
   history lives in a DualView and travels with the atoms on the host, as LAMMPS' own
   KOKKOS fixes with per-atom arrays do.
------------------------------------------------------------------------- */

#ifndef PW_FIX_NVE_SPHERE_TY3_KOKKOS_H
#define PW_FIX_NVE_SPHERE_TY3_KOKKOS_H

#include "fix_nve_sphere_ty3.h"
#include "kokkos_type.h"

namespace LAMMPS_NS {

template <class DeviceType> class FixNVESphereTY3Kokkos : public FixNVESphereTY3 {
 public:
  FixNVESphereTY3Kokkos(class LAMMPS *, int, char **);
  ~FixNVESphereTY3Kokkos() override;
  void initial_integrate(int) override;
  void final_integrate() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;

 protected:
  DAT::tdual_float_2d k_history;    // `history` is its host view
  void forget_history() override;
};

}    // namespace LAMMPS_NS

#endif
