/* -*- c++ -*- ----------------------------------------------------------
   fix nve/sphere/bed: velocity Verlet for a bed of finite-size spheres with its held base,
   gravity and a floor in one pass over the grains per hook, in place of LAMMPS' fixes
   wall/gran (floor), gravity, setforce + nve (held base) and nve/sphere.
------------------------------------------------------------------------- */

#ifndef PW_FIX_NVE_SPHERE_BED_H
#define PW_FIX_NVE_SPHERE_BED_H

#include "fix.h"

#include "input/settings.h"

namespace LAMMPS_NS {

class FixNVESphereBed : public Fix {
 public:
  FixNVESphereBed(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void post_force(int) override;
  void final_integrate() override;

 protected:
  porewater::BedSettings settings;
  int heldbit, gravitybit;    // 0: no such group

  int group_bit_of(const std::string &name, const char *keyword) const;
};

}    // namespace LAMMPS_NS

#endif
