#!/usr/bin/env bash
# The test command: set up every host (packages; LAMMPS 29Sep2021 and 4Feb2025 with the
# plugin for each; Debian's LIGGGHTS with our launcher), compile-check the KOKKOS sources for
# CUDA, then run the tests with ctest on each host. PW_HOSTS (default "lammps liggghts") and
# PW_LAMMPS (default both) narrow it, as for setup.sh.
set -euo pipefail
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export PW_LAMMPS=${PW_LAMMPS:-both}
export PW_HOSTS=${PW_HOSTS:-lammps liggghts}
# shellcheck source=scripts/versions.sh
source "$REPO/scripts/versions.sh"
layers=" ${PW_HOSTS//;/ } "
[ "${PW_LIGGGHTS:-0}" = 1 ] && layers="$layers liggghts "
start=$(date +%s)
bash "$REPO/scripts/setup.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# the core alone, as on a machine without any host (PW_HOSTS=none): it builds and its tests pass
echo "== the core without a host ($REPO/build-core)"
cmake -S "$REPO" -B "$REPO/build-core" -G Ninja -D CMAKE_BUILD_TYPE=Release \
  -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D PW_HOSTS=none >/dev/null
cmake --build "$REPO/build-core" -j "${PW_JOBS:-$(nproc)}"
(cd "$REPO/build-core" && ctest --output-on-failure -j "${PW_TEST_JOBS:-2}" --timeout 900)
# the core's tests again under AddressSanitizer + UndefinedBehaviorSanitizer (seconds; the
# plugin's sanitizer run and Kokkos' bounds check are scripts of their own: doc/install.md)
bash "$REPO/scripts/sanitize.sh" core
if [[ $layers == *" lammps "* ]]; then
  for host in $(pw_hosts); do
    pw_select_host "$host"
    [ "$host" = 2021 ] && bash "$REPO/scripts/cuda_check.sh"
    echo "== ctest on LAMMPS $host ($REPO/$PW_BUILD_NAME)"
    (cd "$REPO/$PW_BUILD_NAME" && ctest --output-on-failure -j "${PW_TEST_JOBS:-2}" --timeout 900)
  done
fi
if [[ $layers == *" liggghts "* ]]; then
  # the unit tests ran already where a LAMMPS host was tested
  only=(); [[ $layers == *" lammps "* ]] && only=(-L liggghts)
  cmake --build "$REPO/build-liggghts" -j "${PW_JOBS:-$(nproc)}"
  echo "== ctest on LIGGGHTS ($REPO/build-liggghts)"
  (cd "$REPO/build-liggghts" && ctest "${only[@]}" --output-on-failure -j "${PW_TEST_JOBS:-2}" --timeout 900)
fi
echo "test command took $(( $(date +%s) - start )) s"
