/* ----------------------------------------------------------------------
   fix nve/sphere/bed (see doc/fix_nve_sphere_bed.rst)

   Where it sits in LAMMPS' Verlet step (integrate/bed_pass.h holds the per-grain passes):
     initial_integrate  half kick and drift of every grain of the group (a held grain along z)
     post_force         the floor on the group's grains, then gravity on its group, at this
                        fix's place among the fixes (define it where wall/gran stood)
     final_integrate    the second half kick
------------------------------------------------------------------------- */

#include "fix_nve_sphere_bed.h"

#include "grains/host_grains.h"
#include "integrate/bed_pass.h"
#include "lammps_compat.h"
#include "lammps_input.h"
#include "sphere_integrator.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixNVESphereBed::FixNVESphereBed(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), heldbit(0), gravitybit(0)
{
  settings = porewater::parse_or_stop(lmp, "fix nve/sphere/bed", narg - 3, arg + 3,
                                      porewater::parse_nve_sphere_bed);
  if (!porewater::has_sphere_attributes(atom))
    error->all(FLERR, "Fix nve/sphere/bed requires atom_style sphere");
  time_integrate = 1;
  heldbit = group_bit_of(settings.held_group, "held");
  gravitybit = group_bit_of(settings.gravity_group, "gravity");
}

// the bit of a group named by `keyword`; 0 when none is named
int FixNVESphereBed::group_bit_of(const std::string &name, const char *keyword) const
{
  if (name.empty()) return 0;
  const int id = group->find(name.c_str());
  if (id < 0)
    error->all(FLERR, "Fix nve/sphere/bed: " + std::string(keyword) + " names group " + name +
                          ", which does not exist");
  return group->bitmask[id];
}

int FixNVESphereBed::setmask()
{
  return INITIAL_INTEGRATE | POST_FORCE | FINAL_INTEGRATE;
}

void FixNVESphereBed::init()
{
  porewater::check_sphere_integrator(lmp, groupbit, "Fix nve/sphere/bed");
}

// the body forces before the first step, as wall/gran and gravity add them in their setup
void FixNVESphereBed::setup(int vflag)
{
  post_force(vflag);
}

/* ---------------------------------------------------------------------- */

void FixNVESphereBed::initial_integrate(int /*vflag*/)
{
  using G = porewater::HostGrains<imageint>;
  porewater::for_each_grain(
      atom->nlocal, porewater::BedInitial<G>{porewater::grains_of_atom(atom), groupbit, heldbit,
                                             porewater::verlet_steps(update->dt, force->ftm2v)});
}

void FixNVESphereBed::post_force(int /*vflag*/)
{
  using G = porewater::HostGrains<imageint>;
  porewater::for_each_grain(
      atom->nlocal,
      porewater::BedForces<G>{porewater::grains_of_atom(atom), groupbit, gravitybit,
                              settings.floor ? 1 : 0, settings.z_floor, settings.kn,
                              -settings.gravity});
}

void FixNVESphereBed::final_integrate()
{
  using G = porewater::HostGrains<imageint>;
  porewater::for_each_grain(
      atom->nlocal, porewater::BedFinal<G>{porewater::grains_of_atom(atom), groupbit, heldbit,
                                           porewater::verlet_steps(update->dt, force->ftm2v)});
}
