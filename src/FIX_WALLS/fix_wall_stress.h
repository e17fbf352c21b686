/* -*- c++ -*- ----------------------------------------------------------
   fix wall/stress: the stress-controlled top wall of the shear experiment (doc/model.md §4), a
   frictionless horizontal plane of mass M that moves in z under the grains' contact forces
   and an applied normal stress S(t). The wall is the core's porewater::StressWall; this
   class adapts LAMMPS to it: atoms, input, variables, MPI, virial, errors, restart.
------------------------------------------------------------------------- */

#ifndef PW_FIX_WALL_STRESS_H
#define PW_FIX_WALL_STRESS_H

#include "fix.h"

#include "grains/grain_list.h"
#include "lammps_input.h"
#include "walls/stress_wall.h"

#include <memory>

namespace LAMMPS_NS {

class FixWallStress : public Fix, protected porewater::StressWallHost {
 public:
  FixWallStress(class LAMMPS *, int, char **);
  ~FixWallStress() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void pre_neighbor() override;
  void initial_integrate(int) override;
  void post_force(int) override;
  void final_integrate() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  void *extract(const char *, int &) override;

 protected:
  std::unique_ptr<porewater::StressWall> wall;    // the same on every rank
  porewater::EqualValue stress;                    // S(t)

  // the grain-wall contacts of the local grains (StressWall::contacts): forces added to
  // the grains, sums = {force on the wall, spring energy, zz virial}; the KOKKOS variant
  // runs them as a kernel over every grain
  virtual void grain_contacts(double *sums);
  // before the stress variable is evaluated, unless `variables time`: the atom data it may
  // read current on the host (the KOKKOS variant copies it from the device)
  virtual void sync_for_variables() {}

  // the CPU fix visits only the grains within reach: those whose top was above
  // z_w − skin when the list was built (at z_w = reach_wall_z). Until LAMMPS re-neighbors no
  // grain moves more than skin/2, so the list holds every grain that can touch the wall
  // while the wall stays above reach_wall_z − skin/2; below, it is built again
  porewater::GrainList reach;
  double reach_wall_z = 0.0;

  // porewater::StressWallHost
  double stress_now() override;
  void contact_sums(double *sums) final;
  void sum_over_ranks(double *values, int n) override;
  double max_over_ranks(double value) override;
  double min_over_ranks(double value) override;
  double highest_grain_top() override;
  double lightest_grain() override;
  porewater::WallBox box() override;
  std::string group_name() const override;
  void stop(const std::string &message) override;
  void warn(const std::string &message) override;
};

}    // namespace LAMMPS_NS

#endif
