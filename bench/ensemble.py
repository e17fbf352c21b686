#!/usr/bin/python3
"""The ensembles of examples/tidal_shear read by both estimators, the package's and the
original program's (analysis/porewater_analysis), and whether 2 MPI ranks shift them.

The runs: `time_to_solution.py --part ensemble` (ENSEMBLE members on 1 rank, two side by
side) and `--part ensemble_np2` (NP2_ENSEMBLE on 2 ranks, one at a time), CYCLES cycles each,
every member but member0 with its sheared bed moved at random by up to PERTURB (seed K: the
same start on either layout). Per run: each metric over cycles 2-4 (the mean of the cycles;
n pooled over their creep samples). Per ensemble: mean, standard deviation, the 95 %
prediction band of one more run. 2 ranks against 1 rank: the difference of the means, its 95 %
interval (Welch), and whether it is outside that interval family-wise (Bonferroni over the
metrics compared).

The other cases of bench/RESULTS_fidelity.md (CASES: the frictionless bed, the original
preset, the low-permeability twin), CASE_MEMBERS members each on 1 rank, by `--run CASE`, two
side by side; their table beside the default's in the report.

Usage (source scripts/env.sh first for --run):
    /usr/bin/python3 bench/ensemble.py [--work DIR] [--run CASE [--members K]]
writes bench/ensemble_results.md and bench/ensemble.png.
"""
import argparse
import glob
import os
import re
from concurrent.futures import ThreadPoolExecutor

import numpy as np
from scipy import stats

from example_runs import complete, head_commit, read_cost
from porewater_analysis.cycles import after_min_n
from porewater_analysis.report import analyse_run
from time_to_solution import (CYCLES, KEEP, PERIOD, band, freeze_plugin, members, np2_members,
                              run_one)
from time_to_solution import METRICS as METRICS_OF_KNOBS

HERE = os.path.dirname(os.path.abspath(__file__))

# key, label, scale, format: ours (porewater_analysis.cycles) as the knobs are judged by, and
# the coordination while creeping; the original's (porewater_analysis.original)
OURS = METRICS_OF_KNOBS + [("z_creep", "Z creeping, our count", 1.0, "%.2f"),
                          ("z_min_after", "min Z of our count: cycles after the minimum of N",
                           1.0, "%.3f"),
                          ("suction_top", "suction in slip under the plate (A; top fluid layer)",
                           1.0, "%.3f")]
ORIGINAL = [
    ("n_original", "n, the original's fit (curve_fit)", 1.0, "%.2f"),
    ("z_creep_original", "Z creeping, the original's count", 1.0, "%.2f"),
    ("z_min_original", "min Z, the original's count", 1.0, "%.3f"),
    ("z_min_after_original", "min Z of the original's count: cycles after the minimum of N",
     1.0, "%.3f"),
    ("stick_fraction", "stick fraction (original: v = 0)", 1.0, "%.3f"),
    ("exit_onset", "velocity leaves the creep band (phase)", 1.0, "%.3f"),
    ("exit_end", "velocity back in the band (phase)", 1.0, "%.3f"),
]
METRICS = OURS + ORIGINAL

# the cases of bench/RESULTS_fidelity.md beside the default: in.tidal_shear -var overrides
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
    freeze_plugin(work, case)
    pool = ThreadPoolExecutor(jobs)
    for name, cpu in pool.map(lambda nv: run_one(work, *nv), case_members(case, count).items()):
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


def mean_over_kept(rows, key):
    values = [r[key] for r in rows if r.get(key) is not None]
    return float(np.mean(values)) if len(values) == len(rows) else None


def run_metrics(work, name):
    """{metric: value over cycles KEEP} of a complete run by both estimators, or None"""
    d = os.path.join(work, name)
    if not complete(os.path.join(d, "timeseries.txt"), CYCLES * PERIOD):
        return None
    result = analyse_run(d, cycles=CYCLES)
    kept = [c for c in result["cycles"] if c["cycle"] in KEEP]
    ours = [dict(c["ours"]) for c in kept]
    original = [dict(c["original"]) for c in kept]
    for row in ours + original:    # a collapse in the landing just past the cycle's end
        row["z_min_after"] = after_min_n(row["z_min_phase"])    # stays next to one before it
    out = {key: mean_over_kept(ours, key) for key, _, _, _ in OURS if key != "n"}
    out.update({key: mean_over_kept(original, key.replace("_original", ""))
                for key, _, _, _ in ORIGINAL if key.endswith("_original") and key != "n_original"})
    out.update({key: mean_over_kept(original, key) for key in ("stick_fraction", "exit_onset",
                                                                "exit_end")})
    pooled = result["pooled"]
    out["n"] = pooled["ours"]["n"] if pooled["ours"] else None
    out["n_original"] = None if np.isnan(pooled["original"]["n"]) else pooled["original"]["n"]
    return {k: v for k, v in out.items() if v is not None}


def processor_grid(work, name):
    """LAMMPS' processor grid of a run, as its log says ("1 by 1 by 2")"""
    found = re.search(r"(\d+ by \d+ by \d+) MPI processor grid",
                      open(os.path.join(work, name, "log.lammps")).read())
    return found.group(1) if found else "?"


def summary(ens, key):
    values = np.array([m[key] for m in ens.values() if key in m])
    return values


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


def layout_comparison(one, two, labels=("1 rank", "2 ranks", "2 - 1")):
    """per metric: means, the difference two - one (2 - 1 ranks) with its 95 % interval
    (Welch) and its family-wise verdict; `labels` name one, two and the difference"""
    compared = [k for k, _, _, _ in METRICS if len(summary(one, k)) >= 3 and len(summary(two, k)) >= 3]
    if not compared:
        return ["Not compared: fewer than 3 complete runs on a side (%s, %s)." % labels[:2]]
    family = 1 - 0.05 / (2 * len(compared))
    lines = ["| metric | %s mean (sd) | %s mean (sd) | %s | 95 %% interval | p (Welch) "
             "| outside, family-wise |" % labels, "|---|---|---|---|---|---|---|"]
    shifted = []
    for key, name, scale, f in METRICS:
        if key not in compared:
            continue
        a, b = summary(one, key), summary(two, key)
        va, vb = a.var(ddof=1) / len(a), b.var(ddof=1) / len(b)
        se = np.sqrt(va + vb)
        dof = (va + vb) ** 2 / (va ** 2 / (len(a) - 1) + vb ** 2 / (len(b) - 1)) if se > 0 else 1
        diff = b.mean() - a.mean()
        half, half_family = stats.t.ppf(0.975, dof) * se, stats.t.ppf(family, dof) * se
        p = stats.ttest_ind(b, a, equal_var=False).pvalue if se > 0 else 1.0
        outside = abs(diff) > half_family
        shifted += [name] if outside else []
        lines.append("| %s | %s (%s) | %s (%s) | %s | ± %s | %.3f | %s |" % (
            name, f % (scale * a.mean()), f % (scale * a.std(ddof=1)), f % (scale * b.mean()),
            f % (scale * b.std(ddof=1)), f % (scale * diff), f % (scale * half), p,
            "**yes**" if outside else "no"))
    lines += ["", "Metrics compared: %d; family-wise: t(1 - 0.025/%d) (Bonferroni). Shifted "
              "beyond it: %s." % (len(compared), len(compared), ", ".join(shifted) or "none")]
    return lines


# the paper's and the original data file's values (bench/RESULTS_fidelity.md says where from),
# and the metrics of both estimators that compare with each: label, reference, ours, original's
AGAINST_PAPER = [
    ("creep exponent n, cycles 2-4 pooled", "6-11 (the paper, by the original's fit)", "n",
     "n_original"),
    ("coordination while creeping (phases 0.2-0.6)", "3.49 (3.47-3.51; the original's data file, "
     "cycles 2-9)", "z_creep", "z_creep_original"),
    ("minimum coordination of a cycle", "0.044 (0.036-0.052)", "z_min", "z_min_original"),
    ("its time: cycles after the minimum of N", "0.264 (median)", "z_min_after",
     "z_min_after_original"),
    ("slip onset (phase): ours 1 cm/s; the original's velocity leaves its creep band",
     "~0.61 (its Figure 3)", "onset", "exit_onset"),
    ("slip end (phase)", "~0.81 (its Figure 3)", "end", "exit_end"),
    ("stick: share of the cycle with the original's velocity 0", "(shaded, no number)", None,
     "stick_fraction"),
]


def mean_band(ens, key):
    """a metric of an ensemble as a cell: mean ± the 95 % prediction band (3 runs or more),
    the mean of fewer, "none" without any"""
    scale, f = {k: (scale, f) for k, _, scale, f in METRICS}[key]
    v = summary(ens, key)
    if not len(v):
        return "none"
    return f % (scale * v.mean()) + (" ± " + f % (scale * band(v)[1]) if len(v) >= 3 else "")


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
    lines = ["# The ensembles by both estimators: bench/ensemble.py", "",
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
    lines += ["## 2 ranks against 1 rank", ""] + layout_comparison(one, two)
    lines += ["", "## The cases, by both estimators", ""] + cases_table(work, one)
    plot(one, two, os.path.join(HERE, "ensemble.png"))
    lines += ["", "![each member by layout; squares: mean and sd](ensemble.png)"]
    open(os.path.join(HERE, "ensemble_results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", default="/tmp/pw_time_to_solution")
    ap.add_argument("--run", choices=sorted(CASES), help="run a case's members (then report)")
    ap.add_argument("--members", type=int, default=CASE_MEMBERS)
    args = ap.parse_args()
    if args.run:
        run_case(args.work, args.run, args.members)
    report(args.work)


if __name__ == "__main__":
    main()
