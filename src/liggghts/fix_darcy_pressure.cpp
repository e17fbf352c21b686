// fix darcy/pressure for LIGGGHTS (see doc/fix_darcy_pressure.rst, section LIGGGHTS).
//
// Every rank holds the whole (small) grid: grains deposit their volume and momentum
// locally, the deposits are summed over ranks, and each rank runs the same solve.
#include "fix_darcy_pressure.h"

#include "liggghts_input.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace porewater_liggghts {

FixDarcyPressure::FixDarcyPressure(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), fluid_force_(nullptr), maxatom_(0)
{
  const porewater::HostBox box = host_box();
  const porewater::DarcySettings s = or_stop(lmp, [&] {
    porewater::check_darcy_host(atom->sphere_flag != 0, box);
    porewater::KeywordReader in("fix darcy/pressure", narg - 3, arg + 3);
    return porewater::parse_darcy(in, box.lo[2], box.hi[2]);
  });
  top_ = porewater::EqualValue(s.top);
  z_top_ = porewater::EqualValue(s.z_top);
  bottom_ = porewater::EqualValue(s.bottom);
  // every rank holds the whole grid: the ranks sharing this node's memory hold as many copies
  MPI_Comm node;
  MPI_Comm_split_type(world, MPI_COMM_TYPE_SHARED, comm->me, MPI_INFO_NULL, &node);
  int ranks_on_node = 1;
  MPI_Comm_size(node, &ranks_on_node);
  MPI_Comm_free(&node);
  fluid_ = or_stop(lmp, [&] {
    return std::unique_ptr<porewater::DarcyFluid>(
        new porewater::DarcyFluid(s, porewater::darcy_grid_geom(s, box), id, ranks_on_node));
  });
  const std::string summary = fluid_->summary();
  print_all(lmp, summary.substr(0, summary.size() - 1));    // print_all ends the line

  vector_flag = 1;
  size_vector = porewater::DarcyFluid::VECTOR_SIZE;
  global_freq = 1;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 3;
  peratom_freq = 1;
  restart_global = 1;
  time_depend = 1;    // the fluid clock counts timesteps: no reset_timestep
  dynamic_group_allow = 1;
}

FixDarcyPressure::~FixDarcyPressure()
{
  memory->destroy(fluid_force_);
}

int FixDarcyPressure::setmask()
{
  return POST_FORCE;
}

void FixDarcyPressure::init()
{
  if (strncmp(update->integrate_style, "respa", 5) == 0)
    error_all(lmp, FLERR, "fix darcy/pressure does not support run_style respa");
  LiggghtsVariables variables(lmp);
  top_.resolve(variables, "fix darcy/pressure", "top");
  z_top_.resolve(variables, "fix darcy/pressure", "ztop");
  bottom_.resolve(variables, "fix darcy/pressure", "bottom");
  // LIGGGHTS flags a box change only as size or shape: a shape change is refused here, a
  // change of the box in x or y by the grid check of every step
  for (int i = 0; i < modify->nfix; ++i)
    if (modify->fix[i]->box_change_shape)
      error_all(lmp, FLERR, std::string("fix darcy/pressure cannot be used with fix ") +
                modify->fix[i]->id + ", which changes the box in x or y");
  check_box();
}

void FixDarcyPressure::check_box()
{
  const std::string mismatch = fluid_->box_mismatch(host_box());
  if (!mismatch.empty()) error_all(lmp, FLERR, mismatch);
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
  return porewater::GrainStep{step, update->atime + (step - update->atimestep) * update->dt,
                              update->dt};
}

void FixDarcyPressure::setup(int /*vflag*/)
{
  fluid_->setup(*this, grains(), now());
}

void FixDarcyPressure::post_force(int /*vflag*/)
{
  if (domain->box_change) check_box();
  fluid_->post_force(*this, grains(), now());
}

porewater::GrainBackend &FixDarcyPressure::grains()
{
  if (atom->nmax > maxatom_) {
    maxatom_ = atom->nmax;
    memory->destroy(fluid_force_);
    memory->create(fluid_force_, maxatom_, 3, "darcy/pressure:fluid_force");
    array_atom = fluid_force_;
  }
  grains_.bind(porewater::coupling_arrays_of(atom, groupbit, fluid_force_));
  return grains_;
}

/* ----------------------------------------------------------------------
   what the fluid needs from LIGGGHTS
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
  const bigint next = update->ntimestep + fluid_->settings().every;
  LiggghtsVariables variables(lmp);
  return porewater::BoundaryValues{top_.evaluate(variables, next), z_top_.evaluate(variables, next),
                                   bottom_.evaluate(variables, next)};
}

// LIGGGHTS migrates, sorts and inserts grains only right before a neighbor list build
bool FixDarcyPressure::grains_reordered_since(long long step)
{
  return neighbor->lastcall > step;
}

long long FixDarcyPressure::first_nonfinite_grain()
{
  long long first = porewater::first_nonfinite_tag(
      porewater::coupling_arrays_of(atom, groupbit, fluid_force_), atom->tag);
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
  error_all(lmp, FLERR, message);
}

void FixDarcyPressure::stop_here(const std::string &message)
{
  error_one(lmp, FLERR, message);
}

void FixDarcyPressure::warn(const std::string &message)
{
  if (comm->me == 0) error->warning(FLERR, message.c_str());
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
  return fluid_->vector(n);
}

void *FixDarcyPressure::extract(const char *name, int &dim)
{
  dim = 1;    // flat per-cell arrays, x fastest; vector fields interleave x, y, z
  return (void *) fluid_->field(name);
}

double FixDarcyPressure::memory_usage()
{
  return (double) maxatom_ * 3 * sizeof(double) + grains_.bytes() + fluid_->bytes();
}

void FixDarcyPressure::write_restart(FILE *fp)
{
  write_restart_state(lmp, fp, porewater::DarcyFluid::RESTART, fluid_->restart_state());
}

// called on every rank before init(), when the restart file has a fix of this ID and style
void FixDarcyPressure::restart(char *buf)
{
  int version = 0;
  const std::vector<double> state =
      read_restart_state(lmp, porewater::DarcyFluid::RESTART, buf, -1, &version);
  or_stop(lmp, [&] {
    fluid_->restore(state, version);
    return 0;
  });
}

}    // namespace porewater_liggghts
