// fix wall/stress for LIGGGHTS (see doc/fix_wall_stress.rst, section LIGGGHTS).
#include "fix_wall_stress.h"

#include "liggghts_input.h"

#include "grains/host_grains.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace porewater_liggghts {

namespace {
enum { BOUNDARY_SHRINK = 2 };    // Domain::boundary value of `s`
}

// fix ID group wall/stress z Z0|auto stress S|v_name mass M kn KN [damping GAMMA]
FixWallStress::FixWallStress(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  const porewater::WallStressSettings settings = or_stop(lmp, [&] {
    porewater::KeywordReader in("fix wall/stress", narg - 3, arg + 3);
    return porewater::parse_wall_stress(in);
  });
  wall_.reset(new porewater::StressWall(settings, id));
  stress_ = porewater::EqualValue(settings.stress);
  if (!atom->sphere_flag) error_all(lmp, FLERR, "Fix wall/stress requires atom_style sphere");
  if (domain->dimension != 3) error_all(lmp, FLERR, "Fix wall/stress requires a 3d simulation");
  if (domain->zperiodic)
    error_all(lmp, FLERR, "Fix wall/stress needs a z-bounded box: boundary f, fm or fs in z, not p");

  scalar_flag = 1;
  vector_flag = 1;
  size_vector = porewater::StressWall::VECTOR_SIZE;
  global_freq = 1;
  extscalar = 1;
  extvector = 0;
  restart_global = 1;
}

FixWallStress::~FixWallStress() = default;

int FixWallStress::setmask()
{
  return INITIAL_INTEGRATE | POST_FORCE | FINAL_INTEGRATE | THERMO_ENERGY;
}

// fix_modify ID virial yes|no: the wall's zz virial in the pressure (LIGGGHTS adds the virial
// of every fix with virial_flag; off by default, as on LAMMPS)
int FixWallStress::modify_param(int narg, char **arg)
{
  if (strcmp(arg[0], "virial") != 0) return 0;
  if (narg < 2 || (strcmp(arg[1], "yes") != 0 && strcmp(arg[1], "no") != 0))
    error_all(lmp, FLERR, "Illegal fix_modify command: virial expects yes or no");
  virial_flag = strcmp(arg[1], "yes") == 0;
  return 2;
}

void FixWallStress::init()
{
  if (strncmp(update->integrate_style, "respa", 5) == 0)
    error_all(lmp, FLERR, "Fix wall/stress does not support run_style respa");
  LiggghtsVariables variables(lmp);
  stress_.resolve(variables, "Fix wall/stress", "stress");
  wall_->init(*this, update->dt);
}

void FixWallStress::start_virial(int vflag)
{
  if (vflag && virial_flag)
    v_setup(vflag);
  else
    evflag = 0;
}

void FixWallStress::setup(int vflag)
{
  start_virial(vflag);
  wall_->setup(*this, update->ntimestep);
}

void FixWallStress::initial_integrate(int /*vflag*/)
{
  wall_->initial_integrate(update->dt);
}

void FixWallStress::post_force(int vflag)
{
  start_virial(vflag);
  wall_->post_force(*this, update->ntimestep);
}

void FixWallStress::final_integrate()
{
  wall_->final_integrate(update->dt);
}

/* ----------------------------------------------------------------------
   what the wall needs from LIGGGHTS
------------------------------------------------------------------------- */

double FixWallStress::stress_now()
{
  LiggghtsVariables variables(lmp);
  return stress_.evaluate(variables, update->ntimestep + 1);
}

void FixWallStress::contact_sums(double *sums)
{
  porewater::sum_over_grains(
      atom->nlocal,
      wall_->contacts(porewater::grains_of_atom(atom),
                      porewater::PerAtomVirialZZ{evflag && vflag_atom ? vatom : nullptr}, groupbit),
      sums);
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
  error_all(lmp, FLERR, message);
}

void FixWallStress::warn(const std::string &message)
{
  if (comm->me == 0) error->warning(FLERR, message.c_str());
}

/* ----------------------------------------------------------------------
   outputs and restart
------------------------------------------------------------------------- */

double FixWallStress::compute_scalar()
{
  return wall_->scalar();
}

double FixWallStress::compute_vector(int n)
{
  return wall_->vector(n, domain->xprd * domain->yprd);
}

void *FixWallStress::extract(const char *name, int &dim)
{
  dim = 0;
  return wall_->extract(name);
}

void FixWallStress::write_restart(FILE *fp)
{
  write_restart_state(lmp, fp, porewater::StressWall::RESTART, wall_->restart_state());
}

void FixWallStress::restart(char *buf)
{
  wall_->restore(read_restart_state(lmp, porewater::StressWall::RESTART, buf, 4));
}

}    // namespace porewater_liggghts
