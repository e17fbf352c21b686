/* ----------------------------------------------------------------------
   fix darcy/pressure (see doc/fix_darcy_pressure.rst)

   Every rank holds the whole (small) grid: grains deposit their volume and momentum
   locally, the deposits are summed over ranks, and each rank runs the same solve, so
   the fluid state is identical everywhere and grains need no ghost cells.
------------------------------------------------------------------------- */

#include "fix_darcy_pressure.h"
#include "fix_darcy_pressure_grid.h"

#include "lammps_compat.h"
#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"


using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixDarcyPressure::FixDarcyPressure(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), fluid_force(nullptr), maxatom(0)
{
  const porewater::HostBox box = host_box();
  porewater::or_stop(lmp, [&] {
    porewater::check_darcy_host(porewater::has_sphere_attributes(atom), box);
    return 0;
  });
  const porewater::DarcySettings s = porewater::parse_or_stop(
      lmp, "fix darcy/pressure", narg - 3, arg + 3,
      [&box](porewater::KeywordReader &in) { return porewater::parse_darcy(in, box.lo[2], box.hi[2]); });
  top = porewater::EqualValue(s.top);
  z_top = porewater::EqualValue(s.z_top);
  bottom = porewater::EqualValue(s.bottom);
  // every rank holds the whole grid: the ranks sharing this node's memory hold as many copies
  int ranks_on_node = 1;
#ifndef MPI_STUBS    // LAMMPS' serial MPI stubs (a LAMMPS built without MPI) have no MPI-3
  MPI_Comm node;
  MPI_Comm_split_type(world, MPI_COMM_TYPE_SHARED, comm->me, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &ranks_on_node);
  MPI_Comm_free(&node);
#endif
  fluid = porewater::or_stop(lmp, [&] {
    return std::unique_ptr<porewater::DarcyFluid>(
        new porewater::DarcyFluid(s, porewater::darcy_grid_geom(s, box), id, ranks_on_node));
  });
  if (comm->me == 0) utils::logmesg(lmp, fluid->summary());

  vector_flag = 1;
  size_vector = porewater::DarcyFluid::VECTOR_SIZE;
  global_freq = 1;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 3;
  peratom_freq = 1;
  restart_global = 1;
#if PW_LAMMPS_HAS_GRID3D
  pergrid_flag = 1;
  pergrid_freq = s.every;    // the fields change on fluid steps only
#endif
  time_depend = 1;    // the fluid clock counts timesteps: no reset_timestep
  dynamic_group_allow = 1;
}

FixDarcyPressure::~FixDarcyPressure()
{
  memory->destroy(fluid_force);
}

int FixDarcyPressure::setmask()
{
  return POST_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixDarcyPressure::init()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "fix darcy/pressure does not support run_style respa");
  porewater::LammpsVariables variables(lmp);
  const bool global = !fluid->settings().variables_read_atoms;
  top.resolve(variables, "fix darcy/pressure", "top", global);
  z_top.resolve(variables, "fix darcy/pressure", "ztop", global);
  bottom.resolve(variables, "fix darcy/pressure", "bottom", global);
  // the grid was laid over the box when the fix was defined and cannot follow it
  for (int i = 0; i < modify->nfix; ++i)
    if (modify->fix[i]->box_change & (BOX_CHANGE_X | BOX_CHANGE_Y | BOX_CHANGE_SHAPE))
      error->all(FLERR, "fix darcy/pressure cannot be used with fix {}, which changes the box "
                 "in x or y", modify->fix[i]->id);
  const std::string mismatch = fluid->box_mismatch(host_box());
  if (!mismatch.empty()) error->all(FLERR, mismatch);
}

porewater::HostBox FixDarcyPressure::host_box() const
{
  return porewater::HostBox{{domain->boxlo[0], domain->boxlo[1], domain->boxlo[2]},
                            {domain->boxhi[0], domain->boxhi[1], domain->boxhi[2]},
                            {domain->xperiodic != 0, domain->yperiodic != 0, domain->zperiodic != 0},
                            domain->triclinic != 0};
}

porewater::GrainStep FixDarcyPressure::now() const
{
  const bigint step = update->ntimestep;
  return porewater::GrainStep{step, porewater::simulated_time(update, step), update->dt};
}

void FixDarcyPressure::setup(int /*vflag*/)
{
  fluid->setup(*this, grains(), now());
}

void FixDarcyPressure::post_force(int /*vflag*/)
{
  fluid->post_force(*this, grains(), now());
}

porewater::GrainBackend &FixDarcyPressure::grains()
{
  if (atom->nmax > maxatom) grow_fluid_force(atom->nmax);
  cpu_grains.bind(porewater::coupling_arrays_of(atom, groupbit, fluid_force));
  return cpu_grains;
}

void FixDarcyPressure::grow_fluid_force(int nmax)
{
  maxatom = nmax;
  memory->destroy(fluid_force);
  memory->create(fluid_force, maxatom, 3, "darcy/pressure:fluid_force");
  array_atom = fluid_force;
}

/* ----------------------------------------------------------------------
   what the fluid needs from LAMMPS
------------------------------------------------------------------------- */

// MPI_Reduce + MPI_Bcast rather than MPI_Allreduce: the standard does not promise the same
// rounding on every rank, and the replicated solves (and their error checks) must agree.
void FixDarcyPressure::sum_over_ranks(double *values, int n)
{
  if (comm->nprocs == 1) return;
  MPI_Reduce(comm->me == 0 ? MPI_IN_PLACE : values, values, n, MPI_DOUBLE, MPI_SUM, 0, world);
  MPI_Bcast(values, n, MPI_DOUBLE, 0, world);
}

porewater::BoundaryValues FixDarcyPressure::boundary_values()
{
  if ((top.is_variable() || z_top.is_variable() || bottom.is_variable()) &&
      fluid->settings().variables_read_atoms)
    sync_for_variables();
  const bigint next = update->ntimestep + fluid->settings().every;
  porewater::LammpsVariables variables(lmp);
  return porewater::BoundaryValues{top.evaluate(variables, next), z_top.evaluate(variables, next),
                                   bottom.evaluate(variables, next)};
}

bool FixDarcyPressure::grains_reordered_since(long long step)
{
  return neighbor->lastcall > step;
}

// only on the error path: the smallest ID of a grain of the group with a non-finite x or v
long long FixDarcyPressure::first_nonfinite_grain()
{
  sync_for_nonfinite_check();
  long long first = porewater::first_nonfinite_tag(
      porewater::coupling_arrays_of(atom, groupbit, fluid_force), atom->tag);
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_LONG_LONG, MPI_MIN, world);
  return first;
}

std::string FixDarcyPressure::group_name() const
{
  return group->names[igroup];
}

int FixDarcyPressure::group_bit(const std::string &name)
{
  const int id = group->find(name.c_str());
  return id < 0 ? 0 : group->bitmask[id];
}

void FixDarcyPressure::stop(const std::string &message)
{
  error->all(FLERR, message);
}

void FixDarcyPressure::stop_here(const std::string &message)
{
  error->one(FLERR, message);
}

void FixDarcyPressure::warn(const std::string &message)
{
  if (comm->me == 0) error->warning(FLERR, message);
}

bool FixDarcyPressure::is_root() const
{
  return comm->me == 0;
}

/* ----------------------------------------------------------------------
   outputs and restart
------------------------------------------------------------------------- */

double FixDarcyPressure::compute_vector(int n)
{
  return fluid->vector(n);
}

void *FixDarcyPressure::extract(const char *name, int &dim)
{
  dim = 1;    // flat per-cell arrays, x fastest; vector fields interleave x, y, z
  return (void *) fluid->field(name);
}

double FixDarcyPressure::memory_usage()
{
  return (double) maxatom * 3 * sizeof(double) + cpu_grains.bytes() + fluid->bytes();
}

void FixDarcyPressure::write_restart(FILE *fp)
{
  porewater::write_restart_state(lmp, fp, porewater::DarcyFluid::RESTART, fluid->restart_state());
}

void FixDarcyPressure::restart(char *buf)
{
  int version = 0;
  const std::vector<double> state =
      porewater::read_restart_state(lmp, porewater::DarcyFluid::RESTART, buf, -1, &version);
  porewater::or_stop(lmp, [&] {
    fluid->restore(state, version);
    return 0;
  });
}
