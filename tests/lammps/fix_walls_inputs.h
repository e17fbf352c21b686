// Scenes for the tests of fix wall/stress, shear/stress, nve/sphere/ty3 and nve/sphere/bed,
// as LAMMPS input.
#ifndef PW_TEST_FIX_WALLS_INPUTS_H
#define PW_TEST_FIX_WALLS_INPUTS_H

#include <string>

namespace pwtest {

// grains of diameter 1 and mass 1
const std::string unit_grains = "set type 1 diameter 1.0\nset type 1 density 1.90985931710274\n";

// An nx × ny × nz simple cubic stack of touching grains (centres at half-integers) in a box
// periodic in x and y, bounded (f) in z from 0 to zhi; group `bottom` is the lowest layer and
// `mobile` the rest. Frictionless contacts of stiffness kn (newton off, as pair
// linear/coulomb/kk needs). No integrator, no wall.
inline std::string cubic_stack(int nx, int ny, int nz, double zhi, double kn = 1.0e4)
{
  auto s = [](double v) {
    return std::to_string(v);
  };
  return "units lj\natom_style sphere\natom_modify map array\nboundary p p f\nnewton off\n"
         "comm_modify vel yes\n"
         "lattice sc 1.0 origin 0.5 0.5 0.5\n"
         "region box block 0 " +
      s(nx) + " 0 " + s(ny) + " 0 " + s(zhi) +
      " units box\n"
      "create_box 1 box\n"
      "region stack block 0 " +
      s(nx) + " 0 " + s(ny) + " 0 " + s(nz) +
      " units box\n"
      "create_atoms 1 region stack\n" +
      unit_grains + "pair_style linear/coulomb\npair_coeff * * " + s(kn) +
      " 0 0\n"
      "neighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\n"
      "region low block INF INF INF INF INF 1 units box\n"
      "group bottom region low\ngroup mobile subtract all bottom\n";
}

// ---- fix wall/stress ------------------------------------------------------------------

// an empty box 2 × 3 (area 6) from z = 0 to 10, periodic in x and y
const std::string empty_box = "units lj\natom_style sphere\nboundary p p f\n"
                              "region box block 0 2 0 3 0 10\ncreate_box 1 box\ntimestep 0.01\n";

// The stack resting on its held bottom layer, damped, under wall w at `stress` (mass one
// per column of grains, kn 1e4, damping 100, and the wall's further `options`).
inline std::string wall_on_stack(const std::string &stress, int columns,
                                 const std::string &options = "")
{
  return "fix hold bottom setforce 0 0 0\nfix integrate all nve/sphere\n"
         "fix damp mobile viscous 20\n"
         "fix w all wall/stress z auto stress " + stress + " mass " + std::to_string(columns) +
      " kn 1e4 damping 100 " + options + "\n";
}

// the 3 × 3 × 4 stack under the wall: S = 10 on 9 columns of 4 springs in series
// (kn = 1e4) compresses each contact by S/kn = 1e-3
const double STACK_STRESS = 10.0, STACK_KN = 1.0e4;
inline std::string loaded_stack(const std::string &stress = "10", const std::string &options = "")
{
  return cubic_stack(3, 3, 4, 8.0, STACK_KN) + "timestep 5e-4\n" +
      wall_on_stack(stress, 9, options);
}

// a stress that keeps the loaded stack ringing: a moving wall in contact. Written with
// step·dt: this LAMMPS version restarts `time` at 0 after read_restart
const std::string oscillating_stress = "variable s equal 10.0+5.0*sin(2*PI*step*dt/0.3)\n";

// ---- fix shear/stress -----------------------------------------------------------------

// six grains 2 apart in one layer (no contacts) in a 6 × 4 box (area 24), moving in y and z
// and spinning, integrated by `integrator`. τ = 0.5, M = 12 give the plate the acceleration
// τ L_x L_y / M = 1.
const double PLATE_ACCELERATION = 1.0;
inline std::string free_layer(const std::string &integrator)
{
  return "units lj\natom_style sphere\natom_modify map array\nboundary p p f\n"
         "comm_modify vel yes\nlattice sc 0.125 origin 0.5 0.5 0.5\n"
         "region box block 0 6 0 4 -4 8 units box\ncreate_box 1 box\n"
         "region layer block 0 6 0 4 0 2 units box\ncreate_atoms 1 region layer\n" +
      unit_grains +
      "velocity all create 1.0 4321 loop geom\nvelocity all set 0 NULL NULL\n"
      "set group all omega 0.3 -0.2 0.5\n"
      "pair_style zero 1.0\npair_coeff * *\nneighbor 0.2 bin\ntimestep 0.001\n"
      "fix integrate all " + integrator + "\n";
}

// the wall that presses the plate of `nxy`² columns at σ = 10 (mass one per column)
inline std::string plate_wall(int nxy)
{
  return "fix w all wall/stress z auto stress 10 mass " + std::to_string(nxy * nxy) +
      " kn 1e4 damping 100\n";
}

// Two layers of an nxy × nxy cubic stack with friction μ = 0.5: the bottom one fixed (not
// integrated), the top one (`mobile`) pressed on it by the wall until settled (2000 steps).
// Each column's contact then holds at most μσ = 5 per unit area; A/M = 1.
inline std::string pressed_layer(int nxy)
{
  return cubic_stack(nxy, nxy, 2, 5.0) +
      "pair_coeff * * 1e4 1e4 0.5\ntimestep 5e-4\nfix integrate mobile nve/sphere\n" +
      plate_wall(nxy) + "run 2000\n";
}

// the pressed layer sheared as the plate at τ
inline std::string shear_plate(double tau, int nxy)
{
  return "fix s mobile shear/stress tau " + std::to_string(tau) + " mass " +
      std::to_string(nxy * nxy) + "\n";
}
inline std::string sheared_stack(double tau) { return pressed_layer(3) + shear_plate(tau, 3); }

// ---- fix nve/sphere/bed ---------------------------------------------------------------

// A loose bed of nxy × nxy × nz grains (spacing 1.05, jitter 0.02, random velocities) in a box
// periodic in x and y, bounded (f) in z from 0 to 20, frictional contacts (kn = kt = 2000,
// μ = 0.5). Group `bottom` is the lowest layer, 0.025 above the plane z = 0, `bed` the rest.
// No fixes: the tests add the floor, gravity, the held base and the integrators.
const double BED_KN = 2000.0;
inline std::string loose_bed(int nxy = 5, int nz = 5)
{
  const std::string side = std::to_string(1.05 * nxy), top = std::to_string(1.05 * nz);
  return "units lj\natom_style sphere\natom_modify map array\nboundary p p f\nnewton off\n"
         "comm_modify vel yes\nlattice sc 0.863837598531476 origin 0.5 0.5 0.5\n"
         "region box block 0 " + side + " 0 " + side + " 0 20 units box\ncreate_box 1 box\n"
         "region stack block 0 " + side + " 0 " + side + " 0 " + top + " units box\n"
         "create_atoms 1 region stack\n" + unit_grains +
         "displace_atoms all random 0.02 0.02 0.02 8121 units box\n"
         "velocity all create 1.0 8122 loop geom\n"
         "region low block INF INF INF INF INF 1 units box\n"
         "group bottom region low\ngroup bed subtract all bottom\n"
         "velocity bottom set 0 0 0\n"
         "pair_style linear/coulomb\npair_coeff * * 2000 2000 0.5\n"
         "neighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\ntimestep 0.001\n";
}

// LAMMPS' frictionless, undamped floor at z = 0 of stiffness kn (the bed's 2000 unless given)
inline std::string native_floor(const std::string &kn = "2000")
{
  return "fix floor all wall/gran hooke " + kn + " NULL 0.0 NULL 0.0 0 zplane 0.0 NULL\n";
}

// LAMMPS' own fixes for what fix nve/sphere/bed does in one: the floor `floor` (first),
// gravity on the bed, the held base (setforce 0 0 NULL and nve), nve/sphere on the bed
inline std::string bed_fixes_native(const std::string &floor = native_floor())
{
  return floor +
         "fix gravity bed gravity 1.0 vector 0 0 -1\n"
         "fix hold bottom setforce 0.0 0.0 NULL\nfix move_bottom bottom nve\n"
         "fix move bed nve/sphere\n";
}

}    // namespace pwtest

#endif
