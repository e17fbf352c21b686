/* ----------------------------------------------------------------------
   fix wall/stress (see doc/fix_wall_stress.rst)

   The wall moves by velocity Verlet in step with the grains:
     initial_integrate  v_w += ½Δt F_w/M,  z_w += Δt v_w
     post_force         grain–wall contacts at the new z_w; F_w = Σ contact forces − S(t)·L_x·L_y
     final_integrate    v_w += ½Δt F_w/M
------------------------------------------------------------------------- */

#include "fix_wall_stress.h"

#include "grains/host_grains.h"
#include "input/restart_state.h"
#include "walls/wall_contact.h"

#include "lammps_compat.h"
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
    applied_stress(0.0), spring_energy(0.0), z_auto(0)
{
  settings = porewater::parse_or_stop(lmp, "fix wall/stress", narg - 3, arg + 3,
                                      porewater::parse_wall_stress);
  z_wall = settings.z;
  z_auto = settings.z_auto ? 1 : 0;
  stress = porewater::EqualValue(settings.stress);
  if (!porewater::has_sphere_attributes(atom)) error->all(FLERR, "Fix wall/stress requires atom_style sphere");
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

FixWallStress::~FixWallStress() = default;

int FixWallStress::setmask()
{
  return INITIAL_INTEGRATE | POST_FORCE | FINAL_INTEGRATE;
}

void FixWallStress::init()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix wall/stress does not support run_style respa");
  stress.resolve(lmp, "Fix wall/stress", "stress");
  warn_if_damping_unstable();
}

// The explicit dashpot on a grain is stable only for damping·Δt/m < 2; near that bound the
// contact chatters, so warn well before it.
void FixWallStress::warn_if_damping_unstable()
{
  const double gamma = settings.damping;
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
  v_wall += 0.5 * dt * wall_force / settings.mass;
  z_wall += dt * v_wall;
}

void FixWallStress::post_force(int vflag)
{
  v_init(vflag);
  applied_stress = current_stress();
  double local[3];
  contact_sums(local);
  if (evflag && vflag_global) virial[2] += local[2];
  double sums[2];
  MPI_Allreduce(local, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  grain_force = sums[0];
  spring_energy = sums[1];
  wall_force = grain_force - applied_stress * area();
  check_wall_in_box();
}

void FixWallStress::final_integrate()
{
  v_wall += 0.5 * update->dt * wall_force / settings.mass;
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

namespace {
// the CPU fix keeps per-atom virials (Fix::v_tally's per-atom part)
struct PerAtomVirialZZ {
  double **vatom;
  void operator()(int i, double w) const
  {
    if (vatom) vatom[i][2] += w;
  }
};
}    // namespace

void FixWallStress::contact_sums(double *sums)
{
  const porewater::HostGrains<imageint> grains{atom->x,      atom->v,      atom->f,
                                               atom->omega,  atom->torque, atom->radius,
                                               atom->rmass,  atom->mask,   atom->image};
  const porewater::WallContacts<porewater::HostGrains<imageint>, PerAtomVirialZZ> contacts{
      grains,         PerAtomVirialZZ{evflag && vflag_atom ? vatom : nullptr},
      groupbit,       z_wall,
      v_wall,         settings.kn,
      settings.damping};
  porewater::sum_over_grains(atom->nlocal, contacts, sums);
}

double FixWallStress::area() const
{
  return domain->xprd * domain->yprd;
}

double FixWallStress::current_stress()
{
  return stress.evaluate(lmp, update->ntimestep + 1);
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

namespace {
const porewater::RestartFormat RESTART{porewater::RestartStyle::WallStress, 1, "fix wall/stress"};
}

void FixWallStress::write_restart(FILE *fp)
{
  porewater::write_restart_state(lmp, fp, RESTART, {z_wall, v_wall, wall_force, (double) z_auto});
}

void FixWallStress::restart(char *buf)
{
  const std::vector<double> state =
      porewater::read_restart_state(lmp, RESTART, buf, 4);
  z_wall = state[0];
  v_wall = state[1];
  wall_force = state[2];
  z_auto = (int) state[3];
}
