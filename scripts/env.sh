# Source this file to run our LAMMPS with the plugin:  source scripts/env.sh
# Puts our lmp on PATH and the plugin directory on LD_LIBRARY_PATH, so that an input's
#   plugin load porewater.so
# resolves from any folder (dlopen searches LD_LIBRARY_PATH; this LAMMPS has no auto-load).
# Where the LIGGGHTS host is built, its `liggghts` (Debian's LIGGGHTS with our styles)
# comes first on PATH, before Debian's /usr/bin/liggghts.
_pw_repo=$(cd "$(dirname "${BASH_SOURCE[0]:-$0}")/.." && pwd)
# shellcheck source=scripts/versions.sh
source "$_pw_repo/scripts/versions.sh"
export PATH="$LAMMPS_PREFIX/bin:$PATH"
if [ -x "$_pw_repo/build-liggghts/bin/liggghts" ]; then
  export PATH="$_pw_repo/build-liggghts/bin:$PATH"
fi
export LD_LIBRARY_PATH="$_pw_repo/build/plugin:$LAMMPS_PREFIX/lib:${LD_LIBRARY_PATH:-}"
export PW_PLUGIN="$_pw_repo/build/plugin/porewater.so"
export OMP_PROC_BIND=${OMP_PROC_BIND:-spread} OMP_PLACES=${OMP_PLACES:-threads}
unset _pw_repo
