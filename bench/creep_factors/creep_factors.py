#!/usr/bin/python3
"""What moves the creep exponent and the suction under the plate: cases that each change one
thing of the default example, as ensembles read by both estimators (RESULTS.md beside this
script).

Every case runs as the default's ensemble does (bench/fidelity/ensemble.py): CASE_MEMBERS members,
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
  kn10      k_n x10 with the wall dashpot's damping ratio kept (gamma_w x sqrt 10), ε 0.07
            (Δt ÷ 3.2), on the shipped bed consolidated again for 0.05 s at that stiffness
            (bench/common/beds.py: STIFF and RESETTLE), its groups kept for its H, phi.
  kn10_eps0.14  the same at ε 0.14: whether the stiff cases may run at the preset's step
            (its members against kn10's band) before k_n x100 is run.
  kn100_eps0.14  k_n x100 (Table S1's), γ_w x10, ε 0.14 (kn10_eps0.14 stayed inside the
            band), on the shipped bed consolidated again at that stiffness.
  tall      Table S1's H/d 23.5 on the reduced footprint: 2,400 grains packed and
            consolidated with friction MU_TALL (--bisect-tall), the groups kept for its H and
            phi, its fluid cells half the default's height (tall_groups).
  packed0.044  the default's 1,200 grains prepared as the tall bed: whether what the tall
            bed changes is its height or its preparation.

Usage (source scripts/env.sh first for --run):
    /usr/bin/python3 bench/creep_factors/creep_factors.py [--work DIR] [--run CASE[,CASE] [--members K]]
writes creep_factors_results.md and creep_factors.png beside this script, every complete run's
metrics kept in creep_factors_runs.json (the table is rebuilt from it when the runs' folders
are gone); --count: creep_factors_count.md; --bisect-tall: creep_factors_bisect.md. The
short setting (bench/smoke.py): every run a few thousand steps (none complete), the bisection
one round.
"""
import argparse
import glob
import json
import os
import re
import shutil
import textwrap
from concurrent.futures import ThreadPoolExecutor

import sys

import numpy as np
from scipy import stats

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import BENCH, EXAMPLE, SMOKE, out_dir, short    # noqa: E402
from common.beds import (MU_PREP_ORIGINAL, RESETTLE, SHIPPED_FRICTIONLESS, SPREAD, STIFF,    # noqa: E402
                         bed_geometry, bed_groups, bisect_mu_prep, prepare_bed)
from common.ensembles import (AGAINST_PAPER, CYCLES, KEEP, METRICS, PERIOD, band, mean_band,    # noqa: E402
                              members, run_metrics, run_one, summary)
from common.runs import REPLICATE_BED, freeze_plugin, head_commit, load, prepare, read_cost, run_lmp    # noqa: E402

OUT = out_dir(HERE)

PLATE_MEAN, PLATE_TOP = 0.2566, 0.2624   # m: the plate in cycles 2-4, default ensemble (8 runs)
CELL_Z = 0.08176                         # the default bed's fluid cells (in.bed_original)
LAYERS = 3                               # active fluid layers under the plate


def face_cell(offset):
    """cell height that puts the face of LAYERS cells `offset` cells under PLATE_MEAN"""
    return PLATE_MEAN / (LAYERS + offset)


# beds of the cases: in.consolidate -var overrides, the shipped bed they start from
STIFF_BEDS = {name: (dict(STIFF[name], settle_time=RESETTLE), "consolidated_0.data")
              for name in STIFF}
# case: (label, in.tidal_shear -var overrides, the case's bed or None for the shipped one)
CASES = {
    "face0.14": ("drained face 0.14 cell under the plate (the default)", {}, None),
    "face0.27": ("drained face 0.27 cell under the plate", {"cell_z": face_cell(0.27)}, None),
    "face0.40": ("drained face 0.40 cell under the plate", {"cell_z": face_cell(0.40)}, None),
    "kn10": ("k_n x10 (ε 0.07)", STIFF["kn10"], "kn10"),
    "kn10_eps0.14": ("k_n x10 at ε 0.14", dict(STIFF["kn10"], eps=0.14), "kn10"),
    "kn100_eps0.14": ("k_n x100 (Table S1's) at ε 0.14", dict(STIFF["kn100"], eps=0.14), "kn100"),
    "tall": ("Table S1's height (2,400 grains, packed with friction 0.044)", {}, "tall"),
    "packed0.044": ("the default's 1,200 grains packed with friction 0.044 (as the tall bed)",
                    {}, "packed"),
}
CASE_MEMBERS = 4
# the table's columns: metric keys of bench/common/ensembles.py (ours, then the original's)
COLUMNS = ["n", "n_original", "z_creep", "z_creep_original", "z_min", "z_min_original",
           "onset", "exit_onset", "end", "exit_end", "stick_fraction", "slip", "suction",
           "suction_top"]


def case_bed(work, case):
    """the case's bed, consolidated again at its stiffness (once), or None; its -var overrides
    (the data file, the groups kept for its H and phi)"""
    bed = CASES[case][2]
    if bed is None:
        return None, {}
    if bed == "tall":
        data = tall_bed(work, MU_TALL)
        return data, dict(tall_groups(*bed_geometry(data)), data="bed.data")
    if bed == "packed":
        data = prepare_bed(work, "packed_mu%.4f" % MU_TALL,
                           {"radius_spread": SPREAD, "mu_prep": MU_TALL})
        return data, dict(bed_groups(*bed_geometry(data)), data="bed.data")
    data = prepare_bed(work, bed, *STIFF_BEDS[bed])
    return data, dict(bed_groups(*bed_geometry(data)), data="bed.data")


def case_members(work, case, count=CASE_MEMBERS):
    """name: -var overrides of a case's runs, perturbed as the default's members"""
    _, bed_variables = case_bed(work, case)
    return {"%s_%s" % (case, name): dict(CASES[case][1], **bed_variables, **variables)
            for name, variables in members("member", count).items()}


def run_member(work, case, name, variables):
    data, _ = case_bed(work, case)
    if data:
        os.makedirs(os.path.join(work, name), exist_ok=True)
        shutil.copy(data, os.path.join(work, name, "bed.data"))
    return run_one(work, name, variables)


def run_cases(work, cases, count, jobs=2):
    """the members of the cases, member by member across the cases (both cores busy)"""
    freeze_plugin(work, "factors")
    runs = [(case, name, v) for k in range(count) for case in cases
            for name, v in list(case_members(work, case, count).items())[k:k + 1]]
    pool = ThreadPoolExecutor(jobs)
    for name, cpu in pool.map(lambda run: run_member(work, *run), runs):
        print("%s: %s" % (name, "done before" if cpu is None else "%.0f s CPU" % cpu), flush=True)


def face_offset(work, name, cell_z, layers=LAYERS):
    """(the drained face's mean depth under the plate in cells, cycles 2-4; the share of
    those samples with the plate above the next layer's centre) of a run of `layers` active
    fluid layers"""
    c = load(os.path.join(work, name, "timeseries.txt"))
    kept = (c["time"] > (KEEP[0] - 1) * PERIOD) & (c["time"] <= KEEP[-1] * PERIOD)
    z = c["z_wall"][kept]
    return (np.mean(z) - layers * cell_z) / cell_z, np.mean(z > (layers + 0.5) * cell_z)


def identical_to_default(work, case):
    """the case's members against the default ensemble's of the same seed: the columns both
    have, how many agree in every row, and the largest relative difference otherwise"""
    lines = []
    for name in sorted(glob.glob(os.path.join(work, case + "_member*"))):
        twin = os.path.join(work, os.path.basename(name).split("_", 1)[1])
        if not os.path.exists(os.path.join(twin, "timeseries.txt")):
            continue
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


RUNS = os.path.join(OUT, "creep_factors_runs.json")   # every run's metrics, kept with the page
# the default ensemble's members, as bench/fidelity/ensemble.py printed them
DEFAULT_TABLE = os.path.join(BENCH, "fidelity", "ensemble_results.md")


def default_members():
    """{member: metrics} of the default's 1-rank ensemble as bench/fidelity/ensemble.py printed them
    (its per-member table: the values rounded as shown), the metrics keyed as METRICS"""
    keys = {label: (key, scale) for key, label, scale, _ in METRICS}
    text = open(DEFAULT_TABLE).read().split("### 1 rank")[1].split("###")[0]
    rows = [[c.strip() for c in line.strip("|").split("|")] for line in text.splitlines()
            if line.startswith("|") and not line.startswith("|---")]
    names = [n for n in rows[0][1:] if n.startswith("member")]
    out = {n: {} for n in names}
    for row in rows[1:]:
        if row[0] in keys:
            key, scale = keys[row[0]]
            for n, cell in zip(names, row[1:]):
                if cell != "none":
                    out[n][key] = float(cell) / scale
    return out


def default_cost():
    """the default ensemble's CPU s per run as bench/fidelity/ensemble.py printed it"""
    return re.search(r"1 rank \(two runs side by side\): ([0-9-]+) CPU s", open(DEFAULT_TABLE).read()).group(1)


def record_runs(work):
    """the store (RUNS) with every complete run of a case in `work` (re)read: {run: {case,
    metrics, face (cells under the plate; share of samples a layer more on), cost, commit}};
    a run whose folder is gone keeps what the store holds of it"""
    store = json.load(open(RUNS)) if os.path.exists(RUNS) else {}
    for case, (_, variables, _) in CASES.items():
        for d in sorted(glob.glob(os.path.join(work, case + "_member*"))):
            name = os.path.basename(d)
            m = run_metrics(work, name)
            if not m:
                continue
            grid = dict(case_bed(work, case)[1], **variables)
            commit = store.get(name, {}).get("commit") or head_commit()   # the run's, kept
            store[name] = {"case": case, "metrics": m, "cost": read_cost(d), "commit": commit,
                           "face": face_offset(work, name, grid.get("cell_z", CELL_Z),
                                               grid.get("grid_z", LAYERS + 1) - 1)}
    with open(RUNS + ".new", "w") as f:
        json.dump(store, f, indent=1, sort_keys=True)
    os.replace(RUNS + ".new", RUNS)
    return store


def ensembles(store):
    """[(label, {name: metrics}, [face per run], [CPU s per run])]: the default's ensemble
    (its face from PLATE_MEAN and PLATE_TOP, which it measured), then every case in the store"""
    default_face = ((PLATE_MEAN - LAYERS * CELL_Z) / CELL_Z,
                    float(PLATE_TOP > (LAYERS + 0.5) * CELL_Z))
    default = default_members()
    out = [("the default ensemble (bench/fidelity/ensemble_results.md)", default,
            [default_face] * len(default), [])]
    for case, (label, _, _) in CASES.items():
        runs = {n: r for n, r in sorted(store.items()) if r["case"] == case}
        if runs:
            out.append((label, {n: {k: v for k, v in r["metrics"].items() if v is not None}
                                for n, r in runs.items()},
                        [r["face"] for r in runs.values()], [r["cost"][0] for r in runs.values()]))
    return out


def step_check(store, case="kn10", coarse="kn10_eps0.14"):
    """lines: the coarse step's runs against the fine one's of the same seed, each metric's
    difference in standard deviations of the default ensemble (its round-off spread; the
    stiff case's own is not known before its ensemble); two runs that differ by round-off
    alone differ by less than t(0.975, N-1) sqrt(2) sd 19 times in 20"""
    default = default_members()
    lines = []
    for name in sorted(n for n in store if n.startswith(coarse + "_member")):
        twin = "%s_member%s" % (case, name.split("_member")[1])
        if twin not in store:
            continue
        a, b = store[name]["metrics"], store[twin]["metrics"]
        cells, outside = [], []
        for key in COLUMNS:
            spread = summary(default, key)
            if key in a and key in b and len(spread) >= 3:
                d = (a[key] - b[key]) / np.std(spread, ddof=1)
                cells.append("%s %+.1f" % (key, d))
                if abs(d) > stats.t.ppf(0.975, len(spread) - 1) * np.sqrt(2):
                    outside.append(key)
        lines.append("- %s against %s (difference / the default's sd): %s; outside: %s" % (
            name, twin, ", ".join(cells), ", ".join(outside) or "none"))
    return lines


def reference_row():
    """the paper's or the original data file's value under the original's estimator's column"""
    ref = {original: text.split(" (")[0] for _, text, _, original in AGAINST_PAPER}
    return "| the paper / the original's data file | | | " + " | ".join(
        ref.get(k, "") if k.endswith("_original") or k.startswith("exit") or k == "stick_fraction"
        else "" for k in COLUMNS) + " |"


def welch(ens, default, key):
    """(p, the case's mean minus the default's, its 95 % half-interval) of Welch's t-test of
    a metric, or None with fewer than 3 runs on either side"""
    a, b = summary(ens, key), summary(default, key)
    if len(a) < 3 or len(b) < 3:
        return None
    va, vb = a.var(ddof=1) / len(a), b.var(ddof=1) / len(b)
    dof = (va + vb) ** 2 / (va ** 2 / (len(a) - 1) + vb ** 2 / (len(b) - 1))
    diff = a.mean() - b.mean()
    return (2 * stats.t.sf(abs(diff) / np.sqrt(va + vb), dof), diff,
            stats.t.ppf(0.975, dof) * np.sqrt(va + vb))


def cell(ens, key):
    """mean_band, with how many runs have the metric where some lack it (the original's fit
    that does not converge from its default p0; the default ensemble's suction_top)"""
    have = len(summary(ens, key))
    return mean_band(ens, key) + ("" if have in (0, len(ens)) else " (%d of %d)" % (have, len(ens)))


def table(store):
    labels = {k: label for k, label, _, _ in METRICS}
    lines = ["| case | runs | face under the plate (cell; a layer more on) | " +
             " | ".join(labels[k] for k in COLUMNS) + " | CPU s per run |",
             "|---|---|---|" + "---|" * (len(COLUMNS) + 1), reference_row()]
    rows = ensembles(store)
    for label, ens, faces, cpu in rows:
        lines.append("| %s | %d | %.2f (%.1f %%) | %s | %s |" % (
            label, len(ens), np.mean([f[0] for f in faces]), 100 * max(f[1] for f in faces),
            " | ".join(cell(ens, k) for k in COLUMNS),
            "%.0f-%.0f" % (min(cpu), max(cpu)) if cpu else default_cost()))
    lines += ["", "Welch's p of each case against the default ensemble (a metric the default's "
              "members lack: none):", "",
              "| case | " + " | ".join(labels[k] for k in COLUMNS) + " |",
              "|---|" + "---|" * len(COLUMNS)]
    for label, ens, _, _ in rows[1:]:
        tests = [welch(ens, rows[0][1], k) for k in COLUMNS]
        lines.append("| %s | %s |" % (label, " | ".join("%.2g" % t[0] if t else "" for t in tests)))
    lines += ["", "n minus the default's, both fits (95 % interval, Welch):", ""]
    for label, ens, _, _ in rows[1:]:
        cells = [welch(ens, rows[0][1], k) for k in ("n", "n_original")]
        lines.append("- %s: %s" % (label, "; ".join(
            "%s %+.2f ± %.2f" % (k, *d[1:]) if d else "%s: fewer than 3 runs" % k
            for k, d in zip(("ours", "the original's"), cells))))
    return lines


def plot(store, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 4))
    rows = ensembles(store)
    for x, (label, ens, _, _) in enumerate(rows):
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
    ax.set_xticklabels([textwrap.fill(label.split(" (")[0], 22) for label, _, _, _ in rows],
                       fontsize=7)
    ax.set_ylim(0, 20)
    ax.set_ylabel("creep exponent n, cycles 2-4\n(mean ± 95 % band, cut at 0 and 20;\ndots: members)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def report(work):
    store = record_runs(work)
    lines = ["# What moves the creep exponent: bench/creep_factors/creep_factors.py", "",
             "Written at commit %s from the runs kept in `creep_factors_runs.json` (run from the "
             "commit each names; examples/tidal_shear, %d cycles each, 1 rank, two side by side; "
             "metrics over cycles %d-%d, mean ± the 95 %% prediction band of one more run; CPU s "
             "with the load in the store). The reference values stand under the original's "
             "estimators only." % (head_commit(), CYCLES, KEEP[0], KEEP[-1]), ""]
    lines += table(store)
    checked = step_check(store)
    if checked:
        lines += ["", "## ε 0.14 against ε 0.07 at k_n x10 (same seed)", ""] + checked
    rerun = identical_to_default(work, "face0.14")
    if rerun:
        lines += ["", "The default's members run again (face0.14) against the default "
                  "ensemble's:", ""] + rerun
    plot(store, os.path.join(OUT, "creep_factors.png"))
    lines += ["", "![n per case, both estimators](creep_factors.png)"]
    open(os.path.join(OUT, "creep_factors_results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def report_counts(work):
    lines = ["# The original's count on Table S1's geometry: bench/creep_factors/creep_factors.py --count", "",
             "Written at commit %s from the runs in `%s`." % (head_commit(), work), ""]
    lines += count_geometry(work)
    open(os.path.join(OUT, "creep_factors_count.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


TALL_GRAINS = 2400               # Table S1's H/d 23.5 on the reduced footprint
MU_TALL = 0.0444                  # --bisect-tall: 4.61 by the original's count on Table S1's
                                  # geometry at the first sample (the original run: 4.58)
# the original's count on Table S1's geometry from the reduced bed's: the footprint measured
# (the default bed tiled 2 x 2, as Table S1's 0.52 x 0.26 m), the height by the interior
HEIGHT_RATIO = 23.5 / 12.49       # H/d of Table S1 over the default bed's (0.2498 m / 0.02 m)
INTERIOR = 3                      # grain diameters from either fixed layer: the interior


BEDS = {"original": "consolidated_0.data", "frictionless": SHIPPED_FRICTIONLESS}


def first_state(work, name, data, tiles, variables, step=1170):
    """{column: per grain} of the dump at the first time-series row (step 1170, 2.5 ms; 0:
    the state as read) of a bed (a data file, in.tidal_shear -var overrides) tiled
    tiles[0] x tiles[1] with its fluid cells"""
    d = os.path.join(work, "tiles", "%s_%dx%d" % ((name,) + tiles))
    dump = os.path.join(d, "grains_%d.dump" % step)
    if not os.path.exists(dump):
        prepare(d, [REPLICATE_BED])
        shutil.copy(data, os.path.join(d, "untiled.data"))
        run_lmp(d, "in.replicate_bed", {"in": "untiled.data", "out": "tiled.data",
                                        "nx": tiles[0], "ny": tiles[1], "nz": 1}, log="log.tile")
        run_lmp(d, "in.tidal_shear", dict(variables, data="tiled.data", lx=0.26 * tiles[0],
                                          ly=0.13 * tiles[1], grid_x=3 * tiles[0],
                                          grid_y=2 * tiles[1], run_steps=1170, dump_every=1170))
    lines = open(dump).read().splitlines()
    names = lines[8].split()[2:]
    grains = np.array([[float(v) for v in l.split()] for l in lines[9:]])
    return {n: grains[:, i] for i, n in enumerate(names)}


def tall_estimate(g, key):
    """the mean count of a bed HEIGHT_RATIO times taller: the grains within INTERIOR
    diameters of either fixed layer as they are, the interior repeated"""
    d = 2 * np.median(g["radius"])
    z, count = g["z"], g[key]
    interior = (z > z.min() + (1 + INTERIOR) * d) & (z < z.max() - (1 + INTERIOR) * d)
    extra = (HEIGHT_RATIO - 1) * len(z)
    return (count.sum() + extra * count[interior].mean()) / (len(z) + extra)


def tall_groups(height, phi):
    """the groups of the default kept for a tall bed (bed_groups), its fluid cells ~4 d as
    the default's: half the height of bed_groups' cells, 6 active layers under the plate"""
    g = bed_groups(height, phi)
    return dict(g, cell_z=g["cell_z"] / 2, grid_z=2 * LAYERS + 1)


def tall_bed(work, mu):
    """a bed of Table S1's height on the reduced footprint, packed and consolidated with
    friction mu (the default's spread of radii); its data file"""
    return prepare_bed(work, "tall_mu%.4f" % mu, {"ngrains": TALL_GRAINS, "radius_spread": SPREAD,
                                                  "mu_prep": mu})


def tall_probe(work, mu):
    """(mu, the original's count at the first sample on Table S1's geometry (the tall bed
    tiled 2 x 2: 9,600 grains, 0.52 x 0.26 m), H, phi) of the tall bed packed with mu"""
    data = tall_bed(work, mu)
    height, phi = bed_geometry(data)
    g = first_state(work, "tall_mu%.4f" % mu, data, (2, 2), tall_groups(height, phi))
    return mu, g["c_coordination_original"].mean(), height, phi


def bisect_tall(work):
    """mu_prep of the tall bed that starts at the original run's count on Table S1's
    geometry (TARGET_Z), between the frictionless and the default's preparation"""
    pool = ThreadPoolExecutor(2)
    probes = bisect_mu_prep(work, lambda f, xs: list(pool.map(f, xs)), low=0.0,
                            high=MU_PREP_ORIGINAL, rounds=short(3, 1), tol=0.05,
                            probe=lambda mu: tall_probe(work, mu))
    return ["# The tall bed's friction while packing: bench/creep_factors/creep_factors.py --bisect-tall", "",
            "Written at commit %s from the beds in `%s`." % (head_commit(), work), "",
            "| mu_prep | the original's count at 2.5 ms, Table S1's geometry | H (m) | phi |",
            "|---|---|---|---|"] + ["| %.4f | %.3f | %.4f | %.4f |" % p for p in probes]


CREEP_STATE_CYCLES = 1.4          # phase 0.4 of cycle 2: the middle of its creep window


def creeping_state(work):
    """the default's member 0 at CREEP_STATE_CYCLES (positions and velocities): its data file"""
    d = os.path.join(work, "tiles", "creeping")
    if not os.path.exists(os.path.join(d, "creeping.data")):
        prepare(d)
        run_lmp(d, "in.tidal_shear", {"cycles": CREEP_STATE_CYCLES, "write_state": "creeping"})
    return os.path.join(d, "creeping.data")


def count_geometry(work):
    """lines: both counts at the start on the reduced bed, on Table S1's footprint (measured)
    and at Table S1's height (the interior repeated); the short setting: the shipped default
    bed's two rows only"""
    rows = [("the default bed", "original", (1, 1)),
            ("the default bed on Table S1's footprint (tiled 2 x 2)", "original", (2, 2)),
            ("the frictionless bed", "frictionless", (1, 1)),
            ("the frictionless bed on Table S1's footprint", "frictionless", (2, 2))]
    lines = ["| bed (at the first sample, 2.5 ms, unless said) | grains | our count | the original's count | "
             "at Table S1's height too (estimate): ours | the original's |", "|---|---|---|---|---|---|"]
    states = [(label, first_state(work, bed, os.path.join(EXAMPLE, BEDS[bed]), tiles,
                                  {"bed": bed}), False) for label, bed, tiles in short(rows, rows[:2])]
    if not SMOKE:
        creeping = creeping_state(work)
        states += [(label, first_state(work, "creeping", creeping, tiles, {}, 0), False)
                   for label, tiles in (
            ("the default bed creeping (member 0 at %.1f cycles, as read)" % CREEP_STATE_CYCLES, (1, 1)),
            ("the same on Table S1's footprint", (2, 2)))]
        for case, label in (("packed0.044", "the default's grains packed with friction 0.044"),
                            ("tall", "the tall bed (2,400 grains, friction 0.044)")):
            data, variables = case_bed(work, case)
            variables = {k: v for k, v in variables.items() if k != "data"}
            states += [(text, first_state(work, CASES[case][2] + "_mu%.4f" % MU_TALL, data, tiles,
                                          variables), case == "tall") for text, tiles in (
                (label, (1, 1)), (label + " on Table S1's footprint", (2, 2)))]
    for label, g, tall in states:                      # tall: already of Table S1's height
        lines.append("| %s | %d | %.2f | %.2f | %s | %s |" % (
            label, len(g["z"]), g["c_contacts"].mean(), g["c_coordination_original"].mean(),
            "(is)" if tall else "%.2f" % tall_estimate(g, "c_contacts"),
            "(is)" if tall else "%.2f" % tall_estimate(g, "c_coordination_original")))
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", default="/tmp/pw_time_to_solution")
    ap.add_argument("--run", help="comma-separated cases to run (then report)")
    ap.add_argument("--members", type=int, default=CASE_MEMBERS)
    ap.add_argument("--count", action="store_true",
                    help="both counts on Table S1's geometry (creep_factors_count.md)")
    ap.add_argument("--bisect-tall", action="store_true",
                    help="find the tall bed's mu_prep (creep_factors_bisect.md)")
    args = ap.parse_args()
    if args.bisect_tall:
        lines = bisect_tall(args.work)
        open(os.path.join(OUT, "creep_factors_bisect.md"), "w").write("\n".join(lines) + "\n")
        print("\n".join(lines))
        return
    if args.count:
        report_counts(args.work)
        return
    if args.run:
        run_cases(args.work, args.run.split(","), args.members)
    report(args.work)


if __name__ == "__main__":
    main()
