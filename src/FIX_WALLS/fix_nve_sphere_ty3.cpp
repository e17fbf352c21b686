/* ----------------------------------------------------------------------
   fix nve/sphere/ty3 (see doc/fix_nve_sphere_ty3.rst)

   Where it sits in LAMMPS' Verlet step, with a = f/m and α = T/I (I = 2/5 m r²):
     initial_integrate  f still holds the forces at x(t): the Taylor step of `sphere`
                        moves x, v and ω to t+Δt using a(t) and a(t−Δt) (the history)
     forces             at the new positions and velocities, as in `sphere`
     final_integrate    only with `corrector yes`: Adams–Moulton correction of v and ω
                        with a(t+Δt)
   Without the corrector this is `sphere`'s scheme step for step.
------------------------------------------------------------------------- */

#include "fix_nve_sphere_ty3.h"

#include "taylor3.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixNVESphereTY3::FixNVESphereTY3(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), corrector(0), ncols(porewater::TY3_COLUMNS), history(nullptr),
    dt_of_history(0.0)
{
  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "corrector") == 0) {
      if (iarg + 2 > narg)
        error->all(FLERR,
                   "Illegal fix nve/sphere/ty3 command: corrector needs a value (yes or no)");
      if (strcmp(arg[iarg + 1], "yes") == 0)
        corrector = 1;
      else if (strcmp(arg[iarg + 1], "no") == 0)
        corrector = 0;
      else
        error->all(FLERR, "Illegal fix nve/sphere/ty3 command: corrector must be yes or no, not {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else {
      error->all(FLERR, "Illegal fix nve/sphere/ty3 keyword: {} (allowed: corrector)", arg[iarg]);
    }
  }
  if (!atom->sphere_flag) error->all(FLERR, "Fix nve/sphere/ty3 requires atom_style sphere");

  time_integrate = 1;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  ncols = corrector ? porewater::TY3_COLUMNS_CORRECTOR : porewater::TY3_COLUMNS;
  maxexchange = ncols;

  FixNVESphereTY3::grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nlocal; i++) FixNVESphereTY3::set_arrays(i);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  dt_of_history = update->dt;
}

FixNVESphereTY3::~FixNVESphereTY3()
{
  if (copymode) return;
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(history);
}

int FixNVESphereTY3::setmask()
{
  int mask = INITIAL_INTEGRATE;
  if (corrector) mask |= FINAL_INTEGRATE;
  return mask;
}

void FixNVESphereTY3::init()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix nve/sphere/ty3 does not support run_style respa");
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  int flag = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && radius[i] == 0.0) flag = 1;
  int flagall = 0;
  MPI_Allreduce(&flag, &flagall, 1, MPI_INT, MPI_MAX, world);
  if (flagall) error->all(FLERR, "Fix nve/sphere/ty3 requires extended particles (radius > 0)");

  // a backward difference over another step size is no jerk: start afresh
  if (update->dt != dt_of_history) forget_history();
}

/* ---------------------------------------------------------------------- */

// step(i, a, alpha) for every local grain of the group, with a = f/m and α = T/I
template <class Step> void FixNVESphereTY3::each_grain(Step step)
{
  double **f = atom->f, **torque = atom->torque;
  const double *rmass = atom->rmass, *radius = atom->radius;
  const int *mask = atom->mask;
  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  const double ftm2v = force->ftm2v;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double a[3], alpha[3];
    porewater::sphere_accelerations(ftm2v, rmass[i], radius[i], f[i], torque[i], a, alpha);
    step(i, a, alpha);
  }
}

void FixNVESphereTY3::initial_integrate(int /*vflag*/)
{
  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  const double dt = update->dt;
  each_grain([&](int i, const double *a, const double *alpha) {
    porewater::ty3_predict_grain(x[i], v[i], omega[i], a, alpha, dt, corrector, history[i]);
  });
  dt_of_history = dt;
}

void FixNVESphereTY3::final_integrate()
{
  double **v = atom->v, **omega = atom->omega;
  const double dt = update->dt;
  each_grain([&](int i, const double *a, const double *alpha) {
    porewater::ty3_correct_grain(v[i], omega[i], a, alpha, dt, history[i]);
  });
}

void FixNVESphereTY3::reset_dt()
{
  if (update->dt != dt_of_history) forget_history();
}

void FixNVESphereTY3::forget_history()
{
  for (int i = 0; i < atom->nlocal; i++)
    history[i][porewater::TY3_STATE] = porewater::TY3_NO_HISTORY;
}

/* ----------------------------------------------------------------------
   global restart state: the step size the per-atom history belongs to
------------------------------------------------------------------------- */

void FixNVESphereTY3::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    const int size = sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(&dt_of_history, sizeof(double), 1, fp);
  }
}

void FixNVESphereTY3::restart(char *buf)
{
  memcpy(&dt_of_history, buf, sizeof(double));
}

/* ----------------------------------------------------------------------
   per-atom history: grown, sorted, migrated and restarted with the atoms
------------------------------------------------------------------------- */

double FixNVESphereTY3::memory_usage()
{
  return (double) atom->nmax * ncols * sizeof(double);
}

void FixNVESphereTY3::grow_arrays(int nmax)
{
  memory->grow(history, nmax, ncols, "nve/sphere/ty3:history");
}

void FixNVESphereTY3::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int m = 0; m < ncols; m++) history[j][m] = history[i][m];
}

void FixNVESphereTY3::set_arrays(int i)
{
  for (int m = 0; m < ncols; m++) history[i][m] = 0.0;    // TY3_STATE = TY3_NO_HISTORY
}

int FixNVESphereTY3::pack_exchange(int i, double *buf)
{
  for (int m = 0; m < ncols; m++) buf[m] = history[i][m];
  return ncols;
}

int FixNVESphereTY3::unpack_exchange(int nlocal, double *buf)
{
  for (int m = 0; m < ncols; m++) history[nlocal][m] = buf[m];
  return ncols;
}

// a restart needs no step increments: the next predictor rebuilds them
int FixNVESphereTY3::pack_restart(int i, double *buf)
{
  buf[0] = porewater::TY3_COLUMNS + 1;    // the count first: other fixes skip over it
  for (int m = 0; m < porewater::TY3_COLUMNS; m++) buf[m + 1] = history[i][m];
  return porewater::TY3_COLUMNS + 1;
}

void FixNVESphereTY3::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < porewater::TY3_COLUMNS; k++) history[nlocal][k] = extra[nlocal][m++];
}

int FixNVESphereTY3::size_restart(int /*nlocal*/)
{
  return porewater::TY3_COLUMNS + 1;
}

int FixNVESphereTY3::maxsize_restart()
{
  return porewater::TY3_COLUMNS + 1;
}
