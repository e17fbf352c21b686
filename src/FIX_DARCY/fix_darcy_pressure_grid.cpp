/* ----------------------------------------------------------------------
   fix darcy/pressure as a source of per-grid data (LAMMPS since 22Dec2022):
     dump ID all grid N file f_ID:grid:pressure f_ID:grid:mean_velocity[3] ...
     fix ID all ave/grid Nevery Nrepeat Nfreq nx ny nz f_ID:grid:pressure
   with N a multiple of the fluid step (`every`). Compiled empty for older LAMMPS.
------------------------------------------------------------------------- */

#include "fix_darcy_pressure_grid.h"

#if PW_LAMMPS_HAS_GRID3D

#include "fix_darcy_pressure.h"
#include "grid3d.h"
#include "memory.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

const std::vector<DarcyGridData::Field> &DarcyGridData::fields()
{
  // the names of porewater::DarcyFluid::field (and of Fix::extract)
  static const std::vector<Field> table = {{"pressure", 0},      {"porosity", 0},
                                           {"permeability", 0},  {"mean_velocity", 3},
                                           {"pressure_gradient", 3}};
  return table;
}

int DarcyGridData::find(const std::string &name, int &ncol)
{
  for (size_t i = 0; i < fields().size(); ++i)
    if (name == fields()[i].name) {
      ncol = fields()[i].ncol;
      return (int) i;
    }
  return -1;
}

DarcyGridData::DarcyGridData(LAMMPS *lmp, int nx, int ny, int nz) :
    Pointers(lmp), nx(nx), ny(ny), nz(nz), grid_(nullptr), lo{0, 0, 0}, hi{-1, -1, -1},
    vectors(fields().size(), nullptr), arrays(fields().size(), nullptr)
{
}

DarcyGridData::~DarcyGridData()
{
  release();
}

void DarcyGridData::release()
{
  for (auto &v : vectors) memory->destroy3d_offset(v, lo[2], lo[1], lo[0]);
  for (auto &a : arrays) memory->destroy4d_offset_last(a, lo[2], lo[1], lo[0]);
  delete grid_;
  grid_ = nullptr;
}

void DarcyGridData::reset()
{
  release();
}

Grid3d *DarcyGridData::grid()
{
  if (!grid_) {
    // partitioned as LAMMPS' own per-grid styles partition it (fix ave/grid reads the
    // bricks over the bounds of its own grid of the same size): the default settings
    grid_ = new Grid3d(lmp, world, nx, ny, nz);
    int out[6];
    grid_->setup_grid(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], out[0], out[1], out[2], out[3],
                      out[4], out[5]);
  }
  return grid_;
}

void *DarcyGridData::brick(int index, const double *values)
{
  grid();
  const int ncol = fields().at(index).ncol;
  if (ncol == 0) {
    double ***&v = vectors[index];
    if (!v)
      memory->create3d_offset(v, lo[2], hi[2], lo[1], hi[1], lo[0], hi[0], "darcy/pressure:grid");
    for (int iz = lo[2]; iz <= hi[2]; ++iz)
      for (int iy = lo[1]; iy <= hi[1]; ++iy)
        for (int ix = lo[0]; ix <= hi[0]; ++ix) v[iz][iy][ix] = values[ix + nx * (iy + ny * iz)];
    return v;
  }
  double ****&a = arrays[index];
  if (!a)
    memory->create4d_offset_last(a, lo[2], hi[2], lo[1], hi[1], lo[0], hi[0], ncol,
                                 "darcy/pressure:grid");
  for (int iz = lo[2]; iz <= hi[2]; ++iz)
    for (int iy = lo[1]; iy <= hi[1]; ++iy)
      for (int ix = lo[0]; ix <= hi[0]; ++ix)
        for (int c = 0; c < ncol; ++c)
          a[iz][iy][ix][c] = values[ncol * (ix + nx * (iy + ny * iz)) + c];
  return a;
}

/* ----------------------------------------------------------------------
   the fix's side: one grid, "grid", with the data sets of DarcyGridData::fields()
------------------------------------------------------------------------- */

int FixDarcyPressure::get_grid_by_name(const std::string &name, int &dim)
{
  if (name != "grid") return -1;
  dim = 3;
  return 0;
}

void *FixDarcyPressure::get_grid_by_index(int index)
{
  if (index != 0) return nullptr;
  if (!grid_data) {
    const porewater::GridGeom &g = fluid->grid().geom;
    grid_data.reset(new DarcyGridData(lmp, g.nx, g.ny, g.nz));
  }
  return grid_data->grid();
}

int FixDarcyPressure::get_griddata_by_name(int igrid, const std::string &name, int &ncol)
{
  return igrid == 0 ? DarcyGridData::find(name, ncol) : -1;
}

void *FixDarcyPressure::get_griddata_by_index(int index)
{
  if (index < 0 || index >= (int) DarcyGridData::fields().size()) return nullptr;
  get_grid_by_index(0);
  return grid_data->brick(index, fluid->field(DarcyGridData::fields()[index].name));
}

void FixDarcyPressure::reset_grid()
{
  if (grid_data) grid_data->reset();
}

#endif
