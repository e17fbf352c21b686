# Source this file to run our LAMMPS with the plugin:  source scripts/env.sh
# (the 2021 host; PW_LAMMPS=2025 source scripts/env.sh for the 4Feb2025 one).
# Puts that host's lmp on PATH and its plugin directory on LD_LIBRARY_PATH, so that an input's
#   plugin load porewater.so
# resolves from any folder (dlopen searches LD_LIBRARY_PATH; 29Sep2021 has no auto-load).
_pw_repo=$(cd "$(dirname "${BASH_SOURCE[0]:-$0}")/.." && pwd)
# shellcheck source=scripts/versions.sh
source "$_pw_repo/scripts/versions.sh"
if [ "$PW_LAMMPS" = both ]; then
  echo "scripts/env.sh uses one host: PW_LAMMPS=2021 or PW_LAMMPS=2025" >&2
else
  pw_select_host "$PW_LAMMPS" && _pw_plugin_dir="$_pw_repo/$PW_BUILD_NAME/plugin" &&
    export PATH="$LAMMPS_PREFIX/bin:$PATH" &&
    export LD_LIBRARY_PATH="$_pw_plugin_dir:$LAMMPS_PREFIX/lib:${LD_LIBRARY_PATH:-}" &&
    export PW_PLUGIN="$_pw_plugin_dir/porewater.so"
fi
# where the LIGGGHTS host is built, its `liggghts` (Debian's LIGGGHTS with our styles) comes
# first on PATH, before Debian's /usr/bin/liggghts
if [ -x "$_pw_repo/build-liggghts/bin/liggghts" ]; then
  export PATH="$_pw_repo/build-liggghts/bin:$PATH"
fi
# the analysis package (analysis/README.md): python3 -m porewater_analysis RUN_DIR
export PYTHONPATH="$_pw_repo/analysis${PYTHONPATH:+:$PYTHONPATH}"
export OMP_PROC_BIND=${OMP_PROC_BIND:-spread} OMP_PLACES=${OMP_PLACES:-threads}
unset _pw_repo _pw_plugin_dir
