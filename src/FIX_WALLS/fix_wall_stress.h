/* -*- c++ -*- ----------------------------------------------------------
   fix wall/stress: the stress-controlled top wall of the shear experiment (doc/model.md §4), a
   frictionless horizontal plane of mass M that moves in z under the grains' contact forces
   and an applied normal stress S(t).
------------------------------------------------------------------------- */

#ifndef PW_FIX_WALL_STRESS_H
#define PW_FIX_WALL_STRESS_H

#include "fix.h"

#include "input/settings.h"
#include "lammps_input.h"

namespace LAMMPS_NS {

class FixWallStress : public Fix {
 public:
  FixWallStress(class LAMMPS *, int, char **);
  ~FixWallStress() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void post_force(int) override;
  void final_integrate() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  void *extract(const char *, int &) override;

 protected:
  void warn_if_damping_unstable();
  // the wall, the same on every rank
  double z_wall, v_wall;
  double wall_force;        // on the wall at the last force evaluation: grain_force − S·L_x·L_y
  double grain_force;       // sum of the grains' contact forces on the wall (≥ 0)
  double applied_stress;    // S at the last force evaluation
  double spring_energy;     // ½ k_n δ² summed over the grain–wall contacts
  int z_auto;               // 1 until `z auto` has put the wall on the highest grain

  porewater::WallStressSettings settings;
  porewater::EqualValue stress;    // S(t)

  double area() const;
  double current_stress();
  void check_wall_in_box();

  double highest_grain_top();    // max z + r over the local grains (host data)
  // the grain-wall contacts of the local grains: forces added to the grains, sums =
  // {force on the wall, spring energy, zz virial}; the KOKKOS variant runs them as a kernel
  virtual void contact_sums(double *sums);
};

}    // namespace LAMMPS_NS

#endif
