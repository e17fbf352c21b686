/* -*- c++ -*- ----------------------------------------------------------
   fix darcy/pressure: pore-water pressure on a periodic Eulerian grid, advanced with
   Crank-Nicolson, pushing on the grains (doc/model.md §3, doc/fix_darcy_pressure.rst).
   The fluid, its clock and checks are the core's porewater::DarcyFluid; this class adapts
   LAMMPS to it: atoms, input, variables, MPI, errors, restart.
------------------------------------------------------------------------- */

#ifndef PW_FIX_DARCY_PRESSURE_H
#define PW_FIX_DARCY_PRESSURE_H

#include "fix.h"

#include "darcy/fluid.h"
#include "darcy/serial_grains.h"
#include "lammps_compat.h"
#include "lammps_input.h"

#include <memory>

namespace LAMMPS_NS {

class FixDarcyPressure : public Fix, protected porewater::FluidHost {
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
  // the fluid's grid and fields, for compute darcy/grain
  const porewater::DarcyFluid &darcy_fluid() const { return *fluid; }
#if PW_LAMMPS_HAS_GRID3D
  // the fields as per-grid data (dump grid, fix ave/grid): fix_darcy_pressure_grid.cpp
  int get_grid_by_name(const std::string &, int &) override;
  void *get_grid_by_index(int) override;
  int get_griddata_by_name(int, const std::string &, int &) override;
  void *get_griddata_by_index(int) override;
  void reset_grid() override;
#endif

 protected:
  // the grains' side: CPU loops here, KOKKOS kernels in the /kk variant
  virtual porewater::GrainBackend &grains();
  virtual void grow_fluid_force(int nmax);
  // atom data equal-style variables may read, on the host before they are evaluated
  virtual void sync_for_variables() {}
  virtual void sync_for_nonfinite_check() {}

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

  std::unique_ptr<porewater::DarcyFluid> fluid;
  porewater::EqualValue top, z_top, bottom;
  double **fluid_force;    // per-atom array: the last fluid force on each grain
  int maxatom;

 private:
  porewater::GrainStep now() const;
  porewater::HostBox host_box() const;
  porewater::SerialGrains cpu_grains;
#if PW_LAMMPS_HAS_GRID3D
  std::unique_ptr<class DarcyGridData> grid_data;
#endif
};

}    // namespace LAMMPS_NS

#endif
