// Scenes for the tests of fix darcy/pressure, as LAMMPS input.
#ifndef PW_TEST_DARCY_INPUTS_H
#define PW_TEST_DARCY_INPUTS_H

#include <string>

namespace pwtest {

// Grain-free column [0,1]^2 x [0,height], z non-periodic. With `unit_diffusivity` the fix's
// parameters give D = k/(beta phi mu) = 1: no grains, so phi = MAX = 0.9, and k = kmax = 0.9
// (the Kozeny-Carman value 72.9 lies above the cap).
inline std::string empty_column(double height = 1.0)
{
  return "units lj\natom_style sphere\nboundary p p f\nregion box block 0 1 0 1 0 " +
      std::to_string(height) + "\ncreate_box 1 box\n";
}
const std::string unit_diffusivity =
    " viscosity 1 compressibility 1 density 1 permeability 1 kmax 0.9";

// Simple-cubic bed of 8 x 8 x 5 grains of diameter d = 0.01 m (SI units) touching in
// columns, the bottom layer (`floor`) not integrated, in a 0.08 x 0.08 x 0.2 m box, under
// gravity; `processors` is put before the box is made. No fluid, no integrator.
inline std::string bed(const std::string &processors = "")
{
  return "units si\natom_style sphere\natom_modify map array\nboundary p p f\n"
         "comm_modify vel yes\n" + processors + "\n"
         "lattice sc 0.01 origin 0.5 0.5 0.5\nregion box block 0 8 0 8 0 20\n"
         "create_box 1 box\nregion bed block 0 8 0 8 0 5\ncreate_atoms 1 region bed\n"
         "set type 1 diameter 0.01\nset type 1 density 2600\n"
         "region floor block INF INF INF INF INF 0.01 units box\ngroup floor region floor\n"
         "group mobile subtract all floor\n"
         "pair_style gran/hooke/history 1e4 NULL 0 NULL 0.5 0\npair_coeff * *\n"
         "neighbor 0.002 bin\nneigh_modify delay 0 every 1 check yes\ntimestep 2.5e-5\n"
         "fix weight mobile gravity 9.81 vector 0 0 -1\n"
         "variable zmean equal xcm(mobile,z)\n";
}

// The bed's fluid, fix fl: grid 2 x 2 x 10 from z = 0 to 0.2 with k capped to a uniform
// 1e-7 m^2 (kc is 1000x the cap, so the cap holds for every porosity >= 0.1): a Dirichlet
// bottom p_b and a top 0 then give the uniform gradient -p_b/0.2 in steady state, grains or
// not.
inline std::string bed_fluid(double p_bottom, int every)
{
  return "fix fl all darcy/pressure grid 2 2 10 viscosity 1e-3 compressibility 5e-6 "
         "density 1000 permeability 1e-4 kmax 1e-7 gravity 0 0 -9.81 bottom " +
      std::to_string(p_bottom) + " every " + std::to_string(every);
}
const int bed_cells = 2 * 2 * 10;

// buoyant weight per grain volume, (rho_s - rho_f) g: the gradient that floats a grain
const double critical_gradient = (2600.0 - 1000.0) * 9.81;
// the bottom pressure that lifts the bed: twice the critical gradient over the column
const double lifting_pressure = 2.0 * critical_gradient * 0.2;

// Two runs that differ by round-off agree in p only to the CG tolerance, 1e-10 max|p|
// (the solves stop at different iterates), here 1e-10 * p_b = 6e-7 Pa: allow 10x that.
const double bed_p_agreement = 1e-9 * lifting_pressure;

// 4 x 4 x 4 box, z closed by reflecting walls, 64 grains of diameter 0.8 on a unit lattice
// (no contacts, no pair style: they move only by their velocity and the fluid force),
// integrated by nve/sphere. No fluid.
const std::string grains_in_box =
    "units lj\natom_style sphere\natom_modify map array\nboundary p p f\n"
    "comm_modify vel yes cutoff 1.0\nlattice sc 1.0 origin 0.5 0.5 0.5\n"
    "region box block 0 4 0 4 0 4\ncreate_box 1 box\ncreate_atoms 1 region box\n"
    "set type 1 diameter 0.8\nset type 1 density 1.0\ntimestep 0.01\n"
    "fix move all nve/sphere\nfix walls all wall/reflect zlo EDGE zhi EDGE\n";
// their fluid, fix fl, closed on all sides: mu = beta = 1, k capped at 0.01
const std::string closed_box_fluid =
    "fix fl all darcy/pressure grid 2 2 2 viscosity 1 compressibility 1 density 1 "
    "permeability 1 kmax 0.01 top noflow bottom noflow";

}    // namespace pwtest

#endif
