/* -*- c++ -*- ----------------------------------------------------------
   compute darcy/grain: the pore pressure and porosity of a fix darcy/pressure at each
   grain's centre, interpolated with the stencil of the grains' coupling (per-atom array:
   1 pressure, 2 porosity), for dumps (doc/compute_darcy_grain.rst).
------------------------------------------------------------------------- */

#ifndef PW_COMPUTE_DARCY_GRAIN_H
#define PW_COMPUTE_DARCY_GRAIN_H

#include "compute.h"

#include <string>

namespace LAMMPS_NS {

class ComputeDarcyGrain : public Compute {
 public:
  ComputeDarcyGrain(class LAMMPS *, int, char **);
  ~ComputeDarcyGrain() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  std::string fix_id;
  class FixDarcyPressure *darcy;
  int nmax;
  double **values;
};

}    // namespace LAMMPS_NS

#endif
