#!/usr/bin/env bash
# The test command: set up (packages, LAMMPS, plugin, LIGGGHTS launcher), compile-check the
# KOKKOS sources for CUDA, then run every test with ctest. PW_HOSTS (default
# "lammps liggghts") selects the host layers, as for setup.sh.
set -euo pipefail
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
start=$(date +%s)
export PW_HOSTS=${PW_HOSTS:-lammps liggghts}
hosts=" ${PW_HOSTS//;/ } "
[ "${PW_LIGGGHTS:-0}" = 1 ] && hosts="$hosts liggghts "
bash "$REPO/scripts/setup.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
if [[ $hosts == *" lammps "* ]]; then
  bash "$REPO/scripts/cuda_check.sh"
  (cd "$REPO/build" && ctest --output-on-failure -j "${PW_TEST_JOBS:-2}" --timeout 900)
fi
if [[ $hosts == *" liggghts "* ]]; then
  # the unit tests ran in build/ already when the LAMMPS host was tested
  only=(); [[ $hosts == *" lammps "* ]] && only=(-L liggghts)
  cmake --build "$REPO/build-liggghts" -j "${PW_JOBS:-$(nproc)}"
  (cd "$REPO/build-liggghts" && ctest "${only[@]}" --output-on-failure -j "${PW_TEST_JOBS:-2}" --timeout 900)
fi
echo "test command took $(( $(date +%s) - start )) s"
