// Test-only fix (not a style of the package): proves that the launcher's registration
// reaches LIGGGHTS' fix map, hooks (post_force), thermo output and MPI.
//
//   fix ID group pwtest/addforce FX FY FZ
//
// adds (FX, FY, FZ) to the force on every grain of the group each step; f_ID is the number
// of grains it pushed (summed over ranks), f_ID[1..3] the total force it added.
#ifndef PW_TEST_FIX_PWTEST_ADDFORCE_H
#define PW_TEST_FIX_PWTEST_ADDFORCE_H

#include "fix.h"

namespace porewater_liggghts_test {

class FixPwtestAddforce : public LAMMPS_NS::Fix {
 public:
  FixPwtestAddforce(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void post_force(int vflag) override;
  double compute_scalar() override;
  double compute_vector(int i) override;

 private:
  double added_[3];
  double pushed_;    // grains pushed on this rank at the last post_force
};

}    // namespace porewater_liggghts_test

#endif
