#include "walls/rigid_plate.h"

#include "walls/shear_plate.h"

#include <cmath>

namespace porewater {

const RestartFormat RigidPlate::RESTART{RestartStyle::ShearStress, 1, "fix shear/stress"};

RigidPlate::RigidPlate(const ShearStressSettings &settings, const std::string &id) :
    settings_(settings), id_(id), state_{0.0, 0.0, 0.0, 0.0}
{
}

void RigidPlate::setup(RigidPlateHost &host, const PlateStep &now)
{
  host.set_velocity_x(velocity(host));
  post_force(host, now);
}

void RigidPlate::post_force(RigidPlateHost &host, const PlateStep &now)
{
  double sums[3];
  host.plate_sums(sums);
  host.sum_over_ranks(sums, 3);
  const PlateStepResult result =
      plate_post_force(state_, sums, now.setup, host.area(), settings_.tau, settings_.mass,
                       host.force_to_velocity(), 0.5 * host.neighbor_skin());
  if (result.verdict != PLATE_MOVING) stop_for(host, result, now);
  host.move_as_plate(state_.force_per_mass);
}

void RigidPlate::stop_for(RigidPlateHost &host, const PlateStepResult &result,
                          const PlateStep &now) const
{
  const std::string at = "Fix shear/stress " + id_ + ": ";
  if (result.verdict == PLATE_EMPTY)
    host.stop(at + "group " + host.group_name() + " has no grains");
  else if (result.verdict == PLATE_RAN_AWAY)
    host.stop(at + "the plate ran away at step " + std::to_string(now.step) + ": it moved " +
              round_trip_text(result.value) + " in one step (v ≈ " +
              round_trip_text(result.value / now.dt) +
              "), more than half the neighbor skin (" + round_trip_text(0.5 * host.neighbor_skin()) + ")");
  else
    host.stop(at + "plate acceleration " + round_trip_text(result.value) + " at step " +
              std::to_string(now.step) + " is not finite");
}

double RigidPlate::velocity(RigidPlateHost &host) const
{
  double sums[2];
  host.momentum_sums(sums);
  host.sum_over_ranks(sums, 2);
  return sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
}

// vector: 1 plate velocity, 2 plate displacement, 3 resisting shear stress
double RigidPlate::vector(RigidPlateHost &host, int n) const
{
  switch (n) {
    case 0:
      return velocity(host);
    case 1:
      return state_.displacement;
    default:
      return state_.resisting_stress;
  }
}

std::string fixes_after_warning(const std::string &id, const std::string &later)
{
  if (later.empty()) return "";
  return "Fix shear/stress " + id + ": fixes defined after it change forces:" + later +
      "; their x-forces bypass the plate. Define fix shear/stress last";
}

}    // namespace porewater
