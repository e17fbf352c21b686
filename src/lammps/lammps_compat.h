// What differs between the LAMMPS versions the plugin builds against (29Sep2021 and
// 4Feb2025), in one place: each entry works on both, says what it bridges and why.
#ifndef PW_LAMMPS_COMPAT_H
#define PW_LAMMPS_COMPAT_H

#include "atom.h"
#include "compute.h"
#include "neighbor.h"
#include "update.h"
#if !PW_LAMMPS_HAS_ADD_REQUEST
#include "neigh_request.h"
#endif

// Grid3d, per-grid data of fixes, dump grid and fix ave/grid: LAMMPS since 22Dec2022 (the
// GridComm of 29Sep2021 has no such interface); PW_LAMMPS_VERSION_NUMBER comes from CMake
#if PW_LAMMPS_VERSION_NUMBER >= 20221222
#define PW_LAMMPS_HAS_GRID3D 1
#else
#define PW_LAMMPS_HAS_GRID3D 0
#endif

namespace porewater {

// atom_style sphere (radius, rmass, omega, torque): Atom::sphere_flag is gone since 2023,
// when other atom styles (bpm/sphere, ...) began to carry the same per-atom fields
inline bool has_sphere_attributes(const LAMMPS_NS::Atom *atom)
{
  return atom->radius_flag && atom->rmass_flag && atom->omega_flag && atom->torque_flag;
}

// The simulated time at `step`, as LAMMPS' `time` keyword computes it. Restart files keep
// atime and atimestep since 3 May 2022 (our 29Sep2021: scripts/patches/lammps-restart-time.patch;
// CMake's PW_LAMMPS_RESTART_HAS_TIME says whether this LAMMPS does); before, a run continued
// from one starts its time at 0.
inline double simulated_time(const LAMMPS_NS::Update *update, LAMMPS_NS::bigint step)
{
  return update->atime + (step - update->atimestep) * update->dt;
}

// An occasional full neighbour list for a compute (built on demand by Neighbor::build_one):
// Neighbor::add_request and its flags since 2022 (CMake's PW_LAMMPS_HAS_ADD_REQUEST), the
// request's fields before.
inline void request_occasional_full_list(LAMMPS_NS::Neighbor *neighbor,
                                         LAMMPS_NS::Compute *compute, int instance)
{
#if PW_LAMMPS_HAS_ADD_REQUEST
  (void) instance;
  neighbor->add_request(compute, LAMMPS_NS::NeighConst::REQ_FULL | LAMMPS_NS::NeighConst::REQ_OCCASIONAL);
#else
  const int request = neighbor->request(compute, instance);
  neighbor->requests[request]->pair = 0;
  neighbor->requests[request]->compute = 1;
  neighbor->requests[request]->half = 0;
  neighbor->requests[request]->full = 1;
  neighbor->requests[request]->occasional = 1;
#endif
}

// Builds a compute's occasional list unless it is current. Neighbor::build_one skips a list
// built at or after the last re-neighboring's step; LAMMPS since 2022 forgets that build at
// each re-neighboring, 29Sep2021 does not, so a list built at the step where one run ended
// was kept after the next run's setup had re-sorted and re-listed the atoms at that step:
// stale indices. There build_one's preflag 1 rebuilds it unless built strictly after.
template <class NeighborT>
inline auto build_occasional_list(NeighborT *neighbor, LAMMPS_NS::NeighList *list, int)
    -> decltype(neighbor->build_one(list, 1), void())
{
  neighbor->build_one(list, 1);
}
template <class NeighborT>
inline void build_occasional_list(NeighborT *neighbor, LAMMPS_NS::NeighList *list, long)
{
  neighbor->build_one(list);
}
inline void build_occasional_list(LAMMPS_NS::Neighbor *neighbor, LAMMPS_NS::NeighList *list)
{
  build_occasional_list(neighbor, list, 0);
}

}    // namespace porewater

#endif
