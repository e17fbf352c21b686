#include "fix_pwtest_addforce.h"

#include "liggghts_compat.h"

#include "atom.h"
#include "force.h"
#include "group.h"

#include <mpi.h>

#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace porewater_liggghts_test {

FixPwtestAddforce::FixPwtestAddforce(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), pushed_(0.0)
{
  if (narg != 6)
    porewater_liggghts::error_all(lmp, FLERR, "Illegal fix pwtest/addforce command: FX FY FZ");
  for (int d = 0; d < 3; d++) added_[d] = force->numeric(FLERR, arg[3 + d]);
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extscalar = 1;
  extvector = 1;
}

int FixPwtestAddforce::setmask()
{
  return POST_FORCE;
}

void FixPwtestAddforce::init()
{
  porewater_liggghts::print_all(
      lmp, std::string("pwtest/addforce: fix ") + id + " pushes group " + group->names[igroup]);
}

void FixPwtestAddforce::setup(int vflag)
{
  post_force(vflag);
}

void FixPwtestAddforce::post_force(int)
{
  double **f = atom->f;
  const int *mask = atom->mask;
  pushed_ = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int d = 0; d < 3; d++) f[i][d] += added_[d];
    pushed_ += 1.0;
  }
}

double FixPwtestAddforce::compute_scalar()
{
  double total = 0.0;
  MPI_Allreduce(&pushed_, &total, 1, MPI_DOUBLE, MPI_SUM, world);
  return total;
}

double FixPwtestAddforce::compute_vector(int i)
{
  return compute_scalar() * added_[i];
}

}    // namespace porewater_liggghts_test
