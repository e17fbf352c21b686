/* ----------------------------------------------------------------------
   fix shear/stress/kk (see doc/fix_shear_stress.rst)
------------------------------------------------------------------------- */

#include "fix_shear_stress_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "domain.h"
#include "force.h"
#include "neighbor.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
template <class DeviceType> using Grains = porewater::KokkosGrains<DeviceType>;
}    // namespace

template <class DeviceType>
FixShearStressKokkos<DeviceType>::FixShearStressKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixShearStress(lmp, narg, arg), on_device(false), host_current(true),
    state("shear/stress:state"),
    d_totals("shear/stress:totals", porewater::KokkosPlateSumsThenStep<DeviceType>::count)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;
  datamask_modify = EMPTY_MASK;
}

// the setup's plate on the host, as the CPU fix; then, on one rank, on the device
template <class DeviceType> void FixShearStressKokkos<DeviceType>::setup(int vflag)
{
  if (on_device && !host_current) pull();
  on_device = false;    // the setup's step is the host's
  summed_in_pass.reset();
  motion_in_final.reset();
  FixShearStress::setup(vflag);
  on_device = comm->nprocs == 1;
  if (!on_device) return;
  porewater::PlateOnDevice fresh{};
  fresh.plate = plate->state();
  fresh.verdict = porewater::PLATE_MOVING;
  state.push(fresh);
  host_current = true;
}

template <class DeviceType> void FixShearStressKokkos<DeviceType>::pull()
{
  const porewater::PlateOnDevice &s = state.pull();
  plate->set_state(s.plate);
  host_current = true;
  if (s.verdict != porewater::PLATE_MOVING)
    plate->stop_for(*this, porewater::PlateStepResult{s.verdict, s.verdict_value},
                    porewater::PlateStep{s.verdict_step, update->dt, false});
}

// the kernels run over every grain with its mask tested: no list of the layer's grains;
// re-neighboring waits for the device anyway: a plate that ran away stops the run here
template <class DeviceType> void FixShearStressKokkos<DeviceType>::pre_neighbor()
{
  if (on_device && !host_current) pull();
}

template <class DeviceType> void FixShearStressKokkos<DeviceType>::post_force(int vflag)
{
  if (!on_device) {
    FixShearStress::post_force(vflag);
    return;
  }
  if (!summed_in_pass.done_at(update->ntimestep)) {
    atomKK->sync(execution_space, X_MASK | F_MASK | RMASS_MASK | IMAGE_MASK | MASK_MASK);
    porewater::kokkos_sum_over_grains_on_device<DeviceType>("shear/stress:step", atom->nlocal,
                                                            sums_kernel(), d_totals);
  }
  if (!motion_in_final.done_at(update->ntimestep)) {
    atomKK->sync(execution_space, V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | MASK_MASK);
    porewater::kokkos_for_each_grain<DeviceType>("shear/stress:motion", atom->nlocal,
                                                 motion_kernel());
    atomKK->modified(execution_space, V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK);
  }
  host_current = false;
}

template <class DeviceType>
porewater::KokkosPlateSumsThenStep<DeviceType> FixShearStressKokkos<DeviceType>::sums_kernel()
{
  return porewater::KokkosPlateSumsThenStep<DeviceType>{
      {Grains<DeviceType>(atomKK), groupbit, image_unwrap()}, state.device, area(),
      plate->settings().tau, plate->settings().mass, force_to_velocity(), 0.5 * neighbor_skin(),
      update->ntimestep};
}

template <class DeviceType>
porewater::KokkosPlateMotion<DeviceType> FixShearStressKokkos<DeviceType>::motion_kernel()
{
  return porewater::KokkosPlateMotion<DeviceType>{Grains<DeviceType>(atomKK), groupbit, state.device};
}

// the host's copy for what reads it between runs; the plate stays on the device for a run
// that skips the setup
template <class DeviceType> void FixShearStressKokkos<DeviceType>::post_run()
{
  if (on_device && !host_current) pull();
}

template <class DeviceType> double FixShearStressKokkos<DeviceType>::compute_vector(int n)
{
  if (on_device && !host_current) pull();
  return FixShearStress::compute_vector(n);
}

template <class DeviceType> void FixShearStressKokkos<DeviceType>::write_restart(FILE *fp)
{
  if (on_device && !host_current) pull();
  FixShearStress::write_restart(fp);
}

template <class DeviceType> void FixShearStressKokkos<DeviceType>::plate_sums(double *sums)
{
  atomKK->sync(execution_space, X_MASK | F_MASK | RMASS_MASK | IMAGE_MASK | MASK_MASK);
  porewater::kokkos_sum_over_grains<DeviceType>(
      "shear/stress:sums", atom->nlocal,
      porewater::PlateSums<Grains<DeviceType>>{Grains<DeviceType>(atomKK), groupbit, image_unwrap()},
      sums);
}

template <class DeviceType> void FixShearStressKokkos<DeviceType>::momentum_sums(double *sums)
{
  atomKK->sync(execution_space, V_MASK | RMASS_MASK | MASK_MASK);
  porewater::kokkos_sum_over_grains<DeviceType>(
      "shear/stress:momentum", atom->nlocal,
      porewater::PlateMomentum<Grains<DeviceType>>{Grains<DeviceType>(atomKK), groupbit}, sums);
}

template <class DeviceType>
void FixShearStressKokkos<DeviceType>::move_as_plate(double force_per_mass)
{
  atomKK->sync(execution_space, V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | MASK_MASK);
  porewater::kokkos_for_each_grain<DeviceType>(
      "shear/stress:move", atom->nlocal, porewater::PlateMotion<Grains<DeviceType>>{Grains<DeviceType>(atomKK), groupbit,
                                                               force_per_mass});
  atomKK->modified(execution_space, V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK);
}

template <class DeviceType> void FixShearStressKokkos<DeviceType>::set_velocity_x(double velocity)
{
  atomKK->sync(execution_space, V_MASK | MASK_MASK);
  porewater::kokkos_for_each_grain<DeviceType>(
      "shear/stress:velocity", atom->nlocal, porewater::PlateVelocity<Grains<DeviceType>>{Grains<DeviceType>(atomKK), groupbit,
                                                                 velocity});
  atomKK->modified(execution_space, V_MASK);
}

namespace LAMMPS_NS {
template class FixShearStressKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixShearStressKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
