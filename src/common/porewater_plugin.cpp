// Registers every style of the package, and the KOKKOS variants, with LAMMPS'
// `plugin load porewater.so`.

#include "lammpsplugin.h"
#include "version.h"

#include "fix.h"
#include "pair.h"


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


}
