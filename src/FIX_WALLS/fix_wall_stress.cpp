/* ----------------------------------------------------------------------
   fix wall/stress (see doc/fix_wall_stress.rst)

   The wall moves by velocity Verlet in step with the grains (walls/stress_wall.h); this
   fix forwards LAMMPS' integrate and force hooks to it.
------------------------------------------------------------------------- */

#include "fix_wall_stress.h"

#include "grains/host_grains.h"

#include "lammps_compat.h"
#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "neighbor.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
enum { BOUNDARY_SHRINK = 2 };    // Domain::boundary value of `s`
}

/* ----------------------------------------------------------------------
   fix ID group wall/stress z Z0|auto stress S|v_name mass M kn KN [damping GAMMA]
------------------------------------------------------------------------- */

FixWallStress::FixWallStress(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  const porewater::WallStressSettings settings = porewater::parse_or_stop(
      lmp, "fix wall/stress", narg - 3, arg + 3, porewater::parse_wall_stress);
  wall.reset(new porewater::StressWall(settings, id));
  stress = porewater::EqualValue(settings.stress);
  if (!porewater::has_sphere_attributes(atom)) error->all(FLERR, "Fix wall/stress requires atom_style sphere");
  if (domain->dimension != 3) error->all(FLERR, "Fix wall/stress requires a 3d simulation");
  if (domain->zperiodic)
    error->all(FLERR, "Fix wall/stress needs a z-bounded box: boundary f, fm or fs in z, not p");

  scalar_flag = 1;
  vector_flag = 1;
  size_vector = porewater::StressWall::VECTOR_SIZE;
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
  return INITIAL_INTEGRATE | PRE_NEIGHBOR | POST_FORCE | FINAL_INTEGRATE;
}

void FixWallStress::init()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix wall/stress does not support run_style respa");
  porewater::LammpsVariables variables(lmp);
  stress.resolve(variables, "Fix wall/stress", "stress", !wall->settings().variables_read_atoms);
  wall->init(*this, update->dt);
}

void FixWallStress::setup(int vflag)
{
  reach.invalidate();    // a run may start with grains moved, added or sorted
  v_init(vflag);
  wall->setup(*this, update->ntimestep);
}

void FixWallStress::pre_neighbor()
{
  reach.invalidate();
}

void FixWallStress::initial_integrate(int /*vflag*/)
{
  wall->initial_integrate(update->dt);
}

void FixWallStress::post_force(int vflag)
{
  v_init(vflag);
  wall->post_force(*this, update->ntimestep);
}

void FixWallStress::final_integrate()
{
  wall->final_integrate(update->dt);
}

/* ----------------------------------------------------------------------
   what the wall needs from LAMMPS
------------------------------------------------------------------------- */

double FixWallStress::stress_now()
{
  if (stress.is_variable() && wall->settings().variables_read_atoms) sync_for_variables();
  porewater::LammpsVariables variables(lmp);
  return stress.evaluate(variables, update->ntimestep + 1);
}

void FixWallStress::grain_contacts(double *sums)
{
  const auto grains = porewater::grains_of_atom(atom);
  const double z_wall = wall->z(), margin = neighbor->skin;
  if (!reach.valid() || z_wall < reach_wall_z - 0.5 * margin) {
    reach.rebuild(atom->nlocal, [&](int i) {
      return (grains.mask(i) & groupbit) && grains.x(i, 2) + grains.radius(i) > z_wall - margin;
    });
    reach_wall_z = z_wall;
  }
  porewater::sum_over_listed(
      reach,
      wall->contacts(grains, porewater::PerAtomVirialZZ{evflag && vflag_atom ? vatom : nullptr},
                     groupbit),
      sums);
}

void FixWallStress::contact_sums(double *sums)
{
  grain_contacts(sums);
  if (evflag && vflag_global) virial[2] += sums[2];
}

void FixWallStress::sum_over_ranks(double *values, int n)
{
  MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, world);
}

double FixWallStress::max_over_ranks(double value)
{
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, world);
  return value;
}

double FixWallStress::min_over_ranks(double value)
{
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, world);
  return value;
}

double FixWallStress::highest_grain_top()
{
  return porewater::highest_grain_top(porewater::grains_of_atom(atom), atom->nlocal, groupbit);
}

double FixWallStress::lightest_grain()
{
  return porewater::lightest_grain(porewater::grains_of_atom(atom), atom->nlocal, groupbit);
}

porewater::WallBox FixWallStress::box()
{
  return porewater::WallBox{domain->boxlo[2], domain->boxhi[2],
                            domain->boundary[2][1] == BOUNDARY_SHRINK, domain->xprd * domain->yprd};
}

std::string FixWallStress::group_name() const
{
  return group->names[igroup];
}

void FixWallStress::stop(const std::string &message)
{
  error->all(FLERR, message);
}

void FixWallStress::warn(const std::string &message)
{
  if (comm->me == 0) error->warning(FLERR, message);
}

/* ----------------------------------------------------------------------
   outputs and restart
------------------------------------------------------------------------- */

double FixWallStress::compute_scalar()
{
  return wall->scalar();
}

double FixWallStress::compute_vector(int n)
{
  return wall->vector(n, domain->xprd * domain->yprd);
}

void *FixWallStress::extract(const char *name, int &dim)
{
  dim = 0;
  return wall->extract(name);
}

void FixWallStress::write_restart(FILE *fp)
{
  porewater::write_restart_state(lmp, fp, porewater::StressWall::RESTART, wall->restart_state());
}

void FixWallStress::restart(char *buf)
{
  wall->restore(porewater::read_restart_state(lmp, porewater::StressWall::RESTART, buf, 4));
}
