// Registers every style of the package, and its KOKKOS variants where this LAMMPS has the
// KOKKOS package, for LAMMPS' `plugin load porewater.so` (porewater_loader.cpp, which
// checks the LAMMPS version first). The only file that includes every style.

#include "lammpsplugin.h"
#include "library.h"
#include "version.h"

#include "fix.h"
#include "pair.h"

#include "compute.h"
#include "compute_coordination_original.h"
#include "compute_darcy_grain.h"
#include "fix_darcy_pressure.h"
#include "fix_print_every.h"
#include "fix_progress.h"
#include "fix_nve_sphere_bed.h"
#include "fix_nve_sphere_ty3.h"
#include "fix_shear_stress.h"
#include "fix_wall_stress.h"
#include "pair_linear_coulomb.h"

#ifdef LMP_KOKKOS
#include "fix_darcy_pressure_kokkos.h"
#include "fix_nve_sphere_bed_kokkos.h"
#include "fix_nve_sphere_ty3_kokkos.h"
#include "fix_shear_stress_kokkos.h"
#include "fix_wall_stress_kokkos.h"
#include "pair_linear_coulomb_kokkos.h"
#else
namespace LAMMPS_NS {    // named by the registration, never instantiated without KOKKOS
template <class> class FixDarcyPressureKokkos;
template <class> class FixNVESphereBedKokkos;
template <class> class FixNVESphereTY3Kokkos;
template <class> class FixShearStressKokkos;
template <class> class FixWallStressKokkos;
template <class> class PairLinearCoulombKokkos;
}    // namespace LAMMPS_NS
#endif

#include <cstdio>
#include <list>
#include <string>

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

template <class T> Compute *compute_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}

// LAMMPS keeps the name and info pointers of every registered style: they must outlive
// the plugin's registration, so the composed `/kk` names live here.
std::list<std::string> &style_strings()
{
  static std::list<std::string> strings;
  return strings;
}

const char *kept(const std::string &text)
{
  style_strings().push_back(text);
  return style_strings().back().c_str();
}

struct Registrar {
  void *lmp;
  lammpsplugin_regfunc register_plugin;
  void *handle;

  // `name` builds the CPU class; with KOKKOS `name/kk` the default-device KOKKOS class,
  // `name/kk/device` and `name/kk/host` as in LAMMPS' own KOKKOS package
  template <class Cpu, template <class> class Kokkos_>
  void add_pair(const char *name, const char *info)
  {
    add("pair", name, info, (void *) &pair_creator<Cpu>, false);
#ifdef LMP_KOKKOS
    add_kokkos("pair", name, (void *) &pair_creator<Kokkos_<LMPDeviceType>>,
               (void *) &pair_creator<Kokkos_<LMPHostType>>, false);
#endif
  }
  template <class Cpu, template <class> class Kokkos_>
  void add_fix(const char *name, const char *info)
  {
    add("fix", name, info, (void *) &fix_creator<Cpu>, true);
#ifdef LMP_KOKKOS
    add_kokkos("fix", name, (void *) &fix_creator<Kokkos_<LMPDeviceType>>,
               (void *) &fix_creator<Kokkos_<LMPHostType>>, true);
#endif
  }

  // styles with no per-grain work of their own: the same class serves KOKKOS runs
  template <class Cpu> void add_host_fix(const char *name, const char *info)
  {
    add("fix", name, info, (void *) &fix_creator<Cpu>, true);
  }
  template <class Cpu> void add_host_compute(const char *name, const char *info)
  {
    add("compute", name, info, (void *) &compute_creator<Cpu>, true);
  }

 private:
  void add_kokkos(const char *style, const char *name, void *device, void *host, bool v2)
  {
    const std::string kk = std::string(name) + "/kk", kk_info = std::string(name) + ", KOKKOS";
    add(style, kept(kk), kept(kk_info), device, v2);
    add(style, kept(kk + "/device"), kept(kk_info + " device"), device, v2);
    add(style, kept(kk + "/host"), kept(kk_info + " host"), host, v2);
  }
  void add(const char *style, const char *name, const char *info, void *creator, bool v2)
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

// called by porewater.so once it has checked that this is the LAMMPS the styles were built for
extern "C" void porewater_register_styles(void *lmp, void *handle, void *regfunc)
{
  Registrar r{lmp, (lammpsplugin_regfunc) regfunc, handle};
  r.add_pair<PairLinearCoulomb, PairLinearCoulombKokkos>(
      "linear/coulomb", "linear spring + Coulomb friction contacts, no damping");
  r.add_fix<FixWallStress, FixWallStressKokkos>(
      "wall/stress", "stress-controlled frictionless top wall with mass");
  r.add_fix<FixShearStress, FixShearStressKokkos>(
      "shear/stress", "top layer as a rigid plate driven by a shear stress");
  r.add_fix<FixNVESphereTY3, FixNVESphereTY3Kokkos>(
      "nve/sphere/ty3", "third-order Taylor integrator of finite-size spheres");
  r.add_fix<FixNVESphereBed, FixNVESphereBedKokkos>(
      "nve/sphere/bed", "velocity Verlet of a bed with held base, gravity and floor in one pass");
  r.add_fix<FixDarcyPressure, FixDarcyPressureKokkos>(
      "darcy/pressure", "pore-water pressure on a Darcy grid, force on grains");
  r.add_host_compute<ComputeDarcyGrain>(
      "darcy/grain", "pore pressure and porosity of fix darcy/pressure at each grain");
  r.add_host_compute<ComputeCoordinationOriginal>(
      "coordination/original", "coordination number as the original program counts it");
  r.add_host_fix<FixProgress>(
      "progress", "progress of a long run, finish time, wall-time limit");
  r.add_host_fix<FixPrintEvery>(
      "print/every", "fix print every N steps, never at a run's setup");
}
