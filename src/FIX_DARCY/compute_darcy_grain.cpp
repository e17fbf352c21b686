/* ----------------------------------------------------------------------
   compute darcy/grain (see doc/compute_darcy_grain.rst)
------------------------------------------------------------------------- */

#include "compute_darcy_grain.h"
#include "fix_darcy_pressure.h"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "utils.h"

using namespace LAMMPS_NS;

ComputeDarcyGrain::ComputeDarcyGrain(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), darcy(nullptr), nmax(0), values(nullptr)
{
  if (narg != 4)
    error->all(FLERR, "compute darcy/grain expects the ID of a fix darcy/pressure, got {} "
               "argument(s)", narg - 3);
  fix_id = arg[3];
  peratom_flag = 1;
  size_peratom_cols = 2;
}

ComputeDarcyGrain::~ComputeDarcyGrain()
{
  memory->destroy(values);
}

void ComputeDarcyGrain::init()
{
  const int index = modify->find_fix(fix_id.c_str());
  if (index < 0) error->all(FLERR, "compute darcy/grain: no fix with ID {}", fix_id);
  if (!utils::strmatch(modify->fix[index]->style, "^darcy/pressure"))
    error->all(FLERR, "compute darcy/grain: fix {} is a fix {}, not a fix darcy/pressure", fix_id,
               modify->fix[index]->style);
  darcy = static_cast<FixDarcyPressure *>(modify->fix[index]);
}

// the fields of the fix's last fluid step, as the fix's own outputs report them
void ComputeDarcyGrain::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(values);
    nmax = atom->nmax;
    memory->create(values, nmax, 2, "darcy/grain:values");
    array_atom = values;
  }
  const porewater::DarcyFluid &fluid = darcy->darcy_fluid();
  const porewater::GridGeom &g = fluid.grid().geom;
  const double *pressure = fluid.field("pressure"), *porosity = fluid.field("porosity");
  double **x = atom->x;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    values[i][0] = values[i][1] = 0.0;
    if (!(mask[i] & groupbit)) continue;
    int idx[8];
    double w[8];
    porewater::stencil(g, x[i][0], x[i][1], x[i][2], idx, w);    // one stencil, both fields
    values[i][0] = porewater::interpolate(pressure, 1, idx, w);
    values[i][1] = porewater::interpolate(porosity, 1, idx, w);
  }
}

double ComputeDarcyGrain::memory_usage()
{
  return (double) nmax * 2 * sizeof(double);
}
