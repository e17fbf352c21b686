/* -*- c++ -*- ----------------------------------------------------------
   fix shear/stress/kk: the KOKKOS variant of shear/stress: the core's plate kernels
   (walls/shear_plate.h) as Kokkos kernels over the atoms. On one rank the plate itself
   lives on the device during a run: the kernel that sums the layer's forces also takes
   the plate's step (plate_post_force, once, on the device), and the next moves the layer;
   nothing comes back to the host but at outputs, re-neighboring and the end of the run.
   On several ranks the sums meet in an MPI_Allreduce and the plate steps on the host, as
   in the CPU fix.
------------------------------------------------------------------------- */

#ifndef PW_FIX_SHEAR_STRESS_KOKKOS_H
#define PW_FIX_SHEAR_STRESS_KOKKOS_H

#include "fix_shear_stress.h"
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

 protected:
  void plate_sums(double *sums) override;
  void momentum_sums(double *sums) override;
  void move_as_plate(double force_per_mass) override;
  void set_velocity_x(double velocity) override;

 private:
  bool on_device;       // this run's plate lives on the device (one rank)
  bool host_current;    // the host's plate is the device's
  porewater::DeviceState<porewater::PlateOnDevice, DeviceType> state;
  Kokkos::View<double *, DeviceType> d_totals;    // the sums (read by the step on the device)
  void pull();    // the device's plate to the host's; stops the run if its step went wrong
};

}    // namespace LAMMPS_NS

#endif
