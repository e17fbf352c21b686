/* ----------------------------------------------------------------------
   The fused pass of fix nve/sphere/bed/kk (see fix_nve_sphere_bed_pass_kokkos.h)
------------------------------------------------------------------------- */

#include "fix_nve_sphere_bed_pass_kokkos.h"

#include "fix_darcy_pressure_kokkos.h"
#include "fix_shear_stress_kokkos.h"
#include "fix_wall_stress_kokkos.h"

#include "atom_kokkos.h"
#include "atom_masks.h"
#include "comm.h"
#include "fix.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {

// One grain's post_force work of the bed and of the members joining this step, in their
// order: the floor and gravity, the wall's contact, the held fluid force, the plate's sums
// (of the forces so far); then, once on the device, the wall's and the plate's steps
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

std::string named(const Fix *fix)
{
  return std::string(fix->style) + " " + fix->id;
}

}    // namespace

template <class DeviceType>
BedPassKokkos<DeviceType>::BedPassKokkos(LAMMPS *lmp) :
    lmp(lmp), wall(nullptr), darcy(nullptr), plate(nullptr), moves_plate(false),
    motion_step(-1), d_totals("nve/sphere/bed:pass totals", BedPass<DeviceType>::count)
{
}

template <class DeviceType> std::string BedPassKokkos<DeviceType>::compose(Fix *bed, bool fuse)
{
  Modify *modify = lmp->modify;
  wall = nullptr;
  darcy = nullptr;
  plate = nullptr;
  moves_plate = false;
  motion_step = -1;
  fixes.assign(modify->fix, modify->fix + modify->nfix);
  const std::string head = "fix " + named(bed) + ": ";
  if (!fuse) return head + "fused pass off (fuse no)\n";
  if (lmp->comm->nprocs != 1)
    return head + "no fused pass on " + std::to_string(lmp->comm->nprocs) +
        " ranks (the wall's and the plate's states live on the host there)\n";

  int k = 0, first_final = -1;
  for (int j = 0; j < modify->nfix && first_final < 0; ++j)
    if (modify->fmask[j] & FixConst::FINAL_INTEGRATE) first_final = j;
  while (k < modify->nfix && modify->fix[k] != bed) ++k;
  int next = 0;    // the place the next member may take: 0 wall, 1 fluid, 2 plate
  std::string joined;
  const Fix *breaker = nullptr;    // the post_force fix that ends the list
  for (++k; k < modify->nfix && next < 3; ++k) {
    if (!(modify->fmask[k] & FixConst::POST_FORCE)) continue;
    Fix *fix = modify->fix[k];
    auto *as_wall = dynamic_cast<FixWallStressKokkos<DeviceType> *>(fix);
    auto *as_darcy = dynamic_cast<FixDarcyPressureKokkos<DeviceType> *>(fix);
    auto *as_plate = dynamic_cast<FixShearStressKokkos<DeviceType> *>(fix);
    if (as_wall && next == 0) {
      wall = as_wall;
      joined += ", " + named(fix) + " (the wall's step)";
      next = 1;
    } else if (as_darcy && next <= 1) {
      darcy = as_darcy;
      joined += ", " + named(fix) + " (its held force between fluid steps)";
      next = 2;
    } else if (as_plate) {
      plate = as_plate;
      joined += ", " + named(fix) + " (its sums and step)";
      next = 3;
    } else {
      breaker = fix;
      break;
    }
  }
  // the layer's motion, the last post_force work, then waits only for the bed's kick
  if (plate && modify->fix[first_final] == bed) {
    moves_plate = true;
    for (; k < modify->nfix; ++k)
      if (modify->fmask[k] & FixConst::POST_FORCE) moves_plate = false;
    if (moves_plate) joined += "; the layer's motion in the bed's final_integrate";
  }
  const std::string ends = breaker
      ? "fix " + named(breaker) + ", the next post_force fix, cannot join (its forces come in its place)"
      : "";
  if (joined.empty())
    return head + "no fused pass: " +
        (breaker ? ends : "no wall/stress/kk, darcy/pressure/kk or shear/stress/kk follows it among "
                          "the post_force fixes") +
        "\n";
  return head + "fused pass of post_force with " + joined.substr(2) +
      (breaker ? "; " + ends : "") + "\n";
}

template <class DeviceType> bool BedPassKokkos<DeviceType>::stale() const
{
  const Modify *modify = lmp->modify;
  if ((int) fixes.size() != modify->nfix) return true;
  for (int k = 0; k < modify->nfix; ++k)
    if (fixes[k] != modify->fix[k]) return true;
  return false;
}

// the fluid joins on steps that only add its held force, and the plate's sums only when
// every fix before it has joined (they are sums of all their forces)
template <class DeviceType>
bool BedPassKokkos<DeviceType>::post_force(const porewater::BedForces<Grains> &bed)
{
  const long long step = lmp->update->ntimestep;
  BedPass<DeviceType> pass{};
  pass.bed = bed;
  pass.wall_on = wall && wall->steps_on_device();
  pass.held_on = darcy && darcy->only_holds_force_now();
  pass.plate_on = plate && plate->steps_on_device() && (!wall || pass.wall_on) &&
      (!darcy || pass.held_on);
  if (moves_plate && plate->steps_on_device()) {
    plate->motion_stamp().done(step);
    motion_step = step;
  }
  if (!pass.wall_on && !pass.held_on && !pass.plate_on) return false;

  AtomKokkos *atomKK = (AtomKokkos *) lmp->atom;
  atomKK->sync(ExecutionSpaceFromDevice<DeviceType>::space,
               X_MASK | V_MASK | F_MASK | RMASS_MASK | RADIUS_MASK | IMAGE_MASK | MASK_MASK);
  if (pass.wall_on) pass.wall = wall->step_kernel();
  if (pass.held_on) pass.held = darcy->held_kernel();
  if (pass.plate_on) pass.plate = plate->sums_kernel();
  porewater::kokkos_sum_over_grains_on_device<DeviceType>("nve/sphere/bed:fused post_force",
                                                          lmp->atom->nlocal, pass, d_totals);
  atomKK->modified(ExecutionSpaceFromDevice<DeviceType>::space, F_MASK);
  if (pass.wall_on) wall->pass_stamp().done(step);
  if (pass.held_on) darcy->pass_stamp().done(step);
  if (pass.plate_on) plate->pass_stamp().done(step);
  return true;
}

template <class DeviceType>
bool BedPassKokkos<DeviceType>::final_integrate(const porewater::BedFinal<Grains> &kick)
{
  if (motion_step != lmp->update->ntimestep) return false;
  AtomKokkos *atomKK = (AtomKokkos *) lmp->atom;
  const auto space = ExecutionSpaceFromDevice<DeviceType>::space;
  atomKK->sync(space, V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK | RMASS_MASK | RADIUS_MASK |
                   MASK_MASK);
  porewater::kokkos_for_each_grain<DeviceType>(
      "nve/sphere/bed:plate motion and final kick", lmp->atom->nlocal,
      PlateMotionThenKick<DeviceType>{plate->motion_kernel(), kick});
  atomKK->modified(space, V_MASK | OMEGA_MASK | F_MASK | TORQUE_MASK);
  return true;
}

namespace LAMMPS_NS {
template class BedPassKokkos<LMPDeviceType>;
#ifdef LMP_KOKKOS_GPU
template class BedPassKokkos<LMPHostType>;
#endif
}    // namespace LAMMPS_NS
