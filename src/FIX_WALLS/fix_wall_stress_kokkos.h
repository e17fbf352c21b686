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
#include "kokkos_fused_pass.h"
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

struct KokkosNoPerAtomVirial {    // the KOKKOS fix keeps the global virial only
  KOKKOS_INLINE_FUNCTION void operator()(int, double) const {}
};

// The wall's step on the device, a body of kokkos_sum_over_grains_on_device: its motion to
// this step, the contacts with it, then (final, once) its force and its box check
template <class DeviceType> struct KokkosWallStep {
  static constexpr int count = 4;    // WallContacts' sums
  KokkosGrains<DeviceType> grains;
  Kokkos::View<WallOnDevice, DeviceType> state;
  int groupbit;
  double kn, damping, mass, plate_damping;
  int damping_velocity;
  double dt, stress;
  WallBox box;
  long long step;
  bool final_kick_due;    // the last step's final_integrate

  // where initial_integrate puts the wall: every grain and the final compute the same
  KOKKOS_INLINE_FUNCTION WallState moved() const
  {
    WallState w = state().wall;
    if (final_kick_due) wall_kick(w, dt, mass);
    wall_initial_integrate(w, dt, mass);
    return w;
  }
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double *sums) const
  {
    const WallState w = moved();
    WallContacts<KokkosGrains<DeviceType>, KokkosNoPerAtomVirial>{
        grains, KokkosNoPerAtomVirial(), groupbit, w.z, w.v, kn, damping, damping_velocity}(i, sums);
  }
  KOKKOS_INLINE_FUNCTION void final(double *sums) const
  {
    WallOnDevice &s = state();
    WallState w = moved();
    wall_post_force(w, sums[0], sums[1], sums[3], stress, box.area, plate_damping);
    s.wall = w;
    s.virial_zz = sums[2];
    const int verdict = wall_verdict(w, box);
    if (verdict != WALL_IN_BOX && s.verdict == WALL_IN_BOX) {
      s.verdict = verdict;
      s.verdict_step = step;
      s.at_verdict = w;
      s.box_at_verdict = box;
    }
  }
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

  // fix nve/sphere/bed/kk's fused pass: while the wall steps on the device, its kernel
  // body of this step may run in that pass, which stamps the step
  bool steps_on_device() const { return on_device; }
  porewater::KokkosWallStep<DeviceType> step_kernel();
  porewater::PassStamp &pass_stamp() { return stepped_in_pass; }

 protected:
  void grain_contacts(double *sums) override;
  void sync_for_variables() override;

 private:
  bool on_device;       // this run's wall lives on the device (one rank)
  bool half_step;       // the device's velocity is the half-step one; its final kick is due
  bool step_done;       // final_integrate has passed since: the host sees the final kick
  bool host_current;    // the host's wall is the device's
  porewater::PassStamp stepped_in_pass;    // the step whose kernel ran in the fused pass
  porewater::DeviceState<porewater::WallOnDevice, DeviceType> state;
  Kokkos::View<double *, DeviceType> d_totals;    // the kernel's sums (read by its final)
  void pull();    // the device's wall to the host's, its final kick applied when past; checks
};

}    // namespace LAMMPS_NS

#endif
