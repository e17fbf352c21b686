// What LAMMPS' fix nve/sphere checks in init, for the package's integrators of finite-size
// spheres (nve/sphere/ty3, nve/sphere/bed): no rRESPA, no grain of zero radius in the group.
#ifndef PW_LAMMPS_SPHERE_INTEGRATOR_H
#define PW_LAMMPS_SPHERE_INTEGRATOR_H

#include "atom.h"
#include "error.h"
#include "lammps.h"
#include "update.h"
#include "utils.h"

#include <mpi.h>

#include <string>

namespace porewater {

// `style` names the fix in the messages, e.g. "Fix nve/sphere/bed"
inline void check_sphere_integrator(LAMMPS_NS::LAMMPS *lmp, int groupbit, const std::string &style)
{
  if (LAMMPS_NS::utils::strmatch(lmp->update->integrate_style, "^respa"))
    lmp->error->all(FLERR, style + " does not support run_style respa");
  const double *radius = lmp->atom->radius;
  const int *mask = lmp->atom->mask;
  int flag = 0;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if ((mask[i] & groupbit) && radius[i] == 0.0) flag = 1;
  int flagall = 0;
  MPI_Allreduce(&flag, &flagall, 1, MPI_INT, MPI_MAX, lmp->world);
  if (flagall) lmp->error->all(FLERR, style + " requires extended particles (radius > 0)");
}

}    // namespace porewater

#endif
