/* -*- c++ -*- ----------------------------------------------------------
   fix nve/sphere/ty3: the third-order Taylor integrator of the reference program `sphere`
   (doc/model.md §2) for finite-size spheres, with an optional Adams–Moulton velocity corrector.
------------------------------------------------------------------------- */

#ifndef PW_FIX_NVE_SPHERE_TY3_H
#define PW_FIX_NVE_SPHERE_TY3_H

#include "fix.h"

namespace LAMMPS_NS {

class FixNVESphereTY3 : public Fix {
 public:
  FixNVESphereTY3(class LAMMPS *, int, char **);
  ~FixNVESphereTY3() override;
  int setmask() override;
  void init() override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void reset_dt() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

 protected:
  int corrector;           // 1: Adams–Moulton velocity correction in final_integrate
  int ncols;               // porewater::TY3_COLUMNS(_CORRECTOR)
  double **history;        // per atom: a row of porewater::Ty3Column
  double dt_of_history;    // the history holds accelerations one step of this size apart

  virtual void forget_history();
  int integrated_count() const;    // nfirst when the group is atom_modify first
};

}    // namespace LAMMPS_NS

#endif
