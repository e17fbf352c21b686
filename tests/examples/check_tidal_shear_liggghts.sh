#!/usr/bin/env bash
# A short examples/tidal_shear_liggghts run from the shipped consolidated state: it
# completes and its time series is finite and physically bounded (the LAMMPS example's
# physics is checked by check_tidal_shear.sh).  Usage: check_tidal_shear_liggghts.sh LIGGGHTS
set -euo pipefail
EXAMPLES=$(cd "$(dirname "$0")/../../examples" && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
mkdir "$work/tidal_shear" "$work/tidal_shear_liggghts"
cp "$EXAMPLES"/tidal_shear/in.* "$EXAMPLES"/tidal_shear/consolidated_0.data "$work/tidal_shear/"
cp "$EXAMPLES"/tidal_shear_liggghts/in.* "$work/tidal_shear_liggghts/"
cd "$work/tidal_shear_liggghts"    # it reads ../tidal_shear/in.params and the data file
"$1" -in in.tidal_shear -var run_steps ${STEPS:-8000} -log log.liggghts -screen /dev/null
/usr/bin/python3 - <<'PY'
import numpy as np, sys
names = open("timeseries.txt").readline().lstrip("# ").split()
d = np.loadtxt("timeseries.txt", ndmin=2)
c = {n: d[:, k] for k, n in enumerate(names)}
ok = True
def check(cond, what):
    global ok
    print(("ok    " if cond else "FAIL  ") + what)
    ok &= bool(cond)
check(len(d) >= 3, f"{len(d)} samples written")
check(np.all(np.isfinite(d)), "every value finite")
t, f, A, s0 = c["time"], 0.4, 70.0e3, 80.0e3    # examples/tidal_shear/in.params
check(np.allclose(c["N_applied"], s0 + A * np.sin(2 * np.pi * f * t), rtol=0, atol=1.0), "plate stress follows sigma0 + A sin(2 pi f t)")
check(np.allclose(c["p_top"], A * np.sin(2 * np.pi * f * t + np.pi), rtol=0, atol=1.0), "top pressure follows A sin(2 pi f t + pi)")
check(np.all((c["z_wall"] > 0.15) & (c["z_wall"] < 0.35)), "plate stays at the bed top (0.15-0.35 m)")
check(np.all((c["phi_mean"] > 0.3) & (c["phi_mean"] < 0.6)), "mean porosity of a packed bed (0.3-0.6)")
check(np.all((c["coordination"] > 2.0) & (c["coordination"] < 8.0)), "coordination of a loaded packing (2-8)")
check(np.all(np.abs(c["p_mean"]) <= 2 * A), "mean pore pressure within twice the forcing amplitude")
check(np.all(np.abs(c["vx_top"]) < 1.0), "top layer slower than 1 m/s")
sys.exit(0 if ok else 1)
PY
