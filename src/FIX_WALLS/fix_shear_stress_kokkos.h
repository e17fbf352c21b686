/* -*- c++ -*- ----------------------------------------------------------
   fix shear/stress/kk: the KOKKOS variant of shear/stress: the core's plate kernels
   (walls/shear_plate.h) as Kokkos kernels over the atoms. On one rank the plate itself
   lives on the device: the kernel that sums the layer's forces also takes the plate's step
   (plate_post_force, once, on the device), and the next moves the layer; nothing comes back
   to the host but at outputs, re-neighboring and the end of a run, and it stays there
   between runs, so a run without its setup (`run N pre no`) goes on from it. Both kernels'
   work may run in fix nve/sphere/bed/kk's fused pass instead
   (fix_nve_sphere_bed_pass_kokkos.h), which stamps the step it did so.
   On several ranks the sums meet in an MPI_Allreduce and the plate steps on the host, as
   in the CPU fix.
------------------------------------------------------------------------- */

#ifndef PW_FIX_SHEAR_STRESS_KOKKOS_H
#define PW_FIX_SHEAR_STRESS_KOKKOS_H

#include "fix_shear_stress.h"
#include "kokkos_fused_pass.h"
#include "kokkos_grains.h"
#include "kokkos_type.h"

namespace porewater {
// the plate on the device, and the first step at which its step went wrong
struct PlateOnDevice {
  PlateState plate;
  int verdict;    // PLATE_MOVING, or the first other verdict of plate_post_force
  long long verdict_step;
  double verdict_value;
};

// The layer's sums and, once on the device with their totals, the plate's step: a body of
// kokkos_sum_over_grains_on_device
template <class DeviceType> struct KokkosPlateSumsThenStep {
  static constexpr int count = PlateSums<KokkosGrains<DeviceType>>::count;
  PlateSums<KokkosGrains<DeviceType>> body;
  Kokkos::View<PlateOnDevice, DeviceType> state;
  double area, tau, mass, force_to_velocity, bound;
  long long step;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double *sums) const { body(i, sums); }
  KOKKOS_INLINE_FUNCTION void final(double *sums) const
  {
    PlateOnDevice &s = state();
    const PlateStepResult r =
        plate_post_force(s.plate, sums, false, area, tau, mass, force_to_velocity, bound);
    if (r.verdict != PLATE_MOVING && s.verdict == PLATE_MOVING) {
      s.verdict = r.verdict;
      s.verdict_step = step;
      s.verdict_value = r.value;
    }
  }
};

// every grain of the layer its share of the plate's force, as the step above left it
template <class DeviceType> struct KokkosPlateMotion {
  KokkosGrains<DeviceType> grains;
  int groupbit;
  Kokkos::View<PlateOnDevice, DeviceType> state;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    PlateMotion<KokkosGrains<DeviceType>>{grains, groupbit, state().plate.force_per_mass}(i);
  }
};
}    // namespace porewater

namespace LAMMPS_NS {

template <class DeviceType> class FixShearStressKokkos : public FixShearStress {
 public:
  FixShearStressKokkos(class LAMMPS *, int, char **);
  void setup(int) override;
  void pre_neighbor() override;
  void post_force(int) override;
  void post_run() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;

  // fix nve/sphere/bed/kk's fused pass: while the plate steps on the device, its sums of
  // this step may run in that pass, which stamps the step; and when it is the last
  // post_force fix, the layer's motion may run in that fix's final_integrate kernel, the
  // next to touch the grains, which the pass stamps too
  bool steps_on_device() const { return on_device; }
  porewater::KokkosPlateSumsThenStep<DeviceType> sums_kernel();
  porewater::PassStamp &pass_stamp() { return summed_in_pass; }
  porewater::KokkosPlateMotion<DeviceType> motion_kernel();
  porewater::PassStamp &motion_stamp() { return motion_in_final; }

 protected:
  void plate_sums(double *sums) override;
  void momentum_sums(double *sums) override;
  void move_as_plate(double force_per_mass) override;
  void set_velocity_x(double velocity) override;

 private:
  bool on_device;       // this run's plate lives on the device (one rank)
  bool host_current;    // the host's plate is the device's
  porewater::PassStamp summed_in_pass;     // the step whose sums ran in the fused pass
  porewater::PassStamp motion_in_final;    // the step whose motion the bed's final moves
  porewater::DeviceState<porewater::PlateOnDevice, DeviceType> state;
  Kokkos::View<double *, DeviceType> d_totals;    // the sums (read by the step on the device)
  void pull();    // the device's plate to the host's; stops the run if its step went wrong
};

}    // namespace LAMMPS_NS

#endif
