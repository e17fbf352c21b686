# Pinned third-party sources and where they live; sourced by setup.sh, env.sh, cuda_*.sh.
LAMMPS_DEB_VERSION=20220106.git7586adbb6a+ds1-2   # LAMMPS 29Sep2021 update 2
LAMMPS_TARBALL=lammps_20220106.git7586adbb6a+ds1.orig.tar.xz
LAMMPS_SHA256=65146c615ad24d8b8bc64f4e05e86226a7f1fdb45c0b5ea9416562b9f3863082
TRILINOS_DEB_VERSION=13.2.0-4                      # packages/kokkos is Kokkos 3.4.01
TRILINOS_TARBALL=trilinos_13.2.0.orig.tar.gz
TRILINOS_SHA256=0ddb47784ba7b8a6b9a07a4822b33be508feb4ccd54301b2a5d10c9e54524b90

PW_CACHE=${PW_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/lammps-porewater}
LAMMPS_SRC=$PW_CACHE/lammps-29Sep2021u2
LAMMPS_BUILD=$PW_CACHE/build-host
LAMMPS_PREFIX=$PW_CACHE/install
LAMMPS_CUDA_BUILD=$PW_CACHE/build-cuda
