// Registers every style of the package, and the KOKKOS variants, with LAMMPS'
// `plugin load porewater.so`.

#include "lammpsplugin.h"
#include "version.h"

#include "fix.h"
#include "pair.h"

#include "fix_darcy_pressure.h"
#include "fix_darcy_pressure_kokkos.h"
#include "fix_nve_sphere_ty3.h"
#include "fix_nve_sphere_ty3_kokkos.h"
#include "fix_shear_stress.h"
#include "fix_shear_stress_kokkos.h"
#include "fix_wall_stress.h"
#include "fix_wall_stress_kokkos.h"

#include "pair_linear_coulomb.h"
#include "pair_linear_coulomb_kokkos.h"

using namespace LAMMPS_NS;

namespace {

template <class T> Pair *pair_creator(LAMMPS *lmp)
{
  return new T(lmp);
}

template <class T> Fix *fix_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}

struct Registrar {
  void *lmp;
  lammpsplugin_regfunc register_plugin;
  void *handle;
  void add(const char *style, const char *name, const char *info, lammpsplugin_factory1 *creator)
  {
    add_any(style, name, info, (void *) creator, false);
  }
  void add(const char *style, const char *name, const char *info, lammpsplugin_factory2 *creator)
  {
    add_any(style, name, info, (void *) creator, true);
  }
  void add_any(const char *style, const char *name, const char *info, void *creator, bool v2)
  {
    lammpsplugin_t plugin;
    plugin.version = LAMMPS_VERSION;
    plugin.style = style;
    plugin.name = name;
    plugin.info = info;
    plugin.author = "lammps-porewater developers";
    if (v2)
      plugin.creator.v2 = (lammpsplugin_factory2 *) creator;
    else
      plugin.creator.v1 = (lammpsplugin_factory1 *) creator;
    plugin.handle = handle;
    (*register_plugin)(&plugin, lmp);
  }
};

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  Registrar r{lmp, (lammpsplugin_regfunc) regfunc, handle};

  // `name/kk` builds the default-device class, `name/kk/device` and `name/kk/host` as in
  // LAMMPS' own KOKKOS package
  r.add("pair", "linear/coulomb", "linear spring + Coulomb friction contacts, no damping",
        (lammpsplugin_factory1 *) &pair_creator<PairLinearCoulomb>);
  r.add("pair", "linear/coulomb/kk", "linear/coulomb, KOKKOS",
        (lammpsplugin_factory1 *) &pair_creator<PairLinearCoulombKokkos<LMPDeviceType>>);
  r.add("pair", "linear/coulomb/kk/device", "linear/coulomb, KOKKOS device",
        (lammpsplugin_factory1 *) &pair_creator<PairLinearCoulombKokkos<LMPDeviceType>>);
  r.add("pair", "linear/coulomb/kk/host", "linear/coulomb, KOKKOS host",
        (lammpsplugin_factory1 *) &pair_creator<PairLinearCoulombKokkos<LMPHostType>>);

  // fixes: r.add("fix", "name", "info", (lammpsplugin_factory2 *) &fix_creator<FixClass>);
  r.add("fix", "wall/stress", "stress-controlled frictionless top wall with mass",
        (lammpsplugin_factory2 *) &fix_creator<FixWallStress>);
  r.add("fix", "wall/stress/kk", "wall/stress, KOKKOS",
        (lammpsplugin_factory2 *) &fix_creator<FixWallStressKokkos<LMPDeviceType>>);
  r.add("fix", "wall/stress/kk/device", "wall/stress, KOKKOS device",
        (lammpsplugin_factory2 *) &fix_creator<FixWallStressKokkos<LMPDeviceType>>);
  r.add("fix", "wall/stress/kk/host", "wall/stress, KOKKOS host",
        (lammpsplugin_factory2 *) &fix_creator<FixWallStressKokkos<LMPHostType>>);
  r.add("fix", "shear/stress", "top layer as a rigid plate driven by a shear stress",
        (lammpsplugin_factory2 *) &fix_creator<FixShearStress>);
  r.add("fix", "shear/stress/kk", "shear/stress, KOKKOS",
        (lammpsplugin_factory2 *) &fix_creator<FixShearStressKokkos<LMPDeviceType>>);
  r.add("fix", "shear/stress/kk/device", "shear/stress, KOKKOS device",
        (lammpsplugin_factory2 *) &fix_creator<FixShearStressKokkos<LMPDeviceType>>);
  r.add("fix", "shear/stress/kk/host", "shear/stress, KOKKOS host",
        (lammpsplugin_factory2 *) &fix_creator<FixShearStressKokkos<LMPHostType>>);
  r.add("fix", "nve/sphere/ty3", "third-order Taylor integrator of finite-size spheres",
        (lammpsplugin_factory2 *) &fix_creator<FixNVESphereTY3>);
  r.add("fix", "nve/sphere/ty3/kk", "nve/sphere/ty3, KOKKOS",
        (lammpsplugin_factory2 *) &fix_creator<FixNVESphereTY3Kokkos<LMPDeviceType>>);
  r.add("fix", "nve/sphere/ty3/kk/device", "nve/sphere/ty3, KOKKOS device",
        (lammpsplugin_factory2 *) &fix_creator<FixNVESphereTY3Kokkos<LMPDeviceType>>);
  r.add("fix", "nve/sphere/ty3/kk/host", "nve/sphere/ty3, KOKKOS host",
        (lammpsplugin_factory2 *) &fix_creator<FixNVESphereTY3Kokkos<LMPHostType>>);

  r.add("fix", "darcy/pressure", "pore-water pressure on a Darcy grid, force on grains",
        (lammpsplugin_factory2 *) &fix_creator<FixDarcyPressure>);
  r.add("fix", "darcy/pressure/kk", "darcy/pressure, KOKKOS",
        (lammpsplugin_factory2 *) &fix_creator<FixDarcyPressureKokkos<LMPDeviceType>>);
  r.add("fix", "darcy/pressure/kk/device", "darcy/pressure, KOKKOS device",
        (lammpsplugin_factory2 *) &fix_creator<FixDarcyPressureKokkos<LMPDeviceType>>);
  r.add("fix", "darcy/pressure/kk/host", "darcy/pressure, KOKKOS host",
        (lammpsplugin_factory2 *) &fix_creator<FixDarcyPressureKokkos<LMPHostType>>);
}
