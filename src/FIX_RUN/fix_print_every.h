/* -*- c++ -*- ----------------------------------------------------------
   fix print/every: LAMMPS' fix print with a constant N that never prints at a run's
   setup: one line at every step that is a multiple of N, so a run made of chunks (one
   `run` each) writes each line once, and LAMMPS calls it on those steps only (with KOKKOS
   the atom data come to the host for it on those steps only). See doc/fix_print_every.rst.
------------------------------------------------------------------------- */

#ifndef PW_FIX_PRINT_EVERY_H
#define PW_FIX_PRINT_EVERY_H

#include "fix.h"

#include <cstdio>

namespace LAMMPS_NS {

class FixPrintEvery : public Fix {
 public:
  FixPrintEvery(class LAMMPS *, int, char **);
  ~FixPrintEvery() override;
  int setmask() override;
  void init() override;
  void end_of_step() override;

 private:
  bool screen;
  FILE *fp;                 // rank 0's file, or none
  char *text, *copy, *work;    // the line as given, and Input::substitute's buffers
  int maxcopy, maxwork;
  bigint next_line() const;    // the next multiple of N after this step
};

}    // namespace LAMMPS_NS

#endif
