// fix darcy/pressure's two seepage forces through LAMMPS on a grid whose pressure and porosity
// are known exactly: seepage pressure puts -V grad p on a grain, seepage full -V grad p/(1 - phi)
// = -grad p times the bulk volume per grain; on a bed whose porosity steps, the grains' forces
// sum to the water's force on the cells under full and to its solids' share under pressure;
// under full a bed floats at the gradient (1 - phi)(rho_s - rho_f) g. CPU and KOKKOS, and on
// 2 and 3 ranks (*Mpi*). The interpolation against hand-made fields is unit-tested
// (tests/unit/test_darcy_coupling.cpp), each force's consolidation against its closed form in
// lammps.seepage_consolidation (bench/seepage), the restart in test_restart_mismatch.cpp,
// /kk, MPI and restart splits in the style matrix.
#include "darcy_inputs.h"
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

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

namespace {

// The lattice of lattice_forces, its upper half (z > 4a) of grains of diameter 0.8a: a loose
// layer (phi 1 - 0.512 pi/6 = 0.732) over a dense one (0.476), the cells between them mixed
// (the rows at 3.5a and 4.5a straddle cells 1 and 2). The same fluid, solved to steady state;
// the grains held. Returns {the grains' total fluid force along z, the same as the cells'
// closed form: -sum_c dp/dz_c s_c V_cell over the cells (s_c = 1 under full, the cell's solid
// fraction 1 - phi_c under pressure), with dp/dz from the cells' pressures as the fix takes
// it (central differences, the Dirichlet faces' ghosts 2 p_face - p)}, and the total x and y
// forces' largest magnitude.
struct Sums {
  double grains, cells, lateral, phi_low, phi_high;
};

Sums porosity_step_sums(Accel accel, const std::string &seepage, MPI_Comm comm = MPI_COMM_WORLD)
{
  Lammps l(accel, comm);
  l.commands("units si\natom_style sphere\natom_modify map array\nboundary p p f\nnewton off\n"
             "lattice sc 0.02 origin 0.5 0.5 0.5\nregion box block 0 8 0 6 0 8\ncreate_box 1 box\n"
             "create_atoms 1 box\nset type 1 diameter 0.02\nset type 1 density 2600\n"
             "region upper block INF INF INF INF 4 INF\nset region upper diameter 0.016\n"
             "timestep 0.01\n");
  l.command("fix fl all darcy/pressure grid 4 3 4" + pwtest::unit_diffusivity +
            " bottom 1000 top -500 tol 1e-13 seepage " + seepage);
  l.command("run 300");
  const int nx = 4, ny = 3, nz = 4, n = nx * ny * nz;
  const std::vector<double> p = l.fix_field("fl", "pressure", n), phi = l.fix_field("fl", "porosity", n);
  const double a = SPACING, v_cell = 8 * a * a * a, dz = 2 * a;
  Sums s{0.0, 0.0, 0.0, 1.0, 0.0};
  for (int k = 0; k < nz; ++k)
    for (int c = k * nx * ny; c < (k + 1) * nx * ny; ++c) {
      const double below = k > 0 ? p[c - nx * ny] : 2.0 * 1000.0 - p[c];
      const double above = k < nz - 1 ? p[c + nx * ny] : 2.0 * -500.0 - p[c];
      const double share = seepage == "full" ? 1.0 : 1.0 - phi[c];
      s.cells -= (above - below) / (2.0 * dz) * share * v_cell;
      s.phi_low = std::min(s.phi_low, phi[c]);
      s.phi_high = std::max(s.phi_high, phi[c]);
    }
  double lateral[2] = {0.0, 0.0};
  for (const auto &grain : l.gather3("f_fl")) {
    s.grains += grain.second[2];
    for (int d = 0; d < 2; ++d) lateral[d] += grain.second[d];
  }
  s.lateral = std::max(std::fabs(lateral[0]), std::fabs(lateral[1]));
  return s;
}

// The water's whole force on the bed under full, the pressure drop across it times its
// area: 1500 Pa x (8a)(6a) = 28.8 N, from the telescoping central differences, whatever the
// porosity; under pressure the cells' solid fractions weigh it. Both to round-off (1e-12 of
// the total: the sums of 384 forces); the lateral totals vanish.
void forces_sum_to_the_waters_force_on_a_bed_whose_porosity_steps(Accel accel, MPI_Comm comm)
{
  const double area = 8 * SPACING * 6 * SPACING, total = 1500.0 * area;
  for (const std::string seepage : {"full", "pressure"}) {
    const Sums s = porosity_step_sums(accel, seepage, comm);
    std::printf("[ report ] seepage %s: grains %.15g N, cells %.15g N (water's force %.15g N), "
                "phi %.3f-%.3f\n",
                seepage.c_str(), s.grains, s.cells, total, s.phi_low, s.phi_high);
    EXPECT_LT(s.phi_low, 0.5);    // the step is there
    EXPECT_GT(s.phi_high, 0.7);
    EXPECT_NEAR(s.grains, s.cells, 1e-12 * total) << seepage;
    EXPECT_NEAR(s.lateral, 0.0, 1e-12 * total) << seepage;
    if (seepage == "full") EXPECT_NEAR(s.grains, total, 1e-12 * total);
    else EXPECT_LT(s.grains, 0.6 * total);    // the solids' share, 27-52 % by cell
  }
}

void on_this_rank(Accel accel)
{
  forces_sum_to_the_waters_force_on_a_bed_whose_porosity_steps(accel, MPI_COMM_WORLD);
}

}    // namespace

PW_TEST_CPU_AND_KOKKOS(FixDarcySeepage, ForcesSumToTheWatersForceOnABedWhosePorositySteps,
                       on_this_rank)
// under mpirun -np 2 and 3 (ctest ...np2, np3) the grid's deposits and the grains are spread
// over the ranks: the same sums
PW_TEST_CPU_AND_KOKKOS(FixDarcySeepage, ForcesSumToTheWatersForceMpiDecomposed, on_this_rank)

namespace {

// The bed of pwtest::bed() four layers high (0.04 m), its grid's top at its surface (grid 2 2
// 2 zhi 0.04: the stencils fold at both faces, so every cell holds two layers of grains,
// phi = 1 - pi/6 in each, and every grain's seepage factor is 1/(1 - phi)); a Dirichlet
// bottom p_b and the top 0 give the uniform gradient -p_b/0.04 in steady state (k capped
// uniform). Under seepage full a grain floats when -dp/dz V/(1 - phi) exceeds its buoyant
// weight (rho_s - rho_f) g V: at the gradient (1 - phi)(rho_s - rho_f) g, pi/6 of seepage
// pressure's. The fluid settles with the grains held (150 steps), then they move for 0.05 s.
double full_mean_rise(double factor)
{
  const double phi = 1.0 - PI / 6.0, critical = (1.0 - phi) * pwtest::critical_gradient;
  std::string bed = pwtest::bed();
  bed.replace(bed.find("region bed block 0 8 0 8 0 5"), 28, "region bed block 0 8 0 8 0 4");
  Lammps l;
  l.commands(bed);
  std::string fluid = pwtest::bed_fluid(factor * critical * 0.04, 1);
  fluid.replace(fluid.find("grid 2 2 10"), 11, "grid 2 2 2 zhi 0.04");
  l.command(fluid + " seepage full");
  l.command("run 150");
  EXPECT_NEAR(l.equal("f_fl[2]"), phi, 1e-12);    // uniform, as said
  const double z0 = l.equal("v_zmean");
  l.commands("fix move mobile nve/sphere\nrun 2000\n");
  return l.equal("v_zmean") - z0;
}

}    // namespace

TEST(FixDarcySeepage, FullForceFloatsTheBedAtItsCriticalGradient)
{
  const double below = full_mean_rise(0.9), above = full_mean_rise(2.0);
  std::printf("[ report ] seepage full, fluidisation: mean rise %.3e m at 0.9x, %.3e m at 2x "
              "(1 - phi)(rho_s - rho_f) g\n",
              below, above);
  // at rest: the contacts carry the remaining 10 % of the buoyant weight (elastic, ~1e-7 m)
  EXPECT_LT(std::fabs(below), 1e-4);    // 1 % of a diameter
  // lifted: the net upward force is the buoyant weight, a = 6.0 m/s^2 for 0.05 s: 7.5 mm,
  // less the suction of the dilating bed
  EXPECT_GT(above, 3e-3);
}
