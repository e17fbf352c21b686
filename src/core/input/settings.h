// The command syntax of every style of the package: what each command accepts, with its
// defaults written here once, read by the one KeywordReader. The doc pages in doc/ describe
// the same keywords; the hosts hand these functions the tokens after the style name and
// turn an InputError into their own error call.
#ifndef PW_INPUT_SETTINGS_H
#define PW_INPUT_SETTINGS_H

#include "contact/linear_coulomb.h"
#include "darcy/coupling.h"
#include "darcy/solver.h"
#include "input/keywords.h"

#include <string>

namespace porewater {

// pair_style linear/coulomb [lever contact|radius] [dissipation yes|no] [overlap_limit X]
struct LinearCoulombSettings {
  int lever = LEVER_CONTACT;
  bool dissipation = false;     // accumulate the frictional dissipation (compute pair)
  double overlap_limit = 0.5;   // a deeper contact, as a fraction of the smaller radius, stops the run
};
LinearCoulombSettings parse_linear_coulomb(KeywordReader &in);

// pair_coeff I J kn kt mu (the tokens after I J)
ContactCoeffs parse_linear_coulomb_coeffs(KeywordReader &in);

// fix ID group wall/stress z Z0|auto stress S|v_name mass M kn KN [damping GAMMA]
//   [damping_velocity relative|absolute] [plate_damping GAMMA_P]
struct WallStressSettings {
  double z = 0.0;
  bool z_auto = false;          // put the wall on the highest grain at the first setup
  NumberOrVariable stress;      // applied normal stress S(t)
  double mass = 0.0;
  double kn = 0.0;
  double damping = 0.0;         // gamma of the grain-wall dashpot
  int damping_velocity = 0;     // WALL_DAMPING_RELATIVE (0) or _ABSOLUTE (1): what it damps
  double plate_damping = 0.0;   // gamma_p of a dashpot on the wall's own velocity
  bool variables_read_atoms = true;  // `variables global`: the stress variable reads none
};
WallStressSettings parse_wall_stress(KeywordReader &in);

// fix ID group shear/stress tau T mass M
struct ShearStressSettings {
  double tau = 0.0;
  double mass = 0.0;
};
ShearStressSettings parse_shear_stress(KeywordReader &in);

// fix ID group nve/sphere/ty3 [corrector yes|no]
struct Ty3Settings {
  bool corrector = false;       // Adams-Moulton velocity correction (third order)
};
Ty3Settings parse_ty3(KeywordReader &in);

// fix ID group nve/sphere/bed [held GROUP] [gravity G GROUP] [floor Z0 KN] [fuse yes|no]
struct BedSettings {
  std::string held_group;       // empty: none (these grains move along z only)
  double gravity = 0.0;         // g, along −z, on gravity_group
  std::string gravity_group;    // empty: no gravity
  bool floor = false;           // a frictionless spring floor at z_floor
  double z_floor = 0.0;
  double kn = 0.0;
  bool fuse = true;             // /kk: the fused pass of the fixes after it (CPU: no effect)
};
BedSettings parse_nve_sphere_bed(KeywordReader &in);

// fix ID group progress end STEP [period T] [walltime HH:MM:SS|S|none] [safety F]
struct ProgressSettings {
  long long end_step = 0;       // the last step of the whole run (as `run STEP upto`)
  double period = 0.0;          // > 0: report the forcing cycle reached (model time / period)
  double walltime = 0.0;        // seconds the job may run (0: no limit)
  double safety = 1.5;          // the next chunk is estimated as this many times the last one
};
ProgressSettings parse_progress(KeywordReader &in);
// fix ID group print/every N "text" [file F | append F] [screen yes|no] [title T]
struct PrintEverySettings {
  int every = 0;             // a line at every step that is a multiple of this
  std::string text;          // with $ variables, substituted at each line
  std::string file;          // empty: none
  bool append = false;       // the file opened to append (append F), else truncated (file F)
  bool screen = true;        // the line on the screen and the log too
  std::string title;         // the file's first line
  bool title_given = false;  // otherwise "# Fix print/every output for fix ID"
};
PrintEverySettings parse_print_every(KeywordReader &in);
// fix ID group darcy/pressure grid Nx Ny Nz viscosity MU compressibility BETA density RHO
//   permeability KC [keywords]; see doc/fix_darcy_pressure.rst
struct DarcySettings {
  int grid[3] = {0, 0, 0};
  double zhi = 0.0;                  // grid top; the host sets the default (its box top)
  DarcyParams params;                // viscosity, compressibility, kc, clamp, kmax, tol...
  double density = 0.0;              // rho_f
  double gravity[3] = {0.0, 0.0, 0.0};
  bool gravity_given = false;
  NumberOrVariable top;              // Dirichlet top pressure (default 0), if top_dirichlet
  bool top_dirichlet = true;         // false: top noflow, a closed box
  NumberOrVariable z_top;            // where it sits (default: grid top)
  bool z_top_given = false;
  NumberOrVariable bottom;           // Dirichlet bottom pressure, if bottom_dirichlet
  bool bottom_dirichlet = false;
  double initial_pressure = 0.0;
  // the grains of this group get no vertical fluid force (buoyancy included), as the
  // original program's shear plate; empty: none
  std::string novertical_group;
  int seepage = SEEPAGE_PRESSURE;    // the fluid force on the grains: -V grad p, or SEEPAGE_FULL
  bool variables_read_atoms = true;  // `variables global`: top/ztop/bottom read no atom data
  int every = 1;                     // fluid step every this many grain steps
  bool interpolate_every_step = true;  // false: grain forces held between fluid steps
  int profile_every = 0;             // 0: no profile file
  std::string profile_path;
  bool profile_append = false;       // continue the profile file (a run continued from a restart)
  int vtk_every = 0;                 // 0: no VTK files
  std::string vtk_prefix;
};
// box_zlo: the host's box bottom, which the grid starts at; zhi defaults to the host's box
// top and must lie above box_zlo
DarcySettings parse_darcy(KeywordReader &in, double box_zlo, double box_zhi);

}    // namespace porewater

#endif
