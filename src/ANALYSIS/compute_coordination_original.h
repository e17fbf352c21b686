/* -*- c++ -*- ----------------------------------------------------------
   compute coordination/original: the coordination number as the original program (sphere)
   counts it, for comparison with the paper's numbers (per-atom: each grain's counted
   contacts; scalar: their mean over the group); doc/compute_coordination_original.rst.
------------------------------------------------------------------------- */

#ifndef PW_COMPUTE_COORDINATION_ORIGINAL_H
#define PW_COMPUTE_COORDINATION_ORIGINAL_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeCoordinationOriginal : public Compute {
 public:
  ComputeCoordinationOriginal(class LAMMPS *, int, char **);
  ~ComputeCoordinationOriginal() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  double compute_scalar() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  int fixed_groupbit;
  class NeighList *list;
  int nmax;
  double *contacts;
};

}    // namespace LAMMPS_NS

#endif
