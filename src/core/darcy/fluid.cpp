#include "darcy/fluid.h"

#include "darcy/output.h"
#include "input/keywords.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <unistd.h>

namespace porewater {

// version 4 records `seepage`; version 3 states (before it) were all seepage pressure
const RestartFormat DarcyFluid::RESTART{RestartStyle::Darcy, 4, "fix darcy/pressure", 3};

namespace {

const int STATE_HEADER = 14;    // values before the solver state, see restart_state()
const int STATE_HEADER_3 = 13;  // the same in format version 3 (no seepage)

const char *seepage_name(int seepage)
{
  return seepage == SEEPAGE_FULL ? "full" : "pressure";
}

// the first non-finite value's index, -1 if all are finite
int first_nonfinite(const std::vector<double> &values)
{
  for (size_t c = 0; c < values.size(); ++c)
    if (!std::isfinite(values[c])) return (int) c;
  return -1;
}

std::string number(double v, int digits = 6)
{
  char text[40];
  std::snprintf(text, sizeof(text), "%.*g", digits, v);
  return text;
}

// a grid whose index arithmetic overflows an int, or that the machine cannot hold, stops
// before anything is allocated or indexed (the settings, checked, for the first member)
const DarcySettings &check_grid_fits(const DarcySettings &s, int copies)
{
  const double cells = (double) s.grid[0] * s.grid[1] * s.grid[2];
  const double blocks = (double) s.grid[0] * s.grid[1] * (s.grid[2] + 1);
  const std::string grid = std::to_string(s.grid[0]) + "x" + std::to_string(s.grid[1]) + "x" +
      std::to_string(s.grid[2]);
  const double largest_index = std::max(6.0 * cells, CouplingGrid::BLOCK_DEPOSITS * blocks + 5.0 * cells);
  if (largest_index > (double) INT_MAX)
    throw InputError("Illegal fix darcy/pressure command: grid " + grid + " has " + number(cells) +
                     " cells; its deposits would need " + number(largest_index) +
                     " array slots, more than an int indexes (" + std::to_string(INT_MAX) + ")");
  const GridGeom geom{0, 0, 0, 1, 1, 1, s.grid[0], s.grid[1], s.grid[2]};
  const double bytes = DarcyFluid::bytes_for(geom), memory = DarcyFluid::machine_memory();
  if (memory > 0.0 && copies * bytes > memory)
    throw InputError("Illegal fix darcy/pressure command: grid " + grid + " has " + number(cells) +
                     " cells and needs " + number(bytes) + " bytes" +
                     (copies > 1 ? " on each of the " + std::to_string(copies) + " ranks of this node"
                                 : std::string()) +
                     ", more than this machine's " + number(memory) + " bytes of memory");
  return s;
}

}    // namespace

void check_darcy_host(bool spheres, const HostBox &box)
{
  if (!spheres) throw InputError("fix darcy/pressure requires atom_style sphere");
  if (box.triclinic) throw InputError("fix darcy/pressure requires an orthogonal box");
  if (!box.periodic[0] || !box.periodic[1] || box.periodic[2])
    throw InputError("fix darcy/pressure requires boundaries periodic in x and y and "
                     "non-periodic in z (the fluid has a bottom and a top)");
}

GridGeom darcy_grid_geom(const DarcySettings &s, const HostBox &box)
{
  const double zlo = box.lo[2];
  return GridGeom{box.lo[0],
                  box.lo[1],
                  zlo,
                  (box.hi[0] - box.lo[0]) / s.grid[0],
                  (box.hi[1] - box.lo[1]) / s.grid[1],
                  (s.zhi - zlo) / s.grid[2],
                  s.grid[0],
                  s.grid[1],
                  s.grid[2]};
}

DarcyFluid::DarcyFluid(const DarcySettings &settings, const GridGeom &geom, const std::string &id,
                       int copies) :
    settings_(check_grid_fits(settings, copies)), grid_(coupling_grid(geom)), id_(id), field_changed_(true),
    stencils_kept_(false), started_(false), last_fluid_step_(0), force_step_(-1),
    last_solve_{true, 0, 0.0, 0.0, -1}, porosity_warned_(false), unsettled_warned_(false),
    profile_(nullptr),
    last_profile_step_(-1), last_vtk_step_(-1), restored_(false)
{
  solver_.reset(new DarcySolver(geom, settings.params));
  if (!settings_.z_top_given) settings_.z_top = NumberOrVariable{solver_->z_grid_top(), ""};
  sums_.assign(grid_.sums_size(), 0.0);
  gradient_table_.assign(grid_.gradient_table_size(), 0.0);
  force_gradient_.assign(3 * (size_t) solver_->ncells(), 0.0);
  field_ = FluidForceField{gradient_table_.data(),
                           force_gradient_.data(),
                           solver_->porosity().data(),
                           {settings.density * settings.gravity[0],
                            settings.density * settings.gravity[1],
                            settings.density * settings.gravity[2]},
                           0};
}

DarcyFluid::~DarcyFluid()
{
  if (profile_) std::fclose(profile_);
}

double DarcyFluid::machine_memory()
{
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? (double) pages * (double) page : 0.0;
}

double DarcyFluid::bytes_for(const GridGeom &geom)
{
  const CouplingGrid grid = coupling_grid(geom);
  return DarcySolver::bytes_for(geom) +
      sizeof(double) * ((double) grid.sums_size() + (double) grid.gradient_table_size());
}

double DarcyFluid::bytes() const
{
  return solver_->bytes() + sizeof(double) * (double) (sums_.capacity() + gradient_table_.capacity());
}

std::string DarcyFluid::summary() const
{
  const GridGeom &g = grid_.geom;
  std::string text = "fix darcy/pressure " + id_ + ": " + std::to_string(g.nx) + "x" +
      std::to_string(g.ny) + "x" + std::to_string(g.nz) + " cells of " + number(g.dx) + " x " +
      number(g.dy) + " x " + number(g.dz) + ", z from " + number(g.zlo) + " to " +
      number(z_grid_top()) + ", fluid step every " + std::to_string(settings_.every) +
      " step(s)\n";
  if (settings_.seepage == SEEPAGE_FULL)
    text += "fix darcy/pressure " + id_ +
        ": seepage full: the grains take -V grad p/(1 - phi), the drag of the flow included\n";
  if (!settings_.gravity_given)
    text += "fix darcy/pressure " + id_ +
        ": no gravity keyword: no buoyancy force (rho_f V g) on the grains\n";
  return text;
}

// the grid was laid over the box when the fix was defined and cannot follow it
std::string DarcyFluid::box_mismatch(const HostBox &box) const
{
  const GridGeom &g = grid_.geom;
  const double slack = 1e-12, lx = box.hi[0] - box.lo[0], ly = box.hi[1] - box.lo[1];
  if (std::fabs(box.lo[0] - g.xlo) > slack * lx || std::fabs(lx - g.nx * g.dx) > slack * lx ||
      std::fabs(box.lo[1] - g.ylo) > slack * ly || std::fabs(ly - g.ny * g.dy) > slack * ly)
    return "fix darcy/pressure: the box changed in x or y since the fix was defined; the fluid "
           "grid cannot follow it";
  return "";
}

/* ---------------------------------------------------------------------- the hooks */

void DarcyFluid::setup(FluidHost &host, GrainBackend &grains, const GrainStep &now)
{
  porosity_warned_ = false;
  unsettled_warned_ = false;
  // `novertical GROUP`, looked up at every setup: groups may be redefined between runs
  if (!settings_.novertical_group.empty()) {
    field_.horizontal_only_bit = host.group_bit(settings_.novertical_group);
    if (!field_.horizontal_only_bit)
      host.stop("fix darcy/pressure " + id_ + ": novertical group " + settings_.novertical_group +
                " does not exist");
  }
  if (host.is_root() && settings_.profile_every && !profile_) {
    bool has_header = false;
    profile_ = settings_.profile_append
        ? continue_profile(settings_.profile_path, now.step, has_header)
        : std::fopen(settings_.profile_path.c_str(), "w");
    if (!profile_)
      host.stop_here("fix darcy/pressure: cannot open profile file " + settings_.profile_path);
    if (!has_header) write_profile_header(profile_, id_);
  }
  if (!started_) start(host, grains, now.step);
  // the restart's step: its outputs are the run's that wrote the file, whose fluid step
  // left the grains' mean velocity that the restart file does not hold
  if (restored_) last_profile_step_ = last_vtk_step_ = now.step;
  restored_ = false;
  apply_or_hold_force(host, grains, now.step, true);
  write_output(host, now.step, now.time);
}

void DarcyFluid::post_force(FluidHost &host, GrainBackend &grains, const GrainStep &now)
{
  const bool fluid_step = is_fluid_step(now.step);
  if (fluid_step) advance(host, grains, now.step, settings_.every * now.dt);
  apply_or_hold_force(host, grains, now.step, fluid_step);
  write_output(host, now.step, now.time);
}

// `interpolate step`: -V grad p at every grain's position every step. `interpolate fluid`:
// only on fluid steps, and again whenever the host has re-ordered its grains since (the
// held forces are per local index); held in between.
bool DarcyFluid::held_force_valid(FluidHost &host) const
{
  return !settings_.interpolate_every_step && force_step_ >= 0 &&
      !host.grains_reordered_since(force_step_);
}

bool DarcyFluid::only_holds_force(FluidHost &host, long long step) const
{
  return !is_fluid_step(step) && held_force_valid(host);
}

void DarcyFluid::apply_or_hold_force(FluidHost &host, GrainBackend &grains, long long step,
                                     bool fluid_step)
{
  if (!fluid_step && held_force_valid(host)) {
    grains.add_held_force();
    return;
  }
  grains.apply_force(grid_, field_, stencils_kept_, field_changed_);
  field_changed_ = false;
  stencils_kept_ = false;
  force_step_ = step;
}

/* ---------------------------------------------------------------------- fluid steps */

void DarcyFluid::start(FluidHost &host, GrainBackend &grains, long long step)
{
  const BoundaryValues b = boundary_values(host, step);
  solver_->set_pressure(std::vector<double>(solver_->ncells(), settings_.initial_pressure),
                        b.p_top, b.p_bottom);
  deposit_and_sum(host, grains, step, 0.0);
  update_porosity(host, step);
  refresh_force_field();
  last_fluid_step_ = step;
  started_ = true;
}

// the force field of the fluid state now: the cells' force gradients (the seepage force's
// factor in them), the corner ones and porosities per block, and the cell porosity
// (update_porosity swaps the solver's porosity arrays)
void DarcyFluid::refresh_force_field()
{
  fill_force_gradient(solver_->ncells(), settings_.seepage, solver_->pressure_gradient().data(),
                      solver_->porosity().data(), force_gradient_.data());
  fill_gradient_table(grid_, force_gradient_.data(), solver_->porosity().data(),
                      gradient_table_.data());
  field_.cell_porosity = solver_->porosity().data();
  field_changed_ = true;
}

// Advance p from the last fluid step to now, t: phi and vbar from the grains at t,
// dphi/dt central about t (grains predicted at x + v*interval), boundary values at t.
void DarcyFluid::advance(FluidHost &host, GrainBackend &grains, long long step, double interval)
{
  deposit_and_sum(host, grains, step, interval);
  update_porosity(host, step);
  const double *cells = sums_.data() + grid_.cell_sums();
  std::copy(cells + grid_.cells.predicted_volume(0), cells + grid_.cells.nonfinite(),
            solver_->solid_volume().begin());
  solver_->update_dphi_dt(interval);

  const BoundaryValues b = boundary_values(host, step);
  last_solve_ = solver_->step(interval, b.p_top, b.z_top, b.p_bottom);
  last_fluid_step_ = step;
  check_solution(host, step);
  refresh_force_field();
}

void DarcyFluid::deposit_and_sum(FluidHost &host, GrainBackend &grains, long long step,
                                 double interval)
{
  std::fill(sums_.begin(), sums_.end(), 0.0);
  grains.deposit(grid_, interval, sums_.data());
  fold_block_deposits(grid_, sums_.data());
  stencils_kept_ = true;
  host.sum_over_ranks(sums_.data() + grid_.cell_sums(), grid_.cells.size());
  const double skipped = sums_[grid_.cell_sums() + grid_.cells.nonfinite()];
  if (skipped > 0.0)
    host.stop("fix darcy/pressure: step " + std::to_string(step) + ": " +
              std::to_string((long long) skipped) + " grain(s) of group " + host.group_name() +
              " have a non-finite "
              "position or velocity, the first atom ID " +
              std::to_string(host.first_nonfinite_grain()));
}

// phi, vbar and k from the deposits of the grains at their current positions; more solid
// than cell (porosity < 0 before the clamp: cells smaller than grains, or strongly
// overlapping grains) is warned about once per run, and the solve goes on clamped
void DarcyFluid::update_porosity(FluidHost &host, long long step)
{
  const double *cells = sums_.data() + grid_.cell_sums();
  std::copy(cells + grid_.cells.volume(0), cells + grid_.cells.momentum(0),
            solver_->solid_volume().begin());
  std::copy(cells + grid_.cells.momentum(0), cells + grid_.cells.predicted_volume(0),
            solver_->solid_momentum().begin());
  solver_->update_porosity();
  if (porosity_warned_ || solver_->porosity_min_unclamped() >= 0.0) return;
  porosity_warned_ = true;
  const std::vector<double> &solid = solver_->solid_volume();
  const int worst = (int) (std::max_element(solid.begin(), solid.end()) - solid.begin());
  host.warn("fix darcy/pressure: step " + std::to_string(step) + ": " + describe_cell(worst) +
            " holds " + number(solid[worst] / cell_volume(grid_.geom), 4) +
            " times its volume of grains (porosity " + number(solver_->porosity_min_unclamped(), 4) +
            " clamped to " + number(settings_.params.porosity_min) +
            "); is the grid finer than the grains? (warned once per run)");
}

BoundaryValues DarcyFluid::boundary_values(FluidHost &host, long long step)
{
  BoundaryValues b = host.boundary_values();
  if (!settings_.z_top_given) b.z_top = solver_->z_grid_top();
  if (!settings_.bottom_dirichlet) b.p_bottom = 0.0;
  const struct {
    const char *keyword;
    const NumberOrVariable &setting;
    double value;
  } values[] = {{"top", settings_.top, b.p_top}, {"ztop", settings_.z_top, b.z_top},
                {"bottom", settings_.bottom, b.p_bottom}};
  for (const auto &v : values)
    if (!std::isfinite(v.value))
      host.stop("fix darcy/pressure: step " + std::to_string(step) + ": " + v.keyword + " (" +
                (v.setting.is_variable() ? "variable " + v.setting.variable : "value") + ") is " +
                number(v.value));
  return b;
}

void DarcyFluid::check_solution(FluidHost &host, long long step)
{
  const std::vector<double> &p = solver_->pressure();
  const StepResult &r = last_solve_;
  const int bad = first_nonfinite(p);
  if (bad < 0 && r.converged) return;    // every fluid step: no message composed
  const std::string at = "fix darcy/pressure: step " + std::to_string(step) + ": ";
  if (bad >= 0)
    host.stop(at + "pressure " + number(p[bad]) + " in " + describe_cell(bad) +
              " after the fluid step (solver residual " + number(r.residual) + ", " +
              std::to_string(r.iterations) + " iterations)");
  const std::string worst = r.worst_cell >= 0 ? describe_cell(r.worst_cell) : "no cell";
  if (!std::isfinite(r.residual))
    host.stop(at + "the pressure system is not finite (residual " + number(r.residual) + " in " +
              worst + "): a pressure, boundary value or permeability overflowed");
  // the original program reports sweeps that do not settle and goes on with the last one
  if (settings_.params.scheme == DarcyParams::Scheme::Relaxed) {
    if (!unsettled_warned_)
      host.warn(at + "the relaxed pressure iteration did not settle in " + std::to_string(r.iterations) +
                " sweeps (largest relative change " + number(r.residual, 4) + " > " +
                number(r.tolerance, 4) + ", in " + worst + "); it goes on with the last sweep, "
                "as the original program did (not reported again in this run)");
    unsettled_warned_ = true;
  } else {
    host.stop(at + "the pressure solve did not converge in " + std::to_string(r.iterations) +
              " iterations: residual " + number(r.residual, 4) + " > tolerance " + number(r.tolerance, 4) +
              ", largest in " + worst + "; raise maxiter or tol");
  }
}

std::string DarcyFluid::describe_cell(int cell) const
{
  const GridGeom &g = grid_.geom;
  const int i = cell % g.nx, j = (cell / g.nx) % g.ny, k = cell / (g.nx * g.ny);
  return "cell (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + "," +
      std::to_string(k + 1) + ") centred at (" + number(g.xlo + (i + 0.5) * g.dx) + ", " +
      number(g.ylo + (j + 0.5) * g.dy) + ", " + number(g.zlo + (k + 0.5) * g.dz) + ")";
}

void DarcyFluid::write_output(FluidHost &host, long long step, double time)
{
  if (!host.is_root()) return;
  const DarcySettings &s = settings_;
  if (s.profile_every && step % s.profile_every == 0 && step != last_profile_step_) {
    write_profile(profile_, *solver_, step, time);
    last_profile_step_ = step;
  }
  if (s.vtk_every && step % s.vtk_every == 0 && step != last_vtk_step_) {
    const std::string path = s.vtk_prefix + "_" + std::to_string(step) + ".vtk";
    if (!write_vtk(path, *solver_, step, time))
      host.stop_here("fix darcy/pressure: cannot write " + path);
    last_vtk_step_ = step;
  }
}

/* ---------------------------------------------------------------------- outputs */

double DarcyFluid::vector(int n) const
{
  const std::vector<double> &p = solver_->pressure(), &phi = solver_->porosity();
  const int active = solver_->active_layers() * grid_.geom.nx * grid_.geom.ny;
  const FluidBalance &balance = solver_->balance();
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
      return last_solve_.iterations;
    case 4:
      return last_solve_.residual;
    case 5:
      return solver_->p_top();
    case 6:
      return balance.residual();
    case 7:
      return balance.stored;
    case 8:
      return balance.boundary;
    case 9:
      return balance.grains;
    case 10:
      return balance.allowance;
    case 11:
      return solver_->active_layers();
    case 12: {    // the topmost active layer: the cells right under the drained face
      if (active == 0) return 0.0;
      const int layer = grid_.geom.nx * grid_.geom.ny;
      double sum = 0.0;
      for (int c = active - layer; c < active; ++c) sum += p[c];
      return sum / layer;
    }
    default:
      return 0.0;
  }
}

const double *DarcyFluid::field(const std::string &name) const
{
  if (name == "pressure") return solver_->pressure().data();
  if (name == "porosity") return solver_->porosity().data();
  if (name == "permeability") return solver_->permeability().data();
  if (name == "mean_velocity") return solver_->mean_velocity().data();
  if (name == "pressure_gradient") return solver_->pressure_gradient().data();
  return nullptr;
}

/* ----------------------------------------------------------------------
   restart: [grid origin and spacing (6), last fluid step, started, the last solve
   (converged, iterations, residual, tolerance, worst cell), seepage, solver state];
   format version 3 had no seepage
------------------------------------------------------------------------- */

std::vector<double> DarcyFluid::restart_state() const
{
  const GridGeom &g = grid_.geom;
  const StepResult &r = last_solve_;
  std::vector<double> state = {g.xlo, g.ylo, g.zlo, g.dx, g.dy, g.dz,
                               (double) last_fluid_step_, started_ ? 1.0 : 0.0,
                               r.converged ? 1.0 : 0.0, (double) r.iterations, r.residual,
                               r.tolerance, (double) r.worst_cell,
                               (double) settings_.seepage};
  const std::vector<double> solver_state = solver_->state();
  state.insert(state.end(), solver_state.begin(), solver_state.end());
  return state;
}

void DarcyFluid::restore(const std::vector<double> &state, int version)
{
  const GridGeom &g = grid_.geom;
  const int header = version >= 4 ? STATE_HEADER : STATE_HEADER_3;
  const size_t expected = header + DarcySolver::state_size(g);
  const std::string ours = std::to_string(g.nx) + "x" + std::to_string(g.ny) + "x" +
      std::to_string(g.nz) + " cells of " + number(g.dx) + " x " + number(g.dy) + " x " +
      number(g.dz) + " from (" + number(g.xlo) + ", " + number(g.ylo) + ", " + number(g.zlo) + ")";
  if (state.size() < (size_t) header + 3)
    throw InputError("fix darcy/pressure: the restart file's fluid state is truncated (" +
                     std::to_string(state.size()) + " values)");
  const double *s = state.data();
  const std::string theirs = number(s[header]) + "x" + number(s[header + 1]) + "x" +
      number(s[header + 2]) + " cells of " + number(s[3]) + " x " + number(s[4]) + " x " +
      number(s[5]) + " from (" + number(s[0]) + ", " + number(s[1]) + ", " + number(s[2]) + ")";
  const double ours_geom[6] = {g.xlo, g.ylo, g.zlo, g.dx, g.dy, g.dz};
  const double length = std::max({g.nx * g.dx, g.ny * g.dy, g.nz * g.dz});
  bool same = (int) s[header] == g.nx && (int) s[header + 1] == g.ny && (int) s[header + 2] == g.nz;
  for (int d = 0; d < 6; ++d) same = same && std::fabs(s[d] - ours_geom[d]) <= 1e-12 * length;
  if (!same)
    throw InputError("fix darcy/pressure: the grid of the restart file (" + theirs +
                     ") differs from this command's (" + ours + ")");
  // the force on the grains is part of the model a run was started with
  const int seepage = version >= 4 ? (int) s[13] : SEEPAGE_PRESSURE;
  if (seepage != settings_.seepage)
    throw InputError(std::string("fix darcy/pressure: the restart file's run had seepage ") +
                     seepage_name(seepage) + ", this command has seepage " +
                     seepage_name(settings_.seepage) +
                     ": continue with the force the run started with, or start a new run");
  if (state.size() != expected ||
      !solver_->set_state(std::vector<double>(state.begin() + header, state.end())))
    throw InputError("fix darcy/pressure: the restart file's fluid state for the grid " + ours +
                     " holds " + std::to_string(state.size()) + " values where " +
                     std::to_string(expected) + " are needed (truncated or damaged)");
  last_fluid_step_ = (long long) s[6];
  started_ = s[7] != 0.0;
  restored_ = true;
  last_solve_ = StepResult{s[8] != 0.0, (int) s[9], s[10], s[11], (int) s[12]};
  refresh_force_field();
  stencils_kept_ = false;
}

}    // namespace porewater
