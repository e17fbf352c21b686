#!/usr/bin/env bash
# Sets up everything the package needs on a Debian bookworm machine and builds it:
#   1. apt packages (compilers, cmake, ninja, ccache, Open MPI, googletest, numpy/matplotlib)
#   2. the LAMMPS source packages of the chosen host(s) (scripts/versions.sh), sha256-checked,
#      cached outside the repo: 2021 = LAMMPS 29Sep2021 update 2 + Kokkos 3.4.01 (from
#      trilinos 13.2.0), 2025 = LAMMPS 4Feb2025
#   3. our own LAMMPS per host (GRANULAR, PLUGIN, MPI, shared; 2021 with KOKKOS OpenMP+Serial,
#      2025 with OPENMP), installed into the cache
#   4. the plugin (this repo) per host: ./build (2021), ./build-2025 (2025)
#   5. the LIGGGHTS host (if selected): Debian's liggghts + libliggghts-dev, and our
#      `liggghts` launcher in ./build-liggghts (LIGGGHTS itself is not rebuilt)
# Re-running on a ready machine only re-runs the incremental builds (seconds).
#
# Environment: PW_HOSTS (host layers: "lammps" (default), "liggghts", "lammps liggghts");
# PW_LIGGGHTS=1 adds liggghts; PW_LAMMPS (the LAMMPS versions of the lammps layer: 2021 |
# 2025 | both; default 2021), PW_CACHE (default ~/.cache/lammps-porewater), PW_JOBS (default
# nproc), PW_DEBIAN_URI (the Debian archive to fetch sources from; default: the one this
# machine's apt sources use).
set -euo pipefail

REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=scripts/versions.sh
source "$REPO/scripts/versions.sh"
JOBS=${PW_JOBS:-$(nproc)}
LAYERS=" ${PW_HOSTS:-lammps} "
LAYERS=${LAYERS//;/ }
[ "${PW_LIGGGHTS:-0}" = 1 ] && LAYERS="$LAYERS liggghts "
has_layer() { [[ $LAYERS == *" $1 "* ]]; }
for h in $LAYERS; do
  case $h in none|lammps|liggghts) ;; *) echo "PW_HOSTS: unknown host layer '$h' (lammps, liggghts)" >&2; exit 1 ;; esac
done
HOSTS=""
has_layer lammps && HOSTS=$(pw_hosts)

log() { printf '[setup %s] %s\n' "$(date +%H:%M:%S)" "$*"; }
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"

# ---- 1. system packages -------------------------------------------------------------
APT_PACKAGES=(build-essential cmake ninja-build ccache pkg-config xz-utils dpkg-dev
  libopenmpi-dev openmpi-bin googletest libgtest-dev python3 python3-numpy python3-scipy python3-matplotlib)
# LIGGGHTS-PUBLIC 3.8.0 (bookworm: 3.8.0+repack1-9+b2): the library, headers and stock binary
has_layer liggghts && APT_PACKAGES+=(liggghts libliggghts-dev)
missing=()
for p in "${APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  log "installing: ${missing[*]}"
  $SUDO apt-get update -q
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# ---- 2. sources ------------------------------------------------------------------------
# Source packages come through a private APT setup in $PW_CACHE/apt: deb-src entries (only)
# for the suites of our pins, on the Debian archive this machine's apt already uses. The
# system's own sources, lists and binary packages are left exactly as they are.
PW_APT=$PW_CACHE/apt
APT_PRIVATE=(-o Dir::Etc::SourceList=/dev/null -o "Dir::Etc::SourceParts=$PW_APT/sources.list.d"
  -o "Dir::State::Lists=$PW_APT/lists" -o "Dir::Cache=$PW_APT/cache"
  -o "APT::Sandbox::User=$(id -un)")

# The archives (URI and Signed-By keyring, tab-separated) of the enabled binary entries for
# this release's own suite with component main, in deb822 *.sources or one-line *.list.
debian_archives() {
  local codename
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
  [ -n "$codename" ] || return 1
  {
    for f in /etc/apt/sources.list.d/*.sources; do [ -f "$f" ] && { cat "$f"; echo; }; done
  } | awk -v want="$codename" '
    function has(list, w) { return (" " list " ") ~ (" " w " ") }
    function flush() {
      if (has(types, "deb") && has(suites, want) && has(comps, "main") &&
          tolower(enabled) != "no" && uris != "") {
        split(uris, u, " "); print u[1] "\t" signed
      }
      types = suites = comps = uris = signed = enabled = ""; key = ""
    }
    /^#/ { next }
    /^[ \t]*$/ { flush(); next }
    /^[ \t]/ { if (key == "uris") uris = uris " " $1; next }
    {
      key = tolower(substr($0, 1, index($0, ":") - 1)); val = substr($0, index($0, ":") + 1)
      gsub(/^[ \t]+|[ \t]+$/, "", val)
      if (key == "types") types = val; else if (key == "suites") suites = val
      else if (key == "components") comps = val; else if (key == "uris") uris = val
      else if (key == "signed-by") signed = val; else if (key == "enabled") enabled = val
    }
    END { flush() }'
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do [ -f "$f" ] && cat "$f"; done |
    awk -v want="$codename" '
      $1 == "deb" {
        signed = ""; i = 2
        if ($2 ~ /^\[/) {
          for (; i <= NF; i++) {
            if ($i ~ /^\[?signed-by=/) {
              signed = $i; sub(/^\[?signed-by=/, "", signed); sub(/\]$/, "", signed)
            }
            if ($i ~ /\]$/) { i++; break }
          }
        }
        if ($(i + 1) != want) next
        for (c = i + 2; c <= NF; c++) if ($c == "main") { print $i "\t" signed; next }
      }'
}

apt_ready=0
private_apt() { # write our deb-src entries and fetch their indexes (once per run)
  [ $apt_ready -eq 0 ] || return 0
  local uri signed entry
  if [ -n "${PW_DEBIAN_URI:-}" ]; then
    uri=$PW_DEBIAN_URI signed=/usr/share/keyrings/debian-archive-keyring.gpg
  else
    # the Debian archive itself (.../debian) rather than another vendor's bookworm/main
    IFS=$'\t' read -r uri signed < <(debian_archives |
      awk -F'\t' '$1 ~ /\/debian\/?$/ { print; found = 1; exit } NR == 1 { first = $0 }
                  END { if (!found && first != "") print first }') || true
    [ -n "${uri:-}" ] || {
      echo "no Debian archive with component main for this release in" \
        "/etc/apt/sources.list{,.d}: set PW_DEBIAN_URI to a Debian mirror" >&2
      exit 1
    }
  fi
  mkdir -p "$PW_APT/sources.list.d" "$PW_APT/lists/partial" "$PW_APT/cache/archives/partial"
  entry=$(printf 'Types: deb-src\nURIs: %s\nSuites: %s\nComponents: main\n' \
    "$uri" "$PW_SOURCE_SUITES"; [ -z "$signed" ] || printf 'Signed-By: %s\n' "$signed")
  if [ "$(cat "$PW_APT/sources.list.d/porewater-src.sources" 2>/dev/null)" != "$entry" ]; then
    echo "$entry" > "$PW_APT/sources.list.d/porewater-src.sources"
  fi
  log "fetching the source indexes of $PW_SOURCE_SUITES from $uri (private apt lists in $PW_APT)"
  apt-get "${APT_PRIVATE[@]}" update -q >"$PW_APT/update.log" 2>&1 ||
    { tail -20 "$PW_APT/update.log"; exit 1; }
  apt_ready=1
}

mkdir -p "$PW_CACHE/src"
verify() { echo "$2  $PW_CACHE/src/$1" | sha256sum -c --quiet - >/dev/null 2>&1; }
fetch() { # fetch PKG=VERSION FILE SHA256
  if ! verify "$2" "$3"; then
    private_apt
    log "downloading source package $1"
    # apt's exit status is not the test: trixie's lammps .dsc answers 404 after the tarballs
    (cd "$PW_CACHE/src" && apt-get "${APT_PRIVATE[@]}" source --download-only -q "$1") \
      >"$PW_APT/source.log" 2>&1 || true
    verify "$2" "$3" ||
      { tail -20 "$PW_APT/source.log"; echo "sha256 mismatch for $2" >&2; exit 1; }
  fi
}

# unpack HOST STAMP: a fresh tree of that host unless its stamp (its tarballs and patches)
# matches; each host has its own tree and stamp, so a change to one never touches the other
unpack() {
  local host=$1 stamp=$2 tmp="$PW_CACHE/unpack-$1" p
  [ "$(cat "$LAMMPS_SRC/.pw-stamp" 2>/dev/null)" != "$stamp" ] || return 0
  log "unpacking LAMMPS ($host) into $LAMMPS_SRC"
  rm -rf "$LAMMPS_SRC" "$tmp"
  mkdir -p "$tmp"
  if [ "$host" = 2021 ]; then
    tar -xf "$PW_CACHE/src/$LAMMPS2021_TARBALL" -C "$tmp"
    mv "$tmp"/lammps-* "$LAMMPS_SRC"
    tar -xzf "$PW_CACHE/src/$TRILINOS_TARBALL" -C "$tmp" --wildcards '*/packages/kokkos/*'
    mv "$tmp"/Trilinos-*/packages/kokkos "$LAMMPS_SRC/lib/kokkos"
  else
    tar -xf "$PW_CACHE/src/$LAMMPS2025_TARBALL" -C "$tmp"
    mv "$tmp"/lammps-* "$LAMMPS_SRC"
  fi
  rm -rf "$tmp"
  host_patches "$host"
  for p in "${PATCHES[@]}"; do
    log "applying $(basename "$p")"
    patch -d "$LAMMPS_SRC" -p1 --forward --quiet < "$p"
  done
  # the build dir stays: ninja recompiles the fresh tree through ccache
  echo "$stamp" > "$LAMMPS_SRC/.pw-stamp"
}
host_patches() { # PATCHES = the patch files of a host, in order
  if [ "$1" = 2021 ]; then PATCHES=("$REPO"/scripts/patches/*.patch)
  else PATCHES=("$REPO"/scripts/patches/2025/*.patch); fi
  [ -e "${PATCHES[0]}" ] || PATCHES=()
}
stamp_of() { # what a host's tree is made of: its pinned tarballs and its patches
  host_patches "$1"
  if [ "$1" = 2021 ]; then
    printf '%s\n' "$LAMMPS2021_TARBALL" "$LAMMPS2021_SHA256" "$TRILINOS_TARBALL" "$TRILINOS_SHA256"
  else
    printf '%s\n' "$LAMMPS2025_TARBALL" "$LAMMPS2025_SHA256"
  fi | cat - "${PATCHES[@]}" | sha256sum | cut -c1-16
}

for host in $HOSTS; do
  if [ "$host" = 2021 ]; then
    fetch "lammps=$LAMMPS2021_DEB_VERSION" "$LAMMPS2021_TARBALL" "$LAMMPS2021_SHA256"
    fetch "trilinos=$TRILINOS_DEB_VERSION" "$TRILINOS_TARBALL" "$TRILINOS_SHA256"
  else
    fetch "lammps=$LAMMPS2025_DEB_VERSION" "$LAMMPS2025_TARBALL" "$LAMMPS2025_SHA256"
  fi
  pw_select_host "$host"
  unpack "$host" "$(stamp_of "$host")"
done

# ---- 3. LAMMPS, 4. the plugin, per host ----------------------------------------------
export CCACHE_DIR=${CCACHE_DIR:-$PW_CACHE/ccache}
# paths relative to the clone, so a fresh clone elsewhere (CI) still hits the cache
export CCACHE_BASEDIR=$REPO CCACHE_NOHASHDIR=1
mkdir -p "$CCACHE_DIR"
ccache --max-size=5G >/dev/null
for host in $HOSTS; do
  pw_select_host "$host"
  logs="$PW_CACHE/lammps-$host"
  if [ "$host" = 2021 ]; then
    host_options=(-D LAMMPS_EXCEPTIONS=on -D PKG_KOKKOS=on
      -D Kokkos_ENABLE_SERIAL=on -D Kokkos_ENABLE_OPENMP=on)
    packages="GRANULAR;PLUGIN;KOKKOS/OpenMP"    # what lammps.lmp_has_packages checks
    cold="~10 min"
  else # exceptions are always on since 2023; no Kokkos source: LAMMPS' OPENMP package instead
    host_options=(-D PKG_OPENMP=on)
    packages="GRANULAR;PLUGIN;OPENMP"
    cold="~7-10 min"
  fi
  if [ ! -f "$LAMMPS_BUILD/build.ninja" ]; then
    log "configuring LAMMPS ($host) in $LAMMPS_BUILD"
    pw_configure_lammps "$LAMMPS_BUILD" "$logs-configure.log" \
      -D CMAKE_INSTALL_PREFIX="$LAMMPS_PREFIX" -D LAMMPS_INSTALL_RPATH=on \
      -D BUILD_SHARED_LIBS=on -D BUILD_MPI=on -D BUILD_OMP=on "${host_options[@]}" || exit 1
  fi
  log "building LAMMPS ($host; cold: $cold on 2 cores; warm: seconds)"
  cmake --build "$LAMMPS_BUILD" -j "$JOBS" >"$logs-build.log" 2>&1 ||
    { tail -40 "$logs-build.log"; exit 1; }
  cmake --install "$LAMMPS_BUILD" >"$logs-install.log" 2>&1 ||
    { tail -20 "$logs-install.log"; exit 1; }

  build="$REPO/$PW_BUILD_NAME"
  # the tests' view of the host: the packages it was built with; the other host's plugin,
  # which this host's lmp must refuse in words (tests/batch, other_host)
  other=build-2025; [ "$host" = 2025 ] && other=build
  settings=("PW_LMP_PACKAGES:STRING=$packages" "PW_OTHER_PLUGIN:FILEPATH=$REPO/$other/plugin/porewater.so")
  configure=0
  [ -f "$build/build.ninja" ] || configure=1
  for s in "${settings[@]}"; do
    grep -qxF "$s" "$build/CMakeCache.txt" 2>/dev/null || configure=1
  done
  if [ $configure = 1 ]; then
    cmake -S "$REPO" -B "$build" -G Ninja -D CMAKE_BUILD_TYPE=Release \
      -D CMAKE_CXX_COMPILER_LAUNCHER=ccache \
      -D LAMMPS_SOURCE_DIR="$LAMMPS_SRC/src" -D LAMMPS_BUILD_DIR="$LAMMPS_BUILD" \
      -D CMAKE_PREFIX_PATH="$LAMMPS_PREFIX" "${settings[@]/#/-D}" >/dev/null
  fi
  log "building the plugin ($host) in $build"
  cmake --build "$build" -j "$JOBS"
done

# ---- 5. the LIGGGHTS host -----------------------------------------------------------------
if has_layer liggghts; then
  log "LIGGGHTS: libliggghts-dev $(dpkg-query -W -f='${Version}' libliggghts-dev)"
  if [ ! -f "$REPO/build-liggghts/build.ninja" ]; then
    cmake -S "$REPO" -B "$REPO/build-liggghts" -G Ninja -D CMAKE_BUILD_TYPE=Release \
      -D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D PW_HOSTS=liggghts >/dev/null
  fi
  log "building the LIGGGHTS launcher (its tests: scripts/test.sh)"
  cmake --build "$REPO/build-liggghts" -j "$JOBS" --target liggghts
fi
if [ "$HOSTS" = 2021 ]; then
  log "done: source $REPO/scripts/env.sh, then lmp -in <input>"
elif [ -n "$HOSTS" ]; then
  log "done: PW_LAMMPS=<2021|2025> source $REPO/scripts/env.sh, then lmp -in <input>"
fi
has_layer liggghts && log "done: source $REPO/scripts/env.sh, then liggghts -in <input>"
exit 0
