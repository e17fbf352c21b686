/* -*- c++ -*- ----------------------------------------------------------
   fix darcy/pressure: pore-water pressure on a periodic Eulerian grid, advanced with
   Crank-Nicolson, pushing on the grains (MODEL.md §3, doc/fix_darcy_pressure.rst).
   The physics lives in the LAMMPS-free porewater::DarcySolver; this class adapts it.
------------------------------------------------------------------------- */

#ifndef PW_FIX_DARCY_PRESSURE_H
#define PW_FIX_DARCY_PRESSURE_H

#include "fix.h"

#include "darcy_grains.h"
#include "darcy_solver.h"
#include "fix_darcy_pressure_settings.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixDarcyPressure : public Fix {
 public:
  FixDarcyPressure(class LAMMPS *, int, char **);
  ~FixDarcyPressure() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;

 protected:
  // The steps the KOKKOS variant runs as kernels:
  // this rank's grains of the group -> deposits (zeroed by the caller), see DepositLayout
  virtual void deposit_grains(double interval);
  // f += fluid force on every grain of the group, also stored in fluid_force
  virtual void apply_fluid_force();
  // f += fluid_force (zero outside the group): `interpolate fluid` between fluid steps
  virtual void add_held_fluid_force();
  virtual void grow_fluid_force(int nmax);
  // atom data to the host: before equal-style variables are evaluated, and on error paths
  virtual void sync_atoms_to_host() {}

  DarcyFixSettings settings;
  std::unique_ptr<porewater::DarcySolver> solver;
  porewater::GridGeom geom;
  porewater::DepositLayout layout;
  std::vector<double> deposits;    // this rank's, then (after sum_deposits) everyone's
  double rho_g[3];                 // rho_f g: the buoyancy term
  bool gradient_changed;           // solver's gradient changed since the kernels copied it
  double **fluid_force;            // per-atom array: the last fluid force on each grain
  int maxatom;

 private:
  void start_fluid();
  void advance_fluid();
  void deposit_and_sum(double interval);
  void sum_deposits();
  void update_porosity();
  double evaluate(const DarcyFixSettings::Value &);
  bool uses_variables() const;
  tagint first_nonfinite_grain();
  void check_porosity();
  void check_solution();
  void write_output();
  std::string describe_cell(int cell) const;
  void apply_or_hold_fluid_force(bool fluid_step);

  // CPU deposits and force interpolation per stencil block (porewater::StencilBlocks):
  // deposits summed per block and corner, [quantity (5)][corner (8)] a block, then folded
  // into the cells; and the pressure gradient at each block's corners, [corner][xyz, 0]
  void fold_block_deposits();
  void update_block_gradient();
  porewater::StencilBlocks blocks;
  std::vector<double> block_deposits;
  std::vector<double> block_gradient;
  // each grain's block (-1: none) and corner weights at x from the last deposit_grains,
  // reused by apply_fluid_force in the same step (the grains have not moved since)
  std::vector<int> grain_block;
  std::vector<double> grain_weights;
  bigint stencils_step;    // the step deposit_grains stored them in, -1: none
  int stencils_nlocal;

  // `interpolate fluid`: the step fluid_force was last interpolated in and for how many
  // local atoms; valid until LAMMPS re-neighbors (atoms migrate or are sorted only then)
  bigint force_step;
  int force_nlocal;

  bool started;              // the fluid state exists (first setup done, or restarted)
  bigint last_fluid_step;    // timestep of the last fluid step (or of the first setup)
  porewater::StepResult last_solve;
  bool porosity_warned;      // once per run
  FILE *profile_fp;
  bigint last_profile_step, last_vtk_step;
};

}    // namespace LAMMPS_NS

#endif
