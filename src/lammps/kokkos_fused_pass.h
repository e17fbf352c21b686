// How a /kk fix's per-grain post_force work joins fix nve/sphere/bed/kk's fused pass
// (FIX_WALLS/fix_nve_sphere_bed_pass_kokkos.h holds the pass and says which fixes join,
// in which order): the pass stamps each member with the step whose work it did, and the
// member does its own work on every other step. A stamp is of one step only, so nothing
// the pass did on an earlier step, in an earlier run or before a fix changed, can stand
// in for a member's work now.
#ifndef PW_LAMMPS_KOKKOS_FUSED_PASS_H
#define PW_LAMMPS_KOKKOS_FUSED_PASS_H

namespace porewater {

struct PassStamp {
  long long step = -1;    // the step whose work the pass did; -1: none
  void done(long long now) { step = now; }
  bool done_at(long long now) const { return step == now; }
  void reset() { step = -1; }
};

}    // namespace porewater

#endif
