#!/usr/bin/env bash
# The GPU kit: the 29Sep2021 host built for one NVIDIA GPU (KOKKOS CUDA + Serial, no MPI: the
# lent machine has no Open MPI of ours) with the plugin, stripped and packed into gpu_kit/
# (ignored by git) for bench/gpu_check.py to run on a lent device machine.
#   scripts/gpu_kit.sh     ~40 min on 2 cores cold (the whole Kokkos-CUDA tree), then seconds
# PW_CUDA_ARCH (default HOPPER90: sm_90, the H100 and H200, by scripts/patches/
# kokkos-hopper90.patch) picks the Kokkos_ARCH_<...>. Kokkos 3.4 refuses at start to run code
# of another major compute capability than the device's, so an sm_80 build does not run there.
# Needs scripts/setup.sh first (sources, patches) and CUDA's nvcc (CUDA_HOME, /usr/local/cuda).
set -euo pipefail
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=scripts/versions.sh
source "$REPO/scripts/versions.sh"
pw_select_host 2021
CUDA_HOME=${CUDA_HOME:-/usr/local/cuda}
ARCH=${PW_CUDA_ARCH:-HOPPER90}
BUILD=$PW_CACHE/build-gpu-kit-$ARCH PREFIX=$PW_CACHE/install-gpu-kit-$ARCH
PLUGIN_BUILD=$REPO/build-gpu-kit KIT=$REPO/gpu_kit
KIT_LIMIT_MIB=56      # a device call carries 64 MiB with the working tree
log() { printf '[gpu-kit %s] %s\n' "$(date +%H:%M:%S)" "$*"; }

[ -x "$CUDA_HOME/bin/nvcc" ] || { echo "no nvcc in $CUDA_HOME: the GPU kit needs CUDA" >&2; exit 1; }
[ -f "$LAMMPS_SRC/.pw-stamp" ] || { echo "no LAMMPS tree in $LAMMPS_SRC: run scripts/setup.sh first" >&2; exit 1; }
export PATH="$CUDA_HOME/bin:$PATH"
export CCACHE_DIR=${CCACHE_DIR:-$PW_CACHE/ccache} CCACHE_BASEDIR=$REPO CCACHE_NOHASHDIR=1
export NVCC_WRAPPER_DEFAULT_COMPILER=${NVCC_WRAPPER_DEFAULT_COMPILER:-g++}
WRAPPER="$LAMMPS_SRC/lib/kokkos/bin/nvcc_wrapper"
JOBS=${PW_JOBS:-$(nproc)}

if [ ! -f "$BUILD/build.ninja" ]; then
  log "configuring LAMMPS (KOKKOS CUDA $ARCH + Serial, serial) in $BUILD"
  pw_configure_lammps "$BUILD" "$PW_CACHE/gpu-kit-configure.log" -D CMAKE_CXX_COMPILER="$WRAPPER" \
    -D CMAKE_INSTALL_PREFIX="$PREFIX" -D BUILD_SHARED_LIBS=on -D BUILD_MPI=off -D BUILD_OMP=off \
    -D LAMMPS_EXCEPTIONS=on -D PKG_KOKKOS=on -D Kokkos_ENABLE_CUDA=on -D Kokkos_ENABLE_SERIAL=on \
    -D "Kokkos_ARCH_$ARCH=on" || exit 1
fi
log "building LAMMPS for $ARCH (~40 min on 2 cores cold; log: $PW_CACHE/gpu-kit-build.log)"
cmake --build "$BUILD" -j "$JOBS" >"$PW_CACHE/gpu-kit-build.log" 2>&1 ||
  { tail -40 "$PW_CACHE/gpu-kit-build.log"; exit 1; }
cmake --install "$BUILD" >"$PW_CACHE/gpu-kit-install.log" 2>&1 ||
  { tail -20 "$PW_CACHE/gpu-kit-install.log"; exit 1; }

if [ ! -f "$PLUGIN_BUILD/build.ninja" ]; then
  cmake -S "$REPO" -B "$PLUGIN_BUILD" -G Ninja -D CMAKE_BUILD_TYPE=Release \
    -D CMAKE_CXX_COMPILER="$WRAPPER" -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D PW_TESTS=OFF \
    -D LAMMPS_SOURCE_DIR="$LAMMPS_SRC/src" -D LAMMPS_BUILD_DIR="$BUILD" \
    -D CMAKE_PREFIX_PATH="$PREFIX" >/dev/null
fi
log "building the plugin for $ARCH in $PLUGIN_BUILD"
cmake --build "$PLUGIN_BUILD" -j "$JOBS"

# the kit: lmp, the shared libraries it loads that a CUDA machine need not have (LAMMPS,
# Kokkos, CUDA's runtime), the plugin; the C and C++ runtimes are the machine's
log "packing $KIT"
rm -rf "$KIT"
mkdir -p "$KIT/bin" "$KIT/lib"
cp "$PREFIX/bin/lmp" "$KIT/bin/"
for lib in $(LD_LIBRARY_PATH="$PREFIX/lib" ldd "$PREFIX/bin/lmp" | awk '$3 ~ "^/" {print $3}'); do
  case $(basename "$lib") in
    libc.so* | libm.so* | libdl.so* | libpthread.so* | librt.so* | ld-linux* | libstdc++* | libgcc_s*) ;;
    *) cp -L "$lib" "$KIT/lib/" ;;
  esac
done
cp "$PLUGIN_BUILD"/plugin/*.so "$KIT/lib/"
# bench/gpu_check.py's Kokkos kernel timer (a profiling hook: no CUDA of its own)
g++ -O2 -shared -fPIC -o "$KIT/lib/kokkos_dispatches.so" "$REPO/bench/kokkos_dispatches.cpp" -ldl
strip --strip-unneeded "$KIT"/bin/lmp "$KIT"/lib/*.so*
printf 'arch %s\nlammps %s\nplugin commit %s\nbuilt %s\n' "$ARCH" "$(basename "$LAMMPS_SRC")" \
  "$(git -C "$REPO" rev-parse --short HEAD)$(git -C "$REPO" diff --quiet || echo +changes)" \
  "$(date -u +%FT%TZ)" >"$KIT/BUILD_INFO"
# carried as one archive: liblammps.so is mostly the kernels' device code, which xz shrinks 6x
tar -C "$REPO" -cf - gpu_kit | xz -T "$JOBS" -6 >"$KIT.tar.xz"
size=$(du -m "$KIT.tar.xz" | cut -f1)
log "$KIT.tar.xz: ${size} MiB ($(ls "$KIT"/lib | tr '\n' ' '))"
[ "$size" -le "$KIT_LIMIT_MIB" ] || { echo "the kit is ${size} MiB, over ${KIT_LIMIT_MIB}" >&2; exit 1; }
