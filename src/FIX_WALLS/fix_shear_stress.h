/* -*- c++ -*- ----------------------------------------------------------
   fix shear/stress: the top layer of the shear experiment (doc/model.md §4) moves in x as one
   rigid plate of mass M driven by a shear stress τ; y-motion and rotation locked, vertical
   motion left to each grain. The plate is the core's porewater::RigidPlate; this class
   adapts LAMMPS to it.
------------------------------------------------------------------------- */

#ifndef PW_FIX_SHEAR_STRESS_H
#define PW_FIX_SHEAR_STRESS_H

#include "fix.h"

#include "walls/rigid_plate.h"

#include <memory>

namespace LAMMPS_NS {

class FixShearStress : public Fix, protected porewater::RigidPlateHost {
 public:
  FixShearStress(class LAMMPS *, int, char **);
  ~FixShearStress() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void pre_neighbor() override;
  void post_force(int) override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  std::unique_ptr<porewater::RigidPlate> plate;

  porewater::ImageUnwrap image_unwrap() const;
  porewater::PlateStep now() const;
  // the core's plate kernels over the local grains (CPU): during a run over the group's
  // grains listed at the last re-neighboring or setup, between runs over every grain
  porewater::SerialPlateGrains<porewater::HostGrains<imageint>> plate_grains() const;
  porewater::GrainList members;
  void list_members();

  // porewater::RigidPlateHost; the KOKKOS variant runs the plate kernels as Kokkos kernels
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
};

}    // namespace LAMMPS_NS

#endif
