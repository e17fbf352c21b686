#!/usr/bin/env bash
# Runs lmp as a batch job runs it (stdin not a terminal, stdout and stderr to files) on an
# input that stops with an error, and checks that the error message reached stdout,
# stderr and log.lammps, each exactly once, before the program stopped without a signal.
#   Usage: check_error_message.sh CASE LMP PLUGIN_DIR MPIEXEC
# Exit status 77: skipped (see serial_grid_memory; the *_kk cases where PW_HOST_KOKKOS=0, a
# LAMMPS without KOKKOS).
set -uo pipefail
CASE=$1 LMP=$2 PLUGIN_DIR=$3 MPIEXEC=$4
HERE=$(cd "$(dirname "$0")" && pwd)
if [[ $CASE == *_kk ]] && [ "${PW_HOST_KOKKOS:?whether lmp has KOKKOS: 1 or 0}" = 0 ]; then
  echo "skipped: this LAMMPS has no KOKKOS package, so the plugin has no /kk styles"; exit 77
fi
export LD_LIBRARY_PATH="$PLUGIN_DIR:${LD_LIBRARY_PATH:-}" OMP_NUM_THREADS=1 OMP_PROC_BIND=false
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
KK=(-k on t 1 -sf kk -pk kokkos neigh half newton off)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failed=0
check() {    # check WHAT CONDITION...
  local what=$1; shift
  if "$@"; then echo "ok    $what"; else echo "FAIL  $what"; failed=1; fi
}
count() { grep -cF -- "$1" "$2" 2>/dev/null || true; }    # lines of file $2 holding $1

# run NP INPUT ARGS...: stdout -> out.txt, stderr -> err.txt, stdin from /dev/null
run() {
  local np=$1 input=$2; shift 2
  [ -f "$input" ] || cp "$HERE/$input" .
  if [ "$np" = 1 ]; then
    "$LMP" -in "$input" "$@" >out.txt 2>err.txt </dev/null
  else
    "$MPIEXEC" --oversubscribe -np "$np" "$LMP" -in "$input" "$@" >out.txt 2>err.txt </dev/null
  fi
  rc=$?
  echo "exit status $rc; the last lines of each file:"
  for f in out.txt err.txt log.lammps; do
    echo "--- $f"; tail -n 4 "$f" 2>/dev/null
  done
  echo "---"
}

# expect MESSAGE [FILES...]: the run failed without a signal, MESSAGE is once in each file
# (default: stdout, stderr and the log), and the log ends with a whole line
expect() {
  local message=$1; shift
  local files=("$@")
  [ ${#files[@]} -gt 0 ] || files=(out.txt err.txt log.lammps)
  check "exit status $rc: an error, not a signal" test "$rc" -ge 1 -a "$rc" -lt 128
  for f in "${files[@]}"; do
    check "'$message' once in $f (found $(count "$message" "$f"))" test "$(count "$message" "$f")" = 1
  done
  check "log.lammps ends with a whole line" test "$(tail -c 1 log.lammps | od -An -c | tr -d ' ')" = '\n'
}

case $CASE in
  serial_pair_one)       # our per-rank check (error->one) in the pair
    run 1 in.overlap
    expect "ERROR on proc 0: Pair linear/coulomb: at step 0 grains 2 and 3" ;;
  serial_pair_one_kk)
    run 1 in.overlap "${KK[@]}"
    expect "ERROR on proc 0: Pair linear/coulomb/kk: at step 0 grains 2 and 3" ;;
  serial_lammps_one)     # LAMMPS' own error->one
    run 1 in.point_grain
    expect "ERROR on proc 0: Fix nve/sphere requires extended particles" ;;
  serial_all)            # error->all
    run 1 in.bad_coeff
    expect "pair_coeff linear/coulomb" ;;
  serial_grid_index)     # a grid whose cells an int cannot index
    run 1 in.grid
    expect "grid 4000x4000x4000 has 6.4e+10 cells" ;;
  serial_grid_memory)    # a grid an int indexes but this machine cannot hold (if it cannot)
    need=$(( 350 * 350 * 350 * 825 ))    # bytes, about (fix darcy/pressure's doc page)
    have=$(( $(getconf _PHYS_PAGES) * $(getconf PAGE_SIZE) ))
    if [ "$have" -gt "$need" ]; then echo "skipped: this machine holds $have bytes"; exit 77; fi
    run 1 in.grid -var n 350
    expect "grid 350x350x350" ;;
  serial_exception)      # a C++ exception (here std::bad_alloc under a memory limit)
    cp "$HERE/in.grid" .
    (ulimit -v 1500000; "$LMP" -in in.grid -var n 150 >out.txt 2>err.txt </dev/null)
    rc=$?
    tail -n 3 out.txt err.txt log.lammps
    expect "ERROR on proc 0: uncaught C++ exception" ;;
  serial_combined)       # 2>&1: stdout and stderr are one file, the message is written once
    cp "$HERE/in.overlap" .
    "$LMP" -in in.overlap >out.txt 2>&1 </dev/null
    rc=$?
    expect "ERROR on proc 0: Pair linear/coulomb" out.txt log.lammps ;;
  serial_terminal)       # on a terminal (a pty from script(1)): once on it
    command -v script >/dev/null || { echo "skipped: no script(1)"; exit 77; }
    cp "$HERE/in.overlap" .
    script -qec "$LMP -in in.overlap" typescript </dev/null >/dev/null
    rc=$?
    expect "ERROR on proc 0: Pair linear/coulomb" typescript log.lammps ;;
  np2_pair_rank1)        # error->one on rank 1 only: it reaches rank 0's log as well
    run 2 in.overlap
    expect "ERROR on proc 1: Pair linear/coulomb: at step 0 grains 2 and 3"
    check "no error on rank 0" test "$(count "ERROR on proc 0" out.txt)" = 0 ;;
  np2_pair_rank1_kk)
    run 2 in.overlap "${KK[@]}"
    expect "ERROR on proc 1: Pair linear/coulomb/kk: at step 0 grains 2 and 3" ;;
  np2_lammps_rank1)
    run 2 in.point_grain
    expect "ERROR on proc 1: Fix nve/sphere requires extended particles" ;;
  np2_all)
    run 2 in.bad_coeff
    expect "pair_coeff linear/coulomb" ;;
  np2_rank1_screen_none) # no screen: the log and stderr still get it
    run 2 in.overlap -screen none
    expect "ERROR on proc 1: Pair linear/coulomb" err.txt log.lammps ;;
  other_host)            # the plugin built for the other LAMMPS host: refused in words
    [ -f "${PW_OTHER_PLUGIN:-}" ] ||
      { echo "skipped: no plugin of another LAMMPS host (PW_OTHER_PLUGIN='${PW_OTHER_PLUGIN:-}'; PW_LAMMPS=both builds one)"; exit 77; }
    printf 'plugin load %s\npair_style linear/coulomb\n' "$PW_OTHER_PLUGIN" > in.other_host
    run 1 in.other_host
    built_for=$(grep -o 'built for LAMMPS version [0-9]*' out.txt | head -1 | grep -o '[0-9]*$')
    check "the plugin names the LAMMPS it was built for ($built_for), not this one ($PW_HOST_VERSION)" \
      test -n "$built_for" -a "$built_for" != "$PW_HOST_VERSION"
    refused="ERROR: porewater.so was built for LAMMPS version $built_for, this LAMMPS is $PW_HOST_VERSION: no styles registered"
    expect "$refused" out.txt err.txt
    # the log echoes the print command that writes it there, so it holds the text twice
    check "'$refused' in log.lammps" grep -qF -- "$refused" log.lammps
    expect "Unrecognized pair style 'linear/coulomb'" ;;
  *) echo "unknown case $CASE"; exit 2 ;;
esac
exit $failed
