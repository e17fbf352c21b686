// The stress-controlled top wall of fix wall/stress (doc/model.md §4), host-free: a
// frictionless horizontal plane of mass M moving in z under the grains' contact forces and
// an applied normal stress S(t), by velocity Verlet in step with the grains:
//   initial_integrate  v_w += ½Δt F_w/M,  z_w += Δt v_w
//   post_force         grain–wall contacts at the new z_w;
//                      F_w = Σ contact forces − S·L_x·L_y − γ_p v_w
//   final_integrate    v_w += ½Δt F_w/M
// A host's fix (LAMMPS, LIGGGHTS) gives it a StressWallHost and forwards its hooks; every
// rank holds the same wall.
#ifndef PW_WALLS_STRESS_WALL_H
#define PW_WALLS_STRESS_WALL_H

#include "input/restart_state.h"
#include "input/settings.h"
#include "walls/wall_contact.h"
#include "walls/wall_motion.h"

#include <limits>
#include <string>
#include <vector>

namespace porewater {

class StressWallHost {
 public:
  virtual double stress_now() = 0;    // S at this step (a constant or an equal-style variable)
  // the contacts of this rank's grains with the wall (StressWall::contacts): forces added
  // to the grains, sums = {force on the wall, spring energy, zz virial, dashpot share}
  virtual void contact_sums(double *sums) = 0;
  virtual void sum_over_ranks(double *values, int n) = 0;    // on every rank
  virtual double max_over_ranks(double value) = 0;
  virtual double min_over_ranks(double value) = 0;
  virtual double highest_grain_top() = 0;    // max z + r over this rank's grains of the group
  virtual double lightest_grain() = 0;       // min mass over them (+inf: none)
  virtual WallBox box() = 0;
  virtual std::string group_name() const = 0;
  // called on every rank with the same message: stop the run
  virtual void stop(const std::string &message) = 0;
  virtual void warn(const std::string &message) = 0;    // called on every rank: print once

 protected:
  ~StressWallHost() = default;
};

// max z + r / min mass over the local grains of the group (serial loops of a CPU host)
template <class G> double highest_grain_top(const G &g, int n, int groupbit)
{
  double top = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i)
    if ((g.mask(i) & groupbit) && g.x(i, 2) + g.radius(i) > top) top = g.x(i, 2) + g.radius(i);
  return top;
}
template <class G> double lightest_grain(const G &g, int n, int groupbit)
{
  double lightest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i)
    if ((g.mask(i) & groupbit) && g.rmass(i) < lightest) lightest = g.rmass(i);
  return lightest;
}

class StressWall {
 public:
  // z_w, v_w, grain force per area, S, the grain dashpots' share of it, plate dashpot per area
  static constexpr int VECTOR_SIZE = 6;
  static const RestartFormat RESTART;

  // `id` names the fix in messages
  StressWall(const WallStressSettings &settings, const std::string &id);

  const WallStressSettings &settings() const { return settings_; }
  bool placement_pending() const { return z_auto_; }

  // the hooks of the fix
  void init(StressWallHost &host, double dt);      // warns of dashpots near their limit
  void setup(StressWallHost &host, long long step);    // `z auto`, then the forces
  void initial_integrate(double dt);
  void post_force(StressWallHost &host, long long step);
  void final_integrate(double dt);

  // the contacts of the grains of `groupbit` with the wall where it is now
  template <class G, class PerAtomVirial>
  WallContacts<G, PerAtomVirial> contacts(const G &grains, const PerAtomVirial &per_atom,
                                          int groupbit) const
  {
    return WallContacts<G, PerAtomVirial>{grains, per_atom, groupbit, state_.z, state_.v,
                                          settings_.kn, settings_.damping,
                                          settings_.damping_velocity};
  }

  double z() const { return state_.z; }
  double scalar() const { return state_.spring_energy; }
  // the whole state, for a host that moves the wall elsewhere between its hooks (fix
  // wall/stress/kk on the device) and hands it back
  const WallState &state() const { return state_; }
  void set_state(const WallState &state) { state_ = state; }
  // stops the run: the wall left the box (wall_verdict) at `step`, being at `w` in `box`
  void stop_outside_box(StressWallHost &host, int verdict, long long step, const WallState &w,
                        const WallBox &box) const;
  double vector(int n, double area) const;
  double *extract(const std::string &name);    // z_wall, v_wall; nullptr otherwise

  std::vector<double> restart_state() const;
  void restore(const std::vector<double> &state);    // 4 values (restart_values checks)

 private:
  void check_in_box(StressWallHost &host, long long step);

  WallStressSettings settings_;
  std::string id_;
  WallState state_;
  bool z_auto_;              // until `z auto` has put the wall on the highest grain
};

}    // namespace porewater

#endif
