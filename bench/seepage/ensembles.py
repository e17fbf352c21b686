#!/usr/bin/python3
"""What the full seepage force changes in the paper's cycle: the ensembles of
examples/tidal_shear with `-var seepage full` beside the paper's force (`pressure`), at the
default permeability and in the low-permeability twin (k_c 3.5e-15), by both estimators.

ENSEMBLES: four ensembles of MEMBERS runs each, CYCLES (4) cycles, 1 rank per run, two side by
side (bench/common/ensembles.py's run_one: member0 the unperturbed start, member K its sheared
bed moved at random by up to PERTURB with seed K, the same starts in every ensemble). Per
run the metrics of bench/common/ensembles.py over cycles 2-4 by our estimators and the original's
(slip, suction in slip and under the plate, n, coordination, stick...); per ensemble the
mean and 95 % prediction band; full against pressure, at each permeability: the difference
of the means with its 95 % interval (Welch) and whether it is outside it family-wise.

Usage (source scripts/env.sh first):
    /usr/bin/python3 bench/seepage/ensembles.py --run [--only default_full,twin_full]
        [--members K] [--work DIR]        the runs (those complete in DIR are not repeated)
    /usr/bin/python3 bench/seepage/ensembles.py                 the report only
    /usr/bin/python3 bench/seepage/ensembles.py --dry STEPS     member0 of default and
        default_full for STEPS steps: the log says which force, and the time series part
writes bench/seepage/ensembles_results.md.
"""
import argparse
import os
import sys
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import out_dir    # noqa: E402
from common.ensembles import (CYCLES, KEEP, METRICS, compare_ensembles, mean_band,    # noqa: E402
                              members, run_metrics, run_one)
from common.runs import chunks_cpu, freeze_plugin, head_commit, prepare, run_lmp    # noqa: E402

WORK = "/work/runs/seepage_ensembles"
MEMBERS = 4
TWIN_KC = 3.5e-15
# name: (label, in.tidal_shear -var overrides)
ENSEMBLES = {
    "default": ("default, seepage pressure (the paper's)", {}),
    "default_full": ("default, seepage full", {"seepage": "full"}),
    "twin": ("twin (k_c 3.5e-15), seepage pressure", {"kc": TWIN_KC}),
    "twin_full": ("twin (k_c 3.5e-15), seepage full", {"kc": TWIN_KC, "seepage": "full"}),
}
PAIRS = [("default", "default_full"), ("twin", "twin_full")]


def runs(only, count):
    """[(run name, -var overrides)] of the ensembles named in only, member by member (so that
    the two cores finish the ensembles' first members first)"""
    out = []
    for member, perturbation in members("member", count).items():
        for name in only:
            out.append(("%s_%s" % (name, member), dict(ENSEMBLES[name][1], **perturbation)))
    return out


def run_all(work, only, count, jobs=2):
    freeze_plugin(work, "seepage")
    pool = ThreadPoolExecutor(jobs)
    for name, cpu in pool.map(lambda nv: run_one(work, *nv), runs(only, count)):
        print("%s: %s" % (name, "done before" if cpu is None else "%.0f s CPU" % cpu), flush=True)


def ensemble(work, name, count):
    found = {n: run_metrics(work, n) for n, _ in runs([name], count)}
    return {n: m for n, m in found.items() if m}


def dry(work, steps):
    """member0 of the paper's force and of the full one for `steps` steps"""
    series = {}
    for name in ("default", "default_full"):
        d = os.path.join(work, "dry", name)
        prepare(d)
        run_lmp(d, "in.tidal_shear", dict(ENSEMBLES[name][1], run_steps=steps, samples=10000))
        log = open(os.path.join(d, "log.lammps")).read()
        said = [line for line in log.splitlines() if line.startswith("fix darcy/pressure darcy: seepage")]
        print("%s: %s" % (name, said[0] if said else "no seepage line in the log (seepage pressure)"))
        series[name] = [line.split() for line in open(os.path.join(d, "timeseries.txt"))
                        if not line.startswith("#")]
    columns = open(os.path.join(work, "dry", "default", "timeseries.txt")).readline().split()[1:]
    a, b = series["default"], series["default_full"]
    first = next((k for k in range(min(len(a), len(b))) if a[k] != b[k]), None)
    if first is None:
        print("the time series are the same: the option did not take effect")
        return 1
    print("the time series part at row %d (t = %s s); the last row:" % (first + 1, a[first][0]))
    for column, x, y in zip(columns, a[-1], b[-1]):
        print("  %-20s pressure %-24s full %s" % (column, x, y))
    return 0


def report(work, count):
    ens = {name: ensemble(work, name, count) for name in ENSEMBLES}
    lines = ["# The full seepage force in the paper's cycle: bench/seepage/ensembles.py", "",
             "Written at commit %s from the runs in `%s` (examples/tidal_shear, %d cycles each, "
             "1 rank; metrics over cycles %d-%d: the mean of the cycles, n pooled over their "
             "samples). Ours: porewater_analysis.cycles; the original's: "
             "porewater_analysis.original (analysis/README.md)." % (
                 head_commit(), work, CYCLES, KEEP[0], KEEP[-1]), ""]
    for name, (label, _) in ENSEMBLES.items():
        # the completed chunks of every leg: a run stopped and continued counts its lost
        # part once (the legs' cost.txt rows miss a killed leg)
        cost = [chunks_cpu(os.path.join(work, n))[0] for n in ens[name]]
        if cost:
            lines.append("%s: %d runs, %.0f-%.0f CPU s each." % (
                label, len(ens[name]), min(cost), max(cost)))
    lines += ["", "## Each ensemble: mean ± 95 % prediction band of one more run", "",
              "| metric | " + " | ".join("%s (%d)" % (ENSEMBLES[n][0], len(ens[n])) for n in ENSEMBLES)
              + " |", "|---|" + "---|" * len(ENSEMBLES)]
    for key, label, _, _ in METRICS:
        lines.append("| %s | %s |" % (label, " | ".join(mean_band(ens[n], key) for n in ENSEMBLES)))
    for pressure, full in PAIRS:
        lines += ["", "## %s against %s" % (ENSEMBLES[full][0], ENSEMBLES[pressure][0]), ""]
        lines += compare_ensembles(ens[pressure], ens[full], ("pressure", "full", "full - pressure"))
    open(os.path.join(out_dir(HERE), "ensembles_results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", default=WORK)
    ap.add_argument("--run", action="store_true", help="run the ensembles' missing members")
    ap.add_argument("--only", default=",".join(ENSEMBLES),
                    help="comma-separated ensembles to run (%s)" % ", ".join(ENSEMBLES))
    ap.add_argument("--members", type=int, default=MEMBERS)
    ap.add_argument("--dry", type=int, default=0, metavar="STEPS",
                    help="only the dry run of member0 of default and default_full")
    args = ap.parse_args()
    if args.dry:
        return dry(args.work, args.dry)
    if args.run:
        only = [n for n in args.only.split(",") if n]
        unknown = [n for n in only if n not in ENSEMBLES]
        if unknown:
            sys.exit("unknown ensemble(s) %s: %s" % (", ".join(unknown), ", ".join(ENSEMBLES)))
        run_all(args.work, only, args.members)
    report(args.work, args.members)
    return 0


if __name__ == "__main__":
    sys.exit(main())
