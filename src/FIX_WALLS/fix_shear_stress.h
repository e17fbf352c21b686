/* -*- c++ -*- ----------------------------------------------------------
   fix shear/stress: the top layer of the shear experiment (MODEL.md §4) moves in x as one
   rigid plate of mass M driven by a shear stress τ; y-motion and rotation locked, vertical
   motion left to each grain.
------------------------------------------------------------------------- */

#ifndef PW_FIX_SHEAR_STRESS_H
#define PW_FIX_SHEAR_STRESS_H

#include "fix.h"

namespace LAMMPS_NS {

class FixShearStress : public Fix {
 public:
  FixShearStress(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  double tau, plate_mass;
  double plate_displacement;    // mass-weighted mean unwrapped x of the group − reference_x
  double reference_x;           // that mean where the displacement was zero
  double resisting_stress;      // −ΣF_x/(L_x L_y), ΣF_x before the plate's own force

  double area() const;
  double plate_velocity();    // mass-weighted mean v_x of the group (a reduction)
  void check_runaway(double step_displacement);

  // local parts, overridden by the KOKKOS variant
  virtual void sum_forces_and_positions(double *sums);      // += {ΣF_x, Σ m x_unwrapped, Σ m}
  virtual void sum_momentum(double *sums);                  // += {Σ m v_x, Σ m}
  virtual void move_as_plate(double plate_acceleration);    // f_x = m a; y and rotation locked
  virtual void set_velocity_x(double velocity);
};

}    // namespace LAMMPS_NS

#endif
