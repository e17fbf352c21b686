#!/usr/bin/python3
"""The Table S1-sized step timed per rank: LAMMPS' own timer (Pair, Neigh, Comm, Output,
Modify, Other: min, mean and max over the ranks) and µs per step, for builds of the plugin
and MPI processor grids side by side, run after run in turn (ABAB...) so that the machine's
drift falls on all of them; the load average before and after each run recorded.

The scene is bench/step_cost.py's `table_s1` (the default bed replicated 2 x 2 x 2, 9,600
grains, -var full 1 -var fast 1 at the k_n it was consolidated at) or `reduced` (the
example, -var fast 1), STEPS steps on RANKS ranks. Time is the machine's: run it alone (no tests, no other benchmark beside it).

Usage (source scripts/env.sh first):
    /usr/bin/python3 bench/step_time.py [--steps N] [--repeat K] [--markdown FILE] \
        LABEL=PLUGIN_DIR[@COMMIT][#GRID] ...
COMMIT: the example's inputs as of that commit (a build older than today's inputs); GRID:
in.tidal_shear's -var processor_grid, e.g. '#2 1 1' (the grid LAMMPS used is read from
its log).
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from example_runs import EXAMPLE, run_lmp    # noqa: E402
from step_cost import SCENES, prepare_scene    # noqa: E402

STEPS, RANKS, REPEAT = 20000, 2, 3
SECTIONS = ("Pair", "Neigh", "Comm", "Output", "Modify", "Other")


def parse_build(text):
    """LABEL=PLUGIN_DIR[@COMMIT][#GRID] -> (label, plugin dir, commit or None, grid or None)"""
    label, rest = text.split("=", 1)
    rest, _, grid = rest.partition("#")
    plugin, _, commit = rest.partition("@")
    return label, os.path.abspath(plugin), commit or None, grid or None


def inputs_at(commit, work):
    """the example's in.* files as of commit, over the current ones in work"""
    root = os.path.dirname(HERE)    # ls-tree's paths are relative to the folder it runs in
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
    for name, lo, avg, hi in re.findall(
            r"^(%s)\s*\|\s*([0-9.eE+-]+)\s*\|\s*([0-9.eE+-]+)\s*\|\s*([0-9.eE+-]+)\s*\|" %
            "|".join(SECTIONS), text, re.M):
        old = sections.get(name, (0.0, 0.0, 0.0))
        sections[name] = tuple(a + float(b) for a, b in zip(old, (lo, avg, hi)))
    grid = re.search(r"(\d+ by \d+ by \d+) MPI processor grid", text)
    nlocal = re.findall(r"Nlocal:\s+([0-9.]+) ave\s+(\d+) max\s+(\d+) min", text)
    return (sections, sum(float(s) for s, _ in loops), sum(int(n) for _, n in loops),
            grid.group(1) if grid else "?", "%s-%s" % nlocal[-1][2:0:-1] if nlocal else "?")


def timed_scene(scene, plugin, commit, grid, steps, ranks):
    """one run of a scene: (timer breakdown, load before, load after)"""
    _, variables = SCENES[scene]
    variables = dict(variables, run_steps=steps)
    if grid:
        variables["processor_grid"] = grid
    with tempfile.TemporaryDirectory() as work:
        env = dict(os.environ, LD_LIBRARY_PATH=plugin + ":" + os.environ.get("LD_LIBRARY_PATH", ""))
        variables = prepare_scene(variables, work, env)
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


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("builds", nargs="+", help="LABEL=PLUGIN_DIR[@COMMIT][#GRID]")
    ap.add_argument("--scene", choices=sorted(SCENES), default="table_s1")
    ap.add_argument("--steps", type=int, default=STEPS)
    ap.add_argument("--ranks", type=int, default=RANKS)
    ap.add_argument("--repeat", type=int, default=REPEAT)
    ap.add_argument("--markdown", help="write the table here too")
    args = ap.parse_args()
    builds = [parse_build(b) for b in args.builds]
    results = {b[0]: [] for b in builds}
    for k in range(args.repeat):
        for label, plugin, commit, grid in builds:
            results[label].append(timed_scene(args.scene, plugin, commit, grid, args.steps,
                                              args.ranks))
            print("%s run %d: %.1f s" % (label, k + 1, results[label][-1][1]), flush=True)
    lines = ["LAMMPS' timer of bench/step_cost.py's scene `%s` (%s), "
             "%d steps on %d ranks, builds run in turn, %d times each." % (
                 args.scene, " ".join("-var %s %s" % kv for kv in SCENES[args.scene][1].items()),
                 args.steps, args.ranks, args.repeat), ""] + table(results, args.steps)
    print("\n".join(lines))
    if args.markdown:
        open(args.markdown, "w").write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
