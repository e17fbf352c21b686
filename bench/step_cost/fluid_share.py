#!/usr/bin/python3
"""The pore water's share of the step, timed by sampling: the reduced example tiled 1, 2, 4
times per side (common.beds.tiled: 1,200, 9,600, 76,800 grains, the fluid cells
tiled with it), -var fast 1, on 1 and 2 ranks, each run under `perf record` (the CPU clock,
RATE samples a second, call stacks unwound from DWARF, 64 KiB of stack each:
the pair kernel's frames are large). A sample is in the run loop when
its stack holds LAMMPS' Verlet::run, and the fluid's when it also holds a method of fix
darcy/pressure: its solve, grain-grid coupling, held force and sums over the ranks (the MPI
calls it makes and their waits). The share is fluid samples over run-loop samples; samples
whose stack was cut before either frame are counted apart (`unwound`: the fraction that
reached one of main or Verlet::run). Unlike 1 - dry/wet (step_time.py --growth), it
times the wet run itself: a dry bed moves differently.

Time is the machine's: run it alone. Usage (source scripts/env.sh first):
    /usr/bin/python3 bench/step_cost/fluid_share.py [--markdown FILE] [--rate HZ] PLUGIN_DIR
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import short    # noqa: E402
from common.beds import prepare_scene, tiled    # noqa: E402
from common.runs import run_lmp    # noqa: E402
from step_time import GROWTH_TIMED_STEPS    # noqa: E402  (this study's own)

RATE = 299
STEPS = short(GROWTH_TIMED_STEPS, {1: 100})    # copies per side: steps (step_time's growth)
IN_LOOP = re.compile(r"LAMMPS_NS::Verlet::run\b")
FLUID = re.compile(r"LAMMPS_NS::FixDarcyPressure\w*(<[^>]*>)?::")
ROOT = re.compile(r"^(main|_start)$|LAMMPS_NS::Verlet::run\b")


def stacks(perf_data):
    """the call stacks (lists of frame names, leaf first) of lmp's samples"""
    text = subprocess.run(["perf", "script", "-i", perf_data, "-F", "comm,ip,sym"],
                          capture_output=True, text=True, check=True).stdout
    for block in text.split("\n\n"):
        lines = block.strip().splitlines()
        if lines and lines[0].strip() == "lmp":
            yield [line.strip().split(" ", 1)[-1] for line in lines[1:]]    # "ADDRESS symbol"


def shares(perf_data):
    """{samples, loop, fluid, unwound} of one profile"""
    counts = dict(samples=0, loop=0, fluid=0, unwound=0)
    for frames in stacks(perf_data):
        counts["samples"] += 1
        counts["unwound"] += any(ROOT.search(f) for f in frames)
        if any(IN_LOOP.search(f) for f in frames):
            counts["loop"] += 1
            counts["fluid"] += any(FLUID.search(f) for f in frames)
    return counts


def profiled_run(copies, ranks, plugin, rate):
    grains, scene = tiled(copies)
    with tempfile.TemporaryDirectory() as work:
        env = dict(os.environ, LD_LIBRARY_PATH=plugin + ":" + os.environ.get("LD_LIBRARY_PATH", ""))
        variables = prepare_scene(dict(scene, run_steps=STEPS[copies]), work, env)
        load = os.getloadavg()[0]
        data = os.path.join(work, "perf.data")
        run_lmp(work, "in.tidal_shear", variables, ranks=ranks, plugin_dir=plugin,
                launcher=["perf", "record", "-q", "-F", str(rate), "--call-graph", "dwarf,65528",
                          "-o", data, "--"])
        return grains, dict(shares(data), load=(load, os.getloadavg()[0]))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("plugin")
    ap.add_argument("--rate", type=int, default=RATE)
    ap.add_argument("--markdown")
    args = ap.parse_args()
    lines = ["| grains | ranks | steps | samples in the run loop | fluid's share | stacks unwound | load before/after |",
             "|---|---|---|---|---|---|---|"]
    for copies in STEPS:
        for ranks in (1, 2):
            grains, c = profiled_run(copies, ranks, os.path.abspath(args.plugin), args.rate)
            lines.append("| %d | %d | %d | %d | %.1f %% | %.1f %% | %.1f/%.1f |" % (
                grains, ranks, STEPS[copies], c["loop"], 100.0 * c["fluid"] / c["loop"],
                100.0 * c["unwound"] / c["samples"], c["load"][0], c["load"][1]))
            print(lines[-1], flush=True)
    head = ["perf record of the reduced example tiled c x c x c (-var fast 1), %d samples a second;"
            " the fluid's share: samples under fix darcy/pressure over samples under Verlet::run." % args.rate, ""]
    if args.markdown:
        open(args.markdown, "w").write("\n".join(head + lines) + "\n")


if __name__ == "__main__":
    main()
