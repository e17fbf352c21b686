#!/usr/bin/python3
"""What moves the creep exponent and the suction under the plate: cases that each change one
thing of the default example, as ensembles read by both estimators (bench/RESULTS_fidelity.md,
"What moves the creep exponent").

Every case runs as the default's ensemble does (bench/ensemble.py): CASE_MEMBERS members,
member 0 unperturbed, member K with its sheared bed moved by up to 1e-12 m (seed K), 4 cycles
on 1 rank, two side by side; metrics over cycles 2-4 by our estimators and the original's
(porewater_analysis). The cases, their parameters fixed before any of their runs:

  face0.14  the default, run again with the time series' p_top_layer column (the mean
            pressure of the topmost active fluid layer, f_darcy[13]): the suction right under
            the plate. Its members repeat the default ensemble's first members exactly (the
            plugin changed since by no result): the report says whether every column agrees.
  face0.27, face0.40  the fluid cells' height set so that the drained face (the top of the
            3 active layers) sits 0.27 and 0.40 of a cell under the plate's mean height in
            cycles 2-4 of the default ensemble (PLATE_MEAN); the default's face sits 0.14 cell
            under it (0.055 at the start). 0.40 is the most that keeps 3 layers: the 4th
            layer's centre, 3.5 cells, stays above the plate's highest point in those cycles
            (PLATE_TOP); half a cell would switch it on whenever the plate rises, and the face
            would jump a cell. The groups (mu_f, the plate mass) depend on H and phi, not on
            the cells: kept.

Usage (source scripts/env.sh first for --run):
    /usr/bin/python3 bench/creep_factors.py [--work DIR] [--run CASE[,CASE] [--members K]]
writes bench/creep_factors_results.md and bench/creep_factors.png.
"""
import argparse
import glob
import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from ensemble import AGAINST_PAPER, METRICS, mean_band, run_metrics, summary
from example_runs import head_commit, load, read_cost
from time_to_solution import CYCLES, KEEP, PERIOD, band, freeze_plugin, members, run_one

HERE = os.path.dirname(os.path.abspath(__file__))

PLATE_MEAN, PLATE_TOP = 0.2566, 0.2624   # m: the plate in cycles 2-4, default ensemble (8 runs)
CELL_Z = 0.08176                         # the default bed's fluid cells (in.bed_original)
LAYERS = 3                               # active fluid layers under the plate


def face_cell(offset):
    """cell height that puts the face of LAYERS cells `offset` cells under PLATE_MEAN"""
    return PLATE_MEAN / (LAYERS + offset)


# case: (label, in.tidal_shear -var overrides)
CASES = {
    "face0.14": ("drained face 0.14 cell under the plate (the default)", {}),
    "face0.27": ("drained face 0.27 cell under the plate", {"cell_z": face_cell(0.27)}),
    "face0.40": ("drained face 0.40 cell under the plate", {"cell_z": face_cell(0.40)}),
}
CASE_MEMBERS = 4
# the table's columns: metric keys of bench/ensemble.py (ours, then the original's)
COLUMNS = ["n", "n_original", "z_creep", "z_creep_original", "z_min", "z_min_original",
           "onset", "exit_onset", "end", "exit_end", "stick_fraction", "slip", "suction",
           "suction_top"]


def case_members(case, count=CASE_MEMBERS):
    return {"%s_%s" % (case, name): dict(CASES[case][1], **variables)
            for name, variables in members("member", count).items()}


def run_cases(work, cases, count, jobs=2):
    """the members of the cases, member by member across the cases (both cores busy)"""
    freeze_plugin(work, "factors")
    runs = [(name, v) for k in range(count) for case in cases
            for name, v in list(case_members(case, count).items())[k:k + 1]]
    pool = ThreadPoolExecutor(jobs)
    for name, cpu in pool.map(lambda nv: run_one(work, *nv), runs):
        print("%s: %s" % (name, "done before" if cpu is None else "%.0f s CPU" % cpu), flush=True)


def face_offset(work, name, cell_z):
    """(the drained face's mean depth under the plate in cells, cycles 2-4; the share of
    those samples with the plate above the 4th layer's centre) of a run"""
    c = load(os.path.join(work, name, "timeseries.txt"))
    kept = (c["time"] > (KEEP[0] - 1) * PERIOD) & (c["time"] <= KEEP[-1] * PERIOD)
    z = c["z_wall"][kept]
    return (np.mean(z) - LAYERS * cell_z) / cell_z, np.mean(z > (LAYERS + 0.5) * cell_z)


def identical_to_default(work, case):
    """the case's members against the default ensemble's of the same seed: the columns both
    have, how many agree in every row, and the largest relative difference otherwise"""
    lines = []
    for name in sorted(glob.glob(os.path.join(work, case + "_member*"))):
        twin = os.path.join(work, os.path.basename(name).split("_", 1)[1])
        a, b = (load(os.path.join(d, "timeseries.txt")) for d in (name, twin))
        rows = min(len(a["time"]), len(b["time"]))
        common = [k for k in a if k in b]
        differ = {k: float(np.max(np.abs(a[k][:rows] - b[k][:rows]) /
                                  np.maximum(np.abs(b[k][:rows]), 1e-300)))
                  for k in common if not np.array_equal(a[k][:rows], b[k][:rows])}
        lines.append("- %s against %s: %d rows, %d of %d columns identical%s" % (
            os.path.basename(name), os.path.basename(twin), rows, len(common) - len(differ),
            len(common), "" if not differ else "; largest relative difference %s" % ", ".join(
                "%s %.1e" % kv for kv in sorted(differ.items(), key=lambda kv: -kv[1])[:3])))
    return lines


def ensembles(work):
    """[(label, {name: metrics}, cell_z)]: the default's ensemble, then every case run"""
    default = {n: run_metrics(work, n) for n in members()}
    out = [("the default ensemble", {n: m for n, m in default.items() if m}, CELL_Z)]
    for case, (label, variables) in CASES.items():
        names = sorted(os.path.basename(d) for d in glob.glob(os.path.join(work, case + "_member*")))
        runs = {n: run_metrics(work, n) for n in names}
        runs = {n: m for n, m in runs.items() if m}
        if runs:
            out.append((label, runs, variables.get("cell_z", CELL_Z)))
    return out


def reference_row():
    """the paper's or the original data file's value under the original's estimator's column"""
    ref = {original: text.split(" (")[0] for _, text, _, original in AGAINST_PAPER}
    return "| the paper / the original's data file | | | " + " | ".join(
        ref.get(k, "") if k.endswith("_original") or k.startswith("exit") or k == "stick_fraction"
        else "" for k in COLUMNS) + " |"


def table(work):
    labels = {k: label for k, label, _, _ in METRICS}
    lines = ["| case | runs | face under the plate (cell; 4th layer on) | " +
             " | ".join(labels[k] for k in COLUMNS) + " | CPU s per run |",
             "|---|---|---|" + "---|" * (len(COLUMNS) + 1), reference_row()]
    for label, ens, cell_z in ensembles(work):
        faces = [face_offset(work, n, cell_z) for n in ens]
        cpu = [read_cost(os.path.join(work, n))[0] for n in ens]
        lines.append("| %s | %d | %.2f (%.1f %%) | %s | %s |" % (
            label, len(ens), np.mean([f[0] for f in faces]), 100 * max(f[1] for f in faces),
            " | ".join(mean_band(ens, k) for k in COLUMNS),
            "%.0f-%.0f" % (min(cpu), max(cpu))))
    return lines


def plot(work, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 4))
    rows = ensembles(work)
    for x, (label, ens, _) in enumerate(rows):
        for dx, key, colour, name in ((-0.15, "n", "C0", "ours"),
                                      (0.15, "n_original", "C3", "the original's fit")):
            v = summary(ens, key)
            ax.plot(x + dx + 0.04 * np.linspace(-1, 1, len(v)), v, "o", color=colour, ms=3,
                    alpha=0.6)
            if len(v) >= 3:
                mean, half = band(v)
                ax.errorbar(x + dx, mean, yerr=half, fmt="s", color=colour, capsize=3,
                            label=name if x == 0 else None)
    ax.axhspan(6, 11, color="0.85", label="the paper: 6-11")
    ax.set_xticks(range(len(rows)))
    ax.set_xticklabels([label.replace(" under the plate", "\nunder the plate")
                        for label, _, _ in rows], fontsize=7)
    ax.set_ylabel("creep exponent n, cycles 2-4\n(mean ± 95 % band; dots: members)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def report(work):
    commit = head_commit()
    lines = ["# What moves the creep exponent: bench/creep_factors.py", "",
             "Written at commit %s from the runs in `%s` (examples/tidal_shear, %d cycles each, "
             "1 rank, two side by side; metrics over cycles %d-%d, mean ± the 95 %% prediction "
             "band of one more run). The reference values stand under the original's "
             "estimators only." % (commit, work, CYCLES, KEEP[0], KEEP[-1]), ""]
    lines += table(work)
    lines += ["", "The default's members run again (face0.14) against the default ensemble's:",
              ""] + identical_to_default(work, "face0.14")
    plot(work, os.path.join(HERE, "creep_factors.png"))
    lines += ["", "![n per case, both estimators](creep_factors.png)"]
    open(os.path.join(HERE, "creep_factors_results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", default="/tmp/pw_time_to_solution")
    ap.add_argument("--run", help="comma-separated cases to run (then report)")
    ap.add_argument("--members", type=int, default=CASE_MEMBERS)
    args = ap.parse_args()
    if args.run:
        run_cases(args.work, args.run.split(","), args.members)
    report(args.work)


if __name__ == "__main__":
    main()
