// The host-free state of fix wall/stress (porewater::StressWall) and fix shear/stress
// (porewater::RigidPlate) driven by a one-rank test host, and the texts they quote values
// with: what every host's fix forwards to.
#include "walls/rigid_plate.h"
#include "walls/stress_wall.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

struct Stopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// one rank, no grains touching the wall, a constant stress; box [0, 10], area 6
class OneRankWallHost : public porewater::StressWallHost {
 public:
  double stress = 0.5, highest = -std::numeric_limits<double>::infinity();
  std::string warning;
  double stress_now() override { return stress; }
  void contact_sums(double *sums) override { sums[0] = sums[1] = sums[2] = 0.0; }
  void sum_over_ranks(double *, int) override {}
  double max_over_ranks(double value) override { return value; }
  double min_over_ranks(double value) override { return value; }
  double highest_grain_top() override { return highest; }
  double lightest_grain() override { return 1.0; }
  porewater::WallBox box() override { return {0.0, 10.0, false, 6.0}; }
  std::string group_name() const override { return "all"; }
  void stop(const std::string &message) override { throw Stopped(message); }
  void warn(const std::string &message) override { warning = message; }
};

// a wall step as the hosts run it: initial_integrate, post_force, final_integrate
void step(porewater::StressWall &wall, OneRankWallHost &host, long long n, double dt)
{
  wall.initial_integrate(dt);
  wall.post_force(host, n);
  wall.final_integrate(dt);
}

porewater::WallStressSettings free_wall(double z)
{
  porewater::WallStressSettings s;
  s.z = z;
  s.mass = 6.0;
  s.kn = 100.0;
  return s;
}

}    // namespace

TEST(StressWall, FreeWallFollowsTheParabolaAndItsStateRestarts)
{
  // M z'' = -S A: a = -0.5; velocity Verlet is exact for a constant acceleration
  OneRankWallHost host;
  porewater::StressWall wall(free_wall(8.0), "w");
  wall.setup(host, 0);
  const double dt = 0.01;
  for (int n = 1; n <= 200; ++n) step(wall, host, n, dt);
  EXPECT_NEAR(wall.vector(0, 6.0), 8.0 - 0.25 * 2.0 * 2.0, 1e-12);
  EXPECT_NEAR(wall.vector(1, 6.0), -0.5 * 2.0, 1e-12);
  EXPECT_EQ(wall.vector(2, 6.0), 0.0);
  EXPECT_EQ(wall.vector(3, 6.0), 0.5);
  // a wall restored from the state goes on exactly as the original
  porewater::StressWall copy(free_wall(1.0), "w");
  copy.restore(wall.restart_state());
  for (int n = 201; n <= 250; ++n) {
    step(wall, host, n, dt);
    step(copy, host, n, dt);
  }
  EXPECT_EQ(copy.vector(0, 6.0), wall.vector(0, 6.0));
  EXPECT_EQ(copy.vector(1, 6.0), wall.vector(1, 6.0));
}

TEST(StressWall, ItsMessagesNameTheFixTheStepAndTheValues)
{
  OneRankWallHost host;
  {
    // pulled up (S < 0): z = 8 + t²/2 passes the top 10 at t = 2, step 200 or 201
    host.stress = -1.0;
    porewater::StressWall wall(free_wall(8.0), "w");
    wall.setup(host, 0);
    try {
      for (int n = 1; n <= 300; ++n) step(wall, host, n, 0.01);
      ADD_FAILURE() << "the wall left the box silently";
    } catch (const Stopped &e) {
      EXPECT_NE(std::string(e.what()).find("Fix wall/stress w: the wall rose to z = 10.0"), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find(", above the box top 10"), std::string::npos) << e.what();
    }
  }
  {
    porewater::WallStressSettings s = free_wall(0.0);
    s.z_auto = true;
    porewater::StressWall wall(s, "w");
    EXPECT_THROW(
        {
          try {
            wall.setup(host, 0);
          } catch (const Stopped &e) {
            EXPECT_STREQ(e.what(), "Fix wall/stress: z auto needs grains in group all");
            throw;
          }
        },
        Stopped);
    host.highest = 4.25;    // the highest grain top
    wall.setup(host, 0);
    EXPECT_EQ(wall.vector(0, 6.0), 4.25);
    EXPECT_FALSE(wall.placement_pending());
  }
  {
    // damping 100, dt 0.01, mass 1: damping*dt/m = 1
    porewater::WallStressSettings s = free_wall(8.0);
    s.damping = 100.0;
    porewater::StressWall wall(s, "w");
    wall.init(host, 0.01);
    EXPECT_EQ(host.warning.rfind("Fix wall/stress: damping 100 with timestep 0.01 and lightest grain "
                                 "mass 1 gives damping*dt/m = 1; ", 0),
              0u)
        << host.warning;
  }
}

namespace {

// one rank, six grains of mass 2 (a plate of mass 12) at mean x 1.5, area 24
class OneRankPlateHost : public porewater::RigidPlateHost {
 public:
  double fx = 0.0, mean_x = 1.5, velocity_x = 0.0, force_per_mass = 0.0;
  void plate_sums(double *sums) override
  {
    sums[0] = fx;
    sums[1] = 12.0 * mean_x;
    sums[2] = 12.0;
  }
  void momentum_sums(double *sums) override
  {
    sums[0] = 12.0 * velocity_x;
    sums[1] = 12.0;
  }
  void move_as_plate(double a) override { force_per_mass = a; }
  void set_velocity_x(double v) override { velocity_x = v; }
  void sum_over_ranks(double *, int) override {}
  double area() override { return 24.0; }
  double force_to_velocity() override { return 1.0; }
  double neighbor_skin() override { return 0.2; }
  std::string group_name() const override { return "top"; }
  void stop(const std::string &message) override { throw Stopped(message); }
};

}    // namespace

TEST(RigidPlate, AccelerationDisplacementRunawayAndRestart)
{
  porewater::ShearStressSettings s;
  s.tau = 0.5;
  s.mass = 12.0;
  OneRankPlateHost host;
  host.fx = -0.6;    // resisting forces on the layer
  host.velocity_x = 0.25;
  porewater::RigidPlate plate(s, "s");
  plate.setup(host, {0, 0.001, true});
  // (τA + ΣF_x)/M, the resisting stress −ΣF_x/A; the displacement starts at 0
  EXPECT_DOUBLE_EQ(host.force_per_mass, (12.0 - 0.6) / 12.0);
  EXPECT_DOUBLE_EQ(plate.vector(host, 2), 0.6 / 24.0);
  EXPECT_EQ(plate.vector(host, 1), 0.0);
  EXPECT_EQ(plate.vector(host, 0), 0.25);
  host.mean_x = 1.55;
  plate.post_force(host, {1, 0.001, false});
  EXPECT_NEAR(plate.vector(host, 1), 0.05, 1e-15);
  // a new run's setup carries the displacement on
  porewater::RigidPlate restarted(s, "s");
  restarted.restore(plate.restart_state());
  host.mean_x = 7.0;
  restarted.setup(host, {2, 0.001, true});
  EXPECT_NEAR(restarted.vector(host, 1), 0.05, 1e-15);
  // more than half the skin (0.1) in one step is a runaway
  host.mean_x = 7.2;
  try {
    restarted.post_force(host, {3, 0.001, false});
    ADD_FAILURE() << "no runaway";
  } catch (const Stopped &e) {
    EXPECT_EQ(std::string(e.what()).rfind("Fix shear/stress s: the plate ran away at step 3: it moved 0.2", 0),
              0u)
        << e.what();
  }
}

TEST(RoundTripText, ShortestTextThatReadsBackLikeFmt)
{
  EXPECT_EQ(porewater::round_trip_text(10.0), "10");
  EXPECT_EQ(porewater::round_trip_text(0.1), "0.1");
  EXPECT_EQ(porewater::round_trip_text(8.5), "8.5");
  EXPECT_EQ(porewater::round_trip_text(1e300), "1e+300");
  EXPECT_EQ(porewater::round_trip_text(-std::numeric_limits<double>::infinity()), "-inf");
  const double x = 10.020049999999989;
  EXPECT_EQ(std::stod(porewater::round_trip_text(x)), x);
}
