# Pinned third-party sources and where they live; sourced by setup.sh, env.sh, cuda_*.sh.
# Two LAMMPS hosts, both built from Debian source packages:
#   2021  LAMMPS 29Sep2021 update 2 (bookworm) + Kokkos 3.4.01 (trilinos): GRANULAR, PLUGIN,
#         KOKKOS (OpenMP + Serial); our patches in scripts/patches/*.patch
#   2025  LAMMPS 4Feb2025 (trixie): GRANULAR, PLUGIN, OPENMP. CPU only: Debian's tarball has
#         no lib/kokkos and no Kokkos 4 exists for bookworm; patches in scripts/patches/2025/
# PW_LAMMPS=2021|2025|both picks the host(s) setup.sh builds and env.sh uses (default 2021).
LAMMPS2021_DEB_VERSION=20220106.git7586adbb6a+ds1-2   # LAMMPS 29Sep2021 update 2
LAMMPS2021_TARBALL=lammps_20220106.git7586adbb6a+ds1.orig.tar.xz
LAMMPS2021_SHA256=65146c615ad24d8b8bc64f4e05e86226a7f1fdb45c0b5ea9416562b9f3863082
TRILINOS_DEB_VERSION=13.2.0-4                        # packages/kokkos is Kokkos 3.4.01
TRILINOS_TARBALL=trilinos_13.2.0.orig.tar.gz
TRILINOS_SHA256=0ddb47784ba7b8a6b9a07a4822b33be508feb4ccd54301b2a5d10c9e54524b90
LAMMPS2025_DEB_VERSION=20250204+dfsg.1-2             # LAMMPS 4Feb2025 (132,367,436 bytes)
LAMMPS2025_TARBALL=lammps_20250204+dfsg.1.orig.tar.xz
LAMMPS2025_SHA256=3671165bd52fad36734e0a9136c5bc5ecb225e03988f8c89aa13366a8b53b1c7
# the Debian suites whose deb-src entries setup.sh uses (bookworm: 2021 and trilinos)
PW_SOURCE_SUITES="bookworm trixie"

PW_CACHE=${PW_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/lammps-porewater}
PW_LAMMPS=${PW_LAMMPS:-2021}
LAMMPS_CUDA_BUILD=$PW_CACHE/build-cuda   # the 2021 tree configured for Kokkos-CUDA

# pw_hosts: the hosts PW_LAMMPS names, one word each
pw_hosts() {
  case $PW_LAMMPS in
    2021 | 2025) echo "$PW_LAMMPS" ;;
    both) echo "2021 2025" ;;
    *) echo "PW_LAMMPS must be 2021, 2025 or both, not '$PW_LAMMPS'" >&2; return 1 ;;
  esac
}

# pw_select_host 2021|2025: sets PW_HOST, LAMMPS_SRC (unpacked tree), LAMMPS_BUILD,
# LAMMPS_PREFIX (its install) and PW_BUILD_NAME (the plugin's build folder in the repo)
pw_select_host() {
  case $1 in
    2021)
      LAMMPS_SRC=$PW_CACHE/lammps-29Sep2021u2 LAMMPS_BUILD=$PW_CACHE/build-host
      LAMMPS_PREFIX=$PW_CACHE/install PW_BUILD_NAME=build ;;
    2025)
      LAMMPS_SRC=$PW_CACHE/lammps-4Feb2025 LAMMPS_BUILD=$PW_CACHE/build-host-2025
      LAMMPS_PREFIX=$PW_CACHE/install-2025 PW_BUILD_NAME=build-2025 ;;
    *) echo "no LAMMPS host '$1' (2021 or 2025)" >&2; return 1 ;;
  esac
  PW_HOST=$1
}
pw_select_host 2021   # cuda_check.sh and the KOKKOS sources use the 2021 tree

# pw_configure_lammps BUILD LOG [CMAKE ARGS...]: the LAMMPS tree in $LAMMPS_SRC configured in
# BUILD with what every build of it here shares (Ninja, Release, ccache, GRANULAR and PLUGIN,
# no image or movie libraries) and the given arguments; CMake's output in LOG, its tail shown
# when it fails
pw_configure_lammps() {
  local build=$1 log=$2
  shift 2
  cmake -S "$LAMMPS_SRC/cmake" -B "$build" -G Ninja -D CMAKE_BUILD_TYPE=Release \
    -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D PKG_GRANULAR=on -D PKG_PLUGIN=on \
    -D WITH_JPEG=off -D WITH_PNG=off -D WITH_FFMPEG=off "$@" >"$log" 2>&1 ||
    { tail -30 "$log"; return 1; }
}
