#!/usr/bin/env bash
# `lmp -h` of the host lists the packages it is meant to have (PW_LMP_PACKAGES: scripts/setup.sh
# names the ones it built each host with). KOKKOS/OpenMP: KOKKOS with its OpenMP backend.
#   Usage: check_lmp_packages.sh LMP PACKAGE...
set -u
lmp=$1; shift
out=$("$lmp" -h)
rc=0
for want in "$@"; do
  pkg=${want%%/*}
  if echo "$out" | sed -n '/Installed packages:/,/List of individual style/p' | grep -qw "$pkg"; then
    echo "found package $pkg"
  else
    echo "MISSING package $pkg in $lmp -h"; rc=1
  fi
  if [ "$want" != "$pkg" ]; then
    backend=${want#*/}
    if echo "$out" | grep -q "KOKKOS package API: .*$backend"; then echo "$pkg has $backend"
    else echo "$pkg lacks $backend"; rc=1; fi
  fi
done
exit $rc
