/* ----------------------------------------------------------------------
   fix wall/stress (see doc/fix_wall_stress.rst)

   The wall moves by velocity Verlet in step with the grains:
     initial_integrate  v_w += ½Δt F_w/M,  z_w += Δt v_w
     post_force         grain–wall contacts at the new z_w; F_w = Σ contact forces − S(t)·L_x·L_y
     final_integrate    v_w += ½Δt F_w/M
------------------------------------------------------------------------- */

#include "fix_wall_stress.h"

#include "keyword_values.h"
#include "wall_stress_contact.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "input.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
enum { BOUNDARY_SHRINK = 2 };    // Domain::boundary value of `s`
}

/* ----------------------------------------------------------------------
   fix ID group wall/stress z Z0|auto stress S|v_name mass M kn KN [damping GAMMA]
------------------------------------------------------------------------- */

FixWallStress::FixWallStress(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), z_wall(0.0), v_wall(0.0), wall_force(0.0), grain_force(0.0),
    applied_stress(0.0), spring_energy(0.0), z_auto(0), wall_mass(0.0), kn(0.0), gamma(0.0),
    stress_value(0.0), stress_var_name(nullptr), stress_var(-1)
{
  bool have_z = false, have_stress = false, have_mass = false, have_kn = false;
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (iarg + 2 > narg)
      error->all(FLERR, "Illegal fix wall/stress command: keyword {} needs a value", key);
    const char *value = arg[iarg + 1];
    if (key == "z") {
      z_auto = strcmp(value, "auto") == 0;
      if (!z_auto) z_wall = porewater::keyword_number(lmp, "wall/stress", key, value, " or auto");
      have_z = true;
    } else if (key == "stress") {
      if (utils::strmatch(value, "^v_")) {
        stress_var_name = utils::strdup(value + 2);
      } else {
        stress_value = porewater::keyword_number(lmp, "wall/stress", key, value, " or v_name");
      }
      have_stress = true;
    } else if (key == "mass") {
      wall_mass = porewater::keyword_number(lmp, "wall/stress", key, value);
      if (wall_mass <= 0.0) error->all(FLERR, "Illegal fix wall/stress command: mass must be > 0");
      have_mass = true;
    } else if (key == "kn") {
      kn = porewater::keyword_number(lmp, "wall/stress", key, value);
      if (kn <= 0.0) error->all(FLERR, "Illegal fix wall/stress command: kn must be > 0");
      have_kn = true;
    } else if (key == "damping") {
      gamma = porewater::keyword_number(lmp, "wall/stress", key, value);
      if (gamma < 0.0) error->all(FLERR, "Illegal fix wall/stress command: damping must be >= 0");
    } else {
      error->all(FLERR,
                 "Illegal fix wall/stress keyword: {} (allowed: z, stress, mass, kn, damping)",
                 key);
    }
    iarg += 2;
  }
  if (!have_z || !have_stress || !have_mass || !have_kn)
    error->all(FLERR, "Illegal fix wall/stress command: z, stress, mass and kn are all required");
  if (!atom->sphere_flag) error->all(FLERR, "Fix wall/stress requires atom_style sphere");
  if (domain->dimension != 3) error->all(FLERR, "Fix wall/stress requires a 3d simulation");
  if (domain->zperiodic)
    error->all(FLERR, "Fix wall/stress needs a z-bounded box: boundary f, fm or fs in z, not p");

  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 4;
  global_freq = 1;
  extscalar = 1;
  extvector = 0;
  energy_global_flag = 1;
  virial_global_flag = virial_peratom_flag = 1;
  restart_global = 1;
}

FixWallStress::~FixWallStress()
{
  if (copymode) return;
  delete[] stress_var_name;
}

int FixWallStress::setmask()
{
  return INITIAL_INTEGRATE | POST_FORCE | FINAL_INTEGRATE;
}

void FixWallStress::init()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix wall/stress does not support run_style respa");
  if (stress_var_name) {
    stress_var = input->variable->find(stress_var_name);
    if (stress_var < 0)
      error->all(FLERR, "Fix wall/stress: variable {} for stress does not exist", stress_var_name);
    if (!input->variable->equalstyle(stress_var))
      error->all(FLERR, "Fix wall/stress: variable {} for stress must be equal-style",
                 stress_var_name);
  }
  warn_if_damping_unstable();
}

// The explicit dashpot on a grain is stable only for damping·Δt/m < 2; near that bound the
// contact chatters, so warn well before it.
void FixWallStress::warn_if_damping_unstable()
{
  if (gamma <= 0.0 || !atom->rmass) return;
  double mass_min = std::numeric_limits<double>::infinity();
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) mass_min = std::min(mass_min, atom->rmass[i]);
  double mass_min_all = mass_min;
  MPI_Allreduce(&mass_min, &mass_min_all, 1, MPI_DOUBLE, MPI_MIN, world);
  const double ratio = gamma * update->dt / mass_min_all;
  if (ratio > 0.5 && comm->me == 0)
    error->warning(FLERR,
                   "Fix wall/stress: damping {} with timestep {} and lightest grain mass {} gives "
                   "damping*dt/m = {:.3g}; the explicit dashpot chatters above ~0.5 and is "
                   "unstable above 2: lower damping or the timestep",
                   gamma, update->dt, mass_min_all, ratio);
}

void FixWallStress::setup(int vflag)
{
  if (z_auto) {
    double top = highest_grain_top();
    double top_all = 0.0;
    MPI_Allreduce(&top, &top_all, 1, MPI_DOUBLE, MPI_MAX, world);
    if (top_all == -std::numeric_limits<double>::infinity())
      error->all(FLERR, "Fix wall/stress: z auto needs grains in group {}", group->names[igroup]);
    z_wall = top_all;
    z_auto = 0;
  }
  post_force(vflag);
}

/* ---------------------------------------------------------------------- */

void FixWallStress::initial_integrate(int /*vflag*/)
{
  const double dt = update->dt;
  v_wall += 0.5 * dt * wall_force / wall_mass;
  z_wall += dt * v_wall;
}

void FixWallStress::post_force(int vflag)
{
  v_init(vflag);
  applied_stress = current_stress();
  double local[2] = {0.0, 0.0};
  add_contact_forces(local);
  double sums[2];
  MPI_Allreduce(local, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  grain_force = sums[0];
  spring_energy = sums[1];
  wall_force = grain_force - applied_stress * area();
  check_wall_in_box();
}

void FixWallStress::final_integrate()
{
  v_wall += 0.5 * update->dt * wall_force / wall_mass;
}

/* ---------------------------------------------------------------------- */

double FixWallStress::highest_grain_top()
{
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  double top = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) top = std::max(top, x[i][2] + radius[i]);
  return top;
}

void FixWallStress::add_contact_forces(double *sums)
{
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const porewater::WallContact c =
        porewater::wall_contact(x[i][2], radius[i], v[i][2], z_wall, v_wall, kn, gamma);
    f[i][2] += c.force_z;
    sums[0] -= c.force_z;
    sums[1] += c.energy;
    if (evflag && c.force_z != 0.0) v_tally(2, i, (x[i][2] - z_wall) * c.force_z);
  }
}

double FixWallStress::area() const
{
  return domain->xprd * domain->yprd;
}

double FixWallStress::current_stress()
{
  if (!stress_var_name) return stress_value;
  modify->clearstep_compute();
  const double s = input->variable->compute_equal(stress_var);
  modify->addstep_compute(update->ntimestep + 1);
  return s;
}

// every rank holds the same wall, so every rank reaches the same verdict
void FixWallStress::check_wall_in_box()
{
  if (!std::isfinite(z_wall) || !std::isfinite(v_wall))
    error->all(FLERR, "Fix wall/stress {}: the wall ran away at step {}: z = {}, v = {}", id,
               update->ntimestep, z_wall, v_wall);
  const double bottom = domain->boxlo[2];
  if (z_wall < bottom)
    error->all(FLERR,
               "Fix wall/stress {}: the wall fell to z = {} at step {}, below the box "
               "bottom {} and so through every grain",
               id, z_wall, update->ntimestep, bottom);
  // a shrink-wrapped top follows the grains: allow a gap as high as the box itself
  const double top = domain->boundary[2][1] == BOUNDARY_SHRINK ? domain->boxhi[2] + domain->zprd
                                                               : domain->boxhi[2];
  if (z_wall > top)
    error->all(FLERR,
               "Fix wall/stress {}: the wall rose to z = {} at step {}, above the box top {}", id,
               z_wall, update->ntimestep, top);
}

/* ----------------------------------------------------------------------
   vector: 1 z_wall, 2 v_wall, 3 grain force per area (effective normal stress), 4 applied S
------------------------------------------------------------------------- */

double FixWallStress::compute_scalar()
{
  return spring_energy;
}

double FixWallStress::compute_vector(int n)
{
  switch (n) {
    case 0:
      return z_wall;
    case 1:
      return v_wall;
    case 2:
      return grain_force / area();
    default:
      return applied_stress;
  }
}

void *FixWallStress::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "z_wall") == 0) return &z_wall;
  if (strcmp(name, "v_wall") == 0) return &v_wall;
  return nullptr;
}

/* ----------------------------------------------------------------------
   restart: the wall's position, velocity, last force and whether `auto` is still pending
------------------------------------------------------------------------- */

void FixWallStress::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    const double state[4] = {z_wall, v_wall, wall_force, (double) z_auto};
    const int size = sizeof(state);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(state, sizeof(double), 4, fp);
  }
}

void FixWallStress::restart(char *buf)
{
  double state[4];
  memcpy(state, buf, sizeof(state));
  z_wall = state[0];
  v_wall = state[1];
  wall_force = state[2];
  z_auto = (int) state[3];
}
