// Scenes for the tests of fix darcy/pressure, as LAMMPS input.
#ifndef PW_TEST_DARCY_INPUTS_H
#define PW_TEST_DARCY_INPUTS_H

#include <string>

namespace pwtest {

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
