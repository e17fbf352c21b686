// fix wall/stress for LIGGGHTS 3.8 (doc/fix_wall_stress.rst): the core's porewater::StressWall
// (a stress-controlled, frictionless top wall with mass, moved by velocity Verlet in
// initial_integrate / final_integrate) over LIGGGHTS' atoms, input, variables and MPI.
#ifndef PW_LIGGGHTS_FIX_WALL_STRESS_H
#define PW_LIGGGHTS_FIX_WALL_STRESS_H

#include "fix.h"

#include "input/host_input.h"
#include "walls/stress_wall.h"

#include <memory>

namespace porewater_liggghts {

class FixWallStress : public LAMMPS_NS::Fix, protected porewater::StressWallHost {
 public:
  FixWallStress(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
  ~FixWallStress() override;
  int setmask() override;
  int modify_param(int narg, char **arg) override;
  void init() override;
  void setup(int vflag) override;
  void initial_integrate(int vflag) override;
  void post_force(int vflag) override;
  void final_integrate() override;
  double compute_scalar() override;
  double compute_vector(int n) override;
  void write_restart(FILE *fp) override;
  void restart(char *buf) override;
  void *extract(const char *name, int &dim) override;

 private:
  void start_virial(int vflag);

  // porewater::StressWallHost
  double stress_now() override;
  void contact_sums(double *sums) override;
  void sum_over_ranks(double *values, int n) override;
  double max_over_ranks(double value) override;
  double min_over_ranks(double value) override;
  double highest_grain_top() override;
  double lightest_grain() override;
  porewater::WallBox box() override;
  std::string group_name() const override;
  void stop(const std::string &message) override;
  void warn(const std::string &message) override;

  std::unique_ptr<porewater::StressWall> wall_;    // the same on every rank
  porewater::EqualValue stress_;                    // S(t)
};

}    // namespace porewater_liggghts

#endif
