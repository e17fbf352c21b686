// porewater.so, what `plugin load porewater.so` opens: it checks that the running LAMMPS is
// the one the styles were built for, and only then opens the styles (porewater_styles.so,
// next to this file) and lets them register. This file uses LAMMPS' C library interface
// alone (lammps_version, lammps_command: the same on every LAMMPS with plugins), so it loads
// into any LAMMPS: the styles, compiled against one LAMMPS' C++ classes, would not even open
// in another (an undefined symbol at dlopen, or a crash at the first changed class), and
// LAMMPS' loader would report no more than the symbol's mangled name.

#include "library.h"

#include <cstdio>
#include <cstring>
#include <dlfcn.h>

namespace {

const char *const STYLES_FILE = "porewater_styles.so";

// says why no style was registered: on stderr (rank 0), and on LAMMPS' screen and in its log
void refuse(void *lmp, const char *why)
{
  if (lammps_extract_setting(lmp, "world_rank") == 0) {
    std::fprintf(stderr, "ERROR: %s\n", why);
    std::fflush(stderr);
  }
  char command[2048];
  std::snprintf(command, sizeof(command), "print \"ERROR: %s\"", why);
  for (char *c = command + 7; c[1]; c++)    // the message inside the quotes has none
    if (*c == '"') *c = '\'';
  lammps_command(lmp, command);
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  char why[1536];
  const int running = lammps_version(lmp);
  if (running != PW_LAMMPS_VERSION_NUMBER) {
    std::snprintf(why, sizeof(why),
                  "porewater.so was built for LAMMPS version %d, this LAMMPS is %d: no styles "
                  "registered; build the plugin against this LAMMPS (README, \"Building the "
                  "plugin yourself\")",
                  PW_LAMMPS_VERSION_NUMBER, running);
    refuse(lmp, why);
    return;
  }
  // the styles' file in this file's folder
  Dl_info self;
  char path[1024] = "";
  if (dladdr((void *) &lammpsplugin_init, &self) && self.dli_fname) {
    const char *slash = std::strrchr(self.dli_fname, '/');
    const int folder = slash ? (int) (slash - self.dli_fname + 1) : 0;
    std::snprintf(path, sizeof(path), "%.*s%s", folder, self.dli_fname, STYLES_FILE);
  }
  void *styles = path[0] ? dlopen(path, RTLD_NOW | RTLD_GLOBAL) : nullptr;
  if (!styles) {
    std::snprintf(why, sizeof(why), "porewater.so: cannot open %s (it belongs next to "
                  "porewater.so): %s", path[0] ? path : STYLES_FILE, dlerror());
    refuse(lmp, why);
    return;
  }
  typedef void register_styles_t(void *, void *, void *);
  auto *register_styles = (register_styles_t *) dlsym(styles, "porewater_register_styles");
  if (!register_styles) {
    std::snprintf(why, sizeof(why), "porewater.so: %s has no porewater_register_styles", path);
    refuse(lmp, why);
    return;
  }
  register_styles(lmp, handle, regfunc);
}
