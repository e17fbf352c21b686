#include "darcy/output.h"

namespace porewater {

void write_profile_header(std::FILE *fp, const std::string &fix_id)
{
  std::fprintf(fp,
               "# fix %s darcy/pressure: x-y averages per grid layer, state of the last fluid "
               "step\n# step time nlayers active_layers\n"
               "# layer z p porosity permeability vbar_z\n",
               fix_id.c_str());
}

void write_profile(std::FILE *fp, const DarcySolver &solver, long long step, double time)
{
  const GridGeom &g = solver.geom();
  const int nxy = g.nx * g.ny;
  std::fprintf(fp, "%lld %.16g %d %d\n", step, time, g.nz, solver.active_layers());
  for (int k = 0; k < g.nz; ++k) {
    double p = 0.0, phi = 0.0, perm = 0.0, solid = 0.0, solid_vz = 0.0;
    for (int c = k * nxy; c < (k + 1) * nxy; ++c) {
      p += solver.pressure()[c];
      phi += solver.porosity()[c];
      perm += solver.permeability()[c];
      solid += 1.0 - solver.porosity()[c];
      solid_vz += (1.0 - solver.porosity()[c]) * solver.mean_velocity()[3 * c + 2];
    }
    std::fprintf(fp, "%d %.16g %.16g %.16g %.16g %.16g\n", k + 1, g.zlo + (k + 0.5) * g.dz,
                 p / nxy, phi / nxy, perm / nxy, solid > 0.0 ? solid_vz / solid : 0.0);
  }
  std::fflush(fp);
}

namespace {

void write_faces(std::FILE *fp, const char *axis, int n, double lo, double delta)
{
  std::fprintf(fp, "%s_COORDINATES %d double\n", axis, n + 1);
  for (int i = 0; i <= n; ++i) std::fprintf(fp, "%.16g%c", lo + i * delta, i < n ? ' ' : '\n');
}

void write_scalars(std::FILE *fp, const char *name, const std::vector<double> &field)
{
  std::fprintf(fp, "SCALARS %s double 1\nLOOKUP_TABLE default\n", name);
  for (double v : field) std::fprintf(fp, "%.16g\n", v);
}

void write_vectors(std::FILE *fp, const char *name, const std::vector<double> &field)
{
  std::fprintf(fp, "VECTORS %s double\n", name);
  for (size_t c = 0; c + 2 < field.size(); c += 3)
    std::fprintf(fp, "%.16g %.16g %.16g\n", field[c], field[c + 1], field[c + 2]);
}

}  // namespace

bool write_vtk(const std::string &path, const DarcySolver &solver, long long step, double time)
{
  std::FILE *fp = std::fopen(path.c_str(), "w");
  if (!fp) return false;
  const GridGeom &g = solver.geom();
  // cells are numbered x fastest, as VTK expects
  std::fprintf(fp, "# vtk DataFile Version 3.0\nfix darcy/pressure step %lld time %.16g\nASCII\n"
               "DATASET RECTILINEAR_GRID\nDIMENSIONS %d %d %d\n",
               step, time, g.nx + 1, g.ny + 1, g.nz + 1);
  write_faces(fp, "X", g.nx, g.xlo, g.dx);
  write_faces(fp, "Y", g.ny, g.ylo, g.dy);
  write_faces(fp, "Z", g.nz, g.zlo, g.dz);
  std::fprintf(fp, "CELL_DATA %d\n", solver.ncells());
  write_scalars(fp, "pressure", solver.pressure());
  write_scalars(fp, "porosity", solver.porosity());
  write_scalars(fp, "permeability", solver.permeability());
  write_vectors(fp, "mean_velocity", solver.mean_velocity());
  write_vectors(fp, "pressure_gradient", solver.pressure_gradient());
  return std::fclose(fp) == 0;
}

}  // namespace porewater
