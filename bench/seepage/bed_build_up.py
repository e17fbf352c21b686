#!/usr/bin/env python3
"""The example's bed in slow-draining water: where its pore pressure's build-up comes from
(bench/seepage/RESULTS.md, "The example's bed").

    bed_build_up.py [--workdir DIR] [--variant-plugin DIR] [--table FILE]

Runs in.bed_consolidation (the tidal shear example's 1,200-grain bed under its plate, the fine
6 x 4 x 7 grid, the water 2,600 times as viscous as the example's and beta_f 5e-9/Pa) from its
drained preparation, each run changing one thing, and reports the largest cell pressure |p|
and the grains' kinetic energy at 0.01, 0.02 and 0.04 s, and the energy's growth rate
(least squares of ln KE over 0.005-0.02 s):

- no load step (dsigma 0): the build-up without any load;
- half the time step; the fluid every 2 steps: whether it is the time stepping;
- beta_f x 10; the viscosity / 10: the water's stiffness and its drainage;
- the 8 kPa step of the page's earlier measurement;
- with --variant-plugin DIR (a build of the plugin with variants/isolation_switches.patch
  applied, never committed): the advection term v.grad(phi) off (PW_VAR_ADVECTION=0), and the
  grains' force taken as -V sum_c F_c p_c grad s(x - X_c), the gradient of the pressure
  interpolated with the deposit's own hat weights (PW_VAR_FORCE=hat), without and with the
  step.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import EXAMPLE, out_dir, runs as example_runs  # noqa: E402

TIMES = (0.01, 0.02, 0.04)
GROWTH_WINDOW = (0.005, 0.02)
# (name, what it is, -var settings, the variant's environment or None)
RUNS = [
    ("no_step", "no load step", dict(dsigma=0.0), None),
    ("half_dt", "no step, half the time step", dict(dsigma=0.0, dt_factor=0.5), None),
    ("every2", "no step, the fluid every 2 steps", dict(dsigma=0.0, fluid_every=2), None),
    ("beta10", "no step, beta_f x 10", dict(dsigma=0.0, beta=5.0e-8), None),
    ("mu_tenth", "no step, the viscosity / 10", dict(dsigma=0.0, mu_bed=5.0e-5), None),
    ("step", "the 8 kPa step", dict(), None),
    ("no_advection", "no step, v.grad(phi) off", dict(dsigma=0.0), {"PW_VAR_ADVECTION": "0"}),
    ("consistent", "no step, the force consistent with the deposit", dict(dsigma=0.0),
     {"PW_VAR_FORCE": "hat"}),
    ("consistent_step", "the 8 kPa step, the force consistent with the deposit", dict(),
     {"PW_VAR_FORCE": "hat"}),
]


def thermo(log):
    """(time from the load's start, max |p|, KE) of the load run's thermo lines"""
    rows, header, columns = [], None, None
    with open(log) as f:
        for line in f:
            words = line.split()
            if words[:2] == ["Step", "Time"]:
                header = columns = words
                continue
            if header and words and words[0] == "Loop":
                header = None
                continue
            if header and len(words) == len(header):
                try:
                    rows.append([float(w) for w in words])
                except ValueError:
                    pass
    data = np.array(rows)
    t = data[:, 1] - data[0, 1]
    return t, data[:, columns.index("f_darcy_load[3]")], data[:, columns.index("c_ke")]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workdir", default=os.path.join(HERE, "work", "bed_build_up"))
    parser.add_argument("--variant-plugin", default=None)
    parser.add_argument("--table", default=os.path.join(out_dir(HERE), "bed_build_up_table.md"))
    args = parser.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    infile = os.path.join(HERE, "in.bed_consolidation")
    common = dict(example=EXAMPLE, thermo_every=200)
    if not os.path.exists(os.path.join(args.workdir, "bed_ready.restart")):
        example_runs.run_lmp(args.workdir, infile, dict(common, stage="prepare"),
                             log="log.prepare")
    rows = ["| run | max \\|p\\| (kPa) at " + ", ".join(f"{x:g}" for x in TIMES) +
            " s | grains' KE (mJ) at the same | KE's growth rate (1/s) |", "|---|---|---|---|"]
    for name, what, settings, env in RUNS:
        if env is not None and not args.variant_plugin:
            rows.append(f"| {what} | needs --variant-plugin | | |")
            continue
        variables = dict(common, stage="load", name=name, run_time=max(TIMES) + 0.001,
                         **settings)
        example_runs.run_lmp(args.workdir, infile, variables, log=f"log.{name}",
                             plugin_dir=args.variant_plugin if env is not None else None,
                             extra_env=env)
        t, pmax, ke = thermo(os.path.join(args.workdir, f"log.{name}"))
        at = [int(np.argmin(np.abs(t - x))) for x in TIMES]
        window = (t >= GROWTH_WINDOW[0]) & (t <= GROWTH_WINDOW[1])
        growth = np.polyfit(t[window], np.log(ke[window]), 1)[0]
        rows.append(f"| {what} | " + " / ".join(f"{pmax[i] / 1e3:.1f}" for i in at) + " | " +
                    " / ".join(f"{ke[i] * 1e3:.3f}" for i in at) + f" | {growth:.0f} |")
        print(rows[-1])
    with open(args.table, "w") as f:
        f.write("\n".join(rows) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
