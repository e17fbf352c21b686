/* ----------------------------------------------------------------------
   fix nve/sphere/bed/kk (see doc/fix_nve_sphere_bed.rst)
------------------------------------------------------------------------- */

#include "fix_nve_sphere_bed_kokkos.h"

#include "fix_darcy_pressure_kokkos.h"
#include "fix_shear_stress_kokkos.h"
#include "fix_wall_stress_kokkos.h"
#include "integrate/bed_pass.h"
#include "kokkos_grains.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "force.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {

// One grain's post_force work of this fix and of those that join its pass, in their order:
// the floor and gravity, the wall's contact, the held fluid force, the plate's sums (of the
// forces so far); then, once on the device, the wall's and the plate's steps
template <class DeviceType> struct BedPass {
  static constexpr int WALL = 0, PLATE = porewater::KokkosWallStep<DeviceType>::count;
  static constexpr int count = PLATE + porewater::KokkosPlateSumsThenStep<DeviceType>::count;
  porewater::BedForces<porewater::KokkosGrains<DeviceType>> bed;
  bool wall_on, held_on, plate_on;
  porewater::KokkosWallStep<DeviceType> wall;
  porewater::KokkosHeldForce<DeviceType> held;
  porewater::KokkosPlateSumsThenStep<DeviceType> plate;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, double *sums) const
  {
    bed(i);
    if (wall_on) wall(i, sums + WALL);
    if (held_on) held(i);
    if (plate_on) plate(i, sums + PLATE);
  }
  KOKKOS_INLINE_FUNCTION void final(double *sums) const
  {
    if (wall_on) wall.final(sums + WALL);
    if (plate_on) plate.final(sums + PLATE);
  }
};

// the plate's motion of the layer's grains (shear/stress's last post_force work), then the
// final kick: what the two kernels did to each grain, in one
template <class DeviceType> struct PlateMotionThenKick {
  porewater::KokkosPlateMotion<DeviceType> motion;
  porewater::BedFinal<porewater::KokkosGrains<DeviceType>> kick;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const
  {
    motion(i);
    kick(i);
  }
};

}    // namespace

template <class DeviceType>
FixNVESphereBedKokkos<DeviceType>::FixNVESphereBedKokkos(LAMMPS *lmp, int narg, char **arg) :
    FixNVESphereBed(lmp, narg, arg), pass_wall(nullptr), pass_darcy(nullptr), pass_plate(nullptr),
    pass_found(false), moves_plate(false), d_totals("nve/sphere/bed:pass totals", BedPass<DeviceType>::count)
{
  kokkosable = 1;
  atomKK = (AtomKokkos *) atom;
  execution_space = ExecutionSpaceFromDevice<DeviceType>::space;
  datamask_read = EMPTY_MASK;    // synced in the hooks themselves
  datamask_modify = EMPTY_MASK;
}

// the fixes may have changed between runs; those that join decide at their setup whether
// they step on the device, after this one's
template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::setup(int vflag)
{
  pass_found = moves_plate = false;
  FixNVESphereBed::setup(vflag);
}

template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::initial_integrate(int)
{
  atomKK->sync(execution_space, X_MASK | V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK |
                                    RMASS_MASK | RADIUS_MASK | MASK_MASK);
  using G = porewater::KokkosGrains<DeviceType>;
  porewater::kokkos_for_each_grain<DeviceType>(
      atom->nlocal, porewater::BedInitial<G>{G(atomKK), groupbit, heldbit,
                                             porewater::verlet_steps(update->dt, force->ftm2v)});
  atomKK->modified(execution_space, X_MASK | V_MASK | OMEGA_MASK);
}

// On one rank, the post_force fixes right after this one that keep their state on the
// device: a wall/stress/kk, then a darcy/pressure/kk, then a shear/stress/kk, each optional;
// any other post_force fix ends the list (its forces must come in their place)
template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::find_pass()
{
  pass_wall = nullptr;
  pass_darcy = nullptr;
  pass_plate = nullptr;
  pass_found = true;
  moves_plate = false;
  if (comm->nprocs != 1) return;
  int k = 0, first_final = -1;
  for (int j = 0; j < modify->nfix && first_final < 0; ++j)
    if (modify->fmask[j] & FixConst::FINAL_INTEGRATE) first_final = j;
  while (k < modify->nfix && modify->fix[k] != this) ++k;
  int next = 0;    // the place the next fix may take: 0 wall, 1 fluid, 2 plate
  for (++k; k < modify->nfix && next < 3; ++k) {
    if (!(modify->fmask[k] & FixConst::POST_FORCE)) continue;
    Fix *fix = modify->fix[k];
    auto *wall = dynamic_cast<FixWallStressKokkos<DeviceType> *>(fix);
    auto *darcy = dynamic_cast<FixDarcyPressureKokkos<DeviceType> *>(fix);
    auto *plate = dynamic_cast<FixShearStressKokkos<DeviceType> *>(fix);
    if (wall && next == 0 && wall->steps_on_device()) {
      pass_wall = wall;
      next = 1;
    } else if (darcy && next <= 1) {
      pass_darcy = darcy;
      next = 2;
    } else if (plate && plate->steps_on_device()) {
      pass_plate = plate;
      next = 3;
    } else {
      break;
    }
  }
  // the layer's motion, the last post_force work, then waits only for this fix's kick
  if (!pass_plate || modify->fix[first_final] != this) return;
  for (; k < modify->nfix; ++k)
    if (modify->fmask[k] & FixConst::POST_FORCE) return;
  moves_plate = true;
  pass_plate->leave_motion_to_final_integrate();
}

// the pass of this step: the fluid joins on steps that only add its held force, and the
// plate only when every fix before it has joined (its sums are of all their forces)
template <class DeviceType> bool FixNVESphereBedKokkos<DeviceType>::run_pass()
{
  if (update->setupflag) return false;    // each fix adds its setup forces itself
  if (!pass_found) find_pass();
  BedPass<DeviceType> pass{};
  pass.wall_on = pass_wall != nullptr;
  pass.held_on = pass_darcy && pass_darcy->only_holds_force_now();
  pass.plate_on = pass_plate && (!pass_darcy || pass.held_on);
  if (!pass.wall_on && !pass.held_on && !pass.plate_on) return false;

  using G = porewater::KokkosGrains<DeviceType>;
  atomKK->sync(execution_space,
               X_MASK | V_MASK | F_MASK | RMASS_MASK | RADIUS_MASK | IMAGE_MASK | MASK_MASK);
  pass.bed = porewater::BedForces<G>{G(atomKK), groupbit, gravitybit, settings.floor ? 1 : 0,
                                     settings.z_floor, settings.kn, -settings.gravity};
  if (pass.wall_on) pass.wall = pass_wall->step_kernel();
  if (pass.held_on) pass.held = pass_darcy->held_kernel();
  if (pass.plate_on) pass.plate = pass_plate->sums_kernel();
  porewater::kokkos_sum_over_grains_on_device<DeviceType>("nve/sphere/bed:post_force pass",
                                                          atom->nlocal, pass, d_totals);
  atomKK->modified(execution_space, F_MASK);
  if (pass.wall_on) pass_wall->stepped_in_the_pass();
  if (pass.held_on) pass_darcy->held_in_the_pass();
  if (pass.plate_on) pass_plate->summed_in_the_pass();
  return true;
}

template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::post_force(int)
{
  if (run_pass()) return;
  atomKK->sync(execution_space, X_MASK | F_MASK | RMASS_MASK | RADIUS_MASK | MASK_MASK);
  using G = porewater::KokkosGrains<DeviceType>;
  porewater::kokkos_for_each_grain<DeviceType>(
      atom->nlocal, porewater::BedForces<G>{G(atomKK), groupbit, gravitybit,
                                            settings.floor ? 1 : 0, settings.z_floor,
                                            settings.kn, -settings.gravity});
  atomKK->modified(execution_space, F_MASK);
}

template <class DeviceType> void FixNVESphereBedKokkos<DeviceType>::final_integrate()
{
  atomKK->sync(execution_space,
               V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | RADIUS_MASK | MASK_MASK);
  using G = porewater::KokkosGrains<DeviceType>;
  const porewater::BedFinal<G> kick{G(atomKK), groupbit, heldbit,
                                    porewater::verlet_steps(update->dt, force->ftm2v)};
  if (moves_plate) {
    porewater::kokkos_for_each_grain<DeviceType>(
        atom->nlocal, PlateMotionThenKick<DeviceType>{pass_plate->motion_kernel(), kick});
    atomKK->modified(execution_space, V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK);
  } else {
    porewater::kokkos_for_each_grain<DeviceType>(atom->nlocal, kick);
    atomKK->modified(execution_space, V_MASK | OMEGA_MASK);
  }
}

namespace LAMMPS_NS {
template class FixNVESphereBedKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class FixNVESphereBedKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
