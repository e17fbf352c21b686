#!/usr/bin/python3
"""The neighbour-list check every N steps instead of every step, by counts: the reduced
example (CPU styles: the builds are the same decisions as with /kk up to round-off) over one
forcing cycle with -var neigh_every N (`neigh_modify delay 0 every N check yes`), the neighbour
list builds and LAMMPS' dangerous builds (a build at the first check after the last one: a
grain may have moved further than half the skin before it) counted every 1,000 steps.

The check is a reduction into a host scalar (NeighborKokkos' distance check): with /kk on a
GPU the one wait for the device left on an ordinary step. Every N steps it runs 1/N times a
step; a build then comes up to N - 1 steps after a grain has moved half the skin, which is
safe while builds are much further apart than N steps (and no build is dangerous).

    source scripts/env.sh; /usr/bin/python3 bench/gpu/neighbor_every.py --work DIR [--every 1,5,10,25]
        [--var NAME VALUE ...] [--markdown OUT.md]
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common.runs import prepare    # noqa: E402
from kokkos_step_counts import print_and_append    # noqa: E402

WINDOW = 1000    # steps per thermo row: builds are counted per window


def run(work, every, variables):
    d = os.path.join(work, "every_%d" % every)
    prepare(d)
    path = os.path.join(d, "in.tidal_shear")
    text = open(path).read()
    old = "thermo $(10*v_nout)"
    if old not in text:
        sys.exit("in.tidal_shear has no line %r" % old)
    text = text.replace("thermo_style custom step", "thermo_style custom step nbuild ndanger")
    open(path, "w").write(text.replace(old, "thermo %d" % WINDOW))
    extra = [a for kv in dict(variables, neigh_every=every).items() for a in ("-var", kv[0], str(kv[1]))]
    subprocess.run(["lmp", "-in", "in.tidal_shear", "-screen", "none", "-log", "log.lammps"] + extra,
                   cwd=d, check=True)
    rows = []
    for line in open(os.path.join(d, "log.lammps")):
        w = line.split()
        if len(w) > 3 and w[0].isdigit() and w[1].isdigit() and w[2].isdigit():
            rows.append((int(w[0]), int(w[1]), int(w[2])))
    # the builds within each window (a chunk's run restarts the counts: differences per run)
    per_window = [b1 - b0 for (s0, b0, _), (s1, b1, _) in zip(rows, rows[1:]) if s1 > s0 and b1 >= b0]
    steps = rows[-1][0] - rows[0][0]
    builds = sum(per_window)
    danger = sum(d1 - d0 for (s0, _, d0), (s1, _, d1) in zip(rows, rows[1:]) if s1 > s0 and d1 >= d0)
    return {"every": every, "steps": steps, "builds": builds, "dangerous": danger,
            "most_in_window": max(per_window), "checks_per_step": 1.0 / every,
            "steps_per_build": steps / max(builds, 1)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--work", required=True)
    ap.add_argument("--every", default="1,5,10,25")
    ap.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    ap.add_argument("--markdown")
    args = ap.parse_args()
    variables = dict([("fast", 1), ("cycles", 1)] + [tuple(v) for v in args.var])
    rows = [run(os.path.abspath(args.work), int(n), variables) for n in args.every.split(",")]
    lines = ["reduced example, CPU styles, %s: one row per `neigh_modify every N check yes`" % " ".join(
        "-var %s %s" % kv for kv in variables.items()), "",
             "| every N | steps | checks per step | builds | steps per build | most builds in %d steps "
             "| dangerous builds |" % WINDOW, "|---|---|---|---|---|---|---|"]
    lines += ["| %(every)d | %(steps)d | %(checks_per_step).3f | %(builds)d | %(steps_per_build).0f "
              "| %(most_in_window)d | %(dangerous)d |" % r for r in rows]
    print_and_append("\n".join(lines) + "\n", args.markdown)


if __name__ == "__main__":
    main()
