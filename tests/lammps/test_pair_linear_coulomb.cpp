// pair linear/coulomb and linear/coulomb/kk against analytic collisions, native
// gran/hooke/history and native granular (hooke + linear_history, undamped; the same on
// 29Sep2021 and 4Feb2025), and the /kk variants the style matrix (test_style_matrix.cpp) does not
// cover: two threads, mixed frictional and frictionless type pairs, the virial, runs split
// by run commands, broken contacts.
#include "granular_inputs.h"
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

using pwtest::Accel;
using pwtest::Lammps;
using pwtest::expect_error;

namespace {

const double PI = 3.14159265358979323846;

// two grains of diameter 1 and mass 1 at z = ±b/2, 0.02 apart along x, approaching along x
// at ±v/2 (impact parameter b)
void two_grains(Lammps &l, double b, double v, const std::string &coeff)
{
  l.commands("units lj\natom_style sphere\natom_modify map array\nboundary f f f\n"
             "comm_modify vel yes\nregion box block -5 5 -5 5 -5 5\ncreate_box 1 box\n");
  const double x0 = 0.5 * std::sqrt(1.0 - b * b) + 0.01;
  l.command("create_atoms 1 single " + std::to_string(-x0) + " 0 " + std::to_string(b / 2) + " units box");
  l.command("create_atoms 1 single " + std::to_string(x0) + " 0 " + std::to_string(-b / 2) + " units box");
  l.commands("set type 1 diameter 1.0\nset type 1 density 1.90985931710274\n"    // m = 1
             "velocity all set 0 0 0\n");
  l.command("velocity all set " + std::to_string(v / 2) + " 0 0 units box");
  l.command("group second id 2");
  l.command("velocity second set " + std::to_string(-v / 2) + " 0 0 units box");
  l.commands("pair_style linear/coulomb\n" + coeff + "\nneighbor 0.3 bin\n"
             "neigh_modify delay 0 every 1 check yes\nfix integrate all nve/sphere\n"
             "compute erot all erotate/sphere\ncompute pair all pair linear/coulomb\n"
             "thermo_style custom step ke c_erot pe c_pair[1]\n"
             "thermo_modify norm no\n"
             "variable gap equal sqrt((x[1]-x[2])^2+(y[1]-y[2])^2+(z[1]-z[2])^2)-1.0\n");
}

double total_kinetic(Lammps &l)
{
  l.command("run 0 post no");
  return l.thermo("ke") + l.equal("c_erot");
}

}    // namespace

TEST(PairLinearCoulomb, HeadOnElasticCollisionExchangesVelocitiesAndLastsHalfAPeriod)
{
  Lammps l;
  const double kn = 1.0e4, v = 1.0, dt = 1.0e-5;
  two_grains(l, 0.0, v, "pair_coeff 1 1 1e4 1e4 0.0");
  l.command("timestep " + std::to_string(dt));
  const double e0 = total_kinetic(l);

  long steps_in_contact = 0;
  bool touched = false;
  for (int step = 0; step < 20000; step++) {
    l.command("run 1 pre no post no");
    const bool overlap = l.equal("v_gap") < 0.0;
    if (overlap) steps_in_contact++, touched = true;
    if (touched && !overlap) break;
  }
  const double duration = steps_in_contact * dt;
  const double expected = PI * std::sqrt(0.5 / kn);    // m_eff = 1/2
  // the contact is resolved to one step: |error| ≤ dt, i.e. 4.5e-4 of the duration
  EXPECT_NEAR(duration, expected, 1.5 * dt);

  // equal masses exchange velocities. The spring switches on and off inside a step, which
  // velocity Verlet sees as an energy jump of at most ½ k_n (v dt)² per switch:
  // |ΔE| ≤ k_n (v dt)² = 1e-6 (4e-6 of E), and velocities to √ of that relative
  const double switch_error = kn * (v * dt) * (v * dt);
  EXPECT_NEAR(l.equal("vx[1]"), -v / 2, 1e-5 * v);
  EXPECT_NEAR(l.equal("vx[2]"), v / 2, 1e-5 * v);
  EXPECT_NEAR(total_kinetic(l), e0, switch_error);
  EXPECT_NEAR(l.equal("c_erot"), 0.0, 1e-20);
}

namespace {

// Kinetic energy the grains leave with, plus what the pair reports dissipated, minus what
// they came with. Continuous time: 0. The step adds ½k_t|v_t Δt|² to the tangential spring
// that no force paid for, so the residual is first order in Δt, bounded by
// T_contact · ½ k_t v² Δt, plus ½k_n (vΔt)² per switch of the normal spring.
double budget_residual(double b, double mu, double dt, Lammps &l)
{
  two_grains(l, b, 1.0, "pair_coeff 1 1 1e4 1e4 " + std::to_string(mu));
  l.command("pair_style linear/coulomb dissipation yes");
  l.command("pair_coeff 1 1 1e4 1e4 " + std::to_string(mu));
  l.command("timestep " + std::to_string(dt));
  const double e0 = total_kinetic(l);
  l.command("run " + std::to_string((int) (0.06 / dt)));
  EXPECT_GT(l.equal("v_gap"), 0.0);    // the grains separated
  return total_kinetic(l) + l.equal("c_pair[1]") - e0;
}

double budget_bound(double dt)
{
  const double kn = 1e4, kt = 1e4, v = 1.0, t_contact = PI * std::sqrt(0.5 / kn);
  return t_contact * 0.5 * kt * v * v * dt + kn * (v * dt) * (v * dt);
}

}    // namespace

TEST(PairLinearCoulomb, ObliqueImpactRespectsCoulombAndSpinsBothGrainsTheSameWay)
{
  Lammps l;
  two_grains(l, 0.5, 1.0, "pair_coeff 1 1 1e4 1e4 0.3");
  l.commands("timestep 1e-5\ncompute pl all pair/local force p4\n");
  const double e0 = total_kinetic(l);
  double worst_ratio = 0.0;
  int contact_steps = 0;
  for (int step = 0; step < 8000; step++) {
    l.command("run 1 pre no post no");
    l.command("run 0 post no");    // make the local compute current
    auto *pl = (double **) lammps_extract_compute(l.lmp, "pl", LMP_STYLE_LOCAL, LMP_TYPE_ARRAY);
    const int rows = *(int *) lammps_extract_compute(l.lmp, "pl", LMP_STYLE_LOCAL, LMP_SIZE_ROWS);
    for (int r = 0; r < rows; r++)
      if (pl[r][0] > 0.0) {
        contact_steps++;
        worst_ratio = std::max(worst_ratio, pl[r][1] / (0.3 * pl[r][0]));
      }
    if (contact_steps > 0 && l.equal("v_gap") > 0.05) break;
  }
  ASSERT_GT(contact_steps, 100);
  EXPECT_LE(worst_ratio, 1.0 + 1e-12);    // |f_t| ≤ μ|f_n| up to round-off
  EXPECT_GT(worst_ratio, 0.99);            // and the contact did slide
  // i (upper left, moving +x) brushes over j: both spin about +y (doc/model.md §1 signs)
  EXPECT_GT(l.of_tag(l.atom()->omega, 1)[1], 0.0);
  EXPECT_GT(l.of_tag(l.atom()->omega, 2)[1], 0.0);
  EXPECT_LT(total_kinetic(l), e0 * (1.0 - 1e-3));    // sliding took energy out
}

TEST(PairLinearCoulomb, FrictionalEnergyBudgetClosesAtFirstOrder)
{
  // sliding (μ = 0.3) and sticking (μ = 10⁶: only projection and the forgotten spring
  // dissipate) impacts; the residual is within its bound and halves with Δt
  for (double mu : {0.3, 1e6}) {
    double res[2];
    const double dts[2] = {1e-5, 5e-6};
    for (int k = 0; k < 2; k++) {
      Lammps l;
      res[k] = budget_residual(0.7, mu, dts[k], l);
      EXPECT_LE(std::abs(res[k]), budget_bound(dts[k])) << "mu " << mu << " dt " << dts[k];
    }
    std::printf("[ report ] mu %g: budget residual %.3e (dt 1e-5), %.3e (dt 5e-6)\n", mu, res[0],
                res[1]);
    EXPECT_NEAR(res[0] / res[1], 2.0, 0.3) << "mu " << mu;
  }
}

// ---------------------------------------------------------------------------------------

namespace {

// the chute of granular_inputs.h with this pair style, 1000 steps, then `then`
std::map<long, std::vector<double>> chute(const std::string &pair_style, const std::string &pair_coeff,
                                          Accel accel = Accel::none, double *ke = nullptr,
                                          std::vector<std::string> args = {},
                                          const std::string &then = "")
{
  Lammps l(accel, MPI_COMM_WORLD, args);
  l.commands(pwtest::chute());
  l.command("pair_style " + pair_style);
  l.commands("pair_coeff " + pair_coeff + "\nrun 1000\n");
  if (!then.empty()) l.commands(then);
  if (ke) *ke = l.thermo("ke");
  return l.unwrapped();
}

// the pair_coeff of pair_style granular with the classic Hooke normal force and a linear
// history spring, every damping coefficient 0 (`damping velocity`, `mass_velocity` and the
// default `viscoelastic` are then all undamped; rolling and twisting are off by default)
std::string granular(const std::string &kn, const std::string &kt, const std::string &mu)
{
  return "* * hooke " + kn + " 0.0 tangential linear_history " + kt + " 0.0 " + mu +
      " damping velocity";
}

}    // namespace

TEST(PairLinearCoulomb, LeverRadiusReproducesNativeGranHookeHistory)
{
  double ke_native = 0, ke_ours = 0, ke_contact = 0;
  const auto native = chute("gran/hooke/history 200000.0 200000.0 0.0 0.0 0.5 0", "* *",
                            Accel::none, &ke_native);
  ASSERT_EQ(native.size(), 3044u);
  const auto ours = chute("linear/coulomb lever radius", "* * 200000.0 200000.0 0.5", Accel::none,
                          &ke_ours);
  // same operations in the same order: expected bit-identical; 1e-12 of a diameter leaves
  // room only for a compiler contracting a multiply-add differently
  EXPECT_LE(pwtest::max_abs_diff(native, ours), 1e-12);
  EXPECT_DOUBLE_EQ(ke_ours, ke_native);

  // the contact-plane lever arm (the seed's geometry) changes the flow slightly
  const auto contact = chute("linear/coulomb lever contact", "* * 200000.0 200000.0 0.5",
                             Accel::none, &ke_contact);
  const double dx = pwtest::max_abs_diff(native, contact);
  std::printf("[ report ] lever contact vs radius after 1000 steps: max |dx| = %.3e, "
              "KE %.6g vs %.6g\n", dx, ke_contact, ke_native);
  EXPECT_GT(dx, 0.0);
  EXPECT_NEAR(ke_contact, ke_native, 0.05 * ke_native);
}

TEST(PairLinearCoulomb, FrictionlessContactsReproduceNativeGranularHooke)
{
  // without a tangential force (μ = 0 or k_t = 0) pair granular computes our normal force
  // in another order of operations: round-off, amplified by 1000 steps of a dense flow
  // (measured 4e-13 of a diameter); 1e-10 as for /kk against CPU (KokkosEqualsCpu)
  const std::array<std::string, 2> kt_mu[2] = {{"200000.0", "0.0"}, {"0.0", "0.5"}};
  for (const auto &c : kt_mu) {
    SCOPED_TRACE("kt " + c[0] + " mu " + c[1]);
    double ke_native = 0, ke_ours = 0;
    const auto native = chute("granular", granular("200000.0", c[0], c[1]), Accel::none, &ke_native);
    const auto ours = chute("linear/coulomb lever radius", "* * 200000.0 " + c[0] + " " + c[1],
                            Accel::none, &ke_ours);
    ASSERT_EQ(native.size(), 3044u);
    EXPECT_LE(pwtest::max_abs_diff(native, ours), 1e-10);
    EXPECT_NEAR(ke_ours, ke_native, 1e-10 * ke_native);
  }
}

TEST(PairLinearCoulomb, FrictionalFlowAgreesWithNativeGranularHookeToAFractionOfFriction)
{
  // With friction pair granular is another model: its contact velocity takes the radius as
  // lever (our `lever radius`), its torque the contact point (our `lever contact`), and
  // linear_history turns the stored spring into the tangent plane before adding to it and
  // keeps its length (we add, then project). Not round-off, so compared as flows: after
  // 2000 steps of the chute the kinetic and rotational energies and the mean flow velocity
  // differ from ours by less than 5% of what friction itself changes (against μ = 0).
  // Measured: 0.4% (ke), 1.6% (erot), 0.9% (flow velocity).
  struct Flow {
    double ke, erot, vx;
  };
  auto flow = [](const std::string &style, const std::string &coeff) {
    Lammps l;
    l.commands(pwtest::chute());
    l.commands("compute erot all erotate/sphere\nthermo_style custom step ke c_erot\npair_style " +
               style + "\npair_coeff " + coeff + "\nrun 2000\n");
    return Flow{l.thermo("ke"), l.equal("c_erot"), l.equal("vcm(active,x)")};
  };
  const Flow native = flow("granular", granular("200000.0", "200000.0", "0.5"));
  const Flow ours = flow("linear/coulomb lever radius", "* * 200000.0 200000.0 0.5");
  const Flow smooth = flow("linear/coulomb lever radius", "* * 200000.0 200000.0 0.0");
  const double got[3][3] = {{native.ke, ours.ke, smooth.ke},
                            {native.erot, ours.erot, smooth.erot},
                            {native.vx, ours.vx, smooth.vx}};
  const char *names[3] = {"ke", "erot", "vcm(active,x)"};
  for (int k = 0; k < 3; k++) {
    const double friction = std::fabs(got[k][1] - got[k][2]), model = std::fabs(got[k][0] - got[k][1]);
    std::printf("[ report ] granular vs linear/coulomb, %s after 2000 steps: %.6g vs %.6g (mu 0: "
                "%.6g): %.2f%% of the friction effect\n", names[k], got[k][0], got[k][1], got[k][2],
                100.0 * model / friction);
    // friction changes each far beyond round-off (measured 2e-3, 0.35, 4e-4 of the value)
    EXPECT_GT(friction, 1e-4 * std::fabs(got[k][1])) << names[k] << ": friction must matter here";
    EXPECT_LE(model, 0.05 * friction) << names[k];
  }
}

TEST(PairLinearCoulomb, FrictionlessPairsSkipTheSpringWithoutChangingTheFlow)
{
  // μ = 0: native gran/hooke/history integrates the spring and caps it to zero every step,
  // ours skips it; then friction is switched on (pair_style/pair_coeff again, history kept)
  // and both go on from the same, empty springs
  const std::string on = "run 500\n";
  double ke_native = 0, ke_ours = 0;
  const auto native = chute("gran/hooke/history 200000.0 200000.0 0.0 0.0 0.0 0", "* *", Accel::none,
                            &ke_native, {},
                            "pair_style gran/hooke/history 200000.0 200000.0 0.0 0.0 0.5 0\n" + on);
  const auto ours = chute("linear/coulomb lever radius", "* * 200000.0 200000.0 0.0", Accel::none,
                          &ke_ours, {}, "pair_coeff * * 200000.0 200000.0 0.5\n" + on);
  // same operations on the normal force, a zero tangential force either way: bit-identical
  // expected, 1e-12 of a diameter as in LeverRadiusReproducesNativeGranHookeHistory
  EXPECT_LE(pwtest::max_abs_diff(native, ours), 1e-12);
  EXPECT_DOUBLE_EQ(ke_ours, ke_native);

  // kt = 0: native keeps integrating a spring that exerts no force, ours keeps none
  const auto native_kt0 = chute("gran/hooke/history 200000.0 0.0 0.0 0.0 0.5 0", "* *");
  const auto ours_kt0 = chute("linear/coulomb lever radius", "* * 200000.0 0.0 0.5");
  EXPECT_LE(pwtest::max_abs_diff(native_kt0, ours_kt0), 1e-12);
}

TEST(PairLinearCoulomb, KokkosFrictionlessPairsSkipTheSpringWithoutChangingTheFlow)
{
  // the frictionless chute, then friction switched on, of the test above: /kk against CPU
  PW_SKIP_WITHOUT_KOKKOS();
  const std::string then = "pair_coeff * * 200000.0 200000.0 0.5\nrun 500\n";
  const auto ours = chute("linear/coulomb lever radius", "* * 200000.0 200000.0 0.0", Accel::none,
                          nullptr, {}, then);
  const auto kk = chute("linear/coulomb lever radius", "* * 200000.0 200000.0 0.0", Accel::kokkos,
                        nullptr, {}, then);
  EXPECT_LE(pwtest::max_abs_diff(ours, kk), 1e-10);    // round-off, as in KokkosEqualsCpu (style matrix)
}

TEST(PairLinearCoulomb, FrictionlessImpactDissipatesNothing)
{
  // μ = 0: no spring is kept, so none is reset and nothing is counted as lost; the energy
  // residual is then only the normal spring's switching error, bounded by ½k_n(vΔt)² per
  // switch (budget_bound without its k_t term), where the frictional bound is 1000× larger
  const double dt = 1e-5, kn = 1e4, v = 1.0;
  Lammps l;
  const double res = budget_residual(0.7, 0.0, dt, l);
  EXPECT_EQ(l.equal("c_pair[1]"), 0.0);
  EXPECT_LE(std::abs(res), kn * (v * dt) * (v * dt));
  std::printf("[ report ] frictionless oblique impact: energy residual %.3e\n", res);
}

namespace {
// per type pair: the flowing grains (type 1) rub each other, slide freely on the base (2)
const std::string mixed_coeffs = "1 1 200000.0 200000.0 0.5\npair_coeff 1 2 200000.0 200000.0 0.0\n"
                                 "pair_coeff 2 2 200000.0 200000.0 0.5";
}    // namespace

TEST(PairLinearCoulomb, FrictionlessTypePairSpeedsTheFlow)
{
  // the frictionless base matters: without friction there the flow is faster
  double ke_mixed = 0, ke_rough = 0;
  chute("linear/coulomb", mixed_coeffs, Accel::none, &ke_mixed);
  chute("linear/coulomb", "* * 200000.0 200000.0 0.5", Accel::none, &ke_rough);
  EXPECT_GT(ke_mixed, ke_rough);
}

TEST(PairLinearCoulomb, KokkosEqualsCpuWithFrictionlessAndFrictionalTypePairs)
{
  PW_SKIP_WITHOUT_KOKKOS();
  double ke_cpu = 0, ke_kk = 0;
  const auto cpu = chute("linear/coulomb", mixed_coeffs, Accel::none, &ke_cpu);
  const auto kk = chute("linear/coulomb", mixed_coeffs, Accel::kokkos, &ke_kk);
  EXPECT_LE(pwtest::max_abs_diff(cpu, kk), 1e-10);    // round-off, as in KokkosEqualsCpu (style matrix)
  EXPECT_NEAR(ke_kk, ke_cpu, 1e-10 * ke_cpu);
}

TEST(PairLinearCoulomb, KokkosWithTwoThreadsEqualsCpu)
{
  PW_SKIP_WITHOUT_KOKKOS();
  // HALFTHREAD neighbor lists: per-thread force copies summed at the end (OpenMP)
  double ke_cpu = 0, ke_kk = 0;
  const auto cpu = chute("linear/coulomb", "* * 200000.0 200000.0 0.5", Accel::none, &ke_cpu);
  const auto kk = chute("linear/coulomb", "* * 200000.0 200000.0 0.5", Accel::none, &ke_kk,
                        {"-k", "on", "t", "2", "-sf", "kk"});
  const double dx = pwtest::max_abs_diff(cpu, kk);
  std::printf("[ report ] linear/coulomb/kk 2 threads vs CPU after 1000 steps: max |dx| = %.3e\n", dx);
  EXPECT_LE(dx, 1e-10);    // round-off, as for one thread (the matrix's KokkosEqualsCpu)
  EXPECT_NEAR(ke_kk, ke_cpu, 1e-10 * ke_cpu);
}

namespace {

// the pressure of a compressed static packing, which comes from the contact virial alone
double packing_pressure(const std::string &style, const std::string &coeff, Accel accel)
{
  Lammps l(accel);
  l.commands(pwtest::dense_gas(5));
  l.command("set type 1 diameter 1.08");    // overlaps of up to 0.08 everywhere
  l.command("pair_style " + style);
  l.command("pair_coeff " + coeff);
  l.command("velocity all set 0 0 0");
  l.command("run 0");
  return l.thermo("press");
}

}    // namespace

TEST(PairLinearCoulomb, VirialEqualsNativeGranHookeHistoryVirial)
{
  const double ours = packing_pressure("linear/coulomb lever radius", "* * 1000.0 1000.0 0.5",
                                       Accel::none);
  const double native = packing_pressure("gran/hooke/history 1000.0 1000.0 0.0 0.0 0.5 0", "* *",
                                         Accel::none);
  ASSERT_GT(ours, 0.0);
  EXPECT_NEAR(native, ours, 1e-12 * ours);
}

TEST(PairLinearCoulomb, KokkosVirialEqualsCpuVirial)
{
  PW_SKIP_WITHOUT_KOKKOS();
  const double cpu = packing_pressure("linear/coulomb lever radius", "* * 1000.0 1000.0 0.5",
                                      Accel::none);
  const double kk = packing_pressure("linear/coulomb lever radius", "* * 1000.0 1000.0 0.5",
                                     Accel::kokkos);
  ASSERT_GT(cpu, 0.0);
  EXPECT_NEAR(kk, cpu, 1e-12 * cpu);    // /kk tallies the same virial
}

namespace {

// each run's setup re-sorts atoms and rebuilds neighbor lists: histories must survive
// (on KOKKOS they did not before scripts/patches/lammps-kokkos-neigh-history.patch)
void split_runs_equal_one_run(Accel accel)
{
  std::map<long, std::vector<double>> one, two;
  for (int pieces : {1, 2}) {
    Lammps l(accel);
    l.commands(pwtest::frictional_gas());
    l.command(pieces == 1 ? "run 300" : "run 150");
    if (pieces == 2) l.command("run 150");
    (pieces == 1 ? one : two) = l.unwrapped();
  }
  EXPECT_LE(pwtest::max_abs_diff(one, two), 1e-12);
}

// grains of radius 0.5 whose centres are 0.4 apart overlap by 1.2 radii: a blown-up state
void broken_contact_is_named(Accel accel)
{
  Lammps l(accel);
  l.commands("units lj\natom_style sphere\natom_modify map array\nboundary p p p\n"
             "newton off on\ncomm_modify vel yes\nregion box block -3 3 -3 3 -3 3\n"
             "create_box 1 box\ncreate_atoms 1 single 0 0 0 units box\n"
             "create_atoms 1 single 0.4 0 0 units box\nset type 1 diameter 1.0\n"
             "set type 1 density 1.9099\npair_style linear/coulomb\n"
             "pair_coeff * * 1000.0 1000.0 0.5\nfix integrate all nve/sphere\n");
  expect_error(l, "run 0", "grains 1 and 2");
}

}    // namespace

PW_TEST_CPU_AND_KOKKOS(PairLinearCoulomb, RunsSplitByRunCommandsEqualOneRun,
                       split_runs_equal_one_run)

TEST(PairLinearCoulomb, KokkosBrokenContactStopsTheRunNamingTheGrains)
{
  PW_SKIP_WITHOUT_KOKKOS();
  broken_contact_is_named(Accel::kokkos);
}

TEST(PairLinearCoulomb, BrokenContactStopsTheRunNamingTheGrains)
{
  broken_contact_is_named(Accel::none);
  // the limit is the user's: 1.3 radii lets the same state run
  Lammps l;
  l.commands("units lj\natom_style sphere\natom_modify map array\nboundary p p p\n"
             "comm_modify vel yes\nregion box block -3 3 -3 3 -3 3\ncreate_box 1 box\n"
             "create_atoms 1 single 0 0 0 units box\ncreate_atoms 1 single 0.4 0 0 units box\n"
             "set type 1 diameter 1.0\nset type 1 density 1.9099\n"
             "pair_style linear/coulomb overlap_limit 1.3\npair_coeff * * 1000.0 1000.0 0.5\n");
  EXPECT_NO_THROW(l.command("run 0"));
}
