#include "walls/rigid_plate.h"

#include "walls/shear_plate.h"

#include <cmath>

namespace porewater {

const RestartFormat RigidPlate::RESTART{RestartStyle::ShearStress, 1, "fix shear/stress"};

RigidPlate::RigidPlate(const ShearStressSettings &settings, const std::string &id) :
    settings_(settings), id_(id), displacement_(0.0), reference_x_(0.0), resisting_stress_(0.0)
{
}

void RigidPlate::setup(RigidPlateHost &host, const PlateStep &now)
{
  host.set_velocity_x(velocity(host));
  post_force(host, now);
}

void RigidPlate::post_force(RigidPlateHost &host, const PlateStep &now)
{
  // the message's prefix, written only when the run stops
  const auto at = [this] { return "Fix shear/stress " + id_ + ": "; };
  double sums[3];
  host.plate_sums(sums);
  host.sum_over_ranks(sums, 3);
  if (sums[2] <= 0.0) host.stop(at() + "group " + host.group_name() + " has no grains");

  const double mean_x = sums[1] / sums[2];
  // a new run (or a restart) carries the displacement on from where it was
  if (now.setup) reference_x_ = mean_x - displacement_;
  const double displacement = mean_x - reference_x_;
  // bound: half the neighbor skin per step, beyond which contacts could be missed
  const double moved = displacement - displacement_, bound = 0.5 * host.neighbor_skin();
  if (!now.setup && !(std::fabs(moved) <= bound))
    host.stop(at() + "the plate ran away at step " + std::to_string(now.step) + ": it moved " +
              round_trip_text(moved) + " in one step (v ≈ " + round_trip_text(moved / now.dt) +
              "), more than half the neighbor skin (" + round_trip_text(bound) + ")");
  displacement_ = displacement;
  const double area = host.area();
  resisting_stress_ = -sums[0] / area;

  const double a = plate_acceleration(settings_.tau, area, sums[0], settings_.mass);
  if (!std::isfinite(a))
    host.stop(at() + "plate acceleration " + round_trip_text(a) + " at step " +
              std::to_string(now.step) + " is not finite");
  host.move_as_plate(a / host.force_to_velocity());
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
      return displacement_;
    default:
      return resisting_stress_;
  }
}

std::string fixes_after_warning(const std::string &id, const std::string &later)
{
  if (later.empty()) return "";
  return "Fix shear/stress " + id + ": fixes defined after it change forces:" + later +
      "; their x-forces bypass the plate. Define fix shear/stress last";
}

}    // namespace porewater
