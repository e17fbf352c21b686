#!/usr/bin/env bash
# CUDA build of the KOKKOS sources with nvcc (no GPU needed: compile only).
#   scripts/cuda_check.sh          configure a Kokkos-CUDA LAMMPS tree (seconds) and compile
#                                  our *_kokkos.cpp against it with nvcc_wrapper
#   scripts/cuda_check.sh --full   also build that whole LAMMPS tree (~20 min on 2 cores)
# Needs scripts/setup.sh first (sources, patches). CUDA_HOME defaults to /usr/local/cuda.
set -euo pipefail
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=scripts/versions.sh
source "$REPO/scripts/versions.sh"
CUDA_HOME=${CUDA_HOME:-/usr/local/cuda}
# Kokkos_ARCH_<...>: the check compiles for AMPERE80 (sm_80); the GPU kit builds for HOPPER90
# (sm_90, scripts/patches/kokkos-hopper90.patch; scripts/gpu_kit.sh)
CUDA_ARCH=${PW_CUDA_ARCH:-AMPERE80}
log() { printf '[cuda %s] %s\n' "$(date +%H:%M:%S)" "$*"; }

if [ ! -x "$CUDA_HOME/bin/nvcc" ]; then
  if [ "${CI:-}" = "true" ] || [ "${PW_REQUIRE_CUDA:-0}" = "1" ]; then
    echo "nvcc not found in $CUDA_HOME: the CUDA compile check cannot run" >&2; exit 1
  fi
  log "no nvcc in $CUDA_HOME: skipping the CUDA compile check"; exit 0
fi
export PATH="$CUDA_HOME/bin:$PATH"
export CCACHE_DIR=${CCACHE_DIR:-$PW_CACHE/ccache} CCACHE_BASEDIR=$REPO CCACHE_NOHASHDIR=1
WRAPPER="$LAMMPS_SRC/lib/kokkos/bin/nvcc_wrapper"
export NVCC_WRAPPER_DEFAULT_COMPILER=${NVCC_WRAPPER_DEFAULT_COMPILER:-g++}

if [ ! -f "$LAMMPS_CUDA_BUILD/build.ninja" ]; then
  log "configuring the Kokkos-CUDA LAMMPS tree in $LAMMPS_CUDA_BUILD"
  pw_configure_lammps "$LAMMPS_CUDA_BUILD" "$PW_CACHE/cuda-configure.log" \
    -D CMAKE_CXX_COMPILER="$WRAPPER" -D BUILD_SHARED_LIBS=on -D BUILD_MPI=on -D BUILD_OMP=off \
    -D LAMMPS_EXCEPTIONS=on -D PKG_KOKKOS=on -D Kokkos_ENABLE_CUDA=on -D Kokkos_ENABLE_SERIAL=on \
    -D "Kokkos_ARCH_$CUDA_ARCH=on" || exit 1
fi

if [ "${1:-}" = "--full" ]; then
  log "building the whole Kokkos-CUDA LAMMPS tree (~20 min on 2 cores cold)"
  cmake --build "$LAMMPS_CUDA_BUILD" -j "${PW_JOBS:-$(nproc)}"
fi

log "compiling the package's KOKKOS sources with nvcc_wrapper"
if [ ! -f "$REPO/build-cuda/build.ninja" ]; then
  cmake -S "$REPO" -B "$REPO/build-cuda" -G Ninja -D CMAKE_BUILD_TYPE=Release \
    -D CMAKE_CXX_COMPILER="$WRAPPER" -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D PW_CUDA_CHECK=ON -D PW_TESTS=OFF \
    -D LAMMPS_SOURCE_DIR="$LAMMPS_SRC/src" -D LAMMPS_BUILD_DIR="$LAMMPS_CUDA_BUILD" >/dev/null
fi
cmake --build "$REPO/build-cuda" -j "${PW_JOBS:-$(nproc)}"
log "CUDA compile check passed"
