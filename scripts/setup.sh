#!/usr/bin/env bash
# Sets up everything the package needs on a Debian bookworm machine and builds it:
#   1. apt packages (compilers, cmake, ninja, ccache, Open MPI, googletest, numpy/matplotlib)
#   2. LAMMPS 29Sep2021 update 2 and Kokkos 3.4.01 (from trilinos 13.2.0) as Debian source
#      packages, sha256-checked, cached outside the repo
#   3. our own LAMMPS (GRANULAR, PLUGIN, KOKKOS OpenMP+Serial, MPI, shared), installed into
#      the cache prefix
#   4. the plugin (this repo) in ./build
#   5. LIGGGHTS host (if selected): Debian's liggghts + libliggghts-dev, and our `liggghts`
#      launcher in ./build-liggghts (LIGGGHTS itself is not rebuilt)
# Re-running on a ready machine only re-runs the incremental builds (seconds).
#
# Environment: PW_HOSTS (host layers: "lammps" (default), "liggghts", "lammps liggghts"),
#   PW_LIGGGHTS=1 (adds liggghts to PW_HOSTS), PW_CACHE (default ~/.cache/lammps-porewater),
#   PW_JOBS (default nproc).
set -euo pipefail

REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=scripts/versions.sh
source "$REPO/scripts/versions.sh"
JOBS=${PW_JOBS:-$(nproc)}
HOSTS=" ${PW_HOSTS:-lammps} "
HOSTS=${HOSTS//;/ }
[ "${PW_LIGGGHTS:-0}" = 1 ] && HOSTS="$HOSTS liggghts "
has_host() { [[ $HOSTS == *" $1 "* ]]; }
for h in $HOSTS; do
  case $h in none|lammps|liggghts) ;; *) echo "PW_HOSTS: unknown host '$h' (lammps, liggghts)" >&2; exit 1 ;; esac
done

log() { printf '[setup %s] %s\n' "$(date +%H:%M:%S)" "$*"; }
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"

# ---- 1. system packages -------------------------------------------------------------
APT_PACKAGES=(build-essential cmake ninja-build ccache pkg-config xz-utils dpkg-dev
  libopenmpi-dev openmpi-bin googletest libgtest-dev python3 python3-numpy python3-matplotlib)
# LIGGGHTS-PUBLIC 3.8.0 (bookworm: 3.8.0+repack1-9+b2): the library, headers and stock binary
has_host liggghts && APT_PACKAGES+=(liggghts libliggghts-dev)
missing=()
for p in "${APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
SRC_LIST=/etc/apt/sources.list.d/lammps-porewater-src.sources
need_update=0
if ! grep -rqs "deb-src\|Types: *deb-src" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  log "adding a deb-src entry for bookworm ($SRC_LIST)"
  printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' |
    $SUDO tee "$SRC_LIST" >/dev/null
  need_update=1
fi
if [ ${#missing[@]} -gt 0 ] || [ $need_update -eq 1 ]; then
  log "apt-get update"
  $SUDO apt-get update -q
fi
if [ ${#missing[@]} -gt 0 ]; then
  log "installing: ${missing[*]}"
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

export CCACHE_DIR=${CCACHE_DIR:-$PW_CACHE/ccache}
# paths relative to the clone, so a fresh clone elsewhere (CI) still hits the cache
export CCACHE_BASEDIR=$REPO CCACHE_NOHASHDIR=1

# ---- 5. the LIGGGHTS host (run after the plugin, or alone) ---------------------------------
liggghts_host() {
  log "LIGGGHTS: libliggghts-dev $(dpkg-query -W -f='${Version}' libliggghts-dev)"
  if [ ! -f "$REPO/build-liggghts/build.ninja" ]; then
    cmake -S "$REPO" -B "$REPO/build-liggghts" -G Ninja -D CMAKE_BUILD_TYPE=Release \
      -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D PW_HOSTS=liggghts >/dev/null
  fi
  log "building the LIGGGHTS launcher (its tests: scripts/test.sh)"
  cmake --build "$REPO/build-liggghts" -j "$JOBS" --target liggghts
}
if ! has_host lammps; then
  if has_host liggghts; then
    liggghts_host
    log "done: source $REPO/scripts/env.sh, then liggghts -in <input>"
  fi
  exit 0
fi

# ---- 2. sources ------------------------------------------------------------------------
mkdir -p "$PW_CACHE/src"
verify() { echo "$2  $PW_CACHE/src/$1" | sha256sum -c --quiet - 2>/dev/null; }
fetch() { # fetch PKG=VERSION FILE SHA256
  if ! verify "$2" "$3"; then
    log "downloading source package $1"
    (cd "$PW_CACHE/src" && apt-get source --download-only -q "$1")
    verify "$2" "$3" || { echo "sha256 mismatch for $2" >&2; exit 1; }
  fi
}
fetch "lammps=$LAMMPS_DEB_VERSION" "$LAMMPS_TARBALL" "$LAMMPS_SHA256"
fetch "trilinos=$TRILINOS_DEB_VERSION" "$TRILINOS_TARBALL" "$TRILINOS_SHA256"

# The unpacked tree is keyed by the tarballs and our patches: a changed patch re-unpacks.
stamp=$(cat "$REPO"/scripts/versions.sh "$REPO"/scripts/patches/*.patch | sha256sum | cut -c1-16)
if [ "$(cat "$LAMMPS_SRC/.pw-stamp" 2>/dev/null)" != "$stamp" ]; then
  log "unpacking LAMMPS and Kokkos into $LAMMPS_SRC"
  rm -rf "$LAMMPS_SRC" "$PW_CACHE/unpack"
  mkdir -p "$PW_CACHE/unpack"
  tar -xf "$PW_CACHE/src/$LAMMPS_TARBALL" -C "$PW_CACHE/unpack"
  mv "$PW_CACHE/unpack"/lammps-* "$LAMMPS_SRC"
  tar -xzf "$PW_CACHE/src/$TRILINOS_TARBALL" -C "$PW_CACHE/unpack" --wildcards '*/packages/kokkos/*'
  mv "$PW_CACHE/unpack"/Trilinos-*/packages/kokkos "$LAMMPS_SRC/lib/kokkos"
  rm -rf "$PW_CACHE/unpack"
  for p in "$REPO"/scripts/patches/*.patch; do
    log "applying $(basename "$p")"
    patch -d "$LAMMPS_SRC" -p1 --forward --quiet < "$p"
  done
  # the build dir stays: ninja recompiles the fresh tree through ccache
  echo "$stamp" > "$LAMMPS_SRC/.pw-stamp"
fi

# ---- 3. LAMMPS -------------------------------------------------------------------------
ccache --max-size=5G >/dev/null
if [ ! -f "$LAMMPS_BUILD/build.ninja" ]; then
  log "configuring LAMMPS in $LAMMPS_BUILD"
  cmake -S "$LAMMPS_SRC/cmake" -B "$LAMMPS_BUILD" -G Ninja \
    -D CMAKE_BUILD_TYPE=Release -D CMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -D CMAKE_INSTALL_PREFIX="$LAMMPS_PREFIX" -D LAMMPS_INSTALL_RPATH=on \
    -D BUILD_SHARED_LIBS=on -D BUILD_MPI=on -D BUILD_OMP=on -D LAMMPS_EXCEPTIONS=on \
    -D PKG_GRANULAR=on -D PKG_PLUGIN=on -D PKG_KOKKOS=on \
    -D Kokkos_ENABLE_SERIAL=on -D Kokkos_ENABLE_OPENMP=on \
    -D WITH_JPEG=off -D WITH_PNG=off -D WITH_FFMPEG=off >"$PW_CACHE/lammps-configure.log" 2>&1 ||
    { tail -30 "$PW_CACHE/lammps-configure.log"; exit 1; }
fi
log "building LAMMPS (cold: ~10 min on 2 cores; warm: seconds)"
cmake --build "$LAMMPS_BUILD" -j "$JOBS" >"$PW_CACHE/lammps-build.log" 2>&1 ||
  { tail -40 "$PW_CACHE/lammps-build.log"; exit 1; }
cmake --install "$LAMMPS_BUILD" >"$PW_CACHE/lammps-install.log" 2>&1 ||
  { tail -20 "$PW_CACHE/lammps-install.log"; exit 1; }

# ---- 4. the plugin ---------------------------------------------------------------------
if [ ! -f "$REPO/build/build.ninja" ]; then
  cmake -S "$REPO" -B "$REPO/build" -G Ninja -D CMAKE_BUILD_TYPE=Release \
    -D CMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -D LAMMPS_SOURCE_DIR="$LAMMPS_SRC/src" -D LAMMPS_BUILD_DIR="$LAMMPS_BUILD" \
    -D CMAKE_PREFIX_PATH="$LAMMPS_PREFIX" >/dev/null
fi
log "building the plugin"
cmake --build "$REPO/build" -j "$JOBS"
if has_host liggghts; then
  liggghts_host
  log "done: source $REPO/scripts/env.sh, then lmp -in <input> or liggghts -in <input>"
else
  log "done: source $REPO/scripts/env.sh, then lmp -in <input>"
fi
