/* -*- c++ -*- ----------------------------------------------------------
   fix progress: one line at the end of every run (chunk) of a long run: the step and
   forcing cycle reached, steps per second over the chunk, the wall time left and the finish
   time; with `walltime`, it stops the run before a chunk that would not end in time (see
   doc/fix_progress.rst). The estimates are the core's (run/progress.h).
------------------------------------------------------------------------- */

#ifndef PW_FIX_PROGRESS_H
#define PW_FIX_PROGRESS_H

#include "fix.h"

#include "input/settings.h"

namespace LAMMPS_NS {

class FixProgress : public Fix {
 public:
  FixProgress(class LAMMPS *, int, char **);
  int setmask() override;
  void setup(int) override;
  void post_run() override;
  double compute_vector(int) override;

 private:
  porewater::ProgressSettings settings;
  double started;           // wall clock (MPI_Wtime) when the fix was defined: rank 0's counts
  double chunk_began;       // when the chunk just ended began: the previous chunk's end
  bool timing;              // chunk_began is set
  bigint chunk_first_step;  // the step that chunk began at
  double values[4];         // stop, steps/s, seconds left, seconds since defined
};

}    // namespace LAMMPS_NS

#endif
