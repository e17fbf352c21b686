/* ----------------------------------------------------------------------
   fix darcy/pressure (see doc/fix_darcy_pressure.rst)

   Every rank holds the whole (small) grid: grains deposit their volume and momentum
   locally, the deposits are summed over ranks, and each rank runs the same solve, so
   the fluid state is identical everywhere and grains need no ghost cells.
------------------------------------------------------------------------- */

#include "fix_darcy_pressure.h"

#include "darcy_output.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
const int RESTART_VERSION = 2;    // 2: the solver state ends with the fluid balance
const int RESTART_HEADER = 14;    // values before the solver state, see write_restart()
const int BLOCK_DEPOSITS = 40;    // per stencil block: 5 quantities at 8 corners
const int BLOCK_GRADIENT = 32;    // per stencil block: 8 corners of 3 components and a pad
}    // namespace

/* ---------------------------------------------------------------------- */

FixDarcyPressure::FixDarcyPressure(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), layout{0}, rho_g{0.0, 0.0, 0.0}, gradient_changed(true),
    fluid_force(nullptr), maxatom(0), blocks{0, 0, 0}, stencils_step(-1), stencils_nlocal(0),
    force_step(-1), force_nlocal(0), started(false), last_fluid_step(0),
    last_solve{true, 0, 0.0, 0.0, -1}, porosity_warned(false), profile_fp(nullptr),
    last_profile_step(-1), last_vtk_step(-1)
{
  if (!atom->sphere_flag) error->all(FLERR, "fix darcy/pressure requires atom_style sphere");
  if (domain->triclinic) error->all(FLERR, "fix darcy/pressure requires an orthogonal box");
  if (!domain->xperiodic || !domain->yperiodic || domain->zperiodic)
    error->all(FLERR, "fix darcy/pressure requires boundaries periodic in x and y and "
               "non-periodic in z (the fluid has a bottom and a top)");
  settings = parse_darcy_fix_settings(lmp, narg, arg);
  const DarcyFixSettings &s = settings;

  // the grid spans the box in x and y and [box bottom, zhi] in z
  geom = porewater::GridGeom{domain->boxlo[0], domain->boxlo[1], domain->boxlo[2],
                             domain->prd[0] / s.grid[0], domain->prd[1] / s.grid[1],
                             (s.zhi - domain->boxlo[2]) / s.grid[2], s.grid[0], s.grid[1], s.grid[2]};
  solver.reset(new porewater::DarcySolver(geom, s.params));
  if (!s.z_top_given) settings.z_top.value = solver->z_grid_top();
  layout = porewater::DepositLayout{solver->ncells()};
  deposits.assign(layout.size(), 0.0);
  blocks = porewater::StencilBlocks{geom.nx, geom.ny, geom.nz};
  block_deposits.assign(BLOCK_DEPOSITS * blocks.count(), 0.0);
  block_gradient.assign(BLOCK_GRADIENT * blocks.count(), 0.0);
  for (int d = 0; d < 3; ++d) rho_g[d] = s.density * s.gravity[d];

  if (comm->me == 0) {
    utils::logmesg(lmp, "fix darcy/pressure {}: {}x{}x{} cells of {:.6g} x {:.6g} x {:.6g}, "
                   "z from {:.6g} to {:.6g}, fluid step every {} step(s)\n", id, s.grid[0],
                   s.grid[1], s.grid[2], geom.dx, geom.dy, geom.dz, geom.zlo,
                   solver->z_grid_top(), s.every);
    if (!s.gravity_given)
      utils::logmesg(lmp, "fix darcy/pressure {}: no gravity keyword: no buoyancy force "
                     "(rho_f V g) on the grains\n", id);
    if (s.profile_every) {
      profile_fp = fopen(s.profile_path.c_str(), "w");
      if (!profile_fp)
        error->one(FLERR, "fix darcy/pressure: cannot open profile file {}: {}", s.profile_path,
                   utils::getsyserror());
      porewater::write_profile_header(profile_fp, id);
    }
  }

  vector_flag = 1;
  size_vector = 11;
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
  if (profile_fp) fclose(profile_fp);
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
  for (DarcyFixSettings::Value *v : {&settings.top, &settings.bottom, &settings.z_top}) {
    if (v->variable.empty()) continue;
    v->ivar = input->variable->find(v->variable.c_str());
    if (v->ivar < 0)
      error->all(FLERR, "fix darcy/pressure: variable {} does not exist", v->variable);
    if (!input->variable->equalstyle(v->ivar))
      error->all(FLERR, "fix darcy/pressure: variable {} is not equal-style", v->variable);
  }
  // the grid was laid over the box when the fix was defined and cannot follow it
  for (int i = 0; i < modify->nfix; ++i)
    if (modify->fix[i]->box_change & (BOX_CHANGE_X | BOX_CHANGE_Y | BOX_CHANGE_SHAPE))
      error->all(FLERR, "fix darcy/pressure cannot be used with fix {}, which changes the box "
                 "in x or y", modify->fix[i]->id);
  const double slack = 1e-12;
  if (std::fabs(domain->boxlo[0] - geom.xlo) > slack * domain->prd[0] ||
      std::fabs(domain->prd[0] - geom.nx * geom.dx) > slack * domain->prd[0] ||
      std::fabs(domain->boxlo[1] - geom.ylo) > slack * domain->prd[1] ||
      std::fabs(domain->prd[1] - geom.ny * geom.dy) > slack * domain->prd[1])
    error->all(FLERR, "fix darcy/pressure: the box changed in x or y since the fix was "
               "defined; the fluid grid cannot follow it");
}

void FixDarcyPressure::setup(int /*vflag*/)
{
  porosity_warned = false;
  if (!started) start_fluid();
  apply_or_hold_fluid_force(true);
  write_output();
}

void FixDarcyPressure::post_force(int /*vflag*/)
{
  const bool fluid_step = update->ntimestep - last_fluid_step >= settings.every;
  if (fluid_step) advance_fluid();
  apply_or_hold_fluid_force(fluid_step);
  write_output();
}

// `interpolate step`: -V grad p at every grain's position every step. `interpolate fluid`:
// only on fluid steps, and again whenever LAMMPS has re-neighbored since (the per-atom
// forces are indexed by local atom, which migrate and are sorted only then); held between.
void FixDarcyPressure::apply_or_hold_fluid_force(bool fluid_step)
{
  const bool held_valid = !settings.interpolate_every_step && force_step >= 0 &&
      force_step >= neighbor->lastcall && force_nlocal == atom->nlocal;
  if (!fluid_step && held_valid) {
    add_held_fluid_force();
    return;
  }
  apply_fluid_force();
  force_step = update->ntimestep;
  force_nlocal = atom->nlocal;
}

void FixDarcyPressure::add_held_fluid_force()
{
  double **f = atom->f;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; ++i)
    for (int d = 0; d < 3; ++d) f[i][d] += fluid_force[i][d];
}

/* ----------------------------------------------------------------------
   the fluid state: the first one, and one fluid step
------------------------------------------------------------------------- */

void FixDarcyPressure::start_fluid()
{
  const DarcyFixSettings &s = settings;
  if (uses_variables()) sync_atoms_to_host();
  const double p_top = evaluate(s.top), p_bottom = s.bottom_dirichlet ? evaluate(s.bottom) : 0.0;
  solver->set_pressure(std::vector<double>(solver->ncells(), s.initial_pressure), p_top, p_bottom);
  deposit_and_sum(0.0);
  update_porosity();
  last_fluid_step = update->ntimestep;
  started = true;
  gradient_changed = true;
}

// Advance p from the last fluid step to now, t: phi and vbar from the grains at t,
// dphi/dt central about t (grains predicted at x + v*interval), boundary values at t.
void FixDarcyPressure::advance_fluid()
{
  const DarcyFixSettings &s = settings;
  const double interval = s.every * update->dt;
  deposit_and_sum(interval);
  update_porosity();
  std::copy(deposits.begin() + layout.predicted_volume(0), deposits.begin() + layout.nonfinite(),
            solver->solid_volume().begin());
  solver->update_dphi_dt(interval);

  if (uses_variables()) sync_atoms_to_host();
  const double p_top = evaluate(s.top), z_top = evaluate(s.z_top);
  const double p_bottom = s.bottom_dirichlet ? evaluate(s.bottom) : 0.0;
  last_solve = solver->step(interval, p_top, z_top, p_bottom);
  last_fluid_step = update->ntimestep;
  gradient_changed = true;
  check_solution();
}

// phi, vbar and k from the deposits of the grains at their current positions
void FixDarcyPressure::update_porosity()
{
  const auto first = deposits.begin();
  std::copy(first + layout.volume(0), first + layout.momentum(0), solver->solid_volume().begin());
  std::copy(first + layout.momentum(0), first + layout.predicted_volume(0),
            solver->solid_momentum().begin());
  solver->update_porosity();
  check_porosity();
}

void FixDarcyPressure::deposit_and_sum(double interval)
{
  std::fill(deposits.begin(), deposits.end(), 0.0);
  deposit_grains(interval);
  sum_deposits();
  const double skipped = deposits[layout.nonfinite()];
  if (skipped > 0.0)
    error->all(FLERR, "fix darcy/pressure: step {}: {} grain(s) of group {} have a non-finite "
               "position or velocity, the first atom ID {}", update->ntimestep, (bigint) skipped,
               group->names[igroup], first_nonfinite_grain());
}

// only on the error path: the smallest ID of a grain of the group with a non-finite x or v
tagint FixDarcyPressure::first_nonfinite_grain()
{
  sync_atoms_to_host();
  double **x = atom->x, **v = atom->v;
  tagint first = MAXTAGINT, first_all = MAXTAGINT;
  for (int i = 0; i < atom->nlocal; ++i) {
    bool finite = true;
    for (int d = 0; d < 3; ++d) finite = finite && std::isfinite(x[i][d]) && std::isfinite(v[i][d]);
    if ((atom->mask[i] & groupbit) && !finite) first = std::min(first, atom->tag[i]);
  }
  MPI_Allreduce(&first, &first_all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  return first_all;
}

// MPI_Reduce + MPI_Bcast rather than MPI_Allreduce: the standard does not promise the same
// rounding on every rank, and the replicated solves (and their error checks) must agree.
void FixDarcyPressure::sum_deposits()
{
  if (comm->nprocs == 1) return;
  double *data = deposits.data();
  MPI_Reduce(comm->me == 0 ? MPI_IN_PLACE : data, data, layout.size(), MPI_DOUBLE, MPI_SUM, 0,
             world);
  MPI_Bcast(data, layout.size(), MPI_DOUBLE, 0, world);
}

// Per grain: the stencil's block and corner weights at x and at x + v*interval, summed
// per block (contiguous adds); the blocks are folded into the cells at the end. Grains
// more than half a cell outside the grid in z deposit into the cells directly.
void FixDarcyPressure::deposit_grains(double interval)
{
  double **x = atom->x, **v = atom->v;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  double *sums = deposits.data();
  const auto add_to_cell = [sums](int slot, double value) { sums[slot] += value; };
  std::fill(block_deposits.begin(), block_deposits.end(), 0.0);
  double *block_sums = block_deposits.data();
  // local copies: the compiler may then keep them in registers across the stores
  const porewater::GridGeom g = geom;
  const porewater::LatticeMap map = porewater::lattice_map(geom);
  const porewater::StencilBlocks grid_blocks = blocks;
  const porewater::DepositLayout slots = layout;
  const int nlocal = atom->nlocal, bit = groupbit;
  // grow with the atoms, never shrink: no allocation in a normal step
  if ((int) grain_block.size() < nlocal) {
    grain_block.resize(atom->nmax);
    grain_weights.resize(8 * (size_t) atom->nmax);
  }
  int *stored_block = grain_block.data();
  double *stored_weights = grain_weights.data();
  for (int i = 0; i < nlocal; ++i) {
    stored_block[i] = -1;
    if (!(mask[i] & bit)) continue;
    const double x0 = x[i][0], x1 = x[i][1], x2 = x[i][2];
    const double v0 = v[i][0], v1 = v[i][1], v2 = v[i][2];
    if (!porewater::grain_is_finite(x0, x1, x2, v0, v1, v2)) {
      sums[slots.nonfinite()] += 1.0;
      continue;
    }
    const double volume = porewater::sphere_volume(radius[i]);
    const porewater::StencilBase at = porewater::stencil_base(map, x0, x1, x2);
    const porewater::StencilBase ahead = porewater::stencil_base(
        map, x0 + v0 * interval, x1 + v1 * interval, x2 + v2 * interval);
    const int block = grid_blocks.block(at), block_ahead = grid_blocks.block(ahead);
    if (block < 0 || block_ahead < 0) {
      porewater::deposit_grain(g, slots, x0, x1, x2, v0, v1, v2, volume, interval,
                               add_to_cell);
      continue;
    }
    double *w = stored_weights + 8 * i, w_ahead[8];
    porewater::corner_weights(at, w);
    porewater::corner_weights(ahead, w_ahead);
    stored_block[i] = block;
    double *sum_at = block_sums + BLOCK_DEPOSITS * block;
    double *sum_ahead = block_sums + BLOCK_DEPOSITS * block_ahead;
    porewater::deposit_corners(w, w_ahead, volume, v0, v1, v2,
                               [sum_at, sum_ahead](int c, int q, double value) {
                                 (q < 4 ? sum_at : sum_ahead)[8 * q + c] += value;
                               });
  }
  fold_block_deposits();
  stencils_step = update->ntimestep;
  stencils_nlocal = nlocal;
}

void FixDarcyPressure::fold_block_deposits()
{
  double *sums = deposits.data();
  for (int block = 0; block < blocks.count(); ++block) {
    const double *from = block_deposits.data() + BLOCK_DEPOSITS * block;
    int idx[8];
    porewater::corner_cells(geom, blocks.base(block), idx);
    for (int c = 0; c < 8; ++c) {
      sums[layout.volume(idx[c])] += from[c];
      for (int d = 0; d < 3; ++d) sums[layout.momentum(idx[c]) + d] += from[8 * (1 + d) + c];
      sums[layout.predicted_volume(idx[c])] += from[32 + c];
    }
  }
}

void FixDarcyPressure::update_block_gradient()
{
  const double *gradient = solver->pressure_gradient().data();
  for (int block = 0; block < blocks.count(); ++block) {
    int idx[8];
    porewater::corner_cells(geom, blocks.base(block), idx);
    porewater::corner_vectors(gradient, idx, block_gradient.data() + BLOCK_GRADIENT * block);
  }
}

// The same interpolation as porewater::fluid_force, from the block's corner gradients.
void FixDarcyPressure::apply_fluid_force()
{
  if (atom->nmax > maxatom) grow_fluid_force(atom->nmax);
  if (gradient_changed) update_block_gradient();
  gradient_changed = false;
  double **x = atom->x, **f = atom->f;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  const double *gradient = solver->pressure_gradient().data();
  const double *corner_gradients = block_gradient.data();
  const double buoyancy[3] = {rho_g[0], rho_g[1], rho_g[2]};
  const porewater::GridGeom g = geom;    // local copies, as in deposit_grains
  const porewater::LatticeMap map = porewater::lattice_map(geom);
  const porewater::StencilBlocks grid_blocks = blocks;
  const int nlocal = atom->nlocal, bit = groupbit;
  // the stencils deposit_grains stored if it ran in this step (a fluid step), else new ones
  const bool stored = stencils_step == update->ntimestep && stencils_nlocal == nlocal;
  stencils_step = -1;
  const int *stored_block = grain_block.data();
  const double *stored_weights = grain_weights.data();
  for (int i = 0; i < nlocal; ++i) {
    double *ff = fluid_force[i];
    if (!(mask[i] & bit)) {
      ff[0] = ff[1] = ff[2] = 0.0;
      continue;
    }
    const double volume = porewater::sphere_volume(radius[i]);
    int block;
    double w[8];
    const double *weights = w;
    if (stored) {
      block = stored_block[i];
      weights = stored_weights + 8 * i;
    } else {
      const porewater::StencilBase at = porewater::stencil_base(map, x[i][0], x[i][1], x[i][2]);
      block = grid_blocks.block(at);
      porewater::corner_weights(at, w);
    }
    if (block >= 0) {
      porewater::fluid_force_from_corners(corner_gradients + BLOCK_GRADIENT * block, buoyancy,
                                          weights, volume, ff);
    } else {
      porewater::fluid_force(g, gradient, buoyancy, x[i][0], x[i][1], x[i][2], volume, ff);
    }
    f[i][0] += ff[0];
    f[i][1] += ff[1];
    f[i][2] += ff[2];
  }
}

void FixDarcyPressure::grow_fluid_force(int nmax)
{
  maxatom = nmax;
  memory->destroy(fluid_force);
  memory->create(fluid_force, maxatom, 3, "darcy/pressure:fluid_force");
  array_atom = fluid_force;
}

/* ---------------------------------------------------------------------- */

bool FixDarcyPressure::uses_variables() const
{
  const DarcyFixSettings &s = settings;
  return !s.top.variable.empty() || !s.z_top.variable.empty() ||
      (s.bottom_dirichlet && !s.bottom.variable.empty());
}

double FixDarcyPressure::evaluate(const DarcyFixSettings::Value &v)
{
  if (v.variable.empty()) return v.value;
  modify->clearstep_compute();
  const double value = input->variable->compute_equal(v.ivar);
  modify->addstep_compute(update->ntimestep + settings.every);
  if (!std::isfinite(value))
    error->all(FLERR, "fix darcy/pressure: step {}: variable {} is {}", update->ntimestep,
               v.variable, value);
  return value;
}

std::string FixDarcyPressure::describe_cell(int cell) const
{
  const int i = cell % geom.nx, j = (cell / geom.nx) % geom.ny, k = cell / (geom.nx * geom.ny);
  return fmt::format("cell ({},{},{}) centred at ({:.6g}, {:.6g}, {:.6g})", i + 1, j + 1, k + 1,
                     geom.xlo + (i + 0.5) * geom.dx, geom.ylo + (j + 0.5) * geom.dy,
                     geom.zlo + (k + 0.5) * geom.dz);
}

// More solid than cell (porosity < 0 before the clamp): cells smaller than grains, or
// strongly overlapping grains. The solve goes on with the clamped porosity.
void FixDarcyPressure::check_porosity()
{
  if (porosity_warned || solver->porosity_min_unclamped() >= 0.0) return;
  porosity_warned = true;
  const std::vector<double> &solid = solver->solid_volume();
  const int worst = (int) (std::max_element(solid.begin(), solid.end()) - solid.begin());
  if (comm->me == 0)
    error->warning(FLERR, "fix darcy/pressure: step {}: {} holds {:.4g} times its volume of "
                   "grains (porosity {:.4g} clamped to {}); is the grid finer than the grains? "
                   "(warned once per run)", update->ntimestep, describe_cell(worst),
                   solid[worst] / porewater::cell_volume(geom),
                   solver->porosity_min_unclamped(), solver->params().porosity_min);
}

void FixDarcyPressure::check_solution()
{
  const std::vector<double> &p = solver->pressure();
  for (int c = 0; c < solver->ncells(); ++c)
    if (!std::isfinite(p[c]))
      error->all(FLERR, "fix darcy/pressure: step {}: pressure {} in {} after the fluid step "
                 "(solver residual {}, {} iterations)", update->ntimestep, p[c], describe_cell(c),
                 last_solve.residual, last_solve.iterations);
  if (!last_solve.converged && !std::isfinite(last_solve.residual))
    error->all(FLERR, "fix darcy/pressure: step {}: the pressure system is not finite (residual "
               "{} in {}): a pressure, boundary value or permeability overflowed",
               update->ntimestep, last_solve.residual,
               last_solve.worst_cell >= 0 ? describe_cell(last_solve.worst_cell) : "no cell");
  if (!last_solve.converged)
    error->all(FLERR, "fix darcy/pressure: step {}: the pressure solve did not converge in {} "
               "iterations: residual {:.4g} > tolerance {:.4g}, largest in {}; raise maxiter or "
               "tol", update->ntimestep, last_solve.iterations, last_solve.residual,
               last_solve.tolerance,
               last_solve.worst_cell >= 0 ? describe_cell(last_solve.worst_cell) : "no cell");
}

void FixDarcyPressure::write_output()
{
  if (comm->me != 0) return;
  const bigint now = update->ntimestep;
  const double time = update->atime + (now - update->atimestep) * update->dt;
  const DarcyFixSettings &s = settings;
  if (s.profile_every && now % s.profile_every == 0 && now != last_profile_step) {
    porewater::write_profile(profile_fp, *solver, now, time);
    last_profile_step = now;
  }
  if (s.vtk_every && now % s.vtk_every == 0 && now != last_vtk_step) {
    const std::string path = fmt::format("{}_{}.vtk", s.vtk_prefix, now);
    if (!porewater::write_vtk(path, *solver, now, time))
      error->one(FLERR, "fix darcy/pressure: cannot write {}: {}", path, utils::getsyserror());
    last_vtk_step = now;
  }
}

/* ----------------------------------------------------------------------
   outputs
------------------------------------------------------------------------- */

double FixDarcyPressure::compute_vector(int n)
{
  const std::vector<double> &p = solver->pressure(), &phi = solver->porosity();
  const int active = solver->active_layers() * geom.nx * geom.ny;
  switch (n) {
    case 0:
    case 1: {
      const std::vector<double> &field = n == 0 ? p : phi;
      double sum = 0.0;
      for (int c = 0; c < active; ++c) sum += field[c];
      return active > 0 ? sum / active : 0.0;
    }
    case 2: {
      double largest = 0.0;
      for (double value : p) largest = std::max(largest, std::fabs(value));
      return largest;
    }
    case 3:
      return last_solve.iterations;
    case 4:
      return last_solve.residual;
    case 5:
      return solver->p_top();
    case 6:
      return solver->balance().residual();
    case 7:
      return solver->balance().stored;
    case 8:
      return solver->balance().boundary;
    case 9:
      return solver->balance().grains;
    case 10:
      return solver->balance().allowance;
    default:
      return 0.0;
  }
}

void *FixDarcyPressure::extract(const char *name, int &dim)
{
  dim = 1;    // flat per-cell arrays, x fastest; vector fields interleave x, y, z
  if (strcmp(name, "pressure") == 0) return (void *) solver->pressure().data();
  if (strcmp(name, "porosity") == 0) return (void *) solver->porosity().data();
  if (strcmp(name, "permeability") == 0) return (void *) solver->permeability().data();
  if (strcmp(name, "mean_velocity") == 0) return (void *) solver->mean_velocity().data();
  if (strcmp(name, "pressure_gradient") == 0) return (void *) solver->pressure_gradient().data();
  return nullptr;
}

double FixDarcyPressure::memory_usage()
{
  // the solver holds about 30 doubles per cell (fields, coefficients, CG work)
  return (double) maxatom * 3 * sizeof(double) +
      (double) (block_deposits.size() + block_gradient.size() + grain_weights.size()) *
          sizeof(double) + (double) grain_block.size() * sizeof(int) +
      (double) (deposits.size() + 30 * solver->ncells()) * sizeof(double);
}

/* ----------------------------------------------------------------------
   restart: [version, grid origin and spacing (6), last fluid step, started, the last
   solve (converged, iterations, residual, tolerance, worst cell), 0 (spare), solver state]
------------------------------------------------------------------------- */

void FixDarcyPressure::write_restart(FILE *fp)
{
  std::vector<double> list = {(double) RESTART_VERSION, geom.xlo, geom.ylo, geom.zlo, geom.dx,
                              geom.dy, geom.dz, (double) last_fluid_step, started ? 1.0 : 0.0,
                              last_solve.converged ? 1.0 : 0.0, (double) last_solve.iterations,
                              last_solve.residual, last_solve.tolerance,
                              (double) last_solve.worst_cell};
  const std::vector<double> state = solver->state();
  list.insert(list.end(), state.begin(), state.end());
  if (comm->me == 0) {
    const int size = (int) (list.size() * sizeof(double));
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list.data(), sizeof(double), list.size(), fp);
  }
}

void FixDarcyPressure::restart(char *buf)
{
  const double *list = (const double *) buf;
  const int version = (int) list[0];
  if (version != RESTART_VERSION && version != 1)
    error->all(FLERR, "fix darcy/pressure: restart data of version {}, expected 1 or {}",
               list[0], RESTART_VERSION);
  // version 1 has no fluid balance (4 values): it restarts from 0
  const size_t state_size = solver->state().size() - (version == 1 ? 4 : 0);
  const double stored[6] = {list[1], list[2], list[3], list[4], list[5], list[6]};
  const double ours[6] = {geom.xlo, geom.ylo, geom.zlo, geom.dx, geom.dy, geom.dz};
  const double length = std::max({domain->prd[0], domain->prd[1], domain->prd[2]});
  bool same = (int) list[RESTART_HEADER] == geom.nx && (int) list[RESTART_HEADER + 1] == geom.ny &&
      (int) list[RESTART_HEADER + 2] == geom.nz;
  for (int d = 0; d < 6; ++d) same = same && std::fabs(stored[d] - ours[d]) <= 1e-12 * length;
  // the state's size follows from nx, ny, nz, checked above
  if (!same || !solver->set_state(std::vector<double>(
                   list + RESTART_HEADER, list + RESTART_HEADER + state_size)))
    error->all(FLERR, "fix darcy/pressure: the grid of the restart file ({}x{}x{} cells of "
               "{:.6g} x {:.6g} x {:.6g} from ({:.6g}, {:.6g}, {:.6g})) differs from this "
               "command's", list[RESTART_HEADER], list[RESTART_HEADER + 1],
               list[RESTART_HEADER + 2], stored[3], stored[4], stored[5], stored[0], stored[1],
               stored[2]);
  last_fluid_step = (bigint) list[7];
  started = list[8] != 0.0;
  last_solve = porewater::StepResult{list[9] != 0.0, (int) list[10], list[11], list[12],
                                     (int) list[13]};
  gradient_changed = true;
}
