#include "walls/stress_wall.h"

#include <cmath>
#include <cstdio>

namespace porewater {

static_assert(WALL_DAMPING_RELATIVE == 0 && WALL_DAMPING_ABSOLUTE == 1,
              "parse_wall_stress reads damping_velocity as the index of relative|absolute");

const RestartFormat StressWall::RESTART{RestartStyle::WallStress, 1, "fix wall/stress"};

StressWall::StressWall(const WallStressSettings &settings, const std::string &id) :
    settings_(settings), id_(id), z_wall_(settings.z), v_wall_(0.0), wall_force_(0.0),
    grain_force_(0.0), grain_damping_(0.0), plate_damping_(0.0), applied_stress_(0.0), spring_energy_(0.0), z_auto_(settings.z_auto)
{
}

// An explicit dashpot γ on a mass m is stable only for γ·Δt/m < 2; near that bound it
// chatters, so warn well before it: the grain–wall one on the lightest grain, the plate's
// on the wall.
void StressWall::init(StressWallHost &host, double dt)
{
  auto warn = [&](const char *keyword, double gamma, const char *which, double mass) {
    const double ratio = gamma * dt / mass;
    if (!(ratio > 0.5)) return;
    char text[16];
    std::snprintf(text, sizeof(text), "%.3g", ratio);
    host.warn(std::string("Fix wall/stress: ") + keyword + " " + round_trip_text(gamma) +
              " with timestep " + round_trip_text(dt) + " and " + which + " " +
              round_trip_text(mass) + " gives " + keyword + "*dt/m = " + text +
              "; the explicit dashpot chatters above ~0.5 and is unstable above 2: lower " +
              keyword + " or the timestep");
  };
  if (settings_.plate_damping > 0.0)
    warn("plate_damping", settings_.plate_damping, "wall mass", settings_.mass);
  if (settings_.damping <= 0.0) return;
  warn("damping", settings_.damping, "lightest grain mass",
       host.min_over_ranks(host.lightest_grain()));
}

void StressWall::setup(StressWallHost &host, long long step)
{
  if (z_auto_) {
    const double top = host.max_over_ranks(host.highest_grain_top());
    if (top == -std::numeric_limits<double>::infinity())
      host.stop("Fix wall/stress: z auto needs grains in group " + host.group_name());
    z_wall_ = top;
    z_auto_ = false;
  }
  post_force(host, step);
}

void StressWall::initial_integrate(double dt)
{
  v_wall_ += 0.5 * dt * wall_force_ / settings_.mass;
  z_wall_ += dt * v_wall_;
}

void StressWall::post_force(StressWallHost &host, long long step)
{
  applied_stress_ = host.stress_now();
  double sums[4];
  host.contact_sums(sums);
  double totals[3] = {sums[0], sums[1], sums[3]};    // the virial, sums[2], stays per rank
  host.sum_over_ranks(totals, 3);
  grain_force_ = totals[0];
  spring_energy_ = totals[1];
  grain_damping_ = totals[2];
  // v_wall_ is the half-step velocity here, as the grains' are for their contact forces
  plate_damping_ = plate_damping_force(v_wall_, settings_.plate_damping);
  wall_force_ = grain_force_ - applied_stress_ * host.box().area + plate_damping_;
  check_in_box(host, step);
}

void StressWall::final_integrate(double dt)
{
  v_wall_ += 0.5 * dt * wall_force_ / settings_.mass;
}

// every rank holds the same wall, so every rank reaches the same verdict; the message is
// written only then (formatting it every step cost as much as the wall's contacts)
void StressWall::check_in_box(StressWallHost &host, long long step)
{
  const WallBox box = host.box();
  // a shrink-wrapped top follows the grains: allow a gap as high as the box itself
  const double top = box.top_shrink_wrapped ? box.top + (box.top - box.bottom) : box.top;
  const bool finite = std::isfinite(z_wall_) && std::isfinite(v_wall_);
  if (finite && z_wall_ >= box.bottom && z_wall_ <= top) return;
  const std::string at = "Fix wall/stress " + id_ + ": ";
  const std::string z = round_trip_text(z_wall_), when = std::to_string(step);
  if (!finite)
    host.stop(at + "the wall ran away at step " + when + ": z = " + z + ", v = " +
              round_trip_text(v_wall_));
  else if (z_wall_ < box.bottom)
    host.stop(at + "the wall fell to z = " + z + " at step " + when + ", below the box bottom " +
              round_trip_text(box.bottom) + " and so through every grain");
  else
    host.stop(at + "the wall rose to z = " + z + " at step " + when + ", above the box top " +
              round_trip_text(top));
}

// vector: 1 z_wall, 2 v_wall, 3 grain force per area (effective normal stress), 4 applied S,
// 5 the grain–wall dashpots' share of 3, 6 the plate dashpot's force per area on the wall
double StressWall::vector(int n, double area) const
{
  switch (n) {
    case 0:
      return z_wall_;
    case 1:
      return v_wall_;
    case 2:
      return grain_force_ / area;
    case 3:
      return applied_stress_;
    case 4:
      return grain_damping_ / area;
    default:
      return plate_damping_ / area;
  }
}

double *StressWall::extract(const std::string &name)
{
  if (name == "z_wall") return &z_wall_;
  if (name == "v_wall") return &v_wall_;
  return nullptr;
}

// restart: the wall's position, velocity, last force and whether `auto` is still pending
std::vector<double> StressWall::restart_state() const
{
  return {z_wall_, v_wall_, wall_force_, z_auto_ ? 1.0 : 0.0};
}

void StressWall::restore(const std::vector<double> &state)
{
  z_wall_ = state[0];
  v_wall_ = state[1];
  wall_force_ = state[2];
  z_auto_ = state[3] != 0.0;
}

}    // namespace porewater
