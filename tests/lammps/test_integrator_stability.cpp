// Energy of the grain integrators at the recommended eps = Δt·√(kn/m) = 0.07 on a frictionless
// dense gas, and a clearly unstable eps stopped by pair linear/coulomb's overlap_limit instead
// of a silent NaN run (the stability map is in bench/integrators/RESULTS.md).
#include "granular_inputs.h"
#include "lammps_fixture.h"

#include "update.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using pwtest::Accel;
using pwtest::Lammps;

namespace {

const double KN = 2000.0;    // grains of mass 1: eps = Δt √KN

// the 216-grain dense gas of granular_inputs.h, frictionless, at eps with `integrator`
void frictionless_gas(Lammps &l, const std::string &integrator, double eps)
{
  l.commands(pwtest::dense_gas(6));
  l.commands("pair_style linear/coulomb\npair_coeff * * " + std::to_string(KN) +
             " 0.0 0.0\nunfix integrate\nfix integrate all " + integrator + "\n");
  char dt[64];
  std::snprintf(dt, sizeof(dt), "timestep %.17g", eps / std::sqrt(KN));
  l.command(dt);
}

struct EnergyChange {
  double lowest, highest, last;    // of (E − E0)/E0 over the samples
};

// relative change of ke + pe (no friction: no rotation) every 100 steps over `steps` steps
EnergyChange energy_change(const std::string &integrator, double eps, int steps)
{
  Lammps l;
  frictionless_gas(l, integrator, eps);
  l.command("run 0");
  const double e0 = l.thermo("ke") + l.thermo("pe");
  EnergyChange c = {0.0, 0.0, 0.0};
  for (int n = 0; n < steps; n += 100) {
    l.command("run 100");
    c.last = (l.thermo("ke") + l.thermo("pe") - e0) / e0;
    c.lowest = std::min(c.lowest, c.last);
    c.highest = std::max(c.highest, c.last);
  }
  std::printf("[ report ] %-30s eps %.2f, %d steps: (E-E0)/E0 in [%.2e, %.2e], last %.2e\n",
              integrator.c_str(), eps, steps, c.lowest, c.highest, c.last);
  return c;
}

}    // namespace

TEST(IntegratorStability, EnergyStaysBoundedAtTheRecommendedEpsilon)
{
  // Bounds from a two-grain contact, ω = √(2kn/m), so h = ωΔt = √2 eps, and the linear
  // analysis of one step (linear_amplification in bench/integrators/integrator_bench.py); most contacts of
  // this gas are binary (clusters of contacts vibrate faster and would grow faster):
  // - velocity Verlet is symplectic: no growth, an energy error fluctuating at O(h²), plus
  //   O(h²) when a contact opens or closes between steps; bound eps² = 4.9e-3 (measured 4.3e-4);
  // - sphere's Taylor step amplifies a contact's amplitude by 1 + h⁴/6 per step (two-step
  //   Adams–Bashforth velocities), so the energy rises, at most by 2h⁴/6 = (4/3)eps⁴ per step
  //   if all of it sat in contacts all the time, plus eps²: 0.101 in 3000 steps (measured
  //   +4.0 %, always rising; 1e5 steps blow up, bench/integrators/RESULTS.md);
  // - the corrector damps by 1 − h⁴/24 per step: it loses at most (1/3)eps⁴ per step, 2.4 %
  //   in 3000 steps, plus eps² (measured −0.9 %), and gains no more than eps².
  // A run that blows up leaves these bounds by orders of magnitude.
  const double eps = 0.07, eps2 = eps * eps, eps4 = eps2 * eps2;
  const int steps = 3000;

  const EnergyChange verlet = energy_change("nve/sphere", eps, steps);
  EXPECT_LT(std::max(-verlet.lowest, verlet.highest), eps2);

  const EnergyChange ty3 = energy_change("nve/sphere/ty3", eps, steps);
  EXPECT_GT(ty3.last, 0.0);    // the weak instability is real: energy is gained
  EXPECT_LT(ty3.highest, 4.0 / 3.0 * eps4 * steps + eps2);
  EXPECT_GT(ty3.lowest, -eps2);

  const EnergyChange corrected = energy_change("nve/sphere/ty3 corrector yes", eps, steps);
  EXPECT_LT(corrected.last, 0.0);    // the corrector dissipates
  EXPECT_GT(corrected.lowest, -(eps4 / 3.0 * steps + eps2));
  EXPECT_LT(corrected.highest, eps2);
}

namespace {

// Each integrator above its limit on this gas in the stability map of
// bench/integrators/RESULTS.md (Verlet 0.2, sphere's Taylor step 0.05; the corrector, which
// dissipates, holds at 1.0 and breaks abruptly by 1.4), yet small enough that the first
// steps are sound: the instability grows over several steps, and pair linear/coulomb's
// overlap_limit must stop the run naming the step and grains, not let it run on with NaN.
void unstable_epsilon_stops(Accel accel)
{
  const std::pair<std::string, double> cases[] = {{"nve/sphere", 1.0},
                                                  {"nve/sphere/ty3", 0.3},
                                                  {"nve/sphere/ty3 corrector yes", 1.2}};
  for (const auto &c : cases) {
    Lammps l(accel);
    frictionless_gas(l, c.first, c.second);
    l.command("run 0");    // the starting state is sound: no contact deeper than the limit
    pwtest::expect_error(l, "run 1000", "more than overlap_limit 0.5 of the smaller radius");
    const long stopped = (long) l.lmp->update->ntimestep;
    std::printf("[ report ] %s%s at eps %.2f: stopped at step %ld\n", c.first.c_str(),
                accel == Accel::kokkos ? " (kk)" : "", c.second, stopped);
    EXPECT_GT(stopped, 2);    // grew over steps, not one impossible step
    EXPECT_LT(stopped, 1000);
  }
}

}    // namespace

PW_TEST_CPU_AND_KOKKOS(IntegratorStability, UnstableEpsilonStopsWithTheOverlapLimitError,
                       unstable_epsilon_stops)
