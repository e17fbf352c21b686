#!/usr/bin/python3
"""Where a step of examples/tidal_shear goes, counted: callgrind instructions of the run loop
(LAMMPS' Verlet::run, setup excluded) per grain-step, by section (the pair style, each fix's
per-step hooks, communication, neighbour checks, force clearing), on one rank, for one or
more builds of the plugin side by side.

Scenes (bench/common/beds.py: SCENES, tiled), both with -var fast 1:
  reduced   the reduced example on one rank, STEPS steps (1,200 grains, fluid every 25
            steps, 3 time-series rows)
  table_s1  the Table S1-sized scene on one rank, S1_STEPS steps: the default bed replicated
            2 x 2 x 2 (bench/common/in.replicate_bed: 9,600 grains in 0.52 x 0.26 x 0.5 m),
            -var full 1 with the reduced k_n it was consolidated at (the cost of a step does
            not depend on k_n; the bed stays at rest)
  growth    the reduced example tiled c x c x c (c = 1, 2, 4: 1,200, 9,600 and 76,800 grains),
            the reduced case's fluid cells tiled with it (grid 3c x 2c x 3c+1), one build, a
            column per size: what grows faster than the grain count (GROWTH_STEPS steps)
Counts do not depend on the machine's load (valgrind counts instructions, not time): two
builds compare exactly, beside other work. One rank: on several, MPI's collectives poll
while they wait, and a rank's count then holds its wait for the others (per-rank time is
LAMMPS' timer's job, step_time.py).

Usage (after scripts/setup.sh; each PLUGIN_DIR holds a porewater.so; NAME=VALUE after it
are further -var settings of that configuration, e.g. own=build/plugin,one_pass=0):
    source scripts/env.sh
    /usr/bin/python3 bench/step_cost/step_cost.py [--scene reduced|table_s1] [--steps N]
                                        [--markdown FILE] LABEL=PLUGIN_DIR[,NAME=VALUE...] ...
    /usr/bin/python3 bench/step_cost/step_cost.py --scene growth [--markdown FILE] LABEL=PLUGIN_DIR
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
from common.beds import SCENES, prepare_scene, tiled    # noqa: E402

STEPS, S1_STEPS = 2000, 400
# growth: copies c per side, steps (multiples of the fluid interval, 25; the time series
# writes a row every 575 steps)
GROWTH_STEPS = short({1: 1150, 2: 575, 4: 100}, {1: 25, 2: 25})
RUN_LOOP = r"LAMMPS_NS::Verlet::run\(int\)"
HOOKS = ("initial_integrate", "post_integrate", "pre_exchange", "pre_neighbor", "pre_force",
         "post_force", "final_integrate", "end_of_step")
# section: the functions (inclusive) it sums, matched against callgrind's names
SECTIONS = [
    ("pair style", r"LAMMPS_NS::Pair\w+::compute\(int, int\)"),
    ("communication", r"LAMMPS_NS::Comm\w*::(forward_comm|reverse_comm|exchange|borders)\(\w*\)"),
    ("neighbour lists (check and build)", r"LAMMPS_NS::Neighbor::(decide|build)\(\w*\)"),
    ("force clearing", r"LAMMPS_NS::Verlet::force_clear\("),
    ("output (thermo, dumps, restarts)", r"LAMMPS_NS::Output::write\("),
]
FIX_HOOK = re.compile(r"LAMMPS_NS::(Fix\w+(?:<[^>]*>)?)::(%s)\(" % "|".join(HOOKS))


def inclusive_counts(profile):
    """{function name: inclusive instructions} of a callgrind profile"""
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", profile],
                          capture_output=True, text=True, check=True).stdout
    counts = {}
    for line in text.splitlines():
        m = re.match(r"\s*([\d,]+)\s+(?:\([^)]*\)\s+)?[^:\s]*:(.*?)(?: \[[^\]]*\])?$", line)
        if m:
            name = m.group(2).strip()
            counts[name] = max(counts.get(name, 0), int(m.group(1).replace(",", "")))
    return counts


def with_settings(text):
    """TEXT[,NAME=VALUE...]: (TEXT, {NAME: VALUE}), a configuration's own -var settings"""
    head, *settings = text.split(",")
    return head, dict(s.split("=", 1) for s in settings)


def configuration(text):
    """LABEL=PLUGIN_DIR[,NAME=VALUE...]: (label, absolute plugin folder, {NAME: VALUE})"""
    label, rest = text.split("=", 1)
    plugin, settings = with_settings(rest)
    return label, os.path.abspath(plugin), settings


def profile(plugin_dir, scene, steps, work, settings=None):
    """the run loop's callgrind profile of a scene (grains, -var overrides), with the
    configuration's own -var settings"""
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false",
               LD_LIBRARY_PATH=plugin_dir + ":" + os.environ.get("LD_LIBRARY_PATH", ""))
    variables = dict(prepare_scene(scene[1], work, env), **(settings or {}))
    args = ["-var", "run_steps", str(steps)]
    for k, v in variables.items():
        args += ["-var", k, str(v)]
    out = os.path.join(work, "callgrind.out")
    subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out,
                    "--toggle-collect=LAMMPS_NS::Verlet::run(int)", "lmp", "-in", "in.tidal_shear",
                    "-log", "none", "-screen", "none"] + args,
                   cwd=work, env=env, check=True, capture_output=True)
    return inclusive_counts(out)


def sections(counts):
    """[(section, instructions)]: the run loop, the named sections, each fix's hooks, and what
    is outside the pair style"""
    total = max(v for k, v in counts.items() if re.search(RUN_LOOP, k))
    rows = [("run loop", total)]
    for label, pattern in SECTIONS:
        rows.append((label, sum(v for k, v in counts.items() if re.search(pattern, k))))
    fixes = {}
    for name, v in counts.items():
        m = FIX_HOOK.search(name)
        if m and "thunk" not in name:
            fixes[m.group(1)] = fixes.get(m.group(1), 0) + v
    rows += [("fix %s" % cls.replace("LAMMPS_NS::", ""), v)
             for cls, v in sorted(fixes.items(), key=lambda kv: -kv[1])]
    rows.append(("outside the pair style", total - rows[1][1]))
    return rows


def table(results, grain_steps):
    """a row per section, a column per result (build, rank or size), each divided by its
    grain-steps; the ratio of two columns"""
    labels = list(results)
    names = [name for name, _ in results[labels[0]]]
    for label in labels[1:]:
        names += [n for n, _ in results[label] if n not in names]
    lines = ["| section (instructions per grain-step) | " + " | ".join(labels) + " |" +
             (" ratio |" if len(labels) == 2 else ""),
             "|---|" + "---|" * (len(labels) + (len(labels) == 2))]
    for name in names:
        values = [dict(results[label]).get(name, 0) / float(grain_steps[label]) for label in labels]
        row = "| %s | %s |" % (name, " | ".join("%.1f" % v for v in values))
        if len(labels) == 2:
            row += " %s |" % ("%.3f" % (values[1] / values[0]) if values[0] else "")
        lines.append(row)
    return lines


def growth(plugin):
    """the tiled scenes with one build: (lines of the table, a column per size)"""
    results, grain_steps = {}, {}
    for copies, steps in GROWTH_STEPS.items():
        scene = tiled(copies)
        with tempfile.TemporaryDirectory() as work:
            counts = profile(os.path.abspath(plugin), scene, steps, work)
        label = "%d grains" % scene[0]
        results[label], grain_steps[label] = sections(counts), steps * scene[0]
    return (["Instructions of the run loop per grain-step (callgrind, inclusive): the reduced "
             "example (-var fast 1, one rank) tiled c x c x c with its fluid cells, c = %s, "
             "for %s steps." % (", ".join(map(str, GROWTH_STEPS)),
                                ", ".join(map(str, GROWTH_STEPS.values()))), ""] +
            table(results, grain_steps))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("builds", nargs="+", help="LABEL=PLUGIN_DIR[,NAME=VALUE...]")
    ap.add_argument("--scene", choices=sorted(SCENES) + ["growth"], default="reduced")
    ap.add_argument("--steps", type=int)
    ap.add_argument("--markdown", help="write the table here too")
    args = ap.parse_args()
    if args.scene == "growth":
        (_, plugin, _), = (configuration(b) for b in args.builds)
        lines = growth(plugin)
    else:
        grains, variables = SCENES[args.scene]
        steps = args.steps or (STEPS if args.scene == "reduced" else S1_STEPS)
        results = {}
        for label, plugin, settings in (configuration(b) for b in args.builds):
            with tempfile.TemporaryDirectory() as work:
                results[label] = sections(profile(plugin, SCENES[args.scene], steps, work,
                                                  settings))
        lines = ["Instructions of the run loop per grain-step of the scene (callgrind, "
                 "inclusive): %s, %s, one rank, %d steps of %d grains." % (
                     args.scene, " ".join("-var %s %s" % kv for kv in variables.items()),
                     steps, grains), ""] + table(results, {k: steps * grains for k in results})
    print("\n".join(lines))
    if args.markdown:
        open(args.markdown, "w").write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
