/* ----------------------------------------------------------------------
   fix wall/stress/kk (see doc/fix_wall_stress.rst)

   On one rank, from a run's setup (on the host, as the CPU fix) on, the wall lives on the
   device; the end of a run brings a copy to the host. The step's velocity Verlet is the CPU
   fix's, in the same order: the kernel of post_force first applies, as every grain sees it,
   the last step's final kick and this step's initial kick and drift, then sums the
   contacts, and its final (once, on the device) takes the wall's force and stores the
   half-step state; the host's initial_integrate and final_integrate do nothing there.
------------------------------------------------------------------------- */

#include "fix_wall_stress_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "update.h"

using namespace LAMMPS_NS;

template <class DeviceType>
FixWallStressKokkos<DeviceType>::FixWallStressKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixWallStress(lmp, narg, arg), on_device(false), half_step(false), step_done(false),
    host_current(true), state("wall/stress:state"),
    d_totals("wall/stress:totals", porewater::KokkosWallStep<DeviceType>::count)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
  virial_peratom_flag = 0;
}

// the forces of the setup on the host, as the CPU fix; `z auto` reads the grains there once
template <class DeviceType> void FixWallStressKokkos<DeviceType>::setup(int vflag)
{
  if (on_device && !host_current) pull();
  on_device = false;    // the setup's step is the host's
  stepped_in_pass.reset();
  if (wall->placement_pending()) atomKK->sync(Host, X_MASK | RADIUS_MASK | MASK_MASK);
  FixWallStress::setup(vflag);
  on_device = comm->nprocs == 1;
  if (!on_device) return;
  porewater::WallOnDevice fresh{};
  fresh.wall = wall->state();
  fresh.verdict = porewater::WALL_IN_BOX;
  state.push(fresh);
  half_step = step_done = false;
  host_current = true;
}

template <class DeviceType> void FixWallStressKokkos<DeviceType>::pull()
{
  const porewater::WallOnDevice &s = state.pull();
  porewater::WallState w = s.wall;
  if (half_step && step_done) porewater::wall_kick(w, update->dt, wall->settings().mass);
  wall->set_state(w);
  host_current = true;
  if (s.verdict != porewater::WALL_IN_BOX)
    wall->stop_outside_box(*this, s.verdict, s.verdict_step, s.at_verdict, s.box_at_verdict);
}

// re-neighboring waits for the device anyway: a wall that left the box stops the run here
template <class DeviceType> void FixWallStressKokkos<DeviceType>::pre_neighbor()
{
  FixWallStress::pre_neighbor();
  if (on_device && !host_current) pull();
}

template <class DeviceType> void FixWallStressKokkos<DeviceType>::initial_integrate(int vflag)
{
  if (!on_device) FixWallStress::initial_integrate(vflag);
}

template <class DeviceType> void FixWallStressKokkos<DeviceType>::post_force(int vflag)
{
  if (!on_device) {
    FixWallStress::post_force(vflag);
    return;
  }
  v_init(vflag);
  if (!stepped_in_pass.done_at(update->ntimestep)) {
    atomKK->sync(execution_space, X_MASK | V_MASK | F_MASK | RADIUS_MASK | MASK_MASK);
    porewater::kokkos_sum_over_grains_on_device<DeviceType>("wall/stress:step", atom->nlocal,
                                                            step_kernel(), d_totals);
    atomKK->modified(execution_space, F_MASK);
  }
  half_step = true;
  step_done = false;
  host_current = false;
  if (evflag && vflag_global) {    // a step whose pressure is asked for
    pull();
    virial[2] += state.host().virial_zz;
  }
}

template <class DeviceType>
porewater::KokkosWallStep<DeviceType> FixWallStressKokkos<DeviceType>::step_kernel()
{
  const porewater::WallStressSettings &s = wall->settings();
  return porewater::KokkosWallStep<DeviceType>{
      porewater::KokkosGrains<DeviceType>(atomKK), state.device, groupbit, s.kn, s.damping, s.mass,
      s.plate_damping, s.damping_velocity, update->dt, stress_now(), box(), update->ntimestep,
      half_step};
}

template <class DeviceType> void FixWallStressKokkos<DeviceType>::final_integrate()
{
  if (on_device) {
    step_done = true;
    host_current = false;    // a copy read during the step lacks the final kick
  } else {
    FixWallStress::final_integrate();
  }
}

// the host's copy for what reads it between runs; the wall stays on the device for a run
// that skips the setup, whose first kernel applies the final kick this copy shows
template <class DeviceType> void FixWallStressKokkos<DeviceType>::post_run()
{
  if (on_device && !host_current) pull();
}

template <class DeviceType> double FixWallStressKokkos<DeviceType>::compute_scalar()
{
  if (on_device && !host_current) pull();
  return FixWallStress::compute_scalar();
}

template <class DeviceType> double FixWallStressKokkos<DeviceType>::compute_vector(int n)
{
  if (on_device && !host_current) pull();
  return FixWallStress::compute_vector(n);
}

template <class DeviceType> void *FixWallStressKokkos<DeviceType>::extract(const char *name, int &dim)
{
  if (on_device && !host_current) pull();
  return FixWallStress::extract(name, dim);
}

template <class DeviceType> void FixWallStressKokkos<DeviceType>::write_restart(FILE *fp)
{
  if (on_device && !host_current) pull();
  FixWallStress::write_restart(fp);
}

// the setup's and (on several ranks) every step's contacts, summed into the host
template <class DeviceType> void FixWallStressKokkos<DeviceType>::grain_contacts(double *sums)
{
  atomKK->sync(execution_space, X_MASK | V_MASK | F_MASK | RADIUS_MASK | MASK_MASK);
  porewater::kokkos_sum_over_grains<DeviceType>(
      "wall/stress:contacts", atom->nlocal,
      wall->contacts(porewater::KokkosGrains<DeviceType>(atomKK), porewater::KokkosNoPerAtomVirial(),
                     groupbit),
      sums);
  atomKK->modified(execution_space, F_MASK);
}

template <class DeviceType> void FixWallStressKokkos<DeviceType>::sync_for_variables()
{
  porewater::sync_for_host_variables(atomKK);
}

namespace LAMMPS_NS {
template class FixWallStressKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixWallStressKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
