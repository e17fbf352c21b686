#!/usr/bin/env bash
# The test command: set up (packages, LAMMPS, plugin), compile-check the KOKKOS sources
# for CUDA, then run every test with ctest.
set -euo pipefail
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
start=$(date +%s)
bash "$REPO/scripts/setup.sh"
bash "$REPO/scripts/cuda_check.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$REPO/build"
ctest --output-on-failure -j "${PW_TEST_JOBS:-2}" --timeout 900
echo "test command took $(( $(date +%s) - start )) s"
