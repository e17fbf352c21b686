#!/usr/bin/env bash
# The package under AddressSanitizer + UndefinedBehaviorSanitizer (GCC's, with their leak
# check), against the LAMMPS 29Sep2021 build of scripts/setup.sh: no second LAMMPS.
#
#   bash scripts/sanitize.sh [core|plugin|all]     (default all)
#
#   core    the core and its unit tests in build-sanitize-core, -O1 (what scripts/test.sh runs)
#   plugin  the plugin and its LAMMPS tests in build-sanitize (RelWithDebInfo), then ctest:
#           the single-rank tests, the MPI tests (np 2, 3) and the example's short run; LAMMPS,
#           Kokkos and Open MPI are not instrumented, so lmp and mpirun'd tests run with the
#           sanitizers' runtimes preloaded
# Any report stops its test (halt_on_error) and fails it. The host libraries' own leaks at
# exit are suppressed by name (scripts/sanitize.supp); a leak of the plugin's counts.
# Costs and findings: doc/install.md, "Sanitizers and Kokkos' bounds check".
set -euo pipefail
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=scripts/versions.sh
source "$REPO/scripts/versions.sh"
what=${1:-all}
case $what in core | plugin | all) ;; *) echo "usage: $0 [core|plugin|all]" >&2; exit 2 ;; esac
JOBS=${PW_JOBS:-$(nproc)}
log() { printf '[sanitize %s] %s\n' "$(date +%H:%M:%S)" "$*"; }
export CCACHE_DIR=${CCACHE_DIR:-$PW_CACHE/ccache} CCACHE_BASEDIR=$REPO CCACHE_NOHASHDIR=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_PROC_BIND=false
FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:abort_on_error=0:detect_odr_violation=0:fast_unwind_on_malloc=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$REPO/scripts/sanitize.supp:print_suppressions=0"
start=$(date +%s)

if [ "$what" != plugin ]; then
  log "the core and its unit tests (build-sanitize-core)"
  # -O1 without debug information: 36 s cold on 2 cores against 3.5 min at RelWithDebInfo (the
  # test command's cost); reports name functions from the symbol table
  cmake -S "$REPO" -B "$REPO/build-sanitize-core" -G Ninja -D CMAKE_BUILD_TYPE=None \
    -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D PW_HOSTS=none -D "CMAKE_CXX_FLAGS=-O1 $FLAGS" >/dev/null
  cmake --build "$REPO/build-sanitize-core" -j "$JOBS"
  (cd "$REPO/build-sanitize-core" && ctest --output-on-failure -j "${PW_TEST_JOBS:-2}" -E '^(analysis|pages)\.')
fi

if [ "$what" != core ]; then
  pw_select_host 2021
  [ -x "$LAMMPS_PREFIX/bin/lmp" ] || { echo "run scripts/setup.sh first (no $LAMMPS_PREFIX/bin/lmp)" >&2; exit 1; }
  build="$REPO/build-sanitize"
  log "the plugin and its tests against LAMMPS 29Sep2021 ($build)"
  cmake -S "$REPO" -B "$build" -G Ninja -D CMAKE_BUILD_TYPE=RelWithDebInfo \
    -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D "CMAKE_CXX_FLAGS=$FLAGS" \
    -D LAMMPS_SOURCE_DIR="$LAMMPS_SRC/src" -D LAMMPS_BUILD_DIR="$LAMMPS_BUILD" \
    -D CMAKE_PREFIX_PATH="$LAMMPS_PREFIX" -D "PW_LMP_PACKAGES=GRANULAR;PLUGIN;KOKKOS/OpenMP" \
    -D PW_OTHER_PLUGIN="$REPO/build-2025/plugin/porewater.so" >/dev/null
  cmake --build "$build" -j "$JOBS"
  # lmp, mpirun and the Python-driven checks start processes that are not instrumented: the
  # runtimes first, so that the plugin's instrumented code finds them when it is loaded
  LD_PRELOAD="$(gcc -print-file-name=libasan.so):$(gcc -print-file-name=libubsan.so)"
  export LD_PRELOAD
  # the benchmarks' smoke, the checks that compare timings or other builds and the one that
  # limits lmp's address space (batch.serial_exception: ulimit -v, which the sanitizers'
  # shadow memory cannot live with) are not run; the example's short run is
  (cd "$build" && ctest --output-on-failure -j "${PW_TEST_JOBS:-2}" --timeout 1800 \
    -E '^(bench\.smoke|lammps\.seepage_consolidation|example\.tidal_shear_(continue|beds).*|batch\..*other_host.*|batch\.serial_exception)$')
fi
log "done in $(( $(date +%s) - start )) s"
