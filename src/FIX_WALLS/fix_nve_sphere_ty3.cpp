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

#include "grains/host_grains.h"
#include "input/restart_state.h"
#include "integrate/taylor3.h"
#include "input/settings.h"
#include "lammps_compat.h"
#include "lammps_input.h"
#include "sphere_integrator.h"

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
  corrector = porewater::parse_or_stop(lmp, "fix nve/sphere/ty3", narg - 3, arg + 3,
                                       porewater::parse_ty3)
                  .corrector;
  if (!porewater::has_sphere_attributes(atom)) error->all(FLERR, "Fix nve/sphere/ty3 requires atom_style sphere");

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
  porewater::check_sphere_integrator(lmp, groupbit, "Fix nve/sphere/ty3");

  // a backward difference over another step size is no jerk: start afresh
  if (update->dt != dt_of_history) forget_history();
}

/* ---------------------------------------------------------------------- */

int FixNVESphereTY3::integrated_count() const
{
  return igroup == atom->firstgroup ? atom->nfirst : atom->nlocal;
}

namespace {
struct HistoryRows {    // grain i's row of the per-atom history
  double **rows;
  double *operator()(int i) const { return rows[i]; }
};
porewater::HostGrains<imageint> host_grains(Atom *atom)
{
  return porewater::HostGrains<imageint>{atom->x,     atom->v,      atom->f,
                                         atom->omega, atom->torque, atom->radius,
                                         atom->rmass, atom->mask,   atom->image};
}
}    // namespace

void FixNVESphereTY3::initial_integrate(int /*vflag*/)
{
  porewater::for_each_grain(integrated_count(),
                            porewater::Ty3Predict<porewater::HostGrains<imageint>, HistoryRows>{
                                host_grains(atom), HistoryRows{history}, groupbit, corrector,
                                update->dt, force->ftm2v});
  dt_of_history = update->dt;
}

void FixNVESphereTY3::final_integrate()
{
  porewater::for_each_grain(integrated_count(),
                            porewater::Ty3Correct<porewater::HostGrains<imageint>, HistoryRows>{
                                host_grains(atom), HistoryRows{history}, groupbit, update->dt,
                                force->ftm2v});
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

namespace {
const porewater::RestartFormat RESTART{porewater::RestartStyle::Ty3, 1, "fix nve/sphere/ty3"};
}

void FixNVESphereTY3::write_restart(FILE *fp)
{
  porewater::write_restart_state(lmp, fp, RESTART, {dt_of_history});
}

void FixNVESphereTY3::restart(char *buf)
{
  dt_of_history =
      porewater::read_restart_state(lmp, RESTART, buf, 1)[0];
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
