#!/usr/bin/env bash
# The /kk styles under Kokkos' bounds check: LAMMPS 29Sep2021 with Kokkos 3.4 configured as
# scripts/setup.sh does (KOKKOS OpenMP + Serial, MPI, shared) plus
# Kokkos_ENABLE_DEBUG_BOUNDS_CHECK, in a build of its own ($PW_CACHE/build-bounds, installed
# in $PW_CACHE/install-bounds); the plugin and its tests against it (build-bounds); then the
# tests of the /kk styles (every test named *Kokkos*, on one rank, and the MPI tests on 2 and
# 3 ranks, whose Kokkos*Mpi* ones run -sf kk) and the example with -sf kk for 2,000 steps.
# An access outside a View's extents aborts with Kokkos' message, naming the View.
#
#   bash scripts/kokkos_bounds_check.sh
#
# Needs scripts/setup.sh first (the unpacked, patched tree). Costs and findings:
# doc/install.md, "Sanitizers and Kokkos' bounds check".
set -euo pipefail
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=scripts/versions.sh
source "$REPO/scripts/versions.sh"
pw_select_host 2021
JOBS=${PW_JOBS:-$(nproc)}
log() { printf '[bounds %s] %s\n' "$(date +%H:%M:%S)" "$*"; }
[ -f "$LAMMPS_SRC/src/lammps.h" ] || { echo "run scripts/setup.sh first (no $LAMMPS_SRC)" >&2; exit 1; }
export CCACHE_DIR=${CCACHE_DIR:-$PW_CACHE/ccache} CCACHE_BASEDIR=$REPO CCACHE_NOHASHDIR=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_PROC_BIND=false
BUILD=$PW_CACHE/build-bounds PREFIX=$PW_CACHE/install-bounds
start=$(date +%s)

if [ ! -f "$BUILD/build.ninja" ]; then
  log "configuring LAMMPS 29Sep2021 with Kokkos' bounds check in $BUILD"
  pw_configure_lammps "$BUILD" "$PW_CACHE/bounds-configure.log" \
    -D CMAKE_INSTALL_PREFIX="$PREFIX" -D LAMMPS_INSTALL_RPATH=on -D BUILD_SHARED_LIBS=on \
    -D BUILD_MPI=on -D BUILD_OMP=on -D LAMMPS_EXCEPTIONS=on -D PKG_KOKKOS=on \
    -D Kokkos_ENABLE_SERIAL=on -D Kokkos_ENABLE_OPENMP=on -D Kokkos_ENABLE_DEBUG_BOUNDS_CHECK=on
fi
log "building it (cold ~15 min on 2 cores)"
cmake --build "$BUILD" -j "$JOBS" >"$PW_CACHE/bounds-build.log" 2>&1 ||
  { tail -40 "$PW_CACHE/bounds-build.log"; exit 1; }
cmake --install "$BUILD" >"$PW_CACHE/bounds-install.log" 2>&1 ||
  { tail -20 "$PW_CACHE/bounds-install.log"; exit 1; }
grep -q "define KOKKOS_ENABLE_DEBUG_BOUNDS_CHECK" "$BUILD"/lib/kokkos/KokkosCore_config.h ||
  { echo "the Kokkos build in $BUILD has no bounds check" >&2; exit 1; }

build="$REPO/build-bounds"
log "the plugin and its tests against it ($build)"
cmake -S "$REPO" -B "$build" -G Ninja -D CMAKE_BUILD_TYPE=Release \
  -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D LAMMPS_SOURCE_DIR="$LAMMPS_SRC/src" \
  -D LAMMPS_BUILD_DIR="$BUILD" -D CMAKE_PREFIX_PATH="$PREFIX" \
  -D "PW_LMP_PACKAGES=GRANULAR;PLUGIN;KOKKOS/OpenMP" >/dev/null
cmake --build "$build" -j "$JOBS"
(cd "$build" && ctest --output-on-failure -j "${PW_TEST_JOBS:-2}" --timeout 1800 \
  -R '(Kokkos|^lammps\..*\.np[23]$)')

log "the example with -sf kk, 2,000 steps"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$REPO"/examples/tidal_shear/in.* "$REPO"/examples/tidal_shear/consolidated_0.data "$work"/
(cd "$work" && LD_LIBRARY_PATH="$build/plugin:${LD_LIBRARY_PATH:-}" \
  "$BUILD/lmp" -in in.tidal_shear -var run_steps 2000 -k on t 1 -sf kk -log none \
  -screen log.kk >/dev/null) || { tail -30 "$work/log.kk"; exit 1; }
log "done in $(( $(date +%s) - start )) s"
