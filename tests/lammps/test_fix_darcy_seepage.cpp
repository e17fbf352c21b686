// fix darcy/pressure's two seepage forces through LAMMPS on a grid whose pressure and porosity
// are known exactly: seepage pressure puts -V grad p on a grain, seepage full -V grad p/(1 - phi)
// = -grad p times the bulk volume per grain. CPU and KOKKOS. The factor against hand-made
// fields is unit-tested (tests/unit/test_darcy_coupling.cpp), each force's consolidation
// against its closed form in lammps.seepage_consolidation (bench/seepage), the restart in
// test_restart_mismatch.cpp, /kk, MPI and restart splits in the style matrix.
#include "darcy_inputs.h"
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using pwtest::Accel;
using pwtest::Lammps;

namespace {

const double PI = 3.14159265358979323846;
const double SPACING = 0.02;    // a: the lattice's spacing and the grains' diameter

// The simple-cubic lattice of touching grains of FixDarcyPressure.SimpleCubicLatticeHas...:
// 8 x 6 x 8 grains in cells of 2a, porosity 1 - pi/6 in every cell exactly (the hat weights
// of the rows sum to 2 per axis, the stencils fold at the bottom and top where the lattice is
// its own mirror image). The fluid: p = 1000 at the bottom face, -500 at the top, k uniform
// (the porosity is), so the steady p is linear, dp/dz = -1500/(8a), and its central
// differences and their interpolation at the grains are exact. The grains do not move. 300
// steps of 0.01 s: the slowest mode (pi^2 D/H^2 = 318/s, D = k/(beta phi mu) = 0.82 m^2/s)
// decays by e^-950. Returns the per-grain fluid force by atom ID.
std::map<long, std::vector<double>> lattice_forces(Accel accel, const std::string &seepage)
{
  Lammps l(accel);
  l.commands("units si\natom_style sphere\natom_modify map array\nboundary p p f\nnewton off\n"
             "lattice sc 0.02 origin 0.5 0.5 0.5\nregion box block 0 8 0 6 0 8\ncreate_box 1 box\n"
             "create_atoms 1 box\nset type 1 diameter 0.02\nset type 1 density 2600\n"
             "timestep 0.01\n");
  l.command("fix fl all darcy/pressure grid 4 3 4" + pwtest::unit_diffusivity +
            " bottom 1000 top -500 tol 1e-13 seepage " + seepage);
  l.command("run 300");
  EXPECT_NEAR(l.equal("f_fl[2]"), 1.0 - PI / 6, 1e-14);
  return l.gather3("f_fl");
}

void full_force_is_the_bulk_volume_per_grain_times_the_gradient(Accel accel)
{
  const double gradient = -1500.0 / (8 * SPACING);
  const double volume = PI / 6 * SPACING * SPACING * SPACING;
  const auto pressure = lattice_forces(accel, "pressure"), full = lattice_forces(accel, "full");
  ASSERT_EQ(full.size(), 8u * 6u * 8u);
  // the linear p to the solve's tolerance, 1e-13 of 1000 Pa: 1e-9 of the force allows 200x that
  const double bulk = SPACING * SPACING * SPACING;    // V/(1 - phi) = a^3
  double worst = 0.0;
  for (const auto &grain : full) {
    const std::vector<double> &f = grain.second, &f_pressure = pressure.at(grain.first);
    EXPECT_NEAR(f_pressure[2], -volume * gradient, 1e-9 * volume * std::fabs(gradient));
    EXPECT_NEAR(f[2], -bulk * gradient, 1e-9 * bulk * std::fabs(gradient));
    // the factor 1/(1 - phi) = 6/pi on the very same field
    worst = std::max(worst, std::fabs(f[2] / f_pressure[2] - 6.0 / PI));
    for (int d = 0; d < 2; ++d) {
      EXPECT_NEAR(f[d], 0.0, 1e-12 * bulk * std::fabs(gradient));
      EXPECT_NEAR(f_pressure[d], 0.0, 1e-12 * volume * std::fabs(gradient));
    }
  }
  std::printf("[ report ] seepage full / seepage pressure: 6/pi to %.1e on 384 grains\n", worst);
  EXPECT_LT(worst, 1e-12);
}

}    // namespace

PW_TEST_CPU_AND_KOKKOS(FixDarcySeepage, FullForceIsTheBulkVolumePerGrainTimesTheGradient,
                       full_force_is_the_bulk_volume_per_grain_times_the_gradient)
