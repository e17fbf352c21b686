/* ----------------------------------------------------------------------
   fix darcy/pressure: parsing of the command line
------------------------------------------------------------------------- */

#include "fix_darcy_pressure_settings.h"

#include "domain.h"
#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

using namespace LAMMPS_NS;

namespace {

const char *const STYLE = "fix darcy/pressure";

bool to_double(const char *s, double &out)
{
  char *end = nullptr;
  errno = 0;
  out = std::strtod(s, &end);
  return end != s && *end == '\0' && errno == 0 && std::isfinite(out);
}

bool to_int(const char *s, int &out)
{
  char *end = nullptr;
  errno = 0;
  const long v = std::strtol(s, &end, 10);
  out = (int) v;
  return end != s && *end == '\0' && errno == 0 && v == out;
}

// Reads keyword arguments with checks whose messages name the keyword and what it accepts.
class Reader {
 public:
  Reader(Error *error, int narg, char **arg) : error(error), narg(narg), arg(arg) {}

  // arg[i] is a keyword followed by `count` values
  void need(int i, int count, const char *usage) const
  {
    if (i + count >= narg) error->all(FLERR, "{}: expected {}", STYLE, usage);
  }
  double real(int i, const char *keyword, const char *allowed) const
  {
    double v;
    if (!to_double(arg[i], v))
      error->all(FLERR, "{}: {} expects {}, got '{}'", STYLE, keyword, allowed, arg[i]);
    return v;
  }
  double positive(int i, const char *keyword) const
  {
    const double v = real(i, keyword, "a number > 0");
    if (!(v > 0.0)) error->all(FLERR, "{}: {} must be > 0, got {}", STYLE, keyword, arg[i]);
    return v;
  }
  double non_negative(int i, const char *keyword) const
  {
    const double v = real(i, keyword, "a number >= 0");
    if (v < 0.0) error->all(FLERR, "{}: {} must be >= 0, got {}", STYLE, keyword, arg[i]);
    return v;
  }
  int count(int i, const char *keyword) const
  {
    int v;
    if (!to_int(arg[i], v) || v < 1)
      error->all(FLERR, "{}: {} expects an integer >= 1, got '{}'", STYLE, keyword, arg[i]);
    return v;
  }
  DarcyFixSettings::Value value(int i, const char *keyword, const char *allowed) const
  {
    DarcyFixSettings::Value s;
    if (utils::strmatch(arg[i], "^v_\\w+$"))
      s.variable = arg[i] + 2;
    else
      s.value = real(i, keyword, allowed);
    return s;
  }

 private:
  Error *error;
  int narg;
  char **arg;
};

}    // namespace

DarcyFixSettings LAMMPS_NS::parse_darcy_fix_settings(LAMMPS *lmp, int narg, char **arg)
{
  Error *error = lmp->error;
  const Reader read(error, narg, arg);
  DarcyFixSettings s;
  s.zhi = lmp->domain->boxhi[2];
  s.params.tol_rel = 1e-10;
  s.params.tol_abs = 0.0;
  s.params.maxiter = 1000;
  bool have_viscosity = false, have_beta = false, have_density = false, have_kc = false;

  for (int i = 3; i < narg;) {
    const std::string key = arg[i];
    if (key == "grid") {
      read.need(i, 3, "grid Nx Ny Nz");
      for (int d = 0; d < 3; ++d) s.grid[d] = read.count(i + 1 + d, "grid");
      i += 4;
    } else if (key == "viscosity") {
      read.need(i, 1, "viscosity MU");
      s.params.viscosity = read.positive(i + 1, "viscosity");
      have_viscosity = true;
      i += 2;
    } else if (key == "compressibility") {
      read.need(i, 1, "compressibility BETA");
      s.params.compressibility = read.positive(i + 1, "compressibility");
      have_beta = true;
      i += 2;
    } else if (key == "density") {
      read.need(i, 1, "density RHO_F");
      s.density = read.non_negative(i + 1, "density");
      have_density = true;
      i += 2;
    } else if (key == "permeability") {
      read.need(i, 1, "permeability KC");
      s.params.kc = read.positive(i + 1, "permeability");
      have_kc = true;
      i += 2;
    } else if (key == "top") {
      read.need(i, 1, "top noflow, top P or top v_name");
      s.top_dirichlet = std::string(arg[i + 1]) != "noflow";
      s.top = DarcyFixSettings::Value();    // noflow: 0, the value cells above ztop hold
      if (s.top_dirichlet) s.top = read.value(i + 1, "top", "noflow, a pressure or v_name");
      i += 2;
    } else if (key == "ztop") {
      read.need(i, 1, "ztop Z or ztop v_name");
      s.z_top = read.value(i + 1, "ztop", "a z coordinate or v_name");
      s.z_top_given = true;
      i += 2;
    } else if (key == "bottom") {
      read.need(i, 1, "bottom noflow, bottom P or bottom v_name");
      s.bottom_dirichlet = std::string(arg[i + 1]) != "noflow";
      if (s.bottom_dirichlet) s.bottom = read.value(i + 1, "bottom", "noflow, a pressure or v_name");
      i += 2;
    } else if (key == "initial") {
      read.need(i, 1, "initial P");
      s.initial_pressure = read.real(i + 1, "initial", "a pressure");
      i += 2;
    } else if (key == "gravity") {
      read.need(i, 3, "gravity gx gy gz");
      for (int d = 0; d < 3; ++d) s.gravity[d] = read.real(i + 1 + d, "gravity", "three numbers");
      s.gravity_given = true;
      i += 4;
    } else if (key == "porosity") {
      read.need(i, 2, "porosity MIN MAX");
      const char *allowed = "MIN MAX with 0 < MIN <= MAX < 1";
      s.params.porosity_min = read.real(i + 1, "porosity", allowed);
      s.params.porosity_max = read.real(i + 2, "porosity", allowed);
      if (!(s.params.porosity_min > 0.0 && s.params.porosity_min <= s.params.porosity_max &&
            s.params.porosity_max < 1.0))
        error->all(FLERR, "{}: porosity MIN MAX needs 0 < MIN <= MAX < 1, got {} {}", STYLE,
                   arg[i + 1], arg[i + 2]);
      i += 3;
    } else if (key == "kmax") {
      read.need(i, 1, "kmax K");
      s.params.kmax = read.positive(i + 1, "kmax");
      i += 2;
    } else if (key == "tol") {
      read.need(i, 1, "tol REL");
      s.params.tol_rel = read.positive(i + 1, "tol");
      i += 2;
    } else if (key == "atol") {
      read.need(i, 1, "atol ABS");
      s.params.tol_abs = read.non_negative(i + 1, "atol");
      i += 2;
    } else if (key == "maxiter") {
      read.need(i, 1, "maxiter N");
      s.params.maxiter = read.count(i + 1, "maxiter");
      i += 2;
    } else if (key == "every") {
      read.need(i, 1, "every N");
      s.every = read.count(i + 1, "every");
      i += 2;
    } else if (key == "interpolate") {
      read.need(i, 1, "interpolate step|fluid");
      const std::string when = arg[i + 1];
      if (when != "step" && when != "fluid")
        error->all(FLERR, "{}: interpolate must be step or fluid, got {}", STYLE, when);
      s.interpolate_every_step = when == "step";
      i += 2;
    } else if (key == "zhi") {
      read.need(i, 1, "zhi Z");
      s.zhi = read.real(i + 1, "zhi", "a z coordinate above the box bottom");
      i += 2;
    } else if (key == "profile") {
      read.need(i, 2, "profile N file");
      s.profile_every = read.count(i + 1, "profile");
      s.profile_path = arg[i + 2];
      i += 3;
    } else if (key == "vtk") {
      read.need(i, 2, "vtk N prefix");
      s.vtk_every = read.count(i + 1, "vtk");
      s.vtk_prefix = arg[i + 2];
      i += 3;
    } else {
      error->all(FLERR, "{}: unknown keyword {} (expected grid, viscosity, compressibility, "
                 "density, permeability, top, ztop, bottom, initial, gravity, porosity, kmax, "
                 "tol, atol, maxiter, every, interpolate, zhi, profile, vtk)", STYLE, key);
    }
  }
  if (!s.grid[0] || !have_viscosity || !have_beta || !have_density || !have_kc)
    error->all(FLERR, "{}: grid, viscosity, compressibility, density and permeability are "
               "required", STYLE);
  if (!(s.zhi > lmp->domain->boxlo[2]))
    error->all(FLERR, "{}: zhi must lie above the box bottom {}, got {}", STYLE,
               lmp->domain->boxlo[2], s.zhi);
  s.params.bottom = s.bottom_dirichlet ? porewater::DarcyParams::Bottom::Dirichlet
                                       : porewater::DarcyParams::Bottom::NoFlow;
  s.params.top = s.top_dirichlet ? porewater::DarcyParams::Top::Dirichlet
                                 : porewater::DarcyParams::Top::NoFlow;
  return s;
}
