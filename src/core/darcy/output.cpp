#include "darcy/output.h"

#include <fstream>
#include <sstream>

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

std::FILE *continue_profile(const std::string &path, long long step, bool &has_header)
{
  has_header = false;
  std::string kept;
  {
    std::ifstream file(path);
    std::stringstream whole;
    whole << file.rdbuf();
    std::string text = whole.str();
    text.resize(text.find_last_of('\n') == std::string::npos ? 0 : text.find_last_of('\n') + 1);
    std::istringstream in(text);    // complete lines only: a row cut by a kill is dropped
    std::string line;
    int layers_left = 0;        // layer rows still to come in the current block
    bool keep = true;
    size_t block_start = 0;     // where the current block begins in `kept`
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      if (layers_left > 0) {
        --layers_left;
      } else if (line[0] == '#') {
        has_header = true;
        keep = true;
      } else {
        std::istringstream head(line);
        long long block_step = 0;
        double time = 0.0;
        int nlayers = 0;
        if (!(head >> block_step >> time >> nlayers) || nlayers < 0) break;
        layers_left = nlayers;
        keep = block_step <= step;
        block_start = kept.size();
      }
      if (keep) kept += line + "\n";
    }
    if (layers_left > 0) kept.resize(block_start);    // a block cut short by a kill
  }
  std::FILE *fp = std::fopen(path.c_str(), "w");
  if (!fp) return nullptr;
  if (std::fputs(kept.c_str(), fp) < 0 || std::fflush(fp) != 0) {
    std::fclose(fp);
    return nullptr;
  }
  return fp;
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
