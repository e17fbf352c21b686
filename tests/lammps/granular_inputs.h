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

// A periodic box of `nside`^3 grains of diameter 1 on a jittered lattice (spacing 1.05,
// jitter 0.02), random velocities, no gravity: a dense granular gas with many collisions
// per 100 steps.
const double dense_gas_spacing = 1.05;
inline std::string dense_gas(int nside = 8, int seed = 12345)
{
  const double len = dense_gas_spacing * nside;
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

// The dense gas of 6^3 grains with friction: pair linear/coulomb kn = kt = 2000, μ = 0.5.
inline std::string frictional_gas()
{
  return dense_gas(6) + "pair_style linear/coulomb\npair_coeff * * 2000.0 2000.0 0.5\n";
}

// LAMMPS' bench/data.chute cut to 3044 grains (x < 19, y < 4 of a 20 × 5 box, so that no
// grain overlaps across the new periodic seams), damping off: a dense flow under gravity on
// a frozen base, integrated by nve/sphere. Everything but the pair style.
inline std::string chute()
{
  return "units lj\natom_style sphere\nboundary p p fs\nnewton off\ncomm_modify vel yes\n"
         "read_data " PW_LAMMPS_BENCH "/data.chute\n"
         "region keep block 0 19 0 4 INF INF units box side out\n"
         "delete_atoms region keep\n"
         "change_box all x final 0 20 y final 0 5 units box\n"
         "reset_atom_ids\n"
         "neighbor 0.1 bin\nneigh_modify every 1 delay 0\ntimestep 0.0001\n"
         "group bottom type 2\ngroup active subtract all bottom\n"
         "neigh_modify exclude group bottom bottom\n"
         "fix 1 all gravity 1.0 chute 26.0\nfix 2 bottom freeze\nfix 3 active nve/sphere\n";
}

}    // namespace pwtest

#endif
