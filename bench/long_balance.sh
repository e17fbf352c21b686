#!/bin/bash
# Long run of the reduced tidal_shear example (issue 6): no NaN, bounded energy, and the
# fluid balance of fix darcy/pressure (f_darcy[7..11]) over it.
#   bash bench/long_balance.sh [steps, default 1000000]     (after: source scripts/env.sh)
# Works in a scratch copy of examples/tidal_shear; prints a summary of its thermo output.
set -euo pipefail
steps=${1:-1000000}
repo=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d /tmp/pw_long_balance.XXXXXX)
cp -r "$repo"/examples/tidal_shear/. "$work"
cd "$work"
# thermo: the balance terms and kinetic energy instead of the example's columns
sed -i 's/^thermo_style custom step time .*/thermo_style custom step time f_wall[1] f_darcy[1] f_darcy[3] f_darcy[4] f_darcy[7] f_darcy[8] f_darcy[9] f_darcy[10] f_darcy[11] ke/; s/^thermo_modify norm no/thermo_modify norm no format float %.10g/' in.tidal_shear
lmp -in in.tidal_shear -var run_steps "$steps" -log long.log -screen none
/usr/bin/python3 - long.log <<'PY'
import math, sys
rows, on = [], False
for line in open(sys.argv[1]):
    w = line.split()
    if w[:2] == ["Step", "Time"]: on = True; continue
    if on and w and w[0] == "Loop": on = False; continue
    if on and len(w) == 12:
        try: rows.append([float(x) for x in w])
        except ValueError: pass
bad = sum(1 for r in rows for x in r if not math.isfinite(x))
last = rows[-1]
res, stored, inflow, grains, allow = last[6:11]
gross = abs(stored) + abs(inflow) + abs(grains)
print(f"steps {int(last[0])}, samples {len(rows)}, non-finite values {bad}")
print(f"max |p| {max(r[4] for r in rows):.4g} Pa, max CG iterations {max(r[5] for r in rows):.0f}")
print(f"kinetic energy: max {max(r[11] for r in rows):.4g} J, last {last[11]:.4g} J")
print(f"balance at the end (m^3): stored {stored:.6e}, inflow {inflow:.6e}, grains {grains:.6e}")
print(f"residual {res:.3e} = {abs(res)/allow:.3e} of the allowance {allow:.3e}, "
      f"{abs(res)/gross:.3e} of |stored|+|inflow|+|grains|")
print(f"largest |residual|/allowance over the run "
      f"{max(abs(r[6])/r[10] for r in rows if r[10] > 0):.3e}")
PY
echo "output in $work"
