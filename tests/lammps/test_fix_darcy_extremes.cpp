// fix darcy/pressure under stress, through LAMMPS: the closed-box fluid balance with grains
// at rest (p exactly constant) and moving (balance closes to the solve tolerance, and
// survives a restart), a stiff fluid at a large fluid step, and the bad states it must
// catch (a non-finite grain, an overflowing system, a grid finer than the grains).
#include "darcy_inputs.h"
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

using pwtest::Accel;
using pwtest::Lammps;
using pwtest::expect_error;

namespace {

std::vector<double> pressure(Lammps &l, int cells)
{
  return l.fix_field("fl", "pressure", cells);
}

// the 64 grains in their 4 x 4 x 4 box of darcy_inputs.h, a 2 x 2 x 2 grid
const int BOX_CELLS = 8;
void grains_in_box(Lammps &l) { l.commands(pwtest::grains_in_box); }

// mu = beta = 1, k capped at KMAX; the defaults tol 1e-10, porosity 0.1 0.9
const double KMAX = 0.01, TOL = 1e-10, PHI_MAX = 0.9;
const std::string closed_fluid = pwtest::closed_box_fluid;

// |balance residual| the solve tolerance allows over `fluid_steps` steps of dt_f (see
// FluidBalance::allowance): per step V dt/mu sum_c A_cc tol max|p|, with
// dt/mu A_cc <= beta phi_max + dt k_max sum_d 2/Delta_d^2 / mu (both faces of each axis)
double allowance(int fluid_steps, double dt_f, double p_max)
{
  const double volume = 8.0, spacing = 2.0;
  const double row = PHI_MAX + dt_f * KMAX * 3 * 2 / (spacing * spacing);
  return fluid_steps * BOX_CELLS * volume * row * TOL * p_max;
}

}    // namespace

TEST(FixDarcyExtremes, ClosedBoxWithGrainsAtRestKeepsPressureExactly)
{
  // no motion: dphi/dt and vbar are exactly 0, uniform p makes every flux exactly 0 and
  // grad p (mirror ghosts) 0, so nothing can change: p stays 5 bit for bit, no CG work
  Lammps l;
  grains_in_box(l);
  l.command(closed_fluid + " initial 5");
  l.command("run 100");
  for (double p : pressure(l, BOX_CELLS)) ASSERT_EQ(p, 5.0);
  EXPECT_EQ(l.equal("f_fl[4]"), 0.0);     // iterations
  EXPECT_EQ(l.equal("f_fl[7]"), 0.0);     // balance residual
  EXPECT_EQ(l.equal("f_fl[8]"), 0.0);     // stored
  EXPECT_EQ(l.equal("f_fl[9]"), 0.0);     // boundary inflow
  EXPECT_EQ(l.equal("f_fl[10]"), 0.0);    // grain source
  double v_max = 0.0;
  for (const auto &kv : l.gather3("v"))
    for (double c : kv.second) v_max = std::max(v_max, std::fabs(c));
  EXPECT_EQ(v_max, 0.0);
}

TEST(FixDarcyExtremes, ClosedBoxWithMovingGrainsBalancesTheFluid)
{
  // grains moving through each other squeeze the fluid; nothing enters or leaves, so the
  // stored change must equal the grain source to the solve tolerance (allowance above)
  const std::string restart = "pw_darcy_balance.restart";
  double p_max = 0.0, stored_whole = 0.0, grains_whole = 0.0;
  const int every = 2, chunks = 10, chunk = 20;
  {
    Lammps l;
    grains_in_box(l);
    l.command("velocity all create 0.5 4928 loop geom");
    l.command(closed_fluid + " initial 1 every 2");
    for (int n = 0; n < chunks; ++n) {
      l.command("run " + std::to_string(chunk));
      p_max = std::max(p_max, l.equal("f_fl[3]"));
      if (n == chunks / 2 - 1) l.command("write_restart " + restart);
    }
    const int fluid_steps = chunks * chunk / every;
    const double bound = allowance(fluid_steps, every * 0.01, p_max);
    const double residual = l.equal("f_fl[7]");
    stored_whole = l.equal("f_fl[8]");
    grains_whole = l.equal("f_fl[10]");
    std::printf("[ report ] closed box: stored %.6e, grain source %.6e, residual %.2e, "
                "allowance %.2e (a-priori bound %.2e), max|p| %.4g\n", stored_whole,
                grains_whole, residual, l.equal("f_fl[11]"), bound, p_max);
    EXPECT_EQ(l.equal("f_fl[9]"), 0.0);    // closed: no face has a coefficient
    EXPECT_GT(std::fabs(grains_whole), 1e3 * bound);    // the grains did force the fluid
    EXPECT_LE(std::fabs(residual), bound);
    // the fix's own allowance (the exact sum behind the a-priori bound) holds it too
    EXPECT_LE(std::fabs(residual), l.equal("f_fl[11]"));
    EXPECT_LE(l.equal("f_fl[11]"), bound);
  }
  {
    // the second half again from the restart: the balance goes on from where it was
    Lammps l;
    l.command("read_restart " + restart);
    l.commands("comm_modify vel yes cutoff 1.0\ntimestep 0.01\nfix move all nve/sphere\n"
               "fix walls all wall/reflect zlo EDGE zhi EDGE\n");
    l.command(closed_fluid + " initial 1 every 2");
    l.command("run " + std::to_string(chunks / 2 * chunk));
    // the grain source follows the trajectories, which agree to round-off (re-sorted
    // sums; the fluid force changes them by ~TOL max|p| V dt^2 / m): 1e-10 relative is
    // ample. Both runs' stored changes equal their grain sources within the allowance.
    const double grains = l.equal("f_fl[10]"), stored = l.equal("f_fl[8]");
    const double bound = allowance(chunks * chunk / every, every * 0.01, p_max);
    std::printf("[ report ] restart vs whole: grain source %.2e, stored %.2e relative\n",
                std::fabs(grains / grains_whole - 1), std::fabs(stored / stored_whole - 1));
    EXPECT_NEAR(grains, grains_whole, 1e-10 * std::fabs(grains_whole));
    EXPECT_NEAR(stored, stored_whole, std::fabs(grains - grains_whole) + 2 * bound);
    EXPECT_GT(std::fabs(stored), 1e3 * bound);    // not restarted from 0
  }
  std::remove(restart.c_str());
}

TEST(FixDarcyExtremes, StiffFluidAtLargeFluidStepStaysBoundedOrSaysItDidNot)
{
  // no grains (phi = 0.9 everywhere), drained top, p0 = 1: Crank-Nicolson cannot raise
  // the energy sum beta phi V p^2, so max|p| <= p0 sqrt(N_cells) = 4 (uniform phi).
  // beta 1e-9 and every 1000 (dt_f = 10, dz = 1/16, k = 72.9 kc) give D dt_f/dz^2 from
  // ~2e8 to ~2e14 over 6 decades of kc.
  for (const char *kc : {"1e-6", "1e-3", "1"}) {
    Lammps l;
    l.commands("units lj\natom_style sphere\nboundary p p f\nregion box block 0 1 0 1 0 1\n"
               "create_box 1 box\ntimestep 0.01\n");
    l.command(std::string("fix fl all darcy/pressure grid 1 1 16 viscosity 1 "
                          "compressibility 1e-9 density 1 initial 1 every 1000 permeability ") + kc);
    double largest = 0.0;
    for (int n = 0; n < 10; ++n) {
      l.command("run 1000");    // one fluid step each, each converged or the run stops
      largest = std::max(largest, l.equal("f_fl[3]"));
    }
    EXPECT_LE(largest, 4.0) << kc;
    EXPECT_GT(l.equal("f_fl[4]"), 0.0) << kc;    // a real solve
    std::printf("[ report ] stiff fluid, kc %s: max|p|/p0 over 10 fluid steps %.4g\n", kc, largest);
  }
  // the same with too few iterations stops at the first fluid step, saying why
  Lammps l;
  l.commands("units lj\natom_style sphere\nboundary p p f\nregion box block 0 1 0 1 0 1\n"
             "create_box 1 box\ntimestep 0.01\n");
  l.command("fix fl all darcy/pressure grid 1 1 16 viscosity 1 compressibility 1e-9 density 1 "
            "initial 1 every 1000 permeability 1 maxiter 2");
  expect_error(l, "run 2000", "step 1000: the pressure solve did not converge in 2 iterations");
}

namespace {

// a grain with an infinite velocity (1e308*10 overflows): the fix names it by its atom ID.
// No reneighboring before step 10: with LAMMPS' default delay (10 on 29Sep2021, 0 on
// 4Feb2025) or a check at step 1, LAMMPS' own "Non-numeric atom coords" stops the run first.
void infinite_grain_is_named(Accel accel)
{
  Lammps l(accel);
  grains_in_box(l);
  l.command("neigh_modify delay 10 every 1 check yes");
  l.command(closed_fluid);
  l.commands("run 0\nvariable huge atom 1e308*10\nset atom 17 vz v_huge\n");
  expect_error(l, "run 5", "step 1: 1 grain(s) of group all have a non-finite position or "
               "velocity, the first atom ID 17");
}

}    // namespace

TEST(FixDarcyExtremes, KokkosInfiniteGrainStopsTheRunNamingIt)
{
  PW_SKIP_WITHOUT_KOKKOS();
  infinite_grain_is_named(Accel::kokkos);
}

TEST(FixDarcyExtremes, BadStatesStopTheRunNamingCauseStepAndPlace)
{
  infinite_grain_is_named(Accel::none);
  {
    // boundary values that overflow the system: not finite, not "raise maxiter"
    Lammps l;
    l.commands("units lj\natom_style sphere\nboundary p p f\nregion box block 0 1 0 1 0 1\n"
               "create_box 1 box\ntimestep 0.01\n");
    l.command("fix fl all darcy/pressure grid 1 1 4 viscosity 1 compressibility 1 density 1 "
              "permeability 1 initial 1e308 top -1e308");
    expect_error(l, "run 2", "step 1: the pressure system is not finite (residual nan in cell "
                 "(1,1,4) centred at (0.5, 0.5, 0.875))");
  }
}

TEST(FixDarcyExtremes, GridFinerThanGrainsWarnsOnceNamingTheCell)
{
  // one grain of diameter 2 at (1.1, 1.1, 1.1) in cells of 0.5: its volume 4.19 lands on
  // 8 cells of volume 0.125, the largest share (0.7^3) on the cell centred at 1.25:
  // 0.343 * 4.18879 / 0.125 = 11.494 times its volume (printed to 4 digits)
  const std::string log = "pw_darcy_warn.log";
  {
    Lammps l(Accel::none, MPI_COMM_WORLD, {"-log", log});
    l.commands("units lj\natom_style sphere\nboundary p p f\nregion box block 0 4 0 4 0 4\n"
               "create_box 1 box\ncreate_atoms 1 single 1.1 1.1 1.1\nset type 1 diameter 2\n"
               "timestep 0.01\n");
    l.command("fix fl all darcy/pressure grid 8 8 8 viscosity 1 compressibility 1 density 1 "
              "permeability 1");
    l.command("run 3");
    EXPECT_EQ(l.equal("f_fl[3]"), 0.0);    // at rest: no forcing, p stays 0
  }
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::string needle = "WARNING: fix darcy/pressure: step 0: cell (3,3,3) centred at "
                             "(1.25, 1.25, 1.25) holds 11.49 times";
  EXPECT_NE(s.find(needle), std::string::npos) << s;
  EXPECT_EQ(s.find(needle), s.rfind("WARNING: fix darcy/pressure"));    // once per run
  std::remove(log.c_str());
}

TEST(FixDarcyExtremes, ClosedBoxBalanceMpiAgreesWithSerialAndAcrossRanks)
{
  // mpirun -np 2 and 3 via ctest: the balance comes from the replicated solve, so every
  // rank must hold the same numbers bit for bit, and they must match a serial run
  auto run = [](MPI_Comm comm, double out[3]) {
    Lammps l(Accel::none, comm);
    grains_in_box(l);
    l.command("velocity all create 0.5 4928 loop geom");
    l.command(closed_fluid + " initial 1 every 2");
    l.command("run 200");
    out[0] = l.equal("f_fl[8]");
    out[1] = l.equal("f_fl[10]");
    out[2] = l.equal("f_fl[11]");
  };
  double parallel[3], serial[3], lowest[3], highest[3];
  run(MPI_COMM_WORLD, parallel);
  run(MPI_COMM_SELF, serial);
  MPI_Allreduce(parallel, lowest, 3, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(parallel, highest, 3, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(lowest[k], highest[k]) << k;
  // trajectories agree to round-off (1e-10 relative for the grain source, as for the
  // restart above); the stored changes each equal their source within the allowance
  EXPECT_NEAR(parallel[1], serial[1], 1e-10 * std::fabs(serial[1]));
  EXPECT_NEAR(parallel[0], serial[0], std::fabs(parallel[1] - serial[1]) + parallel[2] + serial[2]);
}
