// fix darcy/pressure for LIGGGHTS 3.8 (doc/fix_darcy_pressure.rst): the core's
// porewater::DarcyFluid (grid, solver, coupling, fluid clock, checks, outputs, restart)
// over LIGGGHTS' atoms, input, variables, MPI and errors. The grains' loops are the core's
// SerialGrains (LIGGGHTS keeps double** per-atom rows like LAMMPS).
#ifndef PW_LIGGGHTS_FIX_DARCY_PRESSURE_H
#define PW_LIGGGHTS_FIX_DARCY_PRESSURE_H

#include "fix.h"

#include "darcy/fluid.h"
#include "darcy/serial_grains.h"
#include "input/host_input.h"

#include <memory>

namespace porewater_liggghts {

class FixDarcyPressure : public LAMMPS_NS::Fix, protected porewater::FluidHost {
 public:
  FixDarcyPressure(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
  ~FixDarcyPressure() override;
  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void post_force(int vflag) override;
  double compute_vector(int n) override;
  void write_restart(FILE *fp) override;
  void restart(char *buf) override;
  void *extract(const char *name, int &dim) override;
  double memory_usage() override;

 private:
  porewater::HostBox host_box() const;
  porewater::GrainStep now() const;
  porewater::GrainBackend &grains();
  void check_box();

  // porewater::FluidHost
  void sum_over_ranks(double *values, int n) override;
  porewater::BoundaryValues boundary_values() override;
  bool grains_reordered_since(long long step) override;
  long long first_nonfinite_grain() override;
  std::string group_name() const override;
  int group_bit(const std::string &name) override;
  void stop(const std::string &message) override;
  void stop_here(const std::string &message) override;
  void warn(const std::string &message) override;
  bool is_root() const override;

  std::unique_ptr<porewater::DarcyFluid> fluid_;
  porewater::EqualValue top_, z_top_, bottom_;
  porewater::SerialGrains grains_;
  double **fluid_force_;    // per-atom array: the last fluid force on each grain
  int maxatom_;
};

}    // namespace porewater_liggghts

#endif
