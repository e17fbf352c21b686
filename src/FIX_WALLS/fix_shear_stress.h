/* -*- c++ -*- ----------------------------------------------------------
   fix shear/stress: the top layer of the shear experiment (doc/model.md §4) moves in x as one
   rigid plate of mass M driven by a shear stress τ; y-motion and rotation locked, vertical
   motion left to each grain.
------------------------------------------------------------------------- */

#ifndef PW_FIX_SHEAR_STRESS_H
#define PW_FIX_SHEAR_STRESS_H

#include "fix.h"

#include "input/settings.h"
#include "walls/shear_plate.h"

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
  porewater::ShearStressSettings settings;
  double plate_displacement;    // mass-weighted mean unwrapped x of the group − reference_x
  double reference_x;           // that mean where the displacement was zero
  double resisting_stress;      // −ΣF_x/(L_x L_y), ΣF_x before the plate's own force

  double area() const;
  double plate_velocity();    // mass-weighted mean v_x of the group (a reduction)
  void check_runaway(double step_displacement);

  porewater::ImageUnwrap image_unwrap() const;
  // the core's plate kernels over the local grains; the KOKKOS variant runs them as kernels
  virtual void plate_sums(double *sums);                  // {ΣF_x, Σ m x_unwrapped, Σ m}
  virtual void momentum_sums(double *sums);               // {Σ m v_x, Σ m}
  virtual void move_as_plate(double force_per_mass);      // f_x = m a; y and rotation locked
  virtual void set_velocity_x(double velocity);
};

}    // namespace LAMMPS_NS

#endif
