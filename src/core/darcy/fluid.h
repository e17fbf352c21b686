// The pore fluid of fix darcy/pressure, host-free: its grid and solver, the fluid clock
// (a fluid step every N grain steps), the sequence of a fluid step, the force on the grains
// between fluid steps, the checks that stop a bad run, outputs and restart state. A host's
// fix (LAMMPS, LIGGGHTS) gives it two things: a FluidHost (sums over ranks, variables,
// errors) and a GrainBackend (the loops over its grains: CPU, or KOKKOS kernels), and
// forwards setup and post_force.
#ifndef PW_DARCY_FLUID_H
#define PW_DARCY_FLUID_H

#include "darcy/coupling.h"
#include "darcy/solver.h"
#include "input/restart_state.h"
#include "input/settings.h"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace porewater {

// The boundary values of a fluid step, as the settings give them (constants, or the
// host's equal-style variables evaluated now).
struct BoundaryValues {
  double p_top, z_top, p_bottom;
};

// Where the host's time integration stands in a hook.
struct GrainStep {
  long long step;
  double time;    // simulated time at `step`
  double dt;      // grain time step
};

// The host's simulation box, as the fix sees it when it is defined.
struct HostBox {
  double lo[3], hi[3];
  bool periodic[3];
  bool triclinic;
};

// InputError unless the host has what the fix needs: spheres (radius and per-grain mass),
// an orthogonal box periodic in x and y and not in z (the fluid has a bottom and a top)
void check_darcy_host(bool spheres, const HostBox &box);
// the grid the settings lay over the box: x and y span it, z runs from its bottom to zhi
GridGeom darcy_grid_geom(const DarcySettings &settings, const HostBox &box);

class FluidHost {
 public:
  // values[0..n) summed over the ranks, the same result on every rank
  virtual void sum_over_ranks(double *values, int n) = 0;
  // settings' top, ztop (when given) and bottom (when Dirichlet) now
  virtual BoundaryValues boundary_values() = 0;
  // whether LAMMPS-like re-neighboring may have moved grains between ranks or re-ordered
  // them since `step` (the held forces are per local index)
  virtual bool grains_reordered_since(long long step) = 0;
  // smallest ID over all ranks of a grain of the group with a non-finite x or v
  virtual long long first_nonfinite_grain() = 0;
  virtual std::string group_name() const = 0;    // the fix's group, for messages
  // the bit of the group called `name`, 0 if there is none
  virtual int group_bit(const std::string &name) = 0;
  // called on every rank with the same message: stop the run (error->all)
  virtual void stop(const std::string &message) = 0;
  // called on one rank only: stop the run from there (error->one)
  virtual void stop_here(const std::string &message) = 0;
  // called on every rank: print once
  virtual void warn(const std::string &message) = 0;
  virtual bool is_root() const = 0;

 protected:
  ~FluidHost() = default;
};

class GrainBackend {
 public:
  // every local grain of the group deposits into sums (CouplingGrid layout, zeroed by the
  // caller) and keeps its stencil at x
  virtual void deposit(const CouplingGrid &grid, double interval, double *sums) = 0;
  // f += the fluid force on every local grain of the group, held per grain as well; from
  // the stencils the deposit of this step kept (`kept`) or from the positions now.
  // field_changed: the field differs from the one of the last call (a fluid step).
  virtual void apply_force(const CouplingGrid &grid, const FluidForceField &field, bool kept,
                           bool field_changed) = 0;
  // f += the held force of every local grain
  virtual void add_held_force() = 0;

 protected:
  ~GrainBackend() = default;
};

class DarcyFluid {
 public:
  static constexpr int VECTOR_SIZE = 13;    // compute_vector's values, doc/fix_darcy_pressure.rst
  static const RestartFormat RESTART;

  // Throws InputError when the grid cannot be held (int index overflow, more memory than
  // the machine has for `copies` of it: every rank on a node holds the whole grid), before
  // allocating it. `id` names the fix in messages and files.
  DarcyFluid(const DarcySettings &settings, const GridGeom &geom, const std::string &id,
             int copies = 1);
  ~DarcyFluid();
  DarcyFluid(const DarcyFluid &) = delete;
  DarcyFluid &operator=(const DarcyFluid &) = delete;

  // what a fluid of this grid holds, in bytes (solver, deposits, gradient table)
  static double bytes_for(const GridGeom &geom);
  double bytes() const;
  static double machine_memory();    // physical memory in bytes, 0 if unknown

  const DarcySettings &settings() const { return settings_; }
  // what the host logs when the fix is defined (lines ending in newlines)
  std::string summary() const;
  // the host's box now: "" while it still spans the grid in x and y, else the message
  std::string box_mismatch(const HostBox &box) const;
  const CouplingGrid &grid() const { return grid_; }
  const DarcySolver &solver() const { return *solver_; }
  double z_grid_top() const { return solver_->z_grid_top(); }

  // the hooks of the fix: the first fluid state (unless restarted) and the force on the
  // grains; then a fluid step whenever `every` grain steps have passed, and the force
  void setup(FluidHost &host, GrainBackend &grains, const GrainStep &now);
  void post_force(FluidHost &host, GrainBackend &grains, const GrainStep &now);
  // whether post_force at `step` only adds the held force to the grains (no fluid step, no
  // new interpolation): a host may then run that per-grain work in a pass of its own
  bool only_holds_force(FluidHost &host, long long step) const;

  double vector(int n) const;
  // the per-cell field `name` (pressure, porosity, permeability, mean_velocity,
  // pressure_gradient), nullptr if there is none of that name
  const double *field(const std::string &name) const;

  std::vector<double> restart_state() const;
  // a state of RESTART's format `version` (3: before `seepage`, written with seepage
  // pressure); throws InputError saying what differs from this fix's grid or seepage
  void restore(const std::vector<double> &state, int version = RESTART.version);

 private:
  void start(FluidHost &host, GrainBackend &grains, long long step);
  void advance(FluidHost &host, GrainBackend &grains, long long step, double interval);
  void deposit_and_sum(FluidHost &host, GrainBackend &grains, long long step, double interval);
  void update_porosity(FluidHost &host, long long step);
  BoundaryValues boundary_values(FluidHost &host, long long step);
  void check_solution(FluidHost &host, long long step);
  bool is_fluid_step(long long step) const { return step - last_fluid_step_ >= settings_.every; }
  bool held_force_valid(FluidHost &host) const;
  void apply_or_hold_force(FluidHost &host, GrainBackend &grains, long long step, bool fluid_step);
  void refresh_force_field();
  void write_output(FluidHost &host, long long step, double time);
  std::string describe_cell(int cell) const;

  DarcySettings settings_;
  CouplingGrid grid_;
  std::string id_;
  std::unique_ptr<DarcySolver> solver_;
  std::vector<double> sums_;             // this rank's deposits, then everyone's cell deposits
  std::vector<double> force_gradient_;   // the cells' force gradients (fill_force_gradient)
  std::vector<double> gradient_table_;   // per block corner force gradients of the last fluid step
  FluidForceField field_;
  bool field_changed_;
  bool stencils_kept_;       // the last deposit's stencils are those of the grains now

  bool started_;             // the fluid state exists (first setup done, or restarted)
  long long last_fluid_step_;
  long long force_step_;     // the step the held forces were interpolated in, -1: none
  StepResult last_solve_;
  bool porosity_warned_;     // once per run
  bool unsettled_warned_;    // solver relaxed: sweeps that did not settle, once per run
  std::FILE *profile_;
  long long last_profile_step_, last_vtk_step_;
  bool restored_;            // restore() ran: the next setup's step wrote its outputs before
};

}    // namespace porewater

#endif
