// The `liggghts` executable of this package: LIGGGHTS' own main() (same command line, MPI
// set-up and signal handlers) with the package's styles added before the input is read.
#ifndef PW_LIGGGHTS_LAUNCHER_H
#define PW_LIGGGHTS_LAUNCHER_H

#include "style_registry.h"

namespace porewater_liggghts {

// Runs like `liggghts` (Debian's /usr/bin/liggghts, i.e. LIGGGHTS' src/main.cpp) with the
// styles of `fn` installed. Returns the process exit status.
int run_launcher(int argc, char **argv, RegisterFunction fn);

}    // namespace porewater_liggghts

#endif
