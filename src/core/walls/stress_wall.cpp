#include "walls/stress_wall.h"

#include <cmath>
#include <cstdio>

namespace porewater {

static_assert(WALL_DAMPING_RELATIVE == 0 && WALL_DAMPING_ABSOLUTE == 1,
              "parse_wall_stress reads damping_velocity as the index of relative|absolute");

const RestartFormat StressWall::RESTART{RestartStyle::WallStress, 1, "fix wall/stress"};

StressWall::StressWall(const WallStressSettings &settings, const std::string &id) :
    settings_(settings), id_(id), state_{settings.z, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    z_auto_(settings.z_auto)
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
    state_.z = top;
    z_auto_ = false;
  }
  post_force(host, step);
}

void StressWall::initial_integrate(double dt)
{
  wall_initial_integrate(state_, dt, settings_.mass);
}

void StressWall::post_force(StressWallHost &host, long long step)
{
  const double stress = host.stress_now();
  double sums[4];
  host.contact_sums(sums);
  double totals[3] = {sums[0], sums[1], sums[3]};    // the virial, sums[2], stays per rank
  host.sum_over_ranks(totals, 3);
  wall_post_force(state_, totals[0], totals[1], totals[2], stress, host.box().area,
                  settings_.plate_damping);
  check_in_box(host, step);
}

void StressWall::final_integrate(double dt)
{
  wall_kick(state_, dt, settings_.mass);
}

// every rank holds the same wall, so every rank reaches the same verdict; the message is
// written only then (formatting it every step cost as much as the wall's contacts)
void StressWall::check_in_box(StressWallHost &host, long long step)
{
  const WallBox box = host.box();
  const int verdict = wall_verdict(state_, box);
  if (verdict != WALL_IN_BOX) stop_outside_box(host, verdict, step, state_, box);
}

void StressWall::stop_outside_box(StressWallHost &host, int verdict, long long step,
                                  const WallState &w, const WallBox &box) const
{
  const std::string at = "Fix wall/stress " + id_ + ": ";
  const std::string z = round_trip_text(w.z), when = std::to_string(step);
  if (verdict == WALL_NOT_FINITE)
    host.stop(at + "the wall ran away at step " + when + ": z = " + z + ", v = " +
              round_trip_text(w.v));
  else if (verdict == WALL_BELOW_BOX)
    host.stop(at + "the wall fell to z = " + z + " at step " + when + ", below the box bottom " +
              round_trip_text(box.bottom) + " and so through every grain");
  else
    host.stop(at + "the wall rose to z = " + z + " at step " + when + ", above the box top " +
              round_trip_text(wall_box_top(box)));
}

// vector: 1 z_wall, 2 v_wall, 3 grain force per area (effective normal stress), 4 applied S,
// 5 the grain–wall dashpots' share of 3, 6 the plate dashpot's force per area on the wall
double StressWall::vector(int n, double area) const
{
  switch (n) {
    case 0:
      return state_.z;
    case 1:
      return state_.v;
    case 2:
      return state_.grain_force / area;
    case 3:
      return state_.applied_stress;
    case 4:
      return state_.grain_damping / area;
    default:
      return state_.plate_damping / area;
  }
}

double *StressWall::extract(const std::string &name)
{
  if (name == "z_wall") return &state_.z;
  if (name == "v_wall") return &state_.v;
  return nullptr;
}

// restart: the wall's position, velocity, last force and whether `auto` is still pending
std::vector<double> StressWall::restart_state() const
{
  return {state_.z, state_.v, state_.force, z_auto_ ? 1.0 : 0.0};
}

void StressWall::restore(const std::vector<double> &state)
{
  state_.z = state[0];
  state_.v = state[1];
  state_.force = state[2];
  z_auto_ = state[3] != 0.0;
}

}    // namespace porewater
