/* ----------------------------------------------------------------------
   fix shear/stress (see doc/fix_shear_stress.rst)

   In post_force, after the pair style and the fixes defined before it have added their
   forces, the fix sums the x-forces on the group and replaces each grain's f_x by
   m_i·a_plate with a_plate = (τ L_x L_y + ΣF_x)/M. The integrator then moves every grain
   with the same x-acceleration, so the layer stays rigid under nve/sphere as under
   nve/sphere/ty3. f_y, the torque, v_y and ω are zeroed; f_z is left alone.
------------------------------------------------------------------------- */

#include "fix_shear_stress.h"

#include "keyword_values.h"
#include "shear_plate.h"

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
    Fix(lmp, narg, arg), tau(0.0), plate_mass(0.0), plate_displacement(0.0), reference_x(0.0),
    resisting_stress(0.0)
{
  bool have_tau = false, have_mass = false;
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (iarg + 2 > narg)
      error->all(FLERR, "Illegal fix shear/stress command: keyword {} needs a value", key);
    if (key == "tau") {
      tau = porewater::keyword_number(lmp, "shear/stress", key, arg[iarg + 1]);
      have_tau = true;
    } else if (key == "mass") {
      plate_mass = porewater::keyword_number(lmp, "shear/stress", key, arg[iarg + 1]);
      if (plate_mass <= 0.0)
        error->all(FLERR, "Illegal fix shear/stress command: mass must be > 0");
      have_mass = true;
    } else {
      error->all(FLERR, "Illegal fix shear/stress keyword: {} (allowed: tau, mass)", key);
    }
    iarg += 2;
  }
  if (!have_tau || !have_mass)
    error->all(FLERR, "Illegal fix shear/stress command: tau and mass are both required");
  if (!atom->sphere_flag) error->all(FLERR, "Fix shear/stress requires atom_style sphere");
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
  double local[3] = {0.0, 0.0, 0.0};
  sum_forces_and_positions(local);
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

  const double a = porewater::plate_acceleration(tau, area(), sums[0], plate_mass);
  if (!std::isfinite(a))
    error->all(FLERR, "Fix shear/stress {}: plate acceleration {} at step {} is not finite", id, a,
               update->ntimestep);
  move_as_plate(a);
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

void FixShearStress::sum_forces_and_positions(double *sums)
{
  double **x = atom->x;
  double **f = atom->f;
  const double *rmass = atom->rmass;
  const imageint *image = atom->image;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double unwrapped[3];
    domain->unmap(x[i], image[i], unwrapped);
    sums[0] += f[i][0];
    sums[1] += rmass[i] * unwrapped[0];
    sums[2] += rmass[i];
  }
}

void FixShearStress::sum_momentum(double *sums)
{
  double **v = atom->v;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    sums[0] += rmass[i] * v[i][0];
    sums[1] += rmass[i];
  }
}

void FixShearStress::move_as_plate(double plate_acceleration)
{
  double **v = atom->v;
  double **f = atom->f;
  double **omega = atom->omega;
  double **torque = atom->torque;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  const double to_force = plate_acceleration / force->ftm2v;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    f[i][0] = rmass[i] * to_force;
    f[i][1] = 0.0;
    v[i][1] = 0.0;
    for (int k = 0; k < 3; k++) torque[i][k] = omega[i][k] = 0.0;
  }
}

void FixShearStress::set_velocity_x(double velocity)
{
  double **v = atom->v;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) v[i][0] = velocity;
}

/* ---------------------------------------------------------------------- */

double FixShearStress::area() const
{
  return domain->xprd * domain->yprd;
}

double FixShearStress::plate_velocity()
{
  double local[2] = {0.0, 0.0};
  sum_momentum(local);
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

void FixShearStress::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    const int size = sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(&plate_displacement, sizeof(double), 1, fp);
  }
}

void FixShearStress::restart(char *buf)
{
  memcpy(&plate_displacement, buf, sizeof(double));
}
