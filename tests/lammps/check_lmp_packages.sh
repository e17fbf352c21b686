#!/usr/bin/env bash
# `lmp -h` of our build lists the packages the plugin needs.
set -u
out=$("$1" -h)
rc=0
for pkg in GRANULAR KOKKOS PLUGIN; do
  if echo "$out" | sed -n '/Installed packages:/,/List of individual style/p' | grep -qw "$pkg"; then
    echo "found package $pkg"
  else
    echo "MISSING package $pkg in $1 -h"; rc=1
  fi
done
echo "$out" | grep -q "KOKKOS package API: .*OpenMP" && echo "KOKKOS has OpenMP" || { echo "KOKKOS lacks OpenMP"; rc=1; }
exit $rc
