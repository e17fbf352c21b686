/* ----------------------------------------------------------------------
   compute coordination/original (see doc/compute_coordination_original.rst)
------------------------------------------------------------------------- */

#include "compute_coordination_original.h"

#include "analysis/original_contacts.h"
#include "lammps_compat.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;

ComputeCoordinationOriginal::ComputeCoordinationOriginal(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), fixed_groupbit(0), list(nullptr), nmax(0), contacts(nullptr)
{
  if (narg != 5 || strcmp(arg[3], "fixed") != 0)
    error->all(FLERR, "compute coordination/original expects `fixed GROUP-ID` (the group of "
               "the fixed grains: the held base and the shear layer), got {} argument(s)",
               narg - 3);
  const int fixed_group = group->find(arg[4]);
  if (fixed_group < 0)
    error->all(FLERR, "compute coordination/original: fixed: no group named {}", arg[4]);
  fixed_groupbit = group->bitmask[fixed_group];
  if (!atom->radius_flag)
    error->all(FLERR, "compute coordination/original needs the grains' radii (atom_style sphere)");
  scalar_flag = 1;
  extscalar = 0;
  peratom_flag = 1;
  size_peratom_cols = 0;
}

ComputeCoordinationOriginal::~ComputeCoordinationOriginal()
{
  memory->destroy(contacts);
}

void ComputeCoordinationOriginal::init()
{
  if (force->pair == nullptr)
    error->all(FLERR, "compute coordination/original needs a pair style (its neighbour cutoff)");
  if (domain->triclinic)
    error->all(FLERR, "compute coordination/original: the original's box is orthogonal, this one "
               "is triclinic");
  porewater::request_occasional_full_list(neighbor, this, instance_me);
}

void ComputeCoordinationOriginal::init_list(int, NeighList *ptr)
{
  list = ptr;
}

// each grain of the group: its partners the original counts (the core's rule), over a full
// list so that a rank needs no count from another
void ComputeCoordinationOriginal::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(contacts);
    nmax = atom->nmax;
    memory->create(contacts, nmax, "coordination/original:contacts");
    vector_atom = contacts;
  }
  porewater::build_occasional_list(neighbor, list);
  porewater::PeriodicBox box;
  const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  for (int d = 0; d < 3; ++d) {
    box.lo[d] = domain->boxlo[d];
    box.length[d] = domain->prd[d];
    box.periodic[d] = periodic[d] != 0;
  }
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) contacts[i] = 0.0;
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const bool fixed_i = (mask[i] & fixed_groupbit) != 0;
    const int *jlist = list->firstneigh[i];
    int count = 0;
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = jlist[jj] & NEIGHMASK;
      count += porewater::counted_by_original(x[i], x[j], radius[i] + radius[j], fixed_i,
                                              (mask[j] & fixed_groupbit) != 0, box);
    }
    contacts[i] = count;
  }
}

// the mean over the group's grains, the fixed ones counting zero, as the original averages
double ComputeCoordinationOriginal::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  if (invoked_peratom != update->ntimestep) compute_peratom();
  double sum = 0.0;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i)
    if (mask[i] & groupbit) sum += contacts[i];
  MPI_Allreduce(&sum, &scalar, 1, MPI_DOUBLE, MPI_SUM, world);
  const bigint grains = group->count(igroup);
  scalar = grains > 0 ? scalar / grains : 0.0;
  return scalar;
}

double ComputeCoordinationOriginal::memory_usage()
{
  return (double) nmax * sizeof(double);
}
