#!/usr/bin/python3
"""The Table S1-sized step timed per rank: LAMMPS' own timer (Pair, Neigh, Comm, Output,
Modify, Other: min, mean and max over the ranks) and µs per step, for builds of the plugin
and MPI processor grids side by side, run after run in turn (ABAB...) so that the machine's
drift falls on all of them; the load average before and after each run recorded.

The scene is bench/common/beds.py's `table_s1` (the default bed replicated 2 x 2 x 2, 9,600
grains, -var full 1 -var fast 1 at the k_n it was consolidated at) or `reduced` (the
example, -var fast 1), STEPS steps on RANKS ranks. Time is the machine's: run it alone (no tests, no other benchmark beside it).

Usage (source scripts/env.sh first):
    /usr/bin/python3 bench/step_cost/step_time.py [--steps N] [--repeat K] [--markdown FILE] \
        LABEL=PLUGIN_DIR[@COMMIT][#GRID][,NAME=VALUE...] ...
COMMIT: the example's inputs as of that commit (a build older than today's inputs); GRID:
in.tidal_shear's -var processor_grid, e.g. '#2 1 1' (the grid LAMMPS used is read from
its log); NAME=VALUE: further -var settings of that configuration (e.g. ',one_pass=0').

    /usr/bin/python3 bench/step_cost/step_time.py --growth [--repeat K] [--markdown FILE] \
        [--figure PNG] [--gpu-json JSON] PLUGIN_DIR      (PLUGIN_DIR "replot": the figure
                                                          again from the --markdown table)
the reduced example tiled 1, 2, 4 times per side (common.beds.tiled: 1,200, 9,600,
76,800 grains, the fluid cells tiled with it) on 1 and 2 ranks, with and without the pore
water (-var fluid 0): µs per step and per grain-step, and the fluid's share of the step
(1 - dry / wet), every configuration in turn, K times; the fastest run of each.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import EXAMPLE, REPO, short    # noqa: E402
from common.beds import SCENES, prepare_scene, tiled    # noqa: E402
from common.runs import run_lmp    # noqa: E402
from step_cost import with_settings    # noqa: E402  (this study's own)

STEPS, RANKS, REPEAT = 20000, 2, 3
# growth: copies per side -> steps (multiples of the time series' 575 and the fluid's 25)
GROWTH_TIMED_STEPS = short({1: 23000, 2: 5750, 4: 1150}, {1: 575, 2: 25})
SECTIONS = ("Pair", "Neigh", "Comm", "Output", "Modify", "Other")


def parse_build(text):
    """LABEL=PLUGIN_DIR[@COMMIT][#GRID][,NAME=VALUE...] -> (label, plugin dir, commit or None,
    grid or None, {NAME: VALUE})"""
    label, rest = text.split("=", 1)
    rest, settings = with_settings(rest)
    rest, _, grid = rest.partition("#")
    plugin, _, commit = rest.partition("@")
    return label, os.path.abspath(plugin), commit or None, grid or None, settings


def inputs_at(commit, work):
    """the example's in.* files as of commit, over the current ones in work"""
    root = REPO    # ls-tree's paths are relative to the folder it runs in
    folder = os.path.relpath(EXAMPLE, root)
    names = subprocess.run(["git", "-C", root, "ls-tree", "--name-only", commit, folder + "/"],
                           capture_output=True, text=True, check=True).stdout.split()
    for path in names:
        if os.path.basename(path).startswith("in."):
            text = subprocess.run(["git", "-C", root, "show", "%s:%s" % (commit, path)],
                                  capture_output=True, text=True, check=True).stdout
            open(os.path.join(work, os.path.basename(path)), "w").write(text)


def timer_breakdown(log):
    """{section: (min, avg, max) seconds} summed over the log's runs, loop seconds, steps,
    the processor grid, the fewest-most grains on a rank at the end"""
    text = open(log).read()
    loops = re.findall(r"Loop time of ([0-9.eE+]+) on \d+ procs for (\d+) steps", text)
    sections = {}
    # LAMMPS prints only the mean of "Other" (its min and max columns blank): taken for all three
    for name, lo, avg, hi in re.findall(
            r"^(%s)\s*\|\s*([0-9.eE+-]*)\s*\|\s*([0-9.eE+-]+)\s*\|\s*([0-9.eE+-]*)\s*\|" %
            "|".join(SECTIONS), text, re.M):
        lo, hi = lo or avg, hi or avg
        old = sections.get(name, (0.0, 0.0, 0.0))
        sections[name] = tuple(a + float(b) for a, b in zip(old, (lo, avg, hi)))
    grid = re.search(r"(\d+ by \d+ by \d+) MPI processor grid", text)
    nlocal = re.findall(r"Nlocal:\s+([0-9.]+) ave\s+(\d+) max\s+(\d+) min", text)
    return (sections, sum(float(s) for s, _ in loops), sum(int(n) for _, n in loops),
            grid.group(1) if grid else "?", "%s-%s" % nlocal[-1][2:0:-1] if nlocal else "?")


def timed_scene(scene, plugin, commit, grid, steps, ranks, settings=None, bed=None):
    """one run of a scene (a SCENES name, or -var overrides) with a configuration's own -var
    settings, on the bed file `bed` if given: (timer breakdown, load before, load after)"""
    variables = SCENES[scene][1] if isinstance(scene, str) else scene
    variables = dict(variables, run_steps=steps, **(settings or {}))
    if grid:
        variables["processor_grid"] = grid
    with tempfile.TemporaryDirectory() as work:
        env = dict(os.environ, LD_LIBRARY_PATH=plugin + ":" + os.environ.get("LD_LIBRARY_PATH", ""))
        variables = prepare_scene(variables, work, env, bed)
        if commit:
            inputs_at(commit, work)
        load_before = os.getloadavg()[0]
        run_lmp(work, "in.tidal_shear", variables, ranks=ranks, plugin_dir=plugin)
        return timer_breakdown(os.path.join(work, "log.lammps")) + (load_before,
                                                                      os.getloadavg()[0])


def table(results, steps):
    """a column per build: µs per step (its fastest run; the median and the slowest), then
    each timer section's mean and max over the ranks, µs per step (the fastest run's)"""
    labels = list(results)
    # the fastest run of each: the least disturbed by the shared machine's other tenants
    fastest = {label: min(results[label], key=lambda r: r[1]) for label in labels}
    median = {label: sorted(r[1] for r in results[label])[len(results[label]) // 2]
              for label in labels}
    lines = ["| | " + " | ".join(labels) + " |", "|---|" + "---|" * len(labels)]
    lines.append("| processor grid | " + " | ".join(fastest[l][3] for l in labels) + " |")
    lines.append("| grains per rank at the end (fewest-most) | " + " | ".join(
        fastest[l][4] for l in labels) + " |")
    lines.append("| µs per step: the fastest of %s runs (median, slowest) | %s |" % (
        "/".join(str(len(results[l])) for l in labels), " | ".join(
            "**%.0f** (%.0f, %.0f)" % tuple(1e6 * v / steps for v in (
                fastest[l][1], median[l], max(r[1] for r in results[l])))
            for l in labels)))
    for name in SECTIONS:
        lines.append("| %s: mean / max over ranks (µs per step) | %s |" % (name, " | ".join(
            "%.0f / %.0f" % (1e6 * fastest[l][0].get(name, (0, 0, 0))[1] / steps,
                             1e6 * fastest[l][0].get(name, (0, 0, 0))[2] / steps) for l in labels)))
    lines.append("| load average before / after (each run) | %s |" % " | ".join(
        ", ".join("%.1f/%.1f" % (r[5], r[6]) for r in results[l]) for l in labels))
    return lines


def timed_growth(plugin, repeat):
    """{(grains, ranks, fluid): [timer breakdowns]} of the tiled scenes, all in turn"""
    results = {}
    for k in range(repeat):
        for copies, steps in GROWTH_TIMED_STEPS.items():
            grains, variables = tiled(copies)
            for ranks in (1, 2):
                for fluid in (1, 0):
                    r = timed_scene(dict(variables, fluid=fluid), plugin, None, None, steps, ranks)
                    results.setdefault((grains, ranks, fluid), []).append(r)
                    print("%d grains, %d rank(s), fluid %d, run %d: %.1f us per step" % (
                        grains, ranks, fluid, k + 1, 1e6 * r[1] / r[2]), flush=True)
    return results


def growth_table(results):
    """rows: grains, ranks: the fastest run's us per step and per grain-step, its timer
    sections per grain-step, the fluid's share (1 - the fastest dry / the fastest wet)"""
    lines = ["| grains | ranks | µs per step (fastest; median) | µs per grain-step | Pair | Modify "
             "| Comm | fluid's share of the step | load before/after (each run) |",
             "|---|---|---|---|---|---|---|---|---|"]
    rows = []
    for (grains, ranks, fluid), runs in sorted(results.items()):
        if not fluid:
            continue
        per_step = sorted(r[1] / r[2] for r in runs)
        dry = min(r[1] / r[2] for r in results[(grains, ranks, 0)])
        best = min(runs, key=lambda r: r[1] / r[2])
        sec = lambda name: 1e6 * best[0].get(name, (0, 0, 0))[2] / best[2] / grains
        share = 1.0 - dry / per_step[0]
        rows.append((grains, ranks, 1e6 * per_step[0] / grains, share))
        lines.append("| %d | %d | %.0f (%.0f) | %.4f | %.4f | %.4f | %.4f | %.1f %% | %s |" % (
            grains, ranks, 1e6 * per_step[0], 1e6 * per_step[len(per_step) // 2],
            1e6 * per_step[0] / grains, sec("Pair"), sec("Modify"), sec("Comm"), 100 * share,
            ", ".join("%.1f/%.1f" % (r[5], r[6]) for r in runs)))
    return lines, rows


def growth_rows(markdown):
    """the (grains, ranks, us per grain-step, fluid's share) rows of the first --growth table
    in a markdown file"""
    rows = []
    for line in open(markdown):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 9 and cells[0].isdigit():
            rows.append((int(cells[0]), int(cells[1]), float(cells[3]),
                         float(cells[7].rstrip(" %")) / 100.0))
        elif rows:
            break
    return rows


def growth_figure(rows, path, gpu=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.6))
    for ranks, marker in ((1, "o"), (2, "s")):
        mine = [r for r in rows if r[1] == ranks]
        a.plot([r[0] for r in mine], [r[2] for r in mine], marker=marker, label="%d rank%s" % (
            ranks, "s" if ranks > 1 else ""))
        b.plot([r[0] for r in mine], [100 * r[3] for r in mine], marker=marker)
    if gpu:    # bench/gpu/gpu_check.py's growth rows on a GPU: grains, steps, us per step, per grain-step
        a.plot([r[0] for r in gpu["growth"]], [r[3] for r in gpu["growth"]], marker="^", color="k",
               label="one GPU (%s), /kk" % gpu.get("device", "H200"))
        a.set_yscale("log")
    for ax in (a, b):
        ax.set_xscale("log")
        ax.set_xlabel("grains")
    a.set_ylabel("µs per grain-step (fastest run)")
    if not gpu:
        a.set_ylim(bottom=0)
    a.legend()
    b.set_ylabel("pore water's share of the step (%)")
    b.axhline(10, color="grey", lw=0.8, ls="--")
    b.axhline(0, color="grey", lw=0.8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("builds", nargs="+", help="LABEL=PLUGIN_DIR[@COMMIT][#GRID][,NAME=VALUE...]")
    ap.add_argument("--scene", choices=sorted(SCENES), default="table_s1")
    ap.add_argument("--steps", type=int, default=STEPS)
    ap.add_argument("--bed", help="the scene's grains from this data file (e.g. the prepared "
                    "Table S1 bed, common.beds.prepare_full) instead of the replicated bed")
    ap.add_argument("--ranks", type=int, default=RANKS)
    ap.add_argument("--repeat", type=int, default=REPEAT)
    ap.add_argument("--markdown", help="write the table here too")
    ap.add_argument("--growth", action="store_true", help="the tiled scenes, one build")
    ap.add_argument("--figure", help="--growth: the figure's PNG")
    ap.add_argument("--gpu-json", help="--growth: bench/gpu/gpu_check.py's gpu_check.json, its growth "
                    "rows drawn beside (measured on a GPU machine)")
    args = ap.parse_args()
    if args.growth and args.builds == ["replot"]:    # the figure again from --markdown's table
        growth_figure(growth_rows(args.markdown), args.figure,
                      json.load(open(args.gpu_json)) if args.gpu_json else None)
        return
    if args.growth:
        (plugin,) = args.builds
        lines, rows = growth_table(timed_growth(os.path.abspath(plugin), args.repeat))
        lines = ["LAMMPS' timer of the reduced example (-var fast 1) tiled c x c x c, c = %s, "
                 "for %s steps, on 1 and 2 ranks, wet and dry (-var fluid 0), all in turn, %d "
                 "times each; per grain-step: the fastest run's, the timer's sections their "
                 "largest rank's." % (", ".join(map(str, GROWTH_TIMED_STEPS)),
                                      ", ".join(map(str, GROWTH_TIMED_STEPS.values())), args.repeat),
                 ""] + lines
        print("\n".join(lines))
        if args.markdown:
            open(args.markdown, "w").write("\n".join(lines) + "\n")
        if args.figure:
            growth_figure(rows, args.figure, json.load(open(args.gpu_json)) if args.gpu_json else None)
        return
    builds = [parse_build(b) for b in args.builds]
    results = {b[0]: [] for b in builds}
    for k in range(args.repeat):
        for label, plugin, commit, grid, settings in builds:
            results[label].append(timed_scene(args.scene, plugin, commit, grid, args.steps,
                                              args.ranks, settings, args.bed and os.path.abspath(args.bed)))
            print("%s run %d: %.1f s" % (label, k + 1, results[label][-1][1]), flush=True)
    own = "; ".join("%s: %s" % (b[0], " ".join("-var %s %s" % kv for kv in b[4].items()))
                    for b in builds if b[4])
    lines = ["LAMMPS' timer of the scene `%s` (%s)%s%s, "
             "%d steps on %d ranks, builds run in turn, %d times each." % (
                 args.scene, " ".join("-var %s %s" % kv for kv in SCENES[args.scene][1].items()),
                 " with each configuration's own settings over those (%s)" % own if own else "",
                 " on the bed %s" % os.path.basename(args.bed) if args.bed else "",
                 args.steps, args.ranks, args.repeat), ""] + table(results, args.steps)
    print("\n".join(lines))
    if args.markdown:
        open(args.markdown, "w").write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
