/* ----------------------------------------------------------------------
   fix shear/stress (see doc/fix_shear_stress.rst)

   In post_force, after the pair style and the fixes defined before it have added their
   forces, the fix sums the x-forces on the group and replaces each grain's f_x by
   m_i·a_plate with a_plate = (τ L_x L_y + ΣF_x)/M. The integrator then moves every grain
   with the same x-acceleration, so the layer stays rigid under nve/sphere as under
   nve/sphere/ty3. f_y, the torque, v_y and ω are zeroed; f_z is left alone.
------------------------------------------------------------------------- */

#include "fix_shear_stress.h"

#include "grains/host_grains.h"
#include "input/restart_state.h"
#include "lammps_compat.h"
#include "lammps_input.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ----------------------------------------------------------------------
   fix ID group shear/stress tau T mass M
------------------------------------------------------------------------- */

FixShearStress::FixShearStress(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), plate_displacement(0.0), reference_x(0.0), resisting_stress(0.0)
{
  settings = porewater::parse_or_stop(lmp, "fix shear/stress", narg - 3, arg + 3,
                                      porewater::parse_shear_stress);
  if (!porewater::has_sphere_attributes(atom)) error->all(FLERR, "Fix shear/stress requires atom_style sphere");
  if (domain->dimension != 3) error->all(FLERR, "Fix shear/stress requires a 3d simulation");

  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
}

int FixShearStress::setmask()
{
  return POST_FORCE;
}

void FixShearStress::init()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix shear/stress does not support run_style respa");

  // forces added after ours would break the plate's rigidity and miss ΣF_x
  std::string later;
  bool after_this = false;
  for (int i = 0; i < modify->nfix; i++) {
    if (modify->fix[i] == this) {
      after_this = true;
    } else if (after_this && (modify->fmask[i] & POST_FORCE)) {
      later += std::string(" ") + modify->fix[i]->id + " (" + modify->fix[i]->style + ")";
    }
  }
  if (!later.empty() && comm->me == 0)
    error->warning(FLERR,
                   "Fix shear/stress {}: fixes defined after it change forces:{}; their "
                   "x-forces bypass the plate. Define fix shear/stress last",
                   id, later);
}

void FixShearStress::setup(int vflag)
{
  set_velocity_x(plate_velocity());    // one plate, one velocity
  post_force(vflag);
}

/* ---------------------------------------------------------------------- */

void FixShearStress::post_force(int /*vflag*/)
{
  double local[3];
  plate_sums(local);
  double sums[3];
  MPI_Allreduce(local, sums, 3, MPI_DOUBLE, MPI_SUM, world);
  if (sums[2] <= 0.0)
    error->all(FLERR, "Fix shear/stress {}: group {} has no grains", id, group->names[igroup]);

  const double mean_x = sums[1] / sums[2];
  // a new run (or a restart) carries the displacement on from where it was
  if (update->setupflag) reference_x = mean_x - plate_displacement;
  const double displacement = mean_x - reference_x;
  if (!update->setupflag) check_runaway(displacement - plate_displacement);
  plate_displacement = displacement;
  resisting_stress = -sums[0] / area();

  const double a = porewater::plate_acceleration(settings.tau, area(), sums[0], settings.mass);
  if (!std::isfinite(a))
    error->all(FLERR, "Fix shear/stress {}: plate acceleration {} at step {} is not finite", id, a,
               update->ntimestep);
  move_as_plate(a / force->ftm2v);
}

// bound: half the neighbor skin per step, beyond which contacts could be missed
void FixShearStress::check_runaway(double step_displacement)
{
  const double bound = 0.5 * neighbor->skin;
  if (!(std::fabs(step_displacement) <= bound))
    error->all(FLERR,
               "Fix shear/stress {}: the plate ran away at step {}: it moved {} in one step "
               "(v ≈ {}), more than half the neighbor skin ({})",
               id, update->ntimestep, step_displacement, step_displacement / update->dt, bound);
}

/* ---------------------------------------------------------------------- */

namespace {
porewater::HostGrains<imageint> host_grains(Atom *atom)
{
  return porewater::HostGrains<imageint>{atom->x,     atom->v,      atom->f,
                                         atom->omega, atom->torque, atom->radius,
                                         atom->rmass, atom->mask,   atom->image};
}
}    // namespace

porewater::ImageUnwrap FixShearStress::image_unwrap() const
{
  return porewater::ImageUnwrap{IMGMASK,         IMGMAX,          IMGBITS, IMG2BITS,
                                domain->h[0], domain->h[5], domain->h[4]};
}

void FixShearStress::plate_sums(double *sums)
{
  porewater::sum_over_grains(
      atom->nlocal,
      porewater::PlateSums<porewater::HostGrains<imageint>>{host_grains(atom), groupbit, image_unwrap()},
      sums);
}

void FixShearStress::momentum_sums(double *sums)
{
  porewater::sum_over_grains(
      atom->nlocal, porewater::PlateMomentum<porewater::HostGrains<imageint>>{host_grains(atom), groupbit},
      sums);
}

void FixShearStress::move_as_plate(double force_per_mass)
{
  porewater::for_each_grain(atom->nlocal, porewater::PlateMotion<porewater::HostGrains<imageint>>{
                                              host_grains(atom), groupbit, force_per_mass});
}

void FixShearStress::set_velocity_x(double velocity)
{
  porewater::for_each_grain(atom->nlocal, porewater::PlateVelocity<porewater::HostGrains<imageint>>{
                                              host_grains(atom), groupbit, velocity});
}

/* ---------------------------------------------------------------------- */

double FixShearStress::area() const
{
  return domain->xprd * domain->yprd;
}

double FixShearStress::plate_velocity()
{
  double local[2];
  momentum_sums(local);
  double sums[2];
  MPI_Allreduce(local, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  return sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
}

/* ----------------------------------------------------------------------
   vector: 1 plate velocity, 2 plate displacement, 3 resisting shear stress
------------------------------------------------------------------------- */

double FixShearStress::compute_vector(int n)
{
  switch (n) {
    case 0:
      return plate_velocity();
    case 1:
      return plate_displacement;
    default:
      return resisting_stress;
  }
}

namespace {
const porewater::RestartFormat RESTART{porewater::RestartStyle::ShearStress, 1, "fix shear/stress"};
}

void FixShearStress::write_restart(FILE *fp)
{
  porewater::write_restart_state(lmp, fp, RESTART, {plate_displacement});
}

void FixShearStress::restart(char *buf)
{
  plate_displacement =
      porewater::read_restart_state(lmp, RESTART, buf, 1)[0];
}
