/* -*- c++ -*- ----------------------------------------------------------
   fix darcy/pressure's fields as LAMMPS per-grid data (LAMMPS since 22Dec2022: Grid3d,
   dump grid, fix ave/grid). The fluid is replicated on every rank; LAMMPS' per-grid
   consumers read each rank's owned brick of a Grid3d partitioned like the box, so each
   field is copied into that brick when it is read. No grid communication is needed.
------------------------------------------------------------------------- */

#ifndef PW_FIX_DARCY_PRESSURE_GRID_H
#define PW_FIX_DARCY_PRESSURE_GRID_H

#include "lammps_compat.h"

#if PW_LAMMPS_HAS_GRID3D

#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class DarcyGridData : protected Pointers {
 public:
  // the data sets: per-grid vectors (ncol 0) and arrays of 3 columns, x y z
  struct Field {
    const char *name;
    int ncol;
  };
  static const std::vector<Field> &fields();
  static int find(const std::string &name, int &ncol);

  DarcyGridData(LAMMPS *lmp, int nx, int ny, int nz);
  ~DarcyGridData() override;
  DarcyGridData(const DarcyGridData &) = delete;
  DarcyGridData &operator=(const DarcyGridData &) = delete;

  // the Grid3d over the ranks' current subdomains, made at first use
  class Grid3d *grid();
  // the subdomains changed (fix balance): a new grid and bricks at the next use
  void reset();
  // data set `index` of `values` (flat, x fastest; 3 interleaved columns for an array)
  // as this rank's owned brick: double ***[iz][iy][ix], or double ****[iz][iy][ix][col]
  void *brick(int index, const double *values);

 private:
  void release();
  int nx, ny, nz;
  class Grid3d *grid_;
  int lo[3], hi[3];    // the owned cells, inclusive
  std::vector<double ***> vectors;
  std::vector<double ****> arrays;
};

}    // namespace LAMMPS_NS

#endif
#endif
