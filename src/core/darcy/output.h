// Text output of the Darcy grid for fix darcy/pressure: x-y averaged z-profiles and legacy
// VTK files for ParaView. Host-free; DarcyFluid writes them on one rank.
#ifndef PW_DARCY_OUTPUT_H
#define PW_DARCY_OUTPUT_H

#include "darcy/solver.h"

#include <cstdio>
#include <string>

namespace porewater {

// Comment lines naming the columns of write_profile's rows.
void write_profile_header(std::FILE *fp, const std::string &fix_id);

// One block: "step time nlayers active_layers", then per layer k (bottom first)
// "k z p phi k_perm vbar_z": p, phi, k are plain x-y means; vbar_z is weighted with the
// solid fraction 1 - phi (the layer's mean grain velocity).
void write_profile(std::FILE *fp, const DarcySolver &solver, long long step, double time);

// A profile file continued by a run that starts at `step` (`append yes`): keeps its comment
// lines and the blocks up to `step` (the run that wrote the restart file wrote the block of
// its step; those a killed run wrote after it are dropped) and opens it for appending.
// Returns nullptr if it cannot be read or rewritten; `has_header` tells whether the kept
// file already names its columns.
std::FILE *continue_profile(const std::string &path, long long step, bool &has_header);

// Legacy ASCII VTK rectilinear grid (cell faces as coordinates) with the cell fields
// pressure, porosity, permeability, mean_velocity and pressure_gradient. Returns false if
// the file cannot be written.
bool write_vtk(const std::string &path, const DarcySolver &solver, long long step,
               double time);

}  // namespace porewater

#endif
