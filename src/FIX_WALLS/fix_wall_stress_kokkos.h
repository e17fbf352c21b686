/* -*- c++ -*- ----------------------------------------------------------
   fix wall/stress/kk: the KOKKOS variant of wall/stress. The grain–wall contacts run as a
   kernel over the atoms: the core's porewater::WallContacts, as in the CPU fix. On one rank
   the wall itself lives on the device during a run (walls/wall_motion.h): one kernel a
   step moves it, sums the contacts and takes its new force, and nothing comes back to the
   host but at outputs, re-neighboring, the end of the run and steps that need the virial.
   On several ranks the sums meet in an MPI_Allreduce and the wall moves on the host.
------------------------------------------------------------------------- */

#ifndef PW_FIX_WALL_STRESS_KOKKOS_H
#define PW_FIX_WALL_STRESS_KOKKOS_H

#include "fix_wall_stress.h"
#include "kokkos_grains.h"
#include "kokkos_type.h"

namespace porewater {
// the wall on the device, and the first step at which it left the box
struct WallOnDevice {
  WallState wall;
  double virial_zz;          // this rank's zz virial of the last contacts
  int verdict;               // WALL_IN_BOX, or the first other wall_verdict
  long long verdict_step;
  WallState at_verdict;
  WallBox box_at_verdict;
};
}    // namespace porewater

namespace LAMMPS_NS {

template <class DeviceType> class FixWallStressKokkos : public FixWallStress {
 public:
  FixWallStressKokkos(class LAMMPS *, int, char **);
  void setup(int) override;
  void pre_neighbor() override;
  void initial_integrate(int) override;
  void post_force(int) override;
  void final_integrate() override;
  void post_run() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void *extract(const char *, int &) override;
  void write_restart(FILE *) override;

 protected:
  void grain_contacts(double *sums) override;

 private:
  bool on_device;       // this run's wall lives on the device (one rank)
  bool half_step;       // the device's velocity is the half-step one; its final kick is due
  bool step_done;       // final_integrate has passed since: the host sees the final kick
  bool host_current;    // the host's wall is the device's
  porewater::DeviceState<porewater::WallOnDevice, DeviceType> state;
  Kokkos::View<double *, DeviceType> d_totals;    // the kernel's sums (read by its final)
  void pull();    // the device's wall to the host's, its final kick applied when past; checks
};

}    // namespace LAMMPS_NS

#endif
