#!/usr/bin/python3
"""The paper's numbers on the ensembles of examples/tidal_shear, read by both estimators, the
package's and the original program's (analysis/porewater_analysis), and whether 2 MPI ranks
shift them.

The runs (bench/common/ensembles.py): `--run default` (ENSEMBLE members on 1 rank, two side by
side) and `--run np2` (NP2_ENSEMBLE on 2 ranks, one at a time), CYCLES cycles each, every
member but member0 with its sheared bed moved at random by up to PERTURB (seed K: the same
start on either layout). bench/time_to_solution makes the same runs (--part ensemble,
ensemble_np2) in the same folders. Per run: each metric over cycles 2-4 (the mean of the
cycles; n pooled over their creep samples). Per ensemble: mean, standard deviation, the 95 %
prediction band of one more run. 2 ranks against 1 rank: the difference of the means, its 95 %
interval (Welch), and whether it is outside that interval family-wise (Bonferroni over the
metrics compared).

The other cases (CASES: the frictionless bed, the original preset, the low-permeability twin),
CASE_MEMBERS members each on 1 rank, by `--run CASE`, two side by side; their table beside
the default's in the report.

Usage (source scripts/env.sh first for --run):
    /usr/bin/python3 bench/fidelity/ensemble.py [--work DIR] [--run default|np2|CASE [--members K]]
writes bench/fidelity/ensemble_results.md and ensemble.png.
"""
import argparse
import glob
import os
import re
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import out_dir    # noqa: E402
from common.ensembles import (AGAINST_PAPER, CYCLES, KEEP, METRICS, band,    # noqa: E402
                              compare_ensembles, mean_band, members, np2_members, run_metrics,
                              run_one, summary)
from common.runs import freeze_plugin, head_commit, read_cost    # noqa: E402

# the cases beside the default: in.tidal_shear -var overrides
CASES = {
    "frictionless": ("the frictionless bed (the former default)", {"bed": "frictionless"}),
    "original": ("the original preset (-var original 1)", {"original": 1}),
    "twin": ("the low-permeability twin (k_c 3.5e-15)", {"kc": 3.5e-15}),
}
CASE_MEMBERS = 4
# the metrics of the cases' table
CASE_METRICS = ["n", "n_original", "z_creep", "z_creep_original", "z_min", "z_min_original",
                "z_min_after", "z_min_after_original", "onset", "exit_onset", "end", "exit_end",
                "stick_fraction", "slip"]


def case_members(case, count=CASE_MEMBERS):
    """name: -var overrides of a case's runs, perturbed as the default's members"""
    return {"%s_%s" % (case, name): dict(CASES[case][1], **variables)
            for name, variables in members("member", count).items()}


def run_case(work, case, count, jobs=2):
    """the members of a case, of the default (1 rank) or of the default on 2 ranks (one at a
    time: both cores)"""
    freeze_plugin(work, case)
    ranks = 2 if case == "np2" else 1
    runs = {"default": members(), "np2": np2_members()}.get(case) or case_members(case, count)
    pool = ThreadPoolExecutor(1 if ranks > 1 else jobs)
    for name, cpu in pool.map(lambda nv: run_one(work, *nv, ranks=ranks), runs.items()):
        print("%s: %s" % (name, "done before" if cpu is None else "%.0f s CPU" % cpu), flush=True)


def cases_table(work, default):
    """a row per metric, a column per case with runs in work: mean ± the 95 % band (3 runs or
    more), or the mean of its runs; the paper's or the original data file's value beside the
    original's estimator only (ours is not its definition)"""
    labels = {k: label for k, label, _, _ in METRICS}
    reference = {original: ref for _, ref, _, original in AGAINST_PAPER}
    ensembles = [("the default", default)]
    for case, (label, _) in CASES.items():
        names = sorted(os.path.basename(d) for d in glob.glob(os.path.join(work, case + "_member*")))
        runs = {n: run_metrics(work, n) for n in names}    # however many --members ran
        ensembles.append((label, {n: m for n, m in runs.items() if m}))
    ensembles = [(label, ens) for label, ens in ensembles if ens]
    lines = ["| metric | paper / the original's data file | " + " | ".join(
        "%s (%d runs)" % (label, len(ens)) for label, ens in ensembles) + " |",
        "|---|---|" + "---|" * len(ensembles)]
    for key in CASE_METRICS:
        lines.append("| %s | %s | %s |" % (labels[key], reference.get(key, ""), " | ".join(
            mean_band(ens, key) for _, ens in ensembles)))
    lines.append("")
    for label, ens in ensembles[1:]:
        lines += costs(work, ens, 0, "%s, 1 rank (two runs side by side)" % label)
    return lines


def processor_grid(work, name):
    """LAMMPS' processor grid of a run, as its log says ("1 by 1 by 2")"""
    found = re.search(r"(\d+ by \d+ by \d+) MPI processor grid",
                      open(os.path.join(work, name, "log.lammps")).read())
    return found.group(1) if found else "?"


def ensemble_table(label, ens):
    lines = ["| metric | " + " | ".join(ens) + " | mean | sd | band (95 % prediction) |",
             "|---|" + "---|" * (len(ens) + 3)]
    for key, name, scale, f in METRICS:
        v = summary(ens, key)
        cells = " | ".join((f % (scale * m[key])) if key in m else "none" for m in ens.values())
        if len(v) >= 3:
            mean, half = band(v)
            stat = "%s | %s | ± %s" % (f % (scale * mean), f % (scale * v.std(ddof=1)),
                                       f % (scale * half))
        else:
            stat = " | | "
        lines.append("| %s | %s | %s |" % (name, cells, stat))
    return ["### " + label, ""] + lines


def against_paper(one):
    """mean ± the 95 % prediction band of the 1-rank ensemble, by each estimator"""
    lines = ["| | paper / the original's data file | ours, our estimator | ours, the original's "
             "estimator |", "|---|---|---|---|"]
    lines += ["| %s | %s | %s | %s |" % (label, ref, mean_band(one, a) if a else "",
                                         mean_band(one, b)) for label, ref, a, b in AGAINST_PAPER]
    return lines


def costs(work, names, column, label):
    c = [read_cost(os.path.join(work, n)) for n in names]
    c = [x for x in c if x]
    if not c:
        return []
    return ["%s: %.0f-%.0f %s s per run (load before/after %s)." % (
        label, min(x[column] for x in c), max(x[column] for x in c),
        "CPU" if column == 0 else "wall", ", ".join("%.1f/%.1f" % tuple(x[2:4]) for x in c))]


def plot(one, two, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    keys = ["n", "n_original", "z_creep_original", "z_min_original", "slip", "v_creep",
            "stick_fraction", "exit_onset"]
    spec = {k: (label, scale) for k, label, scale, _ in METRICS}
    fig, axes = plt.subplots(2, 4, figsize=(13, 6))
    for ax, key in zip(axes.flat, keys):
        label, scale = spec[key]
        for x, ens, colour in ((0, one, "C0"), (1, two, "C3")):
            v = scale * summary(ens, key)
            ax.plot(x + 0.08 * np.linspace(-1, 1, len(v)), v, "o", color=colour, ms=4)
            if len(v) >= 2:
                ax.errorbar(x + 0.25, v.mean(), yerr=v.std(ddof=1), fmt="s", color=colour)
        ax.set_xticks([0, 1])
        ax.set_xticklabels(["1 rank", "2 ranks"])
        ax.set_title(label, fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=80)


def report(work):
    one = {n: run_metrics(work, n) for n in members()}
    two = {n: run_metrics(work, n) for n in np2_members()}
    one = {n: m for n, m in one.items() if m}
    two = {n: m for n, m in two.items() if m}
    commit = head_commit()
    grids = sorted({processor_grid(work, n) for n in two})
    lines = ["# The ensembles by both estimators: bench/fidelity/ensemble.py", "",
             "Tables written at commit %s from the runs in `%s` (examples/tidal_shear, %d cycles "
             "each; metrics over cycles %d-%d: the mean of the cycles, n pooled over their "
             "samples). Ours: porewater_analysis.cycles; the original's: "
             "porewater_analysis.original (analysis/README.md)." % (
                 commit, work, CYCLES, KEEP[0], KEEP[-1]), ""]
    lines += costs(work, one, 0, "1 rank (two runs side by side)")
    lines += costs(work, two, 1, "2 ranks (%s processor grid, alone on the machine)" % ", ".join(grids))
    lines += ["", "## Against the paper (1 rank: mean ± 95 % prediction band)", ""]
    lines += against_paper(one)
    lines += [""] + ensemble_table("1 rank: %d members" % len(one), one) + [""]
    lines += ensemble_table("2 ranks: %d members" % len(two), two) + [""]
    lines += ["## 2 ranks against 1 rank", ""] + compare_ensembles(one, two)
    lines += ["", "## The cases, by both estimators", ""] + cases_table(work, one)
    out = out_dir(HERE)
    plot(one, two, os.path.join(out, "ensemble.png"))
    lines += ["", "![each member by layout; squares: mean and sd](ensemble.png)"]
    open(os.path.join(out, "ensemble_results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", default="/tmp/pw_time_to_solution")
    ap.add_argument("--run", choices=["default", "np2"] + sorted(CASES),
                    help="run the default's members (1 rank; np2: 2 ranks) or a case's, then report")
    ap.add_argument("--members", type=int, default=CASE_MEMBERS)
    args = ap.parse_args()
    if args.run:
        run_case(args.work, args.run, args.members)
    report(args.work)


if __name__ == "__main__":
    main()
