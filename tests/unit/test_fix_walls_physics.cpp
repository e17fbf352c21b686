// The inline physics of fix wall/stress, shear/stress and nve/sphere/ty3 on their own
// (doc/model.md §2 and §4), without LAMMPS.
#include "walls/shear_plate.h"
#include "integrate/taylor3.h"
#include "walls/wall_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using porewater::wall_contact;
using porewater::WallContact;

TEST(WallContact, LinearSpringOnTheOverlapPushesTheGrainDown)
{
  // grain of radius 0.5 at z = 1.49 under a wall at 1.98: overlap 0.01
  const WallContact c = wall_contact(1.49, 0.5, 0.0, 1.98, 0.0, 1000.0, 0.0);
  EXPECT_NEAR(c.force_z, -10.0, 1e-12);
  EXPECT_NEAR(c.energy, 0.5 * 1000.0 * 1e-4, 1e-15);
  // touching or apart: nothing
  const WallContact touching = wall_contact(1.48, 0.5, 0.0, 1.98, 0.0, 1000.0, 50.0);
  EXPECT_EQ(touching.force_z, 0.0);
  EXPECT_EQ(touching.energy, 0.0);
  EXPECT_EQ(wall_contact(1.0, 0.5, -3.0, 1.98, 0.0, 1000.0, 50.0).force_z, 0.0);
}

TEST(WallContact, DampingActsOnTheVelocityRelativeToTheWall)
{
  const double kn = 1000.0, gamma = 20.0;
  // grain rising into a resting wall at 0.1: spring and damping both push down
  EXPECT_NEAR(wall_contact(1.49, 0.5, 0.1, 1.98, 0.0, kn, gamma).force_z, -10.0 - 2.0, 1e-12);
  // the same approach speed seen from a wall coming down at 0.1 onto a resting grain
  EXPECT_NEAR(wall_contact(1.49, 0.5, 0.0, 1.98, -0.1, kn, gamma).force_z, -12.0, 1e-12);
  // grain and wall moving together: no damping
  EXPECT_NEAR(wall_contact(1.49, 0.5, 0.3, 1.98, 0.3, kn, gamma).force_z, -10.0, 1e-12);
  // separating: damping reduces the push ...
  EXPECT_NEAR(wall_contact(1.49, 0.5, -0.2, 1.98, 0.0, kn, gamma).force_z, -10.0 + 4.0, 1e-12);
  // ... but never turns it into a pull; the spring energy is still stored
  const WallContact released = wall_contact(1.49, 0.5, -1.0, 1.98, 0.0, kn, gamma);
  EXPECT_EQ(released.force_z, 0.0);
  EXPECT_NEAR(released.energy, 0.05, 1e-15);
}

TEST(WallContact, AbsoluteDampingActsOnTheLabFrameVelocity)
{
  using porewater::WALL_DAMPING_ABSOLUTE;
  const double kn = 1000.0, gamma = 20.0;
  // a resting wall: the same as the relative form
  EXPECT_NEAR(wall_contact(1.49, 0.5, 0.1, 1.98, 0.0, kn, gamma, WALL_DAMPING_ABSOLUTE).force_z,
              -12.0, 1e-12);
  // a wall coming down at 0.1 onto a resting grain: no damping (the relative form: -12)
  EXPECT_NEAR(wall_contact(1.49, 0.5, 0.0, 1.98, -0.1, kn, gamma, WALL_DAMPING_ABSOLUTE).force_z,
              -10.0, 1e-12);
  // grain and wall rising together at 0.3: damped by -gamma 0.3 although they do not
  // move apart (the relative form: none)
  const WallContact together =
      wall_contact(1.49, 0.5, 0.3, 1.98, 0.3, kn, gamma, WALL_DAMPING_ABSOLUTE);
  EXPECT_NEAR(together.force_z, -16.0, 1e-12);
  EXPECT_NEAR(together.damping_z, -6.0, 1e-12);
  // the pair dissipates gamma v_z (v_z - v_wall): nothing here, although each feels 6
  const double reaction = -together.force_z;    // what the fix adds to the wall
  EXPECT_NEAR(together.damping_z * 0.3 + (-together.damping_z) * 0.3, 0.0, 1e-15);
  EXPECT_NEAR(reaction, 16.0, 1e-12);
  // grain and wall sinking together: the dashpot lifts the grain's push off the wall, but
  // it is clipped at zero
  EXPECT_NEAR(wall_contact(1.49, 0.5, -0.3, 1.98, -0.3, kn, gamma, WALL_DAMPING_ABSOLUTE).force_z,
              -4.0, 1e-12);
  const WallContact released =
      wall_contact(1.49, 0.5, -1.0, 1.98, -1.0, kn, gamma, WALL_DAMPING_ABSOLUTE);
  EXPECT_EQ(released.force_z, 0.0);
  EXPECT_NEAR(released.damping_z, 10.0, 1e-12);    // cancels the spring exactly
  EXPECT_NEAR(released.energy, 0.05, 1e-15);
}

TEST(WallContact, DampingShareIsTheForceLessTheSpring)
{
  const double kn = 1000.0, gamma = 20.0;
  for (const int form : {porewater::WALL_DAMPING_RELATIVE, porewater::WALL_DAMPING_ABSOLUTE}) {
    const WallContact c = wall_contact(1.49, 0.5, 0.1, 1.98, -0.05, kn, gamma, form);
    EXPECT_NEAR(c.damping_z, c.force_z + 10.0, 1e-12) << form;
    EXPECT_LT(c.damping_z, 0.0) << form;    // approaching: the dashpot adds to the push
    EXPECT_EQ(wall_contact(1.49, 0.5, 0.1, 1.98, -0.05, kn, 0.0, form).damping_z, 0.0) << form;
    EXPECT_EQ(wall_contact(1.0, 0.5, 0.1, 1.98, -0.05, kn, gamma, form).damping_z, 0.0) << form;
  }
}

TEST(WallContact, PlateDashpotOpposesTheWallVelocity)
{
  EXPECT_DOUBLE_EQ(porewater::plate_damping_force(0.25, 400.0), -100.0);
  EXPECT_DOUBLE_EQ(porewater::plate_damping_force(-0.25, 400.0), 100.0);
  EXPECT_EQ(porewater::plate_damping_force(0.25, 0.0), 0.0);
}

TEST(ShearPlate, AccelerationIsAppliedPlusResistingForceOverPlateMass)
{
  EXPECT_DOUBLE_EQ(porewater::plate_acceleration(10.0, 2.0, 0.0, 4.0), 5.0);
  EXPECT_DOUBLE_EQ(porewater::plate_acceleration(10.0, 2.0, -20.0, 4.0), 0.0);    // balanced
  EXPECT_DOUBLE_EQ(porewater::plate_acceleration(10.0, 2.0, -28.0, 4.0), -2.0);
}

// ---------------------------------------------------------------------------------------

namespace {

// One grain stepped as the fix does (ty3_predict_grain, the forces, ty3_correct_grain) to
// T = 3 with step dt, from a fresh history: along x the oscillator x'' = −x with x(0) = 1,
// v(0) = 0.3; about z a spin driven by α(t) = cos t from ω(0) = 0, so ω(t) = sin t.
// Returns the global errors |x − x(T)|, |v − v(T)|, |ω − ω(T)|.
std::vector<double> grain_errors(double dt, bool corrector)
{
  const int steps = (int) std::lround(3.0 / dt);
  double x[3] = {1.0, 0.0, 0.0}, v[3] = {0.3, 0.0, 0.0}, omega[3] = {0.0, 0.0, 0.0};
  double h[porewater::TY3_COLUMNS_CORRECTOR] = {};    // TY3_NO_HISTORY
  double a[3] = {-x[0], 0.0, 0.0}, alpha[3] = {0.0, 0.0, 1.0};
  for (int n = 0; n < steps; n++) {
    porewater::ty3_predict_grain(x, v, omega, a, alpha, dt, corrector, h);
    EXPECT_EQ(h[porewater::TY3_STATE], n == 0 ? porewater::TY3_STARTUP : porewater::TY3_RUNNING);
    a[0] = -x[0];    // the forces at the new positions
    alpha[2] = std::cos((n + 1) * dt);
    if (corrector) porewater::ty3_correct_grain(v, omega, a, alpha, dt, h);
  }
  const double t = steps * dt;
  return {std::fabs(x[0] - (std::cos(t) + 0.3 * std::sin(t))),
          std::fabs(v[0] - (-std::sin(t) + 0.3 * std::cos(t))), std::fabs(omega[2] - std::sin(t))};
}

}    // namespace

TEST(Taylor3, OneStepIsExactForConstantJerk)
{
  // x(t) = 1 + 2t − 0.5t² + t³/3: a = −1 + 2t, ȧ = 2; history a_prev = a(−Δt)
  const double dt = 0.125, t = 0.75;    // binary fractions: exact arithmetic
  auto x = [](double s) {
    return 1 + 2 * s - 0.5 * s * s + s * s * s / 3;
  };
  auto v = [](double s) {
    return 2 - s + s * s;
  };
  auto a = [](double s) {
    return -1 + 2 * s;
  };
  EXPECT_EQ(x(t) + porewater::ty3_displacement(v(t), a(t), a(t - dt), dt), x(t + dt));
  EXPECT_EQ(v(t) + porewater::ty3_velocity_change(a(t), a(t - dt), dt), v(t + dt));
  // the corrector vanishes on a linear a; the start-up one is the exact trapezoid rule
  EXPECT_EQ(porewater::ty3_velocity_correction(a(t + dt), a(t), a(t) - a(t - dt), dt), 0.0);
  EXPECT_EQ(v(t) + dt * a(t) + porewater::ty3_startup_velocity_correction(a(t + dt), a(t), dt),
            v(t + dt));
}

TEST(Taylor3, GrainStepIsSecondOrderAndThirdOrderWithTheCorrector)
{
  // Δt = 0.01 and 0.005: observed order log2(e(Δt)/e(Δt/2)) of x, v and ω, ±0.05
  // (measured within 0.01 of 2 and 3). The first step's ȧ = 0 costs the plain scheme
  // nothing (it is second order anyway); the corrector's trapezoid start keeps it third.
  for (const bool corrector : {false, true}) {
    const auto coarse = grain_errors(0.01, corrector);
    const auto fine = grain_errors(0.005, corrector);
    const double expected = corrector ? 3.0 : 2.0;
    for (int k = 0; k < 3; k++)
      EXPECT_NEAR(std::log2(coarse[k] / fine[k]), expected, 0.05)
          << "corrector " << corrector << ", quantity " << k;
  }
}

TEST(Taylor3, FirstStepOfAGrainTakesNoJerk)
{
  double x[3] = {0, 0, 0}, v[3] = {1, 0, 0}, omega[3] = {0, 0, 0};
  double h[porewater::TY3_COLUMNS_CORRECTOR] = {};
  h[porewater::TY3_A_PREV] = 99.0;    // stale values of a fresh row are not used
  const double a[3] = {2.0, 0, 0}, alpha[3] = {0, 4.0, 0}, dt = 0.5;
  porewater::ty3_predict_grain(x, v, omega, a, alpha, dt, 1, h);
  EXPECT_EQ(x[0], 1.0 * 0.5 + 0.5 * 2.0 * 0.25);
  EXPECT_EQ(v[0], 1.0 + 2.0 * 0.5);
  EXPECT_EQ(omega[1], 4.0 * 0.5);
  EXPECT_EQ(h[porewater::TY3_A_PREV], 2.0);
  EXPECT_EQ(h[porewater::TY3_A_STEP], 0.0);
  EXPECT_EQ(h[porewater::TY3_STATE], porewater::TY3_STARTUP);
}
