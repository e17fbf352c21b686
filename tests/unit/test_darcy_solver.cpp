// DarcySolver: exact zero, mass balance, Terzaghi consolidation with grid convergence,
// tidal top pressure, linear steady state and gradient, CG convergence, grain forcing,
// dphi/dt and restart.
#include "darcy/coupling.h"
#include "darcy/solver.h"

#include "analytic_solutions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <random>
#include <string>

using namespace porewater;

namespace {

// one grain's deposit at x with velocity v into the solver's arrays, as DarcyFluid copies
// the coupling's cell deposits (darcy/coupling.h) there
void deposit(DarcySolver &s, double x, double y, double z, double volume, double vx, double vy,
             double vz)
{
  const DepositLayout layout{s.ncells()};
  std::vector<double> slots(layout.size(), 0.0);
  deposit_grain_in_cells(s.geom(), layout, x, y, z, vx, vy, vz, volume, 0.0,
                         [&slots](int slot, double value) { slots[slot] += value; });
  for (int c = 0; c < s.ncells(); ++c) {
    s.solid_volume()[c] += slots[layout.volume(c)];
    for (int d = 0; d < 3; ++d) s.solid_momentum()[3 * c + d] += slots[layout.momentum(c) + d];
  }
}

// grad p at a point, interpolated from the cell-centre gradients with the stencil
void gradient_at(const DarcySolver &s, double x, double y, double z, double grad[3])
{
  int idx[8];
  double w[8];
  stencil(s.geom(), x, y, z, idx, w);
  for (int d = 0; d < 3; ++d) grad[d] = interpolate(s.pressure_gradient().data() + d, 3, idx, w);
}

const double pi = 3.14159265358979323846;

// No grains: phi = porosity_max = 0.9; with mu = beta = 1 and the cap kmax = 0.9 (the
// Kozeny-Carman value 72.9 is above it) k = 0.9, so D = k/(beta phi mu) = 1.
DarcyParams unit_diffusivity()
{
  DarcyParams p;
  p.viscosity = 1.0;
  p.compressibility = 1.0;
  p.kc = 1.0;
  p.kmax = 0.9;
  p.tol_abs = 0.0;
  p.tol_rel = 1e-12;
  p.maxiter = 500;
  return p;
}

// A 1-D column of height H (nx = ny = 1: a single periodic cell has no lateral flux).
GridGeom column(int nz, double height) { return GridGeom{0, 0, 0, 1, 1, height / nz, 1, 1, nz}; }

double z_centre(const GridGeom &g, int k) { return g.zlo + (k + 0.5) * g.dz; }

std::string sci(double x)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", x);
  return buf;
}

double max_abs(const std::vector<double> &v)
{
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}


// Fill solid_volume so that every cell has the given porosity, and update.
void set_porosity(DarcySolver &s, const std::vector<double> &porosity)
{
  const double vcell = cell_volume(s.geom());
  s.clear_deposits();
  for (int c = 0; c < s.ncells(); ++c) s.solid_volume()[c] = (1.0 - porosity[c]) * vcell;
  s.update_porosity();
}

}  // namespace

TEST(DarcySolver, NoGrainsStaysExactlyZero)
{
  GridGeom g{0, 0, 0, 0.1, 0.1, 0.1, 4, 3, 5};
  DarcySolver s(g, unit_diffusivity());
  s.clear_deposits();
  s.update_porosity();  // nothing deposited: phi = 1, clamped to 0.9
  s.update_dphi_dt(1e-3);
  EXPECT_EQ(s.porosity_min_unclamped(), 1.0);
  for (int n = 0; n < 50; ++n) {
    const StepResult r = s.step(1e-3, 0.0);
    ASSERT_TRUE(r.converged);
    ASSERT_EQ(r.iterations, 0);
  }
  for (double p : s.pressure()) ASSERT_EQ(p, 0.0);  // exactly, not approximately
  for (double d : s.dphi_dt()) ASSERT_EQ(d, 0.0);
  for (double gp : s.pressure_gradient()) ASSERT_EQ(gp, 0.0);
}

TEST(DarcySolver, ClosedBoxConservesFluidMass)
{
  GridGeom g{0, 0, 0, 0.2, 0.25, 0.15, 6, 5, 7};
  DarcyParams params = unit_diffusivity();
  params.kmax = 0.0;
  params.kc = 0.05;
  params.tol_rel = 1e-13;
  params.top = DarcyParams::Top::NoFlow;
  DarcySolver s(g, params);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> porosity(s.ncells()), p0(s.ncells());
  for (int c = 0; c < s.ncells(); ++c) {
    porosity[c] = 0.25 + 0.4 * u(rng);  // heterogeneous k: harmonic face means matter
    p0[c] = 2.0 * u(rng) - 1.0;
  }
  set_porosity(s, porosity);
  s.set_pressure(p0, 0.0);
  auto fluid_mass = [&]() {  // sum beta phi p V_cell
    double m = 0.0;
    for (int c = 0; c < s.ncells(); ++c)
      m += params.compressibility * s.porosity()[c] * s.pressure()[c] * cell_volume(g);
    return m;
  };
  auto abs_mass = [&]() {
    double m = 0.0;
    for (int c = 0; c < s.ncells(); ++c)
      m += params.compressibility * s.porosity()[c] * std::fabs(s.pressure()[c]) * cell_volume(g);
    return m;
  };
  const double m0 = fluid_mass(), scale = abs_mass();
  for (int n = 0; n < 20; ++n) ASSERT_TRUE(s.step(0.05, 0.0).converged);
  // The field must really have diffused (else conservation is trivial)...
  double change = 0.0;
  for (int c = 0; c < s.ncells(); ++c)
    change = std::max(change, std::fabs(s.pressure()[c] - p0[c]));
  EXPECT_GT(change, 0.5);
  // ...while its mass stays put: the fluxes cancel pairwise, so each step changes the
  // mass only by the sum of the final CG residuals (|r_c| <= A_cc 1e-13 max|p|) plus
  // round-off. Measured 4e-14 of sum beta phi |p| V after 20 steps; asserted 1e-12.
  EXPECT_NEAR(fluid_mass(), m0, 1e-12 * scale);
  RecordProperty("mass_drift_relative", sci(std::fabs(fluid_mass() - m0) / scale));
}

TEST(DarcySolver, TerzaghiConsolidationSecondOrder)
{
  const double height = 1.0, p0 = 1.0;
  const double times[3] = {0.05, 0.2, 0.5};  // T_v = D t/H^2 with D = 1
  double error[3][3];                          // [grid][time], max over cells / p0
  const int grids[3] = {16, 32, 64};
  for (int gi = 0; gi < 3; ++gi) {
    const int nz = grids[gi];
    const GridGeom g = column(nz, height);
    DarcySolver s(g, unit_diffusivity());
    ASSERT_NEAR(s.permeability()[0] / (1.0 * 0.9 * 1.0), 1.0, 1e-14);  // D = 1
    s.set_pressure(std::vector<double>(nz, p0), 0.0);
    const int steps_per = nz * 5 / 2;  // dt = 0.02/nz, proportional to dz
    const double dt = 0.05 / steps_per;
    int done = 0;
    for (int ti = 0; ti < 3; ++ti) {
      const int target = (int) std::lround(times[ti] / dt);
      for (; done < target; ++done) ASSERT_TRUE(s.step(dt, 0.0).converged);
      double e = 0.0;
      for (int k = 0; k < nz; ++k)
        e = std::max(e, std::fabs(s.pressure()[k] -
                                  pwtest::terzaghi(p0, z_centre(g, k), height, 1.0, done * dt)));
      error[gi][ti] = e / p0;
    }
  }
  for (int ti = 0; ti < 3; ++ti) {
    const double order1 = std::log2(error[0][ti] / error[1][ti]);
    const double order2 = std::log2(error[1][ti] / error[2][ti]);
    RecordProperty("T" + std::to_string(ti) + "_errors",
                   sci(error[0][ti]) + " " + sci(error[1][ti]) + " " + sci(error[2][ti]));
    // second-order scheme (CN in time with dt ~ dz, 2nd-order space): the observed
    // order must be near 2; 1.7 leaves room for pre-asymptotic behaviour
    EXPECT_GT(order1, 1.7) << "T_v = " << times[ti];
    EXPECT_GT(order2, 1.7) << "T_v = " << times[ti];
    // and the finest grid must be accurate: measured <= 1.6e-4, asserted 4e-4
    EXPECT_LT(error[2][ti], 4e-4) << "T_v = " << times[ti];
  }
}

TEST(DarcySolver, TidalTopPressureDecaysWithDepth)
{
  // D = 1, omega = 2 pi: delta = sqrt(2D/omega) = 0.564; column 3 = 5.3 delta deep,
  // 60 cells (11 per delta), 200 steps per period.
  const double height = 3.0, amplitude = 1.0, omega = 2 * pi, period = 1.0;
  const int nz = 60, steps = 200;
  const double dt = period / steps, delta = std::sqrt(2.0 / omega);
  const GridGeom g = column(nz, height);
  DarcySolver s(g, unit_diffusivity());
  const std::complex<double> kappa = std::sqrt(std::complex<double>(0.0, omega));
  auto response = [&](double z) {  // cosh(kappa z)/cosh(kappa H): p = A Im[G e^{i w t}]
    return std::cosh(kappa * z) / std::cosh(kappa * height);
  };
  // start on the periodic solution at t = 0, so no slow transient needs to decay
  std::vector<double> p(nz);
  for (int k = 0; k < nz; ++k) p[k] = amplitude * response(z_centre(g, k)).imag();
  s.set_pressure(p, 0.0);
  const int periods = 3;
  std::vector<double> a_sin(nz, 0.0), a_cos(nz, 0.0);
  for (int n = 1; n <= (periods + 1) * steps; ++n) {
    const double t = n * dt;
    ASSERT_TRUE(s.step(dt, amplitude * std::sin(omega * t)).converged);
    if (n > periods * steps)  // Fourier projection over the last period (exact for a sinusoid)
      for (int k = 0; k < nz; ++k) {
        a_sin[k] += 2.0 / steps * s.pressure()[k] * std::sin(omega * t);
        a_cos[k] += 2.0 / steps * s.pressure()[k] * std::cos(omega * t);
      }
  }
  double amp_error = 0.0, phase_error = 0.0;
  for (int k = 0; k < nz; ++k) {
    const std::complex<double> exact = amplitude * response(z_centre(g, k));
    const double amp = std::hypot(a_sin[k], a_cos[k]), phase = std::atan2(a_cos[k], a_sin[k]);
    amp_error = std::max(amp_error, std::fabs(amp - std::abs(exact)));
    if (std::abs(exact) > 0.01 * amplitude)  // phase is meaningless where p ~ 0
      phase_error =
          std::max(phase_error, std::fabs(std::remainder(phase - std::arg(exact), 2 * pi)));
    const double depth = height - z_centre(g, k);
    if (depth < 2 * delta) {
      // semi-infinite limit: amplitude e^{-d/delta}, lag d/delta; the bottom reflection
      // changes p by a factor 1 + O(e^{-2(H-d)/delta}) <= 1 + 1.3e-3 here, on top of the
      // discretisation error below
      EXPECT_NEAR(amp, amplitude * std::exp(-depth / delta), 1e-3 * amplitude) << depth;
      EXPECT_NEAR(std::remainder(phase + depth / delta, 2 * pi), 0.0, 6e-3) << depth;
    }
  }
  // Discretisation error: the half-cell Dirichlet ghost 2 p_top - p is off by
  // ~kappa^2 dz^2/8 = i (dz/delta)^2/4 = 2.0e-3 i relative, a phase error of 2.0e-3
  // rad (measured 1.9e-3); amplitude errors are smaller (space and CN time
  // (omega dt)^2/12 ~ 1e-4; measured 2.6e-4). Tolerances: about 2.5x those.
  EXPECT_LT(amp_error, 1e-3 * amplitude);
  EXPECT_LT(phase_error, 5e-3);
  RecordProperty("amplitude_error", sci(amp_error));
  RecordProperty("phase_error", sci(phase_error));
}

TEST(DarcySolver, DirichletTopAndBottomGiveLinearProfile)
{
  const double height = 1.0, p_bottom = 1.0, p_top = -0.5;
  GridGeom g{0, 0, 0, 0.3, 0.2, height / 10, 3, 2, 10};
  DarcyParams params = unit_diffusivity();
  params.bottom = DarcyParams::Bottom::Dirichlet;
  params.p_bottom = p_bottom;
  DarcySolver s(g, params);
  for (int n = 0; n < 400; ++n) ASSERT_TRUE(s.step(0.01, p_top).converged);
  // slowest mode decays as 0.906 per step: 400 steps leave ~1e-17; CG tol 1e-12
  for (int c = 0; c < s.ncells(); ++c) {
    const int k = c / (g.nx * g.ny);
    const double z = z_centre(g, k);
    EXPECT_NEAR(s.pressure()[c], p_bottom + (p_top - p_bottom) * z / height, 1e-10);
  }
  // the Dirichlet ghosts make the centre gradients exact for a linear profile, so the
  // interpolated gradient is exact anywhere, including the folded stencils at the ends
  const double expected = (p_top - p_bottom) / height;
  const double points[4][3] = {
      {0.41, 0.07, 0.37}, {0.89, 0.39, 0.52}, {0.05, 0.1, 0.02}, {0.6, 0.3, 0.99}};
  for (const auto &x : points) {
    double grad[3];
    gradient_at(s, x[0], x[1], x[2], grad);
    EXPECT_NEAR(grad[0], 0.0, 1e-9);
    EXPECT_NEAR(grad[1], 0.0, 1e-9);
    EXPECT_NEAR(grad[2], expected, 1e-9);  // 1e-10 in p over dz = 0.1
  }
}

TEST(DarcySolver, TopBelowGridHoldsUpperCellsAtTopPressure)
{
  // z_top inside the grid: cells with centres at or above it are held at p_top and the
  // Dirichlet face is the top face of the last active cell (here z = 0.6 of 1.0).
  const GridGeom g = column(10, 1.0);
  DarcyParams params = unit_diffusivity();
  params.bottom = DarcyParams::Bottom::Dirichlet;
  params.p_bottom = 1.0;
  DarcySolver s(g, params);
  for (int n = 0; n < 400; ++n) ASSERT_TRUE(s.step(0.01, 0.0, 0.62).converged);
  EXPECT_EQ(s.active_layers(), 6);
  for (int k = 0; k < 10; ++k) {
    const double expected = k < 6 ? 1.0 - z_centre(g, k) / 0.6 : 0.0;
    EXPECT_NEAR(s.pressure()[k], expected, 1e-10) << k;
  }
}

TEST(DarcySolver, ConjugateGradientConvergesOrReportsFailure)
{
  GridGeom g{0, 0, 0, 0.1, 0.1, 0.1, 8, 8, 8};
  DarcyParams params = unit_diffusivity();
  params.kmax = 0.0;
  params.kc = 0.1;  // D ~ 0.04, D dt/dx^2 ~ 0.4: a real elliptic solve
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> porosity(g.nx * g.ny * g.nz), p0(porosity.size());
  for (size_t c = 0; c < porosity.size(); ++c) {
    porosity[c] = 0.3 + 0.3 * u(rng);
    p0[c] = u(rng);
  }
  auto one_step = [&](double tol_rel, int maxiter, std::vector<double> *p) {
    DarcyParams q = params;
    q.tol_rel = tol_rel;
    q.maxiter = maxiter;
    DarcySolver s(g, q);
    set_porosity(s, porosity);
    s.set_pressure(p0, 0.5);
    const StepResult r = s.step(0.1, 0.5);
    if (p) *p = s.pressure();
    return r;
  };
  std::vector<double> tight, tighter;
  const StepResult r = one_step(1e-12, 500, &tight);
  EXPECT_TRUE(r.converged);
  EXPECT_GT(r.iterations, 0);
  EXPECT_LE(r.residual, r.tolerance);
  EXPECT_NEAR(r.tolerance, 1e-12 * max_abs(tight), 1e-12 * 1e-6);  // scale = max|p|, p_top
  // a tighter solve moves p by ~ tolerance x condition number (measured 6e-13): 1e-10
  const StepResult r2 = one_step(1e-14, 1000, &tighter);
  EXPECT_TRUE(r2.converged);
  EXPECT_GE(r2.iterations, r.iterations);
  double diff = 0.0;
  for (size_t c = 0; c < tight.size(); ++c) diff = std::max(diff, std::fabs(tight[c] - tighter[c]));
  EXPECT_LT(diff, 1e-10);
  RecordProperty("tight_vs_tighter", sci(diff));
  // one iteration cannot reach 1e-12
  const StepResult bad = one_step(1e-12, 1, nullptr);
  EXPECT_FALSE(bad.converged);
  EXPECT_EQ(bad.iterations, 1);
  EXPECT_GT(bad.residual, bad.tolerance);
  RecordProperty("iterations", std::to_string(r.iterations) + " " + std::to_string(r2.iterations));
}

TEST(DarcySolver, NonFiniteSystemIsReportedNotConverged)
{
  // porosity_max = 1 with no grains: k = kc/0 and the forcing 0/0 are not finite; the
  // step must say so instead of reporting a zero residual (std::max drops NaN)
  GridGeom g{0, 0, 0, 0.1, 0.1, 0.1, 3, 3, 3};
  DarcyParams params = unit_diffusivity();
  params.kmax = 0.0;
  params.porosity_max = 1.0;
  params.maxiter = 5;
  DarcySolver s(g, params);
  s.set_pressure(std::vector<double>(s.ncells(), 1.0), 0.0);
  const StepResult r = s.step(0.01, 0.0);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(std::isnan(r.residual));
}

namespace {

// A nearly impermeable box (kc = 1e-12) at porosity 0.4 whose centre cell compacts
// (dphi/dt = -0.01): diffusion moves ~1e-13 of the forcing
const GridGeom compaction_box{0, 0, 0, 0.1, 0.1, 0.1, 5, 5, 5};
const int compaction_centre = cell_index(compaction_box, 2, 2, 2);

DarcyParams nearly_impermeable()
{
  DarcyParams params = unit_diffusivity();
  params.kmax = 0.0;
  params.kc = 1e-12;
  params.compressibility = 2.0;
  return params;
}

void compact_centre(DarcySolver &s)
{
  set_porosity(s, std::vector<double>(s.ncells(), 0.4));
  s.dphi_dt()[compaction_centre] = -0.01;  // porosity decreasing: compaction
}

}  // namespace

TEST(DarcySolver, CompactionRaisesPressure)
{
  // the change is the explicit forcing dt (-dphi/dt)/(beta phi (1-phi)) alone
  const GridGeom &g = compaction_box;
  DarcySolver s(g, nearly_impermeable());
  compact_centre(s);
  const int centre = compaction_centre;
  const double dt = 0.1;
  ASSERT_TRUE(s.step(dt, 0.0).converged);
  const double expected = dt * 0.01 / (2.0 * 0.4 * 0.6);
  EXPECT_GT(s.pressure()[centre], 0.0);
  EXPECT_NEAR(s.pressure()[centre], expected, 1e-9 * expected);
  for (int c = 0; c < s.ncells(); ++c) {
    if (c != centre) EXPECT_LT(std::fabs(s.pressure()[c]), 1e-9 * expected);
  }
}

TEST(DarcySolver, GrainAdvectionTermUsesMeanVelocity)
{
  // phi = 0.3 + 0.05 k (layers), grains moving down at w: forcing -w dphi/dz/(beta phi
  // (1-phi)) with the central difference dphi/dz = 0.05/dz; same tolerance as above.
  GridGeom g{0, 0, 0, 0.1, 0.1, 0.1, 3, 3, 5};
  DarcyParams params = unit_diffusivity();
  params.kmax = 0.0;
  params.kc = 1e-12;
  DarcySolver s(g, params);
  const double w = -0.2, vcell = cell_volume(g);
  s.clear_deposits();
  for (int c = 0; c < s.ncells(); ++c) {
    const double solid = (1.0 - (0.3 + 0.05 * (c / 9))) * vcell;
    s.solid_volume()[c] = solid;
    s.solid_momentum()[3 * c + 2] = solid * w;
  }
  s.update_porosity();
  EXPECT_NEAR(s.mean_velocity()[3 * 22 + 2], w, 1e-15);
  const double dt = 0.1;
  ASSERT_TRUE(s.step(dt, 0.0).converged);
  const int middle = cell_index(g, 1, 1, 2);  // phi = 0.4
  const double expected = -dt * w * (0.05 / 0.1) / (0.4 * 0.6);
  EXPECT_GT(expected, 0.0);
  EXPECT_NEAR(s.pressure()[middle], expected, 1e-9 * expected);
}

TEST(DarcySolver, AdvectionAtTheTopActiveLayerIgnoresTheCellsAboveTheTop)
{
  // A uniform bed (phi 0.4) in layers 0-2 below ztop, moving up at w, under layers 3-4
  // that are beyond the top face (the wall and the void above: phi 0.8). Inside the bed
  // grad phi = 0, so v.grad phi adds nothing anywhere: p stays exactly 0 and the grain
  // source of the balance is 0. A gradient taken across the top face from the cell above
  // would give the top layer the spurious forcing -w (0.8-0.4)/(2 dz)/(beta phi (1-phi)).
  const GridGeom g = column(5, 0.5);
  DarcyParams params = unit_diffusivity();
  params.kmax = 0.0;
  params.kc = 1e-12;  // nearly impermeable: a spurious source would stay where it is made
  for (const DarcyParams::Top top : {DarcyParams::Top::Dirichlet, DarcyParams::Top::NoFlow}) {
    params.top = top;
    DarcySolver s(g, params);
    const double w = 0.3, vcell = cell_volume(g);
    s.clear_deposits();
    for (int k = 0; k < 5; ++k) {
      const double solid = (1.0 - (k < 3 ? 0.4 : 0.8)) * vcell;
      s.solid_volume()[k] = solid;
      s.solid_momentum()[3 * k + 2] = solid * w;
    }
    s.update_porosity();
    const double z_top = 0.32;  // centres 0.05 ... 0.45: layers 0-2 active
    ASSERT_TRUE(s.step(0.1, 0.0, z_top).converged);
    ASSERT_EQ(s.active_layers(), 3);
    EXPECT_EQ(s.balance().grains, 0.0);
    for (int k = 0; k < 5; ++k) EXPECT_EQ(s.pressure()[k], 0.0) << "layer " << k;
  }
}

TEST(DarcySolver, DphiDtFromDepositsAndRestart)
{
  GridGeom g{0, 0, 0, 0.1, 0.1, 0.1, 3, 3, 4};
  DarcyParams params = unit_diffusivity();
  params.kmax = 0.0;
  params.kc = 0.01;
  params.porosity_max = 0.99;  // one grain in a cell: phi ~ 0.5-1, keep most unclamped
  DarcySolver a(g, params), b(g, params);
  const double h = 0.01, radius = 0.05, volume = 4.0 / 3.0 * pi * radius * radius * radius;
  auto deposit_grain = [&](DarcySolver &s, double z) {
    s.clear_deposits();
    deposit(s, 0.14, 0.17, z, volume, 0.0, 0.0, -1.0);
  };
  // deposition conserves volume
  deposit_grain(a, 0.01);
  double total = 0.0;
  for (double v : a.solid_volume()) total += v;
  EXPECT_NEAR(total, volume, 1e-14 * volume);  // sum of 8 weights: round-off only
  // a grain sinking at 1: phi(t) at z, predicted at z - h
  double z = 0.25;
  std::vector<double> phi_before;
  for (int n = 0; n < 5; ++n, z -= h) {
    deposit_grain(a, z);
    a.update_porosity();
    if (n == 1) phi_before = a.porosity();
    if (n == 2) {
      deposit_grain(a, z - h);
      a.update_dphi_dt(h);
      DarcySolver probe(g, params);  // phi(t+h) by itself
      deposit_grain(probe, z - h);
      probe.update_porosity();
      // 1e-12: differences of O(1) porosities, round-off ~1e-16/h
      for (int c = 0; c < a.ncells(); ++c)
        EXPECT_NEAR(a.dphi_dt()[c], (probe.porosity()[c] - phi_before[c]) / (2 * h), 1e-12);
      EXPECT_GT(max_abs(a.dphi_dt()), 0.1);  // the grain does move porosity around
    } else {
      deposit_grain(a, z - h);
      a.update_dphi_dt(h);
    }
    ASSERT_TRUE(a.step(h, 0.1 * n).converged);
  }
  EXPECT_GT(max_abs(a.pressure()), 0.0);
  // restart: b continues from a's state and must follow it bit for bit
  ASSERT_TRUE(b.set_state(a.state()));
  EXPECT_FALSE(b.set_state(std::vector<double>(3, 0.0)));
  for (int n = 5; n < 8; ++n, z -= h) {
    for (DarcySolver *s : {&a, &b}) {
      deposit_grain(*s, z);
      s->update_porosity();
      deposit_grain(*s, z - h);
      s->update_dphi_dt(h);
      ASSERT_TRUE(s->step(h, 0.1 * n).converged);
    }
    for (int c = 0; c < a.ncells(); ++c) ASSERT_EQ(a.pressure()[c], b.pressure()[c]);
  }
}

TEST(DarcySolver, TimeDependentBottomIsCrankNicolsonLikeTheTop)
{
  // A column of height 2H with the same p(t) at both ends is symmetric about z = H, and
  // its lower half is a column of height H with a no-flow bottom and that p(t) on top.
  // The top's Crank-Nicolson treatment is tested above; this holds only if the bottom's
  // uses old and new values the same way. Solves to 1e-13: agreement to ~1e-12.
  const int nz = 20;
  const double height = 1.0, dt = 0.01;
  DarcyParams both = unit_diffusivity(), half = unit_diffusivity();
  both.tol_rel = half.tol_rel = 1e-13;
  both.bottom = DarcyParams::Bottom::Dirichlet;
  DarcySolver full(column(2 * nz, 2 * height), both), lower(column(nz, height), half);
  auto boundary = [](double t) { return std::sin(7.0 * t) + 0.3 * t; };
  full.set_pressure(std::vector<double>(2 * nz, 0.0), boundary(0.0), boundary(0.0));
  // the lower column's top face is the full column's top: mirror it (z -> 2H - z)
  lower.set_pressure(std::vector<double>(nz, 0.0), boundary(0.0));
  double worst = 0.0;
  for (int n = 1; n <= 100; ++n) {
    const double t = n * dt;
    ASSERT_TRUE(full.step(dt, boundary(t), full.z_grid_top(), boundary(t)).converged);
    ASSERT_TRUE(lower.step(dt, boundary(t)).converged);
    for (int k = 0; k < nz; ++k)  // cell k from the top of `lower` is cell k from both ends
      worst = std::max({worst, std::fabs(full.pressure()[2 * nz - 1 - k] - lower.pressure()[nz - 1 - k]),
                        std::fabs(full.pressure()[k] - lower.pressure()[nz - 1 - k])});
  }
  EXPECT_GT(max_abs(lower.pressure()), 0.1);  // the boundary did drive the column
  EXPECT_LT(worst, 1e-11);
  RecordProperty("mirror_difference", sci(worst));
  EXPECT_EQ(full.p_bottom(), boundary(100 * dt));
  // restart keeps the bottom value
  DarcySolver copy(column(2 * nz, 2 * height), both);
  ASSERT_TRUE(copy.set_state(full.state()));
  EXPECT_EQ(copy.p_bottom(), full.p_bottom());
}

// ---------------------------------------------------------------------------------------
// `solver relaxed THETA TOL`: the original program's iteration

namespace {
DarcyParams relaxed(DarcyParams p, double theta, double tol)
{
  p.scheme = DarcyParams::Scheme::Relaxed;
  p.theta = theta;
  p.relaxed_tol = tol;
  return p;
}
}    // namespace

// Compaction of one cell of a nearly impermeable box (the CompactionRaisesPressure case):
// the converged update is the explicit forcing dt (-dphi/dt)/(beta phi (1-phi)); one
// relaxed sweep (a tolerance it meets at once) moves p by theta of it, and sweeps to a
// tight tolerance reach it (the relaxation's fixed point is the Crank-Nicolson solution).
TEST(DarcySolver, RelaxedSweepMovesThetaOfTheConvergedUpdate)
{
  const GridGeom &g = compaction_box;
  DarcyParams params = nearly_impermeable();
  params.maxiter = 2000;
  const int centre = compaction_centre;
  const double dt = 0.1, expected = dt * 0.01 / (2.0 * 0.4 * 0.6);
  for (double theta : {0.05, 0.5}) {
    DarcySolver once(g, relaxed(params, theta, 1e30));
    compact_centre(once);
    const StepResult r = once.step(dt, 0.0);
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.iterations, 1);
    EXPECT_NEAR(once.pressure()[centre], theta * expected, 1e-9 * expected) << theta;

    DarcySolver tight(g, relaxed(params, theta, 1e-12));
    compact_centre(tight);
    const StepResult t = tight.step(dt, 0.0);
    EXPECT_TRUE(t.converged);
    EXPECT_EQ(t.iterations % 10, 1);    // tested at sweeps 0, 10, 20, ... (counted from 1)
    // the Crank-Nicolson solution (with its 1e-12-relative diffusion, which the analytic
    // `expected` leaves out): after n sweeps (1 - theta)^n of the update is left,
    // (1 - theta)/theta times the last change, which the tolerance holds to 1e-12 |p|
    DarcyParams cg = params;
    cg.tol_rel = 1e-15;
    DarcySolver converged(g, cg);
    compact_centre(converged);
    ASSERT_TRUE(converged.step(dt, 0.0).converged);
    const double cn = converged.pressure()[centre];
    EXPECT_NEAR(cn, expected, 1e-9 * expected);
    EXPECT_NEAR(tight.pressure()[centre], cn, (1.0 - theta) / theta * 1e-12 * cn + 1e-17) << theta;
  }
}

// With diffusion, one sweep from p(t) is theta times forward Euler: dp = theta dt D
// (p_{k+1} - 2 p_k + p_{k-1})/dz^2 on a column (mirror at the bottom, the Dirichlet top a
// half cell above the top centre: ghost 2 p_top - p, p_top the mean of old and new),
// written out here independently of the solver's operator.
TEST(DarcySolver, RelaxedSweepIsThetaTimesForwardEuler)
{
  const int nz = 8;
  const GridGeom g = column(nz, 1.0);
  const double dz = g.dz, dt = 1e-4, theta = 0.05, p_top_old = 0.2, p_top_new = 0.6;
  DarcySolver s(g, relaxed(unit_diffusivity(), theta, 1e30));
  std::vector<double> p(nz);
  for (int k = 0; k < nz; ++k) p[k] = std::sin(1.3 * (k + 0.5) * dz) + 0.1 * k;
  s.set_pressure(p, p_top_old);
  ASSERT_TRUE(s.step(dt, p_top_new).converged);
  const double p_top_mean = 0.5 * (p_top_old + p_top_new);
  for (int k = 0; k < nz; ++k) {
    const double below = k > 0 ? p[k - 1] : p[k];
    const double above = k < nz - 1 ? p[k + 1] : 2.0 * p_top_mean - p[k];
    const double euler = dt * (above - 2.0 * p[k] + below) / (dz * dz);    // D = 1
    EXPECT_NEAR(s.pressure()[k] - p[k], theta * euler, 1e-12 * std::fabs(euler) + 1e-15) << k;
  }
}

// The sinusoidal column of TidalTopPressureDecaysWithDepth with the original's scheme
// (theta 0.05, TOL 1e-3) next to the converged one, against the exact solution: what
// rerunning the paper's numerics changes there. The relaxed scheme stops after one sweep
// wherever |p| is large, so each fluid step moves p only a twentieth of the way: the
// pressure lags and is damped. Measured, not bounded by the scheme itself: the errors
// are reported, and the test requires the relaxed column to stay finite and to lag (its
// phase error larger than the converged one's) as that reasoning says.
TEST(DarcySolver, RelaxedSchemeOnTheTidalColumn)
{
  const double height = 3.0, amplitude = 1.0, omega = 2 * pi, period = 1.0;
  const int nz = 60, steps = 200;
  const double dt = period / steps;
  const GridGeom g = column(nz, height);
  const std::complex<double> kappa = std::sqrt(std::complex<double>(0.0, omega));
  auto exact = [&](double z) { return amplitude * std::cosh(kappa * z) / std::cosh(kappa * height); };
  double errors[2][2];
  int sweeps = 0;
  for (int scheme = 0; scheme < 2; ++scheme) {
    DarcyParams params = unit_diffusivity();
    params.maxiter = 5000;
    if (scheme == 1) params = relaxed(params, 0.05, 1e-3);
    DarcySolver s(g, params);
    std::vector<double> p(nz);
    for (int k = 0; k < nz; ++k) p[k] = exact(z_centre(g, k)).imag();
    s.set_pressure(p, 0.0);
    const int periods = 6;    // the relaxed column's transient: it starts on the exact cycle
    std::vector<double> a_sin(nz, 0.0), a_cos(nz, 0.0);
    for (int n = 1; n <= (periods + 1) * steps; ++n) {
      const double t = n * dt;
      const StepResult r = s.step(dt, amplitude * std::sin(omega * t));
      ASSERT_TRUE(r.converged) << "step " << n;
      if (scheme == 1) sweeps += r.iterations;
      if (n > periods * steps)
        for (int k = 0; k < nz; ++k) {
          a_sin[k] += 2.0 / steps * s.pressure()[k] * std::sin(omega * t);
          a_cos[k] += 2.0 / steps * s.pressure()[k] * std::cos(omega * t);
        }
    }
    double amp_error = 0.0, phase_error = 0.0;
    for (int k = 0; k < nz; ++k) {
      const std::complex<double> e = exact(z_centre(g, k));
      ASSERT_TRUE(std::isfinite(a_sin[k]) && std::isfinite(a_cos[k]));
      amp_error = std::max(amp_error, std::fabs(std::hypot(a_sin[k], a_cos[k]) - std::abs(e)));
      if (std::abs(e) > 0.01 * amplitude)
        phase_error = std::max(phase_error, std::fabs(std::remainder(
                                                std::atan2(a_cos[k], a_sin[k]) - std::arg(e), 2 * pi)));
    }
    errors[scheme][0] = amp_error;
    errors[scheme][1] = phase_error;
  }
  std::printf("[ report ] tidal column, D dt/dz^2 = %.2f: converged amplitude error %.3e A, phase "
              "%.3e rad; relaxed (0.05, 1e-3) amplitude %.3e A, phase %.3e rad, %.2f sweeps per step\n",
              dt / (g.dz * g.dz), errors[0][0], errors[0][1], errors[1][0], errors[1][1],
              sweeps / double((6 + 1) * steps));
  RecordProperty("relaxed_amplitude_error", sci(errors[1][0]));
  RecordProperty("relaxed_phase_error", sci(errors[1][1]));
  EXPECT_GT(errors[1][1], errors[0][1]);
}
