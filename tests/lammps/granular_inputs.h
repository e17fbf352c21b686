// Small granular scenes shared by the tests, written as LAMMPS input text.
#ifndef PW_TEST_GRANULAR_INPUTS_H
#define PW_TEST_GRANULAR_INPUTS_H

#include <string>

namespace pwtest {

// Settings of the dense gas below that a restart file does not carry.
inline std::string dense_gas_settings()
{
  return "newton off on\n"    // pair off: the KOKKOS neighbor history of this LAMMPS needs it
         "comm_modify vel yes\n"
         "neighbor 0.2 bin\n"
         "neigh_modify delay 0 every 1 check yes\n"
         "fix integrate all nve/sphere\n"
         "compute erot all erotate/sphere\n"
         "thermo_style custom step atoms ke c_erot pe press\n"
         "thermo_modify norm no\n";
}

// A periodic box of `nside`^3 grains of diameter 1 on a jittered lattice (spacing 1.05),
// random velocities, no gravity: a dense granular gas with many collisions per 100 steps.
inline std::string dense_gas(int nside = 8, int seed = 12345)
{
  const double len = 1.05 * nside;
  return "units lj\n"
         "atom_style sphere\n"
         "atom_modify map array\n"
         "boundary p p p\n"
         "lattice sc 0.863837598531476\n"    // reduced density 1/1.05³: spacing 1.05
         "region box block 0 " + std::to_string(len) + " 0 " + std::to_string(len) + " 0 " +
         std::to_string(len) + " units box\n"
         "create_box 1 box\n"
         "create_atoms 1 box\n"
         "set type 1 diameter 1.0\n"
         "set type 1 density 1.9099\n"    // mass 1
         "displace_atoms all random 0.02 0.02 0.02 " + std::to_string(seed) + " units box\n"
         "velocity all create 2.0 " + std::to_string(seed + 1) + " loop geom\n"
         "timestep 0.0005\n" + dense_gas_settings();
}

}    // namespace pwtest

#endif
