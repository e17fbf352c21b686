// fix darcy/pressure driven through LAMMPS: exact zero, Terzaghi and a tidal top through
// the fix's wiring (timestep, every, variables, profile file), the force on one grain,
// porosity of a lattice, fluidisation of a bed. KOKKOS, MPI decompositions, restarts and
// bad input: the style matrix (test_style_matrix.cpp). The solver's accuracy itself is
// tested in tests/unit/test_darcy_solver.cpp.
#include "darcy_inputs.h"
#include "lammps_fixture.h"

#include "analytic_solutions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

using pwtest::Lammps;
using pwtest::critical_gradient;
using pwtest::empty_column;
using pwtest::max_abs_diff;
using pwtest::unit_diffusivity;

namespace {

const double PI = 3.14159265358979323846;

// a per-cell field of fix fl (flat, x fastest)
std::vector<double> field(Lammps &l, const char *name, int size)
{
  return l.fix_field("fl", name, size);
}

// the blocks of a profile file: step -> per layer {z, p, phi, k, vbar_z}
std::map<long, std::vector<std::vector<double>>> read_profile(const std::string &path)
{
  std::map<long, std::vector<std::vector<double>>> blocks;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream head(line);
    long step;
    double time;
    int layers, active;
    head >> step >> time >> layers >> active;
    auto &rows = blocks[step];
    for (int k = 0; k < layers && std::getline(in, line); ++k) {
      std::istringstream row(line);
      int layer;
      std::vector<double> values(5);
      row >> layer;
      for (double &v : values) row >> v;
      rows.push_back(values);
    }
  }
  return blocks;
}

}    // namespace

// ---------------------------------------------------------------------------------------

TEST(FixDarcyPressure, NoGrainsStaysExactlyZero)
{
  for (const char *bottom : {"noflow", "0.0"}) {    // closed below, or fixed at both ends
    Lammps l;
    l.commands(empty_column(1.0));
    l.command(std::string("fix fl all darcy/pressure grid 3 2 8") + unit_diffusivity +
              " bottom " + bottom + " every 3");
    l.commands("timestep 0.01\nrun 200\n");
    for (double p : field(l, "pressure", 3 * 2 * 8)) ASSERT_EQ(p, 0.0) << bottom;
    for (double g : field(l, "pressure_gradient", 3 * 3 * 2 * 8)) ASSERT_EQ(g, 0.0) << bottom;
    EXPECT_EQ(l.equal("f_fl[4]"), 0.0) << bottom;    // iterations of the last solve
    EXPECT_EQ(l.equal("f_fl[5]"), 0.0) << bottom;    // its residual
    EXPECT_EQ(l.equal("f_fl[3]"), 0.0) << bottom;    // max |p|
    EXPECT_NEAR(l.equal("f_fl[2]"), 0.9, 1e-15) << bottom;    // no grains: phi = MAX
  }
}

TEST(FixDarcyPressure, SteadyStateSolvesInZeroIterationsAndKeepsPExactly)
{
  // Dirichlet 1 below, 0 on top, D = 1, 8 layers of 0.125: after 400 steps of 0.01 the
  // slowest mode is down by e^-99, far below tol 1e-12, so the warm-started solve (for the
  // change of p) meets the tolerance before any CG iteration and p stays bit-for-bit.
  for (const char *every : {"1", "3"}) {
    Lammps l;
    l.commands(empty_column(1.0));
    l.command(std::string("fix fl all darcy/pressure grid 2 1 8") + unit_diffusivity +
              " bottom 1 tol 1e-12 every " + every);
    l.commands("timestep 0.01\nrun 400\n");
    const auto steady = field(l, "pressure", 16);
    EXPECT_NEAR(steady[0], 1.0 - 0.0625, 1e-11) << every;    // linear: 1 - z
    l.command("run 30");
    EXPECT_EQ(l.equal("f_fl[4]"), 0.0) << every;    // iterations of the last solve
    EXPECT_EQ(max_abs_diff(field(l, "pressure", 16), steady), 0.0) << every;
  }
}

TEST(FixDarcyPressure, TerzaghiThroughTheFixUsesTimestepAndEvery)
{
  // D = 1, H = 1, 40 layers; fluid step 4e-4 either as 4 steps of 1e-4 or 1 of 4e-4
  // (D dt_f/dz^2 = 0.64). p at steps 500 and 2000 of the first run: T_v = 0.05 and 0.2.
  const std::string profile = "pw_darcy_terzaghi.profile";
  const int nz = 40;
  std::vector<double> by_every, by_timestep;
  {
    Lammps l;
    l.commands(empty_column(1.0));
    l.command("fix fl all darcy/pressure grid 2 1 " + std::to_string(nz) + unit_diffusivity +
              " initial 1.0 every 4 profile 500 " + profile);
    l.commands("timestep 1e-4\nrun 2000\n");
    by_every = field(l, "pressure", 2 * nz);
    EXPECT_GT(l.equal("f_fl[4]"), 0.0);                      // the solve did iterate
    EXPECT_LE(l.equal("f_fl[5]"), 1e-10 * l.equal("f_fl[3]"));    // to tol 1e-10 max|p|
  }
  {
    Lammps l;
    l.commands(empty_column(1.0));
    l.command("fix fl all darcy/pressure grid 2 1 " + std::to_string(nz) + unit_diffusivity +
              " initial 1.0");
    l.commands("timestep 4e-4\nrun 500\n");
    by_timestep = field(l, "pressure", 2 * nz);
  }
  // the same solves, but 4 * 1e-4 and 4e-4 may differ in the last bit: CG stops at 1e-10
  // relative, so the two may differ by that much
  EXPECT_LT(max_abs_diff(by_every, by_timestep), 1e-9);

  const auto blocks = read_profile(profile);
  std::remove(profile.c_str());
  ASSERT_EQ(blocks.size(), 5u);    // steps 0, 500, ..., 2000
  double worst[2] = {0.0, 0.0};
  const long steps[2] = {500, 2000};
  for (int s = 0; s < 2; ++s) {
    const auto &rows = blocks.at(steps[s]);
    ASSERT_EQ(rows.size(), (size_t) nz);
    for (const auto &row : rows)
      worst[s] = std::max(worst[s], std::fabs(row[1] - pwtest::terzaghi(1.0, row[0], 1.0, 1.0,
                                                                         steps[s] * 1e-4)));
  }
  // the profile holds the fix's state: layer means of the extracted field, to print digits
  EXPECT_NEAR(blocks.at(2000)[7][1], 0.5 * (by_every[14] + by_every[15]), 1e-15);
  // The scheme is second order in dz and dt (unit test: 1.6e-4 at T 0.05 with 64 layers),
  // so 40 layers should give ~1.6e-4 (64/40)^2 = 4.1e-4: measured 4.0e-4 (T 0.05) and
  // 9.0e-5 (T 0.2). A timestep or `every` wired wrongly (time off by 4x) errs by > 0.1.
  std::printf("[ report ] Terzaghi through the fix: max |p - series| = %.2e (T 0.05), "
              "%.2e (T 0.2)\n", worst[0], worst[1]);
  EXPECT_LT(worst[0], 6e-4);
  EXPECT_LT(worst[1], 1.5e-4);
}

TEST(FixDarcyPressure, SinusoidalTopDecaysWithDepth)
{
  // D = 1, f = 10, omega = 20 pi: skin depth delta = sqrt(2D/omega) = 0.178; column 1 =
  // 5.6 delta, 60 layers (11 per delta), 200 steps per period. p starts at 0; the start-up
  // transient has decayed to ~1e-3 after 9 periods. Fourier projection over the 10th
  // period from 20 samples (exact for a sinusoid).
  Lammps l;
  l.commands(empty_column(1.0));
  l.command("variable ptop equal 2.0*sin(2*PI*10*time)");
  l.command("fix fl all darcy/pressure grid 1 1 60" + unit_diffusivity + " top v_ptop");
  l.commands("timestep 5e-4\nrun 1800\n");
  const double omega = 20 * PI, delta = std::sqrt(2.0 / omega), amplitude = 2.0;
  std::vector<double> a_sin(60, 0.0), a_cos(60, 0.0);
  for (int n = 1; n <= 20; ++n) {
    l.command("run 10 pre no post no");
    const double t = 1800 * 5e-4 + n * 10 * 5e-4;
    EXPECT_NEAR(l.equal("f_fl[6]"), amplitude * std::sin(omega * t), 1e-12);
    const auto p = field(l, "pressure", 60);
    for (int k = 0; k < 60; ++k) {
      a_sin[k] += 2.0 / 20 * p[k] * std::sin(omega * t);
      a_cos[k] += 2.0 / 20 * p[k] * std::cos(omega * t);
    }
  }
  double amp_error = 0.0, lag_error = 0.0;
  for (int k = 0; k < 60; ++k) {
    const double depth = 1.0 - (k + 0.5) / 60;
    if (depth > 2 * delta) continue;
    const double amp = std::hypot(a_sin[k], a_cos[k]), lag = -std::atan2(a_cos[k], a_sin[k]);
    amp_error = std::max(amp_error, std::fabs(amp / (amplitude * std::exp(-depth / delta)) - 1));
    lag_error = std::max(lag_error, std::fabs(lag - depth / delta));
  }
  // loose (the unit test is strict): semi-infinite e^(-d/delta) and lag d/delta to 1% and
  // 0.01 rad; measured 1.5e-3 and 2.2e-3 rad (discretisation, as in the unit test)
  std::printf("[ report ] tidal top through the fix: amplitude error %.2e, lag error %.2e rad\n",
              amp_error, lag_error);
  EXPECT_LT(amp_error, 0.01);
  EXPECT_LT(lag_error, 0.01);
}

TEST(FixDarcyPressure, ZtopVariableMovesTheTopConditionAndVtkHoldsTheGrid)
{
  // 10 layers of 0.1, bottom 1, top 0 at ztop = 0.62 (a variable): layers with centres
  // below 0.62 (6) are active and the Dirichlet face is at 0.6, so p = 1 - z/0.6 there
  // and 0 above. D = 1: 400 steps of 0.01 leave the slowest mode at e^-110.
  const std::string prefix = "pw_darcy_ztop";
  Lammps l;
  l.commands(empty_column(1.0));
  l.command("variable zt equal 0.62");
  l.command("fix fl all darcy/pressure grid 1 2 10" + unit_diffusivity +
            " bottom 1 ztop v_zt tol 1e-13 vtk 400 " + prefix);
  l.commands("timestep 0.01\nrun 400\n");
  const auto p = field(l, "pressure", 20);
  double mean = 0.0;
  for (int c = 0; c < 20; ++c) {
    const int k = c / 2;
    const double expected = k < 6 ? 1.0 - (k + 0.5) * 0.1 / 0.6 : 0.0;
    EXPECT_NEAR(p[c], expected, 1e-10) << c;
    if (k < 6) mean += expected / 12;
  }
  EXPECT_NEAR(l.equal("f_fl[1]"), mean, 1e-10);    // mean p of the active cells
  EXPECT_NEAR(l.equal("f_fl[13]"), 1.0 - 0.55 / 0.6, 1e-10);    // the top active layer's
  // the VTK file of step 400 carries the same pressures (printed to 16 digits)
  const std::string path = prefix + "_400.vtk";
  std::ifstream in(path);
  std::string line;
  std::vector<double> from_vtk;
  while (std::getline(in, line) && line != "SCALARS pressure double 1") {}
  std::getline(in, line);    // LOOKUP_TABLE
  for (int c = 0; c < 20 && std::getline(in, line); ++c) from_vtk.push_back(std::stod(line));
  std::remove(path.c_str());
  std::remove((prefix + "_0.vtk").c_str());
  ASSERT_EQ(from_vtk.size(), 20u);
  EXPECT_LT(max_abs_diff(from_vtk, p), 1e-15);
}

TEST(FixDarcyPressure, OneGrainFeelsTheGradientAndBuoyancy)
{
  // A static grain of radius 0.01 in 0.25 x 0.25 x 0.1 cells deposits at most 0.07% solid:
  // its cells stay at phi = MAX, k stays uniform and the steady profile exactly linear.
  const double radius = 0.01, volume = 4.0 / 3.0 * PI * radius * radius * radius;
  auto scene = [&](Lammps &l, const std::string &fluid) {
    l.commands("units si\natom_style sphere\nboundary p p f\nregion box block 0 0.5 0 0.5 0 1\n"
               "create_box 1 box\ncreate_atoms 1 single 0.13 0.41 0.437\n"
               "set atom 1 diameter 0.02\nset atom 1 density 2600\ntimestep 0.02\n");
    l.command("fix fl all darcy/pressure grid 2 2 10" + unit_diffusivity + fluid);
  };
  {
    // bottom 1000, top -500: D = 1, slowest mode decays as exp(-pi^2 t), 300 steps of
    // 0.02: e^-59; p then linear to about the CG tolerance 1e-13 * 1000 (measured 7e-10)
    Lammps l;
    scene(l, " bottom 1000 top -500 tol 1e-13");
    l.command("run 300");
    const auto p = field(l, "pressure", 40);
    double worst = 0.0;
    for (int c = 0; c < 40; ++c)
      worst = std::max(worst, std::fabs(p[c] - (1000.0 - 1500.0 * ((c / 4) + 0.5) / 10)));
    std::printf("[ report ] linear profile: max |p - exact| = %.2e of 1000\n", worst);
    EXPECT_LT(worst, 5e-9);
    const double expected = volume * 1500.0;    // -V dp/dz, dp/dz = -1500
    const double *f = l.atom()->f[0];
    const double *fluid = ((double **) lammps_extract_fix(l.lmp, "fl", LMP_STYLE_ATOM,
                                                          LMP_TYPE_ARRAY, 0, 0))[0];
    // the interpolated gradient is exact for a linear p; error from the solve: 5e-9/0.1
    EXPECT_NEAR(f[2], expected, 5e-8 * volume);
    EXPECT_NEAR(f[0], 0.0, 1e-12 * expected);    // laterally uniform to round-off
    EXPECT_NEAR(f[1], 0.0, 1e-12 * expected);
    for (int d = 0; d < 3; ++d) EXPECT_EQ(fluid[d], f[d]);    // the only force
    EXPECT_NEAR(l.equal("f_fl[6]"), -500.0, 0.0);             // top pressure output
  }
  {
    // still water (p = 0 everywhere) with gravity: buoyancy rho_f V g exactly
    Lammps l;
    scene(l, " density 1000 gravity 0 0 -9.81");
    l.command("run 10");
    EXPECT_EQ(l.equal("f_fl[3]"), 0.0);
    EXPECT_DOUBLE_EQ(l.atom()->f[0][2], volume * 1000.0 * 9.81);
    EXPECT_EQ(l.atom()->f[0][0], 0.0);
    EXPECT_EQ(l.atom()->f[0][1], 0.0);
  }
}

TEST(FixDarcyPressure, SimpleCubicLatticeHasPorosityOneMinusPiOverSix)
{
  // touching grains of diameter a on a lattice of spacing a from a/2; cells of 2a: the hat
  // weights of a row of grains spaced a sum to exactly 2 per axis, so every cell holds 8
  // grain volumes: solid fraction 8 (pi/6) a^3 / (2a)^3 = pi/6. The bottom and top cells
  // are exact too: their stencils fold the weight outside the grid back (= mirrored
  // grains), and this lattice is its own mirror image about z = 0 and z = 8a.
  Lammps l;
  l.commands("units si\natom_style sphere\nboundary p p f\nlattice sc 0.02 origin 0.5 0.5 0.5\n"
             "region box block 0 8 0 6 0 8\ncreate_box 1 box\ncreate_atoms 1 box\n"
             "set type 1 diameter 0.02\nset type 1 density 2600\n");
  l.command("fix fl all darcy/pressure grid 4 3 4" + unit_diffusivity);
  l.command("run 0");
  ASSERT_EQ(l.atom()->natoms, 8 * 6 * 8);
  for (double phi : field(l, "porosity", 4 * 3 * 4)) EXPECT_NEAR(phi, 1.0 - PI / 6, 1e-14);
  EXPECT_NEAR(l.equal("f_fl[2]"), 1.0 - PI / 6, 1e-14);
}

TEST(FixDarcyPressure, UpwardGradientFluidisesTheBedAboveCritical)
{
  // The bed rests on its frozen bottom layer. Each grain feels gravity, buoyancy and the
  // upward -V dp/dz = V G: it floats when G > (rho_s - rho_f) g (per grain: no drag).
  // The fluid first settles to the linear profile with the grains held (150 steps: the
  // slowest mode, rate pi^2 D/H^2 ~ 6e3/s with D ~ 25 m^2/s, decays by e^-20), then the
  // grains move for 0.05 s.
  auto mean_rise = [](double factor) {
    Lammps l;
    l.commands(pwtest::bed());
    l.command(pwtest::bed_fluid(factor * critical_gradient * 0.2, 1));
    l.command("run 150");
    EXPECT_NEAR(l.equal("f_fl[3]"), factor * critical_gradient * 0.2 *
                (1.0 - 0.01 / 0.2), 1e-6 * critical_gradient);    // p of the bottom cells
    const double z0 = l.equal("v_zmean");
    l.commands("fix move mobile nve/sphere\nrun 2000\n");
    return l.equal("v_zmean") - z0;
  };
  const double below = mean_rise(0.9), above = mean_rise(2.0);
  std::printf("[ report ] fluidisation: mean rise %.3e m at 0.9x, %.3e m at 2x critical\n",
              below, above);
  // at rest: contacts carry the remaining 10% of the weight (elastic, ~1e-7 m)
  EXPECT_LT(std::fabs(below), 1e-4);    // 1% of a diameter
  // lifted: net upward force = buoyant weight, a = 6.0 m/s^2 for 0.05 s: 7.5 mm, less the
  // suction of the dilating bed
  EXPECT_GT(above, 3e-3);
}

// compute darcy/grain: the steady linear column of OneGrainFeelsTheGradientAndBuoyancy
// (p = 1000 - 1500 z to the solve's 5e-9), with the porosity clamp raised so that the
// grains' deposits show in phi. At a grain of the group: p as the linear profile (trilinear
// interpolation is exact for a linear field; the field's own error 5e-9), phi as the
// trilinear hat weights of the fix's cell porosities written out here (periodic in x, y;
// the grain lies between cell centres in z); zero for a grain outside the group.
TEST(ComputeDarcyGrain, PressureAndPorosityAtTheGrains)
{
  Lammps l;
  l.commands("units si\natom_style sphere\natom_modify map array\nboundary p p f\n"
             "region box block 0 0.5 0 0.5 0 1\ncreate_box 1 box\n"
             "create_atoms 1 single 0.13 0.41 0.437\ncreate_atoms 1 single 0.38 0.07 0.71\n"
             "set type 1 diameter 0.02\nset type 1 density 2600\ntimestep 0.02\n"
             "group one id 1\n");
  l.command("fix fl all darcy/pressure grid 2 2 10" + unit_diffusivity +
            " bottom 1000 top -500 tol 1e-13 porosity 0.1 0.99999");
  l.command("compute water one darcy/grain fl");
  l.command("run 300");
  // the library interface computes a per-atom compute that is not current
  double **water = (double **) lammps_extract_compute(l.lmp, "water", LMP_STYLE_ATOM,
                                                      LMP_TYPE_ARRAY);
  ASSERT_NE(water, nullptr);
  const double *one = water[l.atom()->map(1)], *two = water[l.atom()->map(2)];
  const double p1 = one[0], phi1 = one[1];
  EXPECT_NEAR(p1, 1000.0 - 1500.0 * 0.437, 5e-9);
  const auto phi = field(l, "porosity", 40);
  const double x[3] = {0.13, 0.41, 0.437}, d[3] = {0.25, 0.25, 0.1};
  double expected = 0.0, lowest = 1.0;
  for (int c = 0; c < 40; ++c) {
    const int ijk[3] = {c % 2, (c / 2) % 2, c / 4};
    double w = 1.0;
    for (int a = 0; a < 3; ++a) {
      double offset = x[a] - (ijk[a] + 0.5) * d[a];
      if (a < 2) offset -= 0.5 * std::round(offset / 0.5);    // periodic: nearest image
      w *= std::max(0.0, 1.0 - std::fabs(offset) / d[a]);
    }
    expected += w * phi[c];
    lowest = std::min(lowest, phi[c]);
  }
  // the deposits show: the nearest cell of a grain takes at least 1/8 of its volume,
  // 1/8 x 4.19e-6 / 6.25e-3 m3 = 8.4e-5 of the cell (measured 4.9e-4)
  EXPECT_LT(lowest, 1.0 - 8.4e-5);
  EXPECT_NEAR(phi1, expected, 1e-15);
  EXPECT_EQ(two[0], 0.0);    // not in the group
  EXPECT_EQ(two[1], 0.0);
}
