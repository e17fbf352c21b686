// fix shear/stress for LIGGGHTS 3.8 (doc/fix_shear_stress.rst): the core's
// porewater::RigidPlate (the top layer moved in x as one rigid plate under a shear stress)
// over LIGGGHTS' atoms and MPI, with the core's serial plate kernels.
#ifndef PW_LIGGGHTS_FIX_SHEAR_STRESS_H
#define PW_LIGGGHTS_FIX_SHEAR_STRESS_H

#include "fix.h"

#include "walls/rigid_plate.h"

#include <memory>

namespace porewater_liggghts {

class FixShearStress : public LAMMPS_NS::Fix, protected porewater::RigidPlateHost {
 public:
  FixShearStress(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
  ~FixShearStress() override;
  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void post_force(int vflag) override;
  double compute_vector(int n) override;
  void write_restart(FILE *fp) override;
  void restart(char *buf) override;

 private:
  porewater::PlateStep now() const;
  // the core's plate kernels over this rank's grains
  porewater::SerialPlateGrains<porewater::HostGrains<LAMMPS_NS::tagint>> plate_grains() const;

  // porewater::RigidPlateHost
  void plate_sums(double *sums) override;
  void momentum_sums(double *sums) override;
  void move_as_plate(double force_per_mass) override;
  void set_velocity_x(double velocity) override;
  void sum_over_ranks(double *values, int n) override;
  double area() override;
  double force_to_velocity() override;
  double neighbor_skin() override;
  std::string group_name() const override;
  void stop(const std::string &message) override;

  std::unique_ptr<porewater::RigidPlate> plate_;
};

}    // namespace porewater_liggghts

#endif
