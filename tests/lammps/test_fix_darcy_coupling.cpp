// The coupled scene of the tidal shear experiment through the fixes: pressure made by
// grains that compact an undrained cell, the fluid's x-force in the shear plate's sum and
// no vertical fluid force on the plate (novertical), and a top condition that follows a
// moving ztop. CPU, KOKKOS and MPI decompositions.
#include "lammps_fixture.h"

#include "fix.h"
#include "modify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using pwtest::Accel;
using pwtest::Lammps;

namespace {

const double PI = 3.14159265358979323846;

LAMMPS_NS::Fix *fix_of(Lammps &l, const char *id)
{
  const int i = l.lmp->modify->find_fix(id);
  return i < 0 ? nullptr : l.lmp->modify->fix[i];
}

std::vector<double> field(Lammps &l, const char *name, int size)
{
  int dim = 0;
  const double *data = (const double *) fix_of(l, "fl")->extract(name, dim);
  return std::vector<double>(data, data + size);
}

// ---- an undrained pair of cells compacted and dilated by moving grains
//
// Box [0,2] x [0,1] x [0,1], fluid grid 2 x 1 x 1: cell 0 centred at x = 0.5, cell 1 at
// 1.5, each of volume 1. With one cell in y and z every grain deposits its whole volume
// into its x-cells, with the hat weights 1.5 - x and x - 0.5 while 0.5 <= x <= 1.5, and
// with two periodic cells the central grad phi in x is (phi_c - phi_c)/2dx = 0: the grain
// term is dphi/dt alone. Four static grains of radius 0.24 (V = 0.0579) sit at each centre;
// eight "movers" start at x = 0.6 and 0.7 and move at w = 0.2 in +x for t = 1, so each
// cell's solid volume changes linearly in time: cell 0 dilates (phi 0.375 -> 0.467), cell
// 1 compacts (phi 0.699 -> 0.606). k_c = 1e-30 makes the cells undrained (D ~ 1e-27).
const double R = 0.24, W = 0.2, BETA = 0.01, DT = 1e-3;
const int STEPS = 1000;
const double VOLUME = 4.0 / 3.0 * PI * R * R * R;

// units lj, a box periodic in x and y with the given extent, newton off (for /kk)
void open_box(Lammps &l, const std::string &box, const std::string &processors)
{
  l.commands("units lj\natom_style sphere\natom_modify map array\nboundary p p f\nnewton off\n"
             "comm_modify vel yes\n" + processors + "\nregion box block " + box +
             " units box\ncreate_box 1 box\n");
}

// The static grains and the movers (group movers, at velocity W) in [0,2] x [0,1] x [0,1];
// with `plate` also four grains at x = 1.1 and 1.3, z = 0.75 (group top; the others: rest)
void cells_scene(Lammps &l, bool plate, const std::string &processors)
{
  open_box(l, "0 2 0 1 0 1", processors);
  for (const double x : {0.5, 1.5, 0.6, 0.7, 1.1, 1.3})
    for (const double y : {0.25, 0.75})
      for (const double z : {0.25, 0.75}) {
        if (x > 1.0 && x < 1.4 && (!plate || z < 0.5)) continue;
        l.command("create_atoms 1 single " + std::to_string(x) + " " + std::to_string(y) + " " +
                  std::to_string(z) + " units box");
      }
  l.commands("set type 1 diameter " + std::to_string(2 * R) +
             "\nset type 1 density 1\n"
             "region movers block 0.55 0.75 INF INF INF INF units box\ngroup movers region movers\n"
             "region plate block 1.0 1.4 INF INF INF INF units box\ngroup top region plate\n"
             "group rest subtract all top\n"
             "velocity movers set " + std::to_string(W) + " 0 0\n"
             "neighbor 0.1 bin\ntimestep " + std::to_string(DT) + "\n");
}

void undrained_cells(Lammps &l, int every, const std::string &processors = "")
{
  cells_scene(l, false, processors);
  l.command("fix fl all darcy/pressure grid 2 1 1 viscosity 1 compressibility " +
            std::to_string(BETA) +
            " density 0 permeability 1e-30 top noflow porosity 0.05 0.99 tol 1e-13 every " +
            std::to_string(every));
  l.commands("fix move all nve\nfix prescribed all setforce 0 0 0\n");    // after the fluid
}

// cell porosities at time t (the scene's deposits, computed here independently)
std::vector<double> cell_porosity(double t)
{
  double solid[2] = {4 * VOLUME, 4 * VOLUME};
  for (const double x0 : {0.6, 0.7}) {
    const double x = x0 + W * t;
    solid[0] += 4 * VOLUME * (1.5 - x);
    solid[1] += 4 * VOLUME * (x - 0.5);
  }
  return {1.0 - solid[0], 1.0 - solid[1]};
}

// undrained: dp = -dphi/(beta phi (1 - phi)), so p(t) - p(0) = -[ln(phi/(1-phi))]/beta
double undrained_pressure(double phi0, double phi1)
{
  return -(std::log(phi1 / (1.0 - phi1)) - std::log(phi0 / (1.0 - phi0))) / BETA;
}

// The fix advances p by -dt_f dphi/dt/(beta phi (1-phi)) with phi at the end of each fluid
// step and dphi/dt exact (phi is linear in t): a right-endpoint Riemann sum of the integral,
// whose error is at most 1/2 |dphi per step| |dphi total| max|f'| with f = 1/(beta phi
// (1-phi)), f' = -(1 - 2 phi)/(beta phi^2 (1-phi)^2), over the porosities passed.
double riemann_bound(double phi0, double phi1, int fluid_steps)
{
  double worst = 0.0;
  for (int k = 0; k <= 100; ++k) {
    const double phi = phi0 + (phi1 - phi0) * k / 100.0;
    worst = std::max(worst, std::fabs(1 - 2 * phi) / (BETA * std::pow(phi * (1 - phi), 2)));
  }
  return 0.5 * std::fabs(phi1 - phi0) / fluid_steps * std::fabs(phi1 - phi0) * worst;
}

}    // namespace

static void check_undrained_cells(Accel accel)
{
  const std::vector<double> phi0 = cell_porosity(0.0), phi1 = cell_porosity(STEPS * DT);
  for (int every : {1, 10}) {
    Lammps l(accel);
    undrained_cells(l, every);
    l.command("run 0");
    const auto start = field(l, "porosity", 2);
    for (int c = 0; c < 2; ++c) ASSERT_NEAR(start[c], phi0[c], 1e-14) << c;
    l.command("run " + std::to_string(STEPS));
    const auto p = field(l, "pressure", 2);
    const auto end = field(l, "porosity", 2);
    const char *which = accel == Accel::none ? "cpu" : "kk";
    for (int c = 0; c < 2; ++c) {
      ASSERT_NEAR(end[c], phi1[c], 1e-12) << c;
      const double expected = undrained_pressure(phi0[c], phi1[c]);
      const double bound = riemann_bound(phi0[c], phi1[c], STEPS / every);
      std::printf("[ report ] undrained cell %d (%s, every %d): phi %.4f -> %.4f, p %.6g, "
                  "exact %.6g, |dp| %.2e <= bound %.2e\n", c, which, every, phi0[c], phi1[c],
                  p[c], expected, std::fabs(p[c] - expected), bound);
      // the linearised -dphi/(beta phi (1-phi)) at the mean porosity is within 2% here
      const double mid = 0.5 * (phi0[c] + phi1[c]);
      EXPECT_NEAR(p[c], -(phi1[c] - phi0[c]) / (BETA * mid * (1 - mid)), 0.02 * std::fabs(expected));
      // the discrete scheme: within its Riemann-sum bound (plus the solve's 1e-13)
      EXPECT_LE(std::fabs(p[c] - expected), bound + 1e-10 * std::fabs(expected))
          << which << " every " << every << " cell " << c;
    }
    EXPECT_GT(p[1], 0.0);    // compaction raises the pressure
    EXPECT_LT(p[0], 0.0);    // dilation lowers it
    // closed box: the stored change is the grain source, the inflow 0
    EXPECT_EQ(l.equal("f_fl[9]"), 0.0);
    EXPECT_LE(std::fabs(l.equal("f_fl[7]")), l.equal("f_fl[11]") + 1e-12 * std::fabs(l.equal("f_fl[8]")));
  }
}
PW_TEST_CPU_AND_KOKKOS(FixDarcyCoupling, UndrainedCellsFollowTheirPorosity, check_undrained_cells)

TEST(FixDarcyCoupling, UndrainedCellsMpiDecompositionDoesNotChangeThem)
{
  auto run = [](MPI_Comm comm) {
    Lammps l(Accel::none, comm);
    undrained_cells(l, 10, "processors * 1 1");
    l.command("run " + std::to_string(STEPS));
    return field(l, "pressure", 2);
  };
  const auto parallel = run(MPI_COMM_WORLD), serial = run(MPI_COMM_SELF);
  // deposits summed in another order: round-off, then the same solves
  for (int c = 0; c < 2; ++c) EXPECT_NEAR(parallel[c], serial[c], 1e-12 * std::fabs(serial[c])) << c;
}

// ---- the shear plate in a pressure field
//
// The movers of the scene above, on a 4 x 1 x 1 grid, make a pressure that varies in x; a
// plate of four grains (group top, at x = 1.1 and 1.3) rides in it under fix shear/stress
// with tau = 0, and every grain feels buoyancy (rho_f = 1, g = 1). The plate's x-force sum
// is the fluid's alone (no contacts): the resisting stress -sum F_x/(L_x L_y) must be the
// sum of the plate grains' fluid x-forces (the fix's per-atom array), which must not vanish;
// with novertical top their vertical fluid force is 0 and the other grains keep theirs.
void plate_in_fluid(Lammps &l, bool novertical, const std::string &processors = "")
{
  cells_scene(l, true, processors);
  l.command("fix fl all darcy/pressure grid 4 1 1 viscosity 1 compressibility " +
            std::to_string(BETA) +
            " density 1 gravity 0 0 -1 permeability 1e-3 top noflow porosity 0.05 0.99 "
            "tol 1e-13 every 5" + std::string(novertical ? " novertical top" : ""));
  l.commands("fix move all nve\nfix prescribed rest setforce 0 0 0\n"
             "fix s top shear/stress tau 0 mass 2\n"
             "compute fx_top top reduce sum f_fl[1]\ncompute fz_top top reduce sum f_fl[3]\n"
             "compute fz_rest rest reduce sum f_fl[3]\n"
             "thermo_style custom step c_fx_top c_fz_top c_fz_rest f_s[3]\n");    // current
}

static void check_plate_in_fluid(Accel accel)
{
  const char *which = accel == Accel::none ? "cpu" : "kk";
  for (bool novertical : {false, true}) {
    Lammps l(accel);
    plate_in_fluid(l, novertical);
    l.command("run 400");
    const double fx = l.equal("c_fx_top"), fz = l.equal("c_fz_top");
    const double resisting = l.equal("f_s[3]"), area = 2.0;
    std::printf("[ report ] plate in fluid (%s, novertical %d): sum fluid f_x %.6g, "
                "-resisting stress x area %.6g, sum fluid f_z %.6g, others' f_z %.6g\n", which,
                novertical, fx, -resisting * area, fz, l.equal("c_fz_rest"));
    ASSERT_GT(std::fabs(fx), 1e-6) << which;    // the pressure does vary in x
    EXPECT_NEAR(-resisting * area, fx, 1e-12 * std::fabs(fx)) << which;
    // the others feel buoyancy V rho_f g (16 grains) plus a vertical gradient of 0
    EXPECT_NEAR(l.equal("c_fz_rest"), 16 * VOLUME, 1e-9) << which;
    if (novertical) {
      EXPECT_EQ(fz, 0.0) << which;
    } else {
      EXPECT_NEAR(fz, 4 * VOLUME, 1e-9) << which;
    }
    // the plate moves as one, with the acceleration of the fluid's x-force over its mass
    EXPECT_NE(l.equal("f_s[1]"), 0.0) << which;
  }
}
PW_TEST_CPU_AND_KOKKOS(FixDarcyCoupling, ShearPlateSumsTheFluidForceAndNoverticalDropsItsVerticalPart,
                       check_plate_in_fluid)

TEST(FixDarcyCoupling, ShearPlateInFluidMpiDecompositionDoesNotChangeIt)
{
  auto run = [](MPI_Comm comm) {
    Lammps l(Accel::none, comm);
    plate_in_fluid(l, true, "processors * 1 1");
    l.command("run 400");
    return std::vector<double>{l.equal("f_s[1]"), l.equal("f_s[2]"), l.equal("f_s[3]"),
                               l.equal("c_fz_top")};
  };
  const auto parallel = run(MPI_COMM_WORLD), serial = run(MPI_COMM_SELF);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(parallel[k], serial[k], 1e-12 * std::max(1e-6, std::fabs(serial[k]))) << k;
  EXPECT_EQ(parallel[3], 0.0);
}

// ---- a top condition that follows a moving ztop
//
// A 2 x 2 x 10 grid over [0,1]^2 x [0,1] with a grain bed in the lower half, the grains
// moving (a shear-like x-velocity and a slow vertical breathing, no forces), Dirichlet top
// p_top(t) = 0.3 sin(2 pi t) at ztop(t) = 0.96 - 0.5 t: over t = 1 the top face sweeps
// down through five cell centres, switching layers off one by one. At every check the
// inactive cells hold p_top exactly, the balance residual stays within its allowance (the
// switched-off cells leave the balance without a jump) and the active-layer count follows
// ztop.
void moving_top(Lammps &l, const std::string &processors = "")
{
  open_box(l, "0 1 0 1 0 1", processors);
  l.commands("lattice sc 512 origin 0.5 0.5 0.5\nregion bed block 0 1 0 1 0 0.5 units box\n"
             "create_atoms 1 region bed\nset type 1 diameter 0.1\nset type 1 density 1\n"
             "variable vx atom 0.05*z\nvariable vz atom 0.02*(0.25-z)\n"
             "velocity all set v_vx 0 v_vz\n"
             "variable ptop equal 0.3*sin(2*PI*time)\nvariable ztop equal 0.96-0.5*time\n"
             "neighbor 0.05 bin\ntimestep 1e-3\n"
             "fix fl all darcy/pressure grid 2 2 10 viscosity 1 compressibility 1 density 0 "
             "permeability 0.1 top v_ptop ztop v_ztop tol 1e-12 every 4\n"
             "fix move all nve\nfix prescribed all setforce 0 0 0\n");
}

static void check_moving_top(Accel accel)
{
  const char *which = accel == Accel::none ? "cpu" : "kk";
  Lammps l(accel);
  moving_top(l);
  l.command("run 0");
  int switches = 0, last = (int) l.equal("f_fl[12]");
  EXPECT_EQ(last, 10) << which;    // ztop 0.96: every centre below it
  double worst = 0.0;
  for (int n = 1; n <= 25; ++n) {
    l.command("run 40 pre no post no");
    const double t = n * 40 * 1e-3, ztop = 0.96 - 0.5 * t;
    const int layers = (int) l.equal("f_fl[12]");
    // layer k active while its centre (k + 0.5)/10 lies below ztop
    EXPECT_EQ(layers, (int) std::ceil(ztop * 10 - 0.5)) << which << " t " << t;
    if (layers != last) ++switches;
    last = layers;
    const auto p = field(l, "pressure", 40);
    // (read from the fix itself: an equal-style variable rounds by a few ulp)
    const double p_top = fix_of(l, "fl")->compute_vector(5);
    for (int c = layers * 4; c < 40; ++c) ASSERT_EQ(p[c], p_top) << which << c;
    EXPECT_NEAR(l.equal("f_fl[6]"), 0.3 * std::sin(2 * PI * t), 1e-12) << which;
    const double residual = std::fabs(l.equal("f_fl[7]")), allowance = l.equal("f_fl[11]");
    const double gross = std::fabs(l.equal("f_fl[8]")) + std::fabs(l.equal("f_fl[9]")) +
        std::fabs(l.equal("f_fl[10]"));
    ASSERT_GT(gross, 0.0);
    worst = std::max(worst, residual / (allowance + 1e-300));
    EXPECT_LE(residual, allowance + 1e-12 * gross) << which << " t " << t;
  }
  std::printf("[ report ] moving ztop (%s): %d layer switches, balance residual at most "
              "%.2g of its allowance\n", which, switches, worst);
  EXPECT_EQ(switches, 5) << which;
  EXPECT_GT(std::fabs(l.equal("f_fl[10]")), 0.0) << which;    // the grains drive the fluid
}
PW_TEST_CPU_AND_KOKKOS(FixDarcyCoupling, TopConditionFollowsAMovingZtopWithoutABalanceJump,
                       check_moving_top)

TEST(FixDarcyCoupling, MovingZtopMpiDecompositionDoesNotChangeIt)
{
  auto run = [](MPI_Comm comm) {
    Lammps l(Accel::none, comm);
    moving_top(l, "processors * * 1");
    l.command("run 1000");
    return field(l, "pressure", 40);
  };
  const auto parallel = run(MPI_COMM_WORLD), serial = run(MPI_COMM_SELF);
  double scale = 0.0;
  for (double p : serial) scale = std::max(scale, std::fabs(p));
  // two runs that differ by round-off agree to the CG tolerance (1e-12 of max |p|)
  for (int c = 0; c < 40; ++c) EXPECT_NEAR(parallel[c], serial[c], 1e-10 * scale) << c;
}
