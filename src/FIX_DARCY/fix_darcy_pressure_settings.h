/* -*- c++ -*- ----------------------------------------------------------
   The command line of fix darcy/pressure, parsed and checked
   (fix_darcy_pressure_settings.cpp; keywords in doc/fix_darcy_pressure.rst).
------------------------------------------------------------------------- */

#ifndef PW_FIX_DARCY_PRESSURE_SETTINGS_H
#define PW_FIX_DARCY_PRESSURE_SETTINGS_H

#include "darcy_solver.h"

#include <string>

namespace LAMMPS_NS {

class LAMMPS;

struct DarcyFixSettings {
  // a constant or an equal-style variable (v_name), evaluated on fluid steps
  struct Value {
    double value = 0.0;
    std::string variable;    // empty: constant
    int ivar = -1;           // resolved in init()
  };

  int grid[3] = {0, 0, 0};
  double zhi = 0.0;                  // grid top (default: box top when defined)
  porewater::DarcyParams params;     // viscosity, compressibility, kc, clamp, kmax, tol...
  double density = 0.0;              // rho_f
  double gravity[3] = {0.0, 0.0, 0.0};
  bool gravity_given = false;
  Value top;                         // Dirichlet top pressure (default 0), if top_dirichlet
  bool top_dirichlet = true;         // false: top noflow, a closed box
  Value z_top;                       // where it sits (default: grid top)
  bool z_top_given = false;
  Value bottom;                      // Dirichlet bottom pressure, if bottom_dirichlet
  bool bottom_dirichlet = false;
  double initial_pressure = 0.0;
  int every = 1;                     // fluid step every this many grain steps
  bool interpolate_every_step = true;  // false: grain forces held between fluid steps
  int profile_every = 0;             // 0: no profile file
  std::string profile_path;
  int vtk_every = 0;                 // 0: no VTK files
  std::string vtk_prefix;
};

// arg as given to the fix (arg[3] is the first keyword); bad input is error->all naming
// the keyword and what it accepts
DarcyFixSettings parse_darcy_fix_settings(LAMMPS *lmp, int narg, char **arg);

}    // namespace LAMMPS_NS

#endif
