// fix darcy/pressure and darcy/pressure/kk driven through LAMMPS: exact zero, Terzaghi
// and a tidal top through the fix's wiring (timestep, every, variables, profile file),
// the force on one grain, porosity of a lattice, fluidisation of a bed, MPI
// decompositions, restarts, KOKKOS and bad input. The solver's accuracy itself is
// tested in tests/unit/test_darcy_solver.cpp.
#include "lammps_fixture.h"

#include "fix.h"

#include "analytic_solutions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

using pwtest::Accel;
using pwtest::Lammps;
using pwtest::expect_error;

namespace {

const double PI = 3.14159265358979323846;

LAMMPS_NS::Fix *fix_of(Lammps &l, const char *id = "fl")
{
  const int i = l.lmp->modify->find_fix(id);
  return i < 0 ? nullptr : l.lmp->modify->fix[i];
}

// a per-cell field of the fix (flat, x fastest), via Fix::extract
std::vector<double> field(Lammps &l, const char *name, int size)
{
  int dim = 0;
  const double *data = (const double *) fix_of(l)->extract(name, dim);
  return std::vector<double>(data, data + size);
}

double max_abs_diff(const std::vector<double> &a, const std::vector<double> &b)
{
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::fabs(a[i] - b[i]));
  return worst;
}

// Grain-free column [0,1]^2 x [0,height], z non-periodic. The fix's parameters give
// D = k/(beta phi mu) = 1: no grains, so phi = MAX = 0.9, and k = kmax = 0.9 (the
// Kozeny-Carman value 72.9 lies above the cap).
void empty_column(Lammps &l, double height)
{
  l.commands("units lj\natom_style sphere\nboundary p p f\n");
  l.command("region box block 0 1 0 1 0 " + std::to_string(height));
  l.command("create_box 1 box");
}
const std::string unit_diffusivity =
    " viscosity 1 compressibility 1 density 1 permeability 1 kmax 0.9";


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

// Simple-cubic bed of 8 x 8 x 5 grains of diameter d = 0.01 m (SI units) touching in
// columns, the bottom layer frozen (not integrated), in a 0.08 x 0.08 x 0.2 m box. Fluid
// grid 2 x 2 x 10 from z = 0 to 0.2 with k capped to a uniform 1e-7 m^2 (kc is 1000x the
// cap, so the cap holds for every porosity >= 0.1): a Dirichlet bottom p_b and a top 0 then
// give the uniform gradient -p_b/0.2 in steady state, grains or not.
void bed(Lammps &l, double p_bottom, int every, bool integrate, const std::string &processors = "")
{
  l.commands("units si\natom_style sphere\natom_modify map array\nboundary p p f\n"
             "comm_modify vel yes\n" + processors + "\n"
             "lattice sc 0.01 origin 0.5 0.5 0.5\nregion box block 0 8 0 8 0 20\n"
             "create_box 1 box\nregion bed block 0 8 0 8 0 5\ncreate_atoms 1 region bed\n"
             "set type 1 diameter 0.01\nset type 1 density 2600\n"
             "region floor block INF INF INF INF INF 0.01 units box\ngroup floor region floor\n"
             "group mobile subtract all floor\n"
             "pair_style gran/hooke/history 1e4 NULL 0 NULL 0.5 0\npair_coeff * *\n"
             "neighbor 0.002 bin\nneigh_modify delay 0 every 1 check yes\ntimestep 2.5e-5\n"
             "fix weight mobile gravity 9.81 vector 0 0 -1\n"
             "variable zmean equal xcm(mobile,z)\n");
  l.command("fix fl all darcy/pressure grid 2 2 10 viscosity 1e-3 compressibility 5e-6 "
            "density 1000 permeability 1e-4 kmax 1e-7 gravity 0 0 -9.81 bottom " +
            std::to_string(p_bottom) + " every " + std::to_string(every));
  if (integrate) l.command("fix move mobile nve/sphere");
}

const int bed_cells = 2 * 2 * 10;

// positions keyed by lattice site instead of atom ID: create_atoms numbers the grains in
// an order that depends on the decomposition (grains move far less than a spacing here)
std::map<long, std::vector<double>> by_site(const std::map<long, std::vector<double>> &x)
{
  std::map<long, std::vector<double>> out;
  for (const auto &kv : x) {
    const auto &r = kv.second;
    const long i = std::lround(r[0] / 0.01 - 0.5), j = std::lround(r[1] / 0.01 - 0.5),
               k = std::lround(r[2] / 0.01 - 0.5);
    out[i + 8 * (j + 8 * k)] = r;
  }
  return out;
}

// buoyant weight per grain volume, (rho_s - rho_f) g: the gradient that floats a grain
const double critical_gradient = (2600.0 - 1000.0) * 9.81;

// Two runs that differ by round-off agree in p only to the CG tolerance, 1e-10 max|p|
// (the solves stop at different iterates), here 1e-10 * p_b = 6e-7 Pa: allow 10x that.
const double bed_p_agreement = 1e-9 * 2.0 * critical_gradient * 0.2;

}    // namespace

// ---------------------------------------------------------------------------------------

TEST(FixDarcyPressure, NoGrainsStaysExactlyZero)
{
  for (const char *bottom : {"noflow", "0.0"}) {    // closed below, or fixed at both ends
    Lammps l;
    empty_column(l, 1.0);
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
    empty_column(l, 1.0);
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
    empty_column(l, 1.0);
    l.command("fix fl all darcy/pressure grid 2 1 " + std::to_string(nz) + unit_diffusivity +
              " initial 1.0 every 4 profile 500 " + profile);
    l.commands("timestep 1e-4\nrun 2000\n");
    by_every = field(l, "pressure", 2 * nz);
    EXPECT_GT(l.equal("f_fl[4]"), 0.0);                      // the solve did iterate
    EXPECT_LE(l.equal("f_fl[5]"), 1e-10 * l.equal("f_fl[3]"));    // to tol 1e-10 max|p|
  }
  {
    Lammps l;
    empty_column(l, 1.0);
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
  empty_column(l, 1.0);
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
  empty_column(l, 1.0);
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
    bed(l, factor * critical_gradient * 0.2, 1, false);
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

TEST(FixDarcyPressure, MpiDecompositionDoesNotChangeTheResult)
{
  // lifting bed, x-y decomposition (the bed is thin in z): mpirun -np 2 and 3 via ctest
  auto run = [](MPI_Comm comm, std::vector<double> *p) {
    Lammps l(Accel::none, comm);
    bed(l, 2.0 * critical_gradient * 0.2, 2, true, "processors * * 1");
    l.command("run 400");
    *p = field(l, "pressure", bed_cells);
    return by_site(l.gather3("x"));
  };
  std::vector<double> p_parallel, p_serial;
  const auto parallel = run(MPI_COMM_WORLD, &p_parallel);
  const auto serial = run(MPI_COMM_SELF, &p_serial);
  ASSERT_EQ(parallel.size(), 320u);
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0)
    std::printf("[ report ] MPI vs serial: max |dx| = %.2e m, max |dp| = %.2e Pa\n",
              pwtest::max_abs_diff(parallel, serial), max_abs_diff(p_parallel, p_serial));
  // deposits and contact forces summed in another order: round-off, not amplified by a
  // lifting lattice (measured 2e-15 m); 1e-12 m is 1e-10 of a diameter. p: measured 1e-10
  // Pa (np 2) and 4e-7 Pa (np 3), see bed_p_agreement
  EXPECT_LE(pwtest::max_abs_diff(parallel, serial), 1e-12);
  EXPECT_LE(max_abs_diff(p_parallel, p_serial), bed_p_agreement);
}

TEST(FixDarcyPressure, RestartSplitRunEqualsUnsplitRun)
{
  // every 3: the split at step 200 falls between fluid steps (198, 201)
  for (Accel accel : {Accel::none, Accel::kokkos}) {
    const std::string restart = std::string("pw_darcy_split") + (accel == Accel::none ? "" : "_kk") + ".restart";
    std::map<long, std::vector<double>> whole, split;
    std::vector<double> p_whole, p_split;
    {
      Lammps l(accel);
      bed(l, 2.0 * critical_gradient * 0.2, 3, true);
      l.command("run 200");
      l.command("write_restart " + restart);
      l.command("run 200");
      whole = l.gather3("x");
      p_whole = field(l, "pressure", bed_cells);
    }
    {
      Lammps l(accel);
      l.command("read_restart " + restart);
      l.commands("comm_modify vel yes\nneighbor 0.002 bin\nneigh_modify delay 0 every 1 check yes\n"
                 "timestep 2.5e-5\nfix weight mobile gravity 9.81 vector 0 0 -1\n");
      l.command("fix fl all darcy/pressure grid 2 2 10 viscosity 1e-3 compressibility 5e-6 "
                "density 1000 permeability 1e-4 kmax 1e-7 gravity 0 0 -9.81 bottom " +
                std::to_string(2.0 * critical_gradient * 0.2) + " every 3 initial 123");
      l.commands("fix move mobile nve/sphere\nrun 200\n");
      split = l.gather3("x");
      p_split = field(l, "pressure", bed_cells);
    }
    std::remove(restart.c_str());
    // atoms re-sorted after read_restart: sums in another order, round-off only (the
    // restart holds p, phi and the fluid clock; `initial 123` must be ignored)
    const char *which = accel == Accel::none ? "cpu" : "kk";
    std::printf("[ report ] restart split vs whole (%s): max |dx| = %.2e m, max |dp| = %.2e Pa\n",
                which, pwtest::max_abs_diff(whole, split), max_abs_diff(p_whole, p_split));
    EXPECT_LE(pwtest::max_abs_diff(whole, split), 1e-12) << which;
    EXPECT_LE(max_abs_diff(p_whole, p_split), bed_p_agreement) << which;
  }
}

TEST(FixDarcyPressure, KokkosEqualsCpu)
{
  auto run = [](Accel accel, std::vector<double> *p, std::vector<double> *fz) {
    Lammps l(accel);
    bed(l, 2.0 * critical_gradient * 0.2, 2, true);
    EXPECT_STREQ(fix_of(l)->style, accel == Accel::kokkos ? "darcy/pressure/kk" : "darcy/pressure");
    l.command("run 400");
    *p = field(l, "pressure", bed_cells);
    // the per-atom fluid force (z) by tag, read from the fix's array on the host
    auto **fluid = (double **) lammps_extract_fix(l.lmp, "fl", LMP_STYLE_ATOM, LMP_TYPE_ARRAY, 0, 0);
    fz->assign(l.atom()->natoms, 0.0);
    for (int i = 0; i < l.atom()->nlocal; ++i) (*fz)[l.atom()->tag[i] - 1] = fluid[i][2];
    return l.gather3("x");
  };
  std::vector<double> p_cpu, p_kk, f_cpu, f_kk;
  const auto cpu = run(Accel::none, &p_cpu, &f_cpu);
  const auto kk = run(Accel::kokkos, &p_kk, &f_kk);
  ASSERT_GT(*std::max_element(f_cpu.begin(), f_cpu.end()), 0.0);
  std::printf("[ report ] kk vs cpu: max |dx| = %.2e m, max |dp| = %.2e Pa, max |dfz| = %.2e N\n",
              pwtest::max_abs_diff(cpu, kk), max_abs_diff(p_cpu, p_kk), max_abs_diff(f_cpu, f_kk));
  // same stencil functions in the same order on one thread: round-off at most
  EXPECT_LE(pwtest::max_abs_diff(cpu, kk), 1e-12);
  EXPECT_LE(max_abs_diff(p_cpu, p_kk), bed_p_agreement);
  EXPECT_LE(max_abs_diff(f_cpu, f_kk), 1e-12 * *std::max_element(f_cpu.begin(), f_cpu.end()));
}

TEST(FixDarcyPressure, BadInputGivesClearErrors)
{
  {
    Lammps periodic;
    periodic.commands("units lj\natom_style sphere\nregion box block 0 1 0 1 0 1\ncreate_box 1 box\n");
    expect_error(periodic, "fix bad all darcy/pressure grid 2 2 2" + unit_diffusivity, "non-periodic in z");
  }
  {
    Lammps atomic;
    atomic.commands("units lj\natom_style atomic\nboundary p p f\nregion box block 0 1 0 1 0 1\n"
                    "create_box 1 box\n");
    expect_error(atomic, "fix bad all darcy/pressure grid 2 2 2" + unit_diffusivity, "requires atom_style sphere");
  }
  Lammps l;
  empty_column(l, 1.0);
  const std::string fix = "fix bad all darcy/pressure grid 2 2 4";
  expect_error(l, fix + " viscosity 1 density 1 permeability 1",
               "missing required keyword(s): compressibility");
  expect_error(l, fix + unit_diffusivity + " porosity 0.2 1.0", "porosity MIN MAX needs 0 < MIN <= MAX < 1");
  expect_error(l, fix + unit_diffusivity + " bottom closed", "bottom expects noflow, a finite number or v_name, got 'closed'");
  expect_error(l, fix + unit_diffusivity + " top closed", "top expects noflow, a finite number or v_name, got 'closed'");
  expect_error(l, fix + unit_diffusivity + " every 0", "every expects an integer >= 1, got '0'");
  expect_error(l, fix + unit_diffusivity + " viscosity -1", "viscosity expects a finite number > 0, got '-1'");
  expect_error(l, fix + unit_diffusivity + " gravity 0 0", "gravity expects a finite number, but the command ends there");
  expect_error(l, fix + unit_diffusivity + " damping 1", "unknown keyword 'damping' (allowed: grid, viscosity,");
  expect_error(l, "fix bad all darcy/pressure grid 2 0 4" + unit_diffusivity, "grid expects an integer >= 1, got '0'");

  // variables are checked when the run starts
  l.command(fix + unit_diffusivity + " top v_nowhere");
  expect_error(l, "run 0", "variable nowhere for top does not exist");
  l.command("unfix bad");
  l.command("variable atomic atom x");
  l.command(fix + unit_diffusivity + " ztop v_atomic");
  expect_error(l, "run 0", "variable atomic for ztop is not equal-style");
  l.command("unfix bad");

  // a solve that cannot reach its tolerance stops the run and says where and why (last:
  // the run is left half done)
  l.command(fix + unit_diffusivity + " initial 1.0 tol 1e-14 maxiter 1");
  l.command("timestep 1e-3");
  expect_error(l, "run 1", "the pressure solve did not converge in 1 iterations");
}
