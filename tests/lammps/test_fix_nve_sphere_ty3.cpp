// fix nve/sphere/ty3 and nve/sphere/ty3/kk: exactness on a constant jerk, convergence order on
// a head-on collision (against nve/sphere), history through restarts, sorting, MPI
// migration and KOKKOS, input errors.
#include "fix_walls_inputs.h"
#include "granular_inputs.h"
#include "lammps_fixture.h"

#include "fix.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using pwtest::Accel;
using pwtest::Lammps;
using pwtest::expect_error;

namespace {

const double PI = 3.14159265358979323846;
const char *TY3 = "nve/sphere/ty3";
const char *TY3_CORRECTED = "nve/sphere/ty3 corrector yes";

// one grain of mass 1 at rest at the origin of a closed box, pushed by f(t) = F0 + F1 t
const double F0[3] = {0.3, -0.2, 0.1}, F1[3] = {2.0, 1.0, -3.0}, DT = 0.01;
void jerked_grain(Lammps &l, const std::string &integrator)
{
  l.commands("units lj\natom_style sphere\natom_modify map array\nboundary f f f\n"
             "region box block -20 20 -20 20 -20 20\ncreate_box 1 box\n"
             "create_atoms 1 single 0 0 0 units box\n" +
             pwtest::unit_grains +
             "velocity all set 0.5 0.0 -0.25\npair_style zero 1.0\npair_coeff * *\n"
             "timestep " +
             std::to_string(DT) + "\n");
  const char *axis = "xyz";
  for (int k = 0; k < 3; k++)
    l.command(std::string("variable f") + axis[k] + " equal " + std::to_string(F0[k]) + "+" +
              std::to_string(F1[k]) + "*time");
  l.command("fix push all addforce v_fx v_fy v_fz");
  l.command("fix integrate all " + integrator);
}

}    // namespace

TEST(FixNVESphereTY3, ConstantJerkIsIntegratedExactlyAfterTheFirstStep)
{
  for (const char *integrator : {TY3, TY3_CORRECTED, "nve/sphere"}) {
    Lammps l;
    jerked_grain(l, integrator);
    l.command("run 0");
    const std::vector<double> x0 = l.gather3("x").at(1), v0 = l.gather3("v").at(1);
    l.command("run 1");
    // the first step has no a_prev and takes ȧ = 0: x1 = x0 + v0Δt + ½a0Δt²
    const std::vector<double> x1 = l.gather3("x").at(1), v1 = l.gather3("v").at(1);
    double worst = 0.0;
    for (int n = 1; n <= 20; n++) {
      l.command("run 10");
      const double tau = 10.0 * n * DT;    // since step 1
      const auto x = l.gather3("x").at(1), v = l.gather3("v").at(1);
      for (int k = 0; k < 3; k++) {
        const double a1 = F0[k] + F1[k] * DT, j = F1[k];
        worst = std::max(worst,
                         std::fabs(x[k] - (x1[k] + tau * (v1[k] + tau * (a1 / 2 + tau * j / 6)))));
        worst = std::max(worst, std::fabs(v[k] - (v1[k] + tau * (a1 + tau * j / 2))));
      }
    }
    std::printf("[ report ] %s: largest deviation from the cubic through step 1 after 200 steps: "
                "%.3e\n",
                integrator, worst);
    if (std::string(integrator) == "nve/sphere") {
      EXPECT_GT(worst, 1e-6);    // velocity Verlet is not exact here: x lags by jΔt²τ/6
      continue;
    }
    // positions and velocities of order 1-10, 200 steps of sums: round-off stays below 1e-12
    EXPECT_LT(worst, 1e-12) << integrator;
    for (int k = 0; k < 3; k++) {
      const double a0 = F0[k], a1 = F0[k] + F1[k] * DT;
      EXPECT_NEAR(x1[k], x0[k] + v0[k] * DT + 0.5 * a0 * DT * DT, 1e-15) << integrator;
      // the predictor alone: v0 + a0Δt; the corrector starts with the trapezoid rule
      const double v1_expected = std::string(integrator) == TY3 ? v0[k] + a0 * DT
                                                                : v0[k] + 0.5 * (a0 + a1) * DT;
      EXPECT_NEAR(v1[k], v1_expected, 1e-15) << integrator;
    }
  }
}

// ---------------------------------------------------------------------------------------

namespace {

// Two grains of mass 1 and diameter 1 touching at t = 0 (x = ∓0.5), approaching at ±0.5,
// frictionless linear spring kn: while in contact the gap s = d − 1 is the harmonic
// s(t) = −sin(ωt)/ω, ω = √(kn/m_eff), m_eff = ½; the contact lasts T_c = π/ω. The contact
// starts on a step (t = 0), so the force is smooth on every step until release.
const double KN = 1.0e4, OMEGA = std::sqrt(KN / 0.5), T_CONTACT = PI / OMEGA;

// exact x of grain 2 and its velocity at time t
void head_on_exact(double t, double &x2, double &v2)
{
  if (t <= T_CONTACT) {
    x2 = 0.5 * (1.0 - std::sin(OMEGA * t) / OMEGA);
    v2 = -0.5 * std::cos(OMEGA * t);
  } else {    // velocities exchanged
    x2 = 0.5 + 0.5 * (t - T_CONTACT);
    v2 = 0.5;
  }
}

// |x2 − exact| and |v2 − exact| after `steps` steps of `duration`/steps
std::pair<double, double> head_on_error(const std::string &integrator, double duration, int steps)
{
  Lammps l;
  l.commands("units lj\natom_style sphere\natom_modify map array\nboundary f f f\nnewton off\n"
             "comm_modify vel yes\nregion box block -5 5 -5 5 -5 5\ncreate_box 1 box\n"
             "create_atoms 1 single -0.5 0 0 units box\ncreate_atoms 1 single 0.5 0 0 units box\n" +
             pwtest::unit_grains +
             "velocity all set 0.5 0 0 units box\ngroup second id 2\n"
             "velocity second set -0.5 0 0 units box\n"
             "pair_style linear/coulomb\npair_coeff * * " +
             std::to_string(KN) +
             " 0 0\n"
             "neighbor 0.3 bin\nneigh_modify delay 0 every 1 check yes\n");
  char dt[64];
  std::snprintf(dt, sizeof(dt), "timestep %.17g", duration / steps);
  l.command(dt);
  l.command("fix integrate all " + integrator);
  l.command("run " + std::to_string(steps));
  double x2, v2;
  head_on_exact(duration, x2, v2);
  return {std::fabs(l.equal("x[2]") - x2), std::fabs(l.equal("vx[2]") - v2)};
}

// observed orders log2(e(Δt)/e(Δt/2)) of x and v over a ladder of step counts
struct Orders {
  double x, v, finest_x;
};
Orders observed_orders(const std::string &integrator, double duration,
                       const std::vector<int> &ladder)
{
  std::vector<std::pair<double, double>> e;
  for (int steps : ladder) e.push_back(head_on_error(integrator, duration, steps));
  const size_t n = e.size();
  std::printf("[ report ] %-30s t = %.2f T_c  steps:", integrator.c_str(), duration / T_CONTACT);
  for (size_t k = 0; k < n; k++)
    std::printf(" %d: |dx| %.2e |dv| %.2e;", ladder[k], e[k].first, e[k].second);
  const Orders o = {std::log2(e[n - 2].first / e[n - 1].first),
                    std::log2(e[n - 2].second / e[n - 1].second), e[n - 1].first};
  std::printf("  order x %.2f v %.2f\n", o.x, o.v);
  return o;
}

}    // namespace

TEST(FixNVESphereTY3, HeadOnCollisionConvergesAtTheExpectedOrder)
{
  // measured at 0.6 T_c, inside the contact where the force is smooth: velocity Verlet is
  // second order; sphere's Taylor step is also second order, because its velocity update
  // v + aΔt + ½(a − a_prev)Δt is two-step Adams–Bashforth (local error 5/12 äΔt³); the
  // corrector makes it three-step Adams–Moulton, third order. Margin ±0.1 on the order
  // (measured within 0.02 of 2 and 3).
  const std::vector<int> ladder = {20, 40, 80, 160};
  const double t = 0.6 * T_CONTACT;
  const Orders verlet = observed_orders("nve/sphere", t, ladder);
  const Orders ty3 = observed_orders(TY3, t, ladder);
  const Orders corrected = observed_orders(TY3_CORRECTED, t, ladder);
  EXPECT_NEAR(verlet.x, 2.0, 0.1);
  EXPECT_NEAR(verlet.v, 2.0, 0.1);
  EXPECT_NEAR(ty3.x, 2.0, 0.1);
  EXPECT_NEAR(ty3.v, 2.0, 0.1);
  EXPECT_NEAR(corrected.x, 3.0, 0.1);
  EXPECT_NEAR(corrected.v, 3.0, 0.1);

  // after the release (1.7 T_c: the release falls between steps) the force's kink costs
  // every scheme an O(Δt²) velocity error; reported, asserted only to converge
  const std::vector<int> after = {34, 68, 136, 272};
  for (const char *integrator : {"nve/sphere", TY3, TY3_CORRECTED}) {
    const Orders o = observed_orders(integrator, 1.7 * T_CONTACT, after);
    EXPECT_GT(o.v, 1.0) << integrator;
  }
}

// ---------------------------------------------------------------------------------------

namespace {

// the dense gas of granular_inputs.h with friction, integrated by `integrator`
std::string frictional_gas(const std::string &integrator, int nside = 6)
{
  return pwtest::dense_gas(nside) +
      "pair_style linear/coulomb\npair_coeff * * 2000.0 2000.0 0.5\n"
      "unfix integrate\nfix integrate all " +
      integrator + "\n";
}

}    // namespace

TEST(FixNVESphereTY3, RestartSplitRunEqualsUnsplitRun)
{
  // separate lmp processes, as users run them (see the pair style's restart test)
  const std::vector<std::string> values = {"ke", "c_erot"};
  for (const std::string integrator : {TY3, TY3_CORRECTED}) {
    for (const std::string accel : {"", "-k on t 1 -sf kk"}) {
      const std::string tag =
          std::string(integrator == TY3 ? "ty3" : "ty3c") + (accel.empty() ? "_cpu" : "_kk");
      const std::string whole = "pw_ty3_whole_" + tag, split = "pw_ty3_split_" + tag,
                        forgot = "pw_ty3_forgot_" + tag;
      pwtest::run_lmp(frictional_gas(integrator) + "run 150\nwrite_restart " + split +
                          ".restart\nrun 150\n" + pwtest::save_results(whole, values),
                      accel, whole);
      const std::string resume = "read_restart " + split + ".restart\n" +
          pwtest::dense_gas_settings() + "unfix integrate\n";
      pwtest::run_lmp(resume + "fix integrate all " + integrator + "\nrun 150\n" +
                          pwtest::save_results(split, values),
                      accel, split);
      // control: another fix ID finds no history in the file and restarts with ȧ = 0
      pwtest::run_lmp(resume + "fix fresh all " + integrator + "\nrun 150\n" +
                          pwtest::save_results(forgot, values),
                      accel, forgot);
      const double lost = pwtest::max_abs_diff(pwtest::read_dump(whole + ".dump"),
                                               pwtest::read_dump(forgot + ".dump"));
      std::printf("[ report ] %s: without the stored history the run differs by %.2e\n",
                  tag.c_str(), lost);
      EXPECT_GT(lost, 1e-8) << tag;
      pwtest::remove_results(forgot);
      // the same operations in the same order: bit for bit (17 printed digits)
      pwtest::expect_identical_results(whole, split, tag);
    }
  }
}

TEST(FixNVESphereTY3, SortingAtomsKeepsEachAtomsHistory)
{
  // atom_modify sort reorders the local atoms every 5 steps, moving the history with
  // copy_arrays; forces then sum in another order: round-off amplified by a dense gas over
  // 300 steps stays below 1e-9 (a scrambled history would give O(1e-3))
  std::map<long, std::vector<double>> x[2];
  for (int k = 0; k < 2; k++) {
    Lammps l;
    l.commands(frictional_gas(TY3_CORRECTED));
    l.command(k == 0 ? "atom_modify sort 0 0.0" : "atom_modify sort 5 0.5");
    l.command("run 300");
    x[k] = l.gather3("x");
  }
  std::printf("[ report ] sorted vs unsorted after 300 steps: max |dx| %.1e\n",
              pwtest::max_abs_diff(x[0], x[1]));
  EXPECT_LE(pwtest::max_abs_diff(x[0], x[1]), 1e-9);
}

TEST(FixNVESphereTY3, KokkosEqualsCpu)
{
  for (const std::string integrator : {TY3, TY3_CORRECTED}) {
    std::map<long, std::vector<double>> x[2], omega[2];
    std::string style;
    const Accel accel[2] = {Accel::none, Accel::kokkos};
    for (int k = 0; k < 2; k++) {
      Lammps l(accel[k]);
      l.commands(frictional_gas(integrator));
      l.command("run 300");
      x[k] = l.gather3("x");
      omega[k] = l.gather3("omega");
      style = l.lmp->modify->fix[l.lmp->modify->find_fix("integrate")]->style;
    }
    EXPECT_EQ(style, "nve/sphere/ty3/kk");
    std::printf("[ report ] %s/kk vs CPU after 300 steps: max |dx| %.1e max |domega| %.1e\n",
                integrator.c_str(), pwtest::max_abs_diff(x[0], x[1]),
                pwtest::max_abs_diff(omega[0], omega[1]));
    // contacts summed in another order: round-off amplified by 300 steps of a dense gas
    EXPECT_LE(pwtest::max_abs_diff(x[0], x[1]), 1e-9) << integrator;
    EXPECT_LE(pwtest::max_abs_diff(omega[0], omega[1]), 1e-7) << integrator;
  }
}

TEST(FixNVESphereTY3, MpiMigrationCarriesTheHistory)
{
  // under mpirun -np 2 and 3 grains cross between ranks and take their a_prev along
  auto run = [](MPI_Comm comm) {
    Lammps l(Accel::none, comm);
    l.commands(frictional_gas(TY3_CORRECTED));
    l.command("run 300");
    return l.gather3("x");
  };
  const auto parallel = run(MPI_COMM_WORLD);
  const auto serial = run(MPI_COMM_SELF);
  std::printf("[ report ] ty3 decomposed vs serial: max |dx| %.1e\n",
              pwtest::max_abs_diff(parallel, serial));
  EXPECT_LE(pwtest::max_abs_diff(parallel, serial), 1e-9);
}

TEST(FixNVESphereTY3, BadInputGivesClearErrors)
{
  {
    Lammps l;
    l.commands(pwtest::dense_gas(3));
    expect_error(l, "fix t all nve/sphere/ty3 corrector", "corrector expects yes or no, but the command ends there");
    expect_error(l, "fix t all nve/sphere/ty3 corrector maybe",
                 "corrector expects yes or no, got 'maybe'");
    expect_error(l, "fix t all nve/sphere/ty3 disc", "unknown keyword 'disc' (allowed: corrector)");
  }
  Lammps atomic;    // one instance at a time (see lammps_fixture.h)
  atomic.commands("units lj\natom_style atomic\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\n");
  expect_error(atomic, "fix t all nve/sphere/ty3", "requires atom_style sphere");
}
