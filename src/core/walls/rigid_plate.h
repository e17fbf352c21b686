// The top layer of fix shear/stress (doc/model.md §4), host-free: it moves in x as one rigid
// plate of mass M driven by a shear stress τ; y-motion and rotation locked, vertical motion
// left to each grain. In post_force, after the pair style and the fixes defined before it
// have added their forces, the plate sums the x-forces on the group and replaces each
// grain's f_x by m_i·a_plate with a_plate = (τ L_x L_y + ΣF_x)/M, so the integrator moves
// every grain of the layer with the same x-acceleration. A host's fix (LAMMPS, LIGGGHTS)
// gives it a RigidPlateHost (the per-grain kernels of walls/shear_plate.h over its grains)
// and forwards setup and post_force.
#ifndef PW_WALLS_RIGID_PLATE_H
#define PW_WALLS_RIGID_PLATE_H

#include "grains/grain_list.h"
#include "grains/host_grains.h"
#include "input/restart_state.h"
#include "input/settings.h"
#include "walls/shear_plate.h"

#include <string>
#include <vector>

namespace porewater {

class RigidPlateHost {
 public:
  // this rank's grains of the group (walls/shear_plate.h kernels)
  virtual void plate_sums(double *sums) = 0;        // {ΣF_x, Σ m x_unwrapped, Σ m}
  virtual void momentum_sums(double *sums) = 0;     // {Σ m v_x, Σ m}
  virtual void move_as_plate(double force_per_mass) = 0;    // f_x = m a; y, rotation locked
  virtual void set_velocity_x(double velocity) = 0;
  virtual void sum_over_ranks(double *values, int n) = 0;    // on every rank
  virtual double area() = 0;                 // L_x L_y
  virtual double force_to_velocity() = 0;    // the host's ftm2v (1 in SI)
  virtual double neighbor_skin() = 0;
  virtual std::string group_name() const = 0;
  // called on every rank with the same message: stop the run
  virtual void stop(const std::string &message) = 0;

 protected:
  ~RigidPlateHost() = default;
};

// The plate kernels of a CPU host, serial loops over its grains G (grains/host_grains.h):
// every grain [0, n), each with its mask tested, or the group's grains listed in `members`
// (grains/grain_list.h); the KOKKOS fix runs the same kernels as Kokkos kernels.
template <class G> struct SerialPlateGrains {
  G grains;
  int n, groupbit;
  ImageUnwrap unwrap;
  const GrainList *members;    // nullptr: every grain
  void plate_sums(double *sums) const { sum(PlateSums<G>{grains, groupbit, unwrap}, sums); }
  void momentum_sums(double *sums) const { sum(PlateMomentum<G>{grains, groupbit}, sums); }
  void move_as_plate(double force_per_mass) const
  {
    each(PlateMotion<G>{grains, groupbit, force_per_mass});
  }
  void set_velocity_x(double velocity) const { each(PlateVelocity<G>{grains, groupbit, velocity}); }

 private:
  template <class Body> void sum(const Body &body, double *sums) const
  {
    if (members)
      sum_over_listed(*members, body, sums);
    else
      sum_over_grains(n, body, sums);
  }
  template <class Body> void each(const Body &body) const
  {
    if (members)
      for_each_listed(*members, body);
    else
      for_each_grain(n, body);
  }
};
template <class G>
SerialPlateGrains<G> serial_plate_grains(const G &grains, int n, int groupbit, const ImageUnwrap &unwrap,
                                         const GrainList *members = nullptr)
{
  return SerialPlateGrains<G>{grains, n, groupbit, unwrap, members};
}

// Where the host's time integration stands in post_force.
struct PlateStep {
  long long step;
  double dt;
  bool setup;    // the forces of a run's setup (the host's update->setupflag)
};

class RigidPlate {
 public:
  static constexpr int VECTOR_SIZE = 3;    // velocity, displacement, resisting stress
  static const RestartFormat RESTART;

  RigidPlate(const ShearStressSettings &settings, const std::string &id);
  const ShearStressSettings &settings() const { return settings_; }

  void setup(RigidPlateHost &host, const PlateStep &now);    // one plate, one velocity
  void post_force(RigidPlateHost &host, const PlateStep &now);

  double velocity(RigidPlateHost &host) const;    // mass-weighted mean v_x (a reduction)
  double vector(RigidPlateHost &host, int n) const;

  std::vector<double> restart_state() const { return {state_.displacement}; }
  void restore(const std::vector<double> &state) { state_.displacement = state[0]; }

  // the whole state, for a host that moves the plate elsewhere between its hooks (fix
  // shear/stress/kk on the device) and hands it back
  const PlateState &state() const { return state_; }
  void set_state(const PlateState &state) { state_ = state; }
  // stops the run for what plate_post_force found at `now` (its verdict is not PLATE_MOVING)
  void stop_for(RigidPlateHost &host, const PlateStepResult &result, const PlateStep &now) const;

 private:
  ShearStressSettings settings_;
  std::string id_;
  PlateState state_;
};

// The fixes after `self` in the host's list (Modify: nfix, fix[], fmask[]) whose mask has
// `hook`, as " ID (style)" each: fix shear/stress warns of forces it cannot see.
template <class Modify, class Fix>
std::string fixes_after(const Modify &modify, const Fix *self, int hook)
{
  std::string later;
  bool after_self = false;
  for (int i = 0; i < modify.nfix; i++) {
    if (modify.fix[i] == self)
      after_self = true;
    else if (after_self && (modify.fmask[i] & hook))
      later += std::string(" ") + modify.fix[i]->id + " (" + modify.fix[i]->style + ")";
  }
  return later;
}

// the warning for those fixes ("" if there are none)
std::string fixes_after_warning(const std::string &id, const std::string &later);

}    // namespace porewater

#endif
