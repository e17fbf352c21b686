"""The tables of paper_scene.py's runs (bench/fidelity/RESULTS.md, "The paper's numbers"): each
of the paper's numbers by both estimators against Table S1 (cycles 2-3), the stiff preset's
ensemble and the default's; the stiff preset's time step; the original's creep fit as its
script runs it and the minimum it seeks; the original's count checked on Table S1's dumps."""
import glob
import os

import numpy as np

from common import COMMON
from common.ensembles import METRICS, mean_band, run_metrics
from common.runs import chunks_cpu, load, loop_time, read_cost, run_logs
from paper_scene import (COST_RANKS, DEFAULT_MEMBERS, ORIGINAL_MEMBERS, STIFF_EPS_CHECK,
                         STIFF_MEMBERS, TABLE_S1_CYCLES, TABLE_S1_PERIOD, TARGET_Z,
                         inside_band)
from porewater_analysis import original
from porewater_analysis.cycles import original_data_file_metrics
from porewater_analysis.dump import box_bounds, read_dump
from porewater_analysis.report import parameters
from porewater_analysis.timeseries import nearest_rows, run_parameters

DATA_FILE = os.path.join(COMMON, "original_run_contacts.txt")
PAPER_N = (6.0, 11.0)
TABLE_S1_KEEP = (2, 3)       # the original's creep windows 6-8 s and 11-13 s
LABEL = {k: (label, scale, f) for k, label, scale, f in METRICS}

# the paper's numbers: label, the paper's value (None: the data file's, cycles 2-3), the
# original's estimator's key and ours (common.ensembles.METRICS)
PAPER_NUMBERS = [
    ("creep exponent n (cycles 2 on, pooled)", "6-11 (its fit)", "n_original", "n"),
    ("coordination while creeping (phases 0.2-0.6)", None, "z_creep_original", "z_creep"),
    ("collapse: the cycle's minimum coordination", None, "z_min_original", "z_min"),
    ("collapse: cycles after the minimum of N", None, "z_min_after_original", "z_min_after"),
    ("slip onset (phase): the original's velocity leaves its creep band; ours 1 cm/s",
     "~0.61 (its Figure 3)", "exit_onset", "onset"),
    ("slip end (phase)", "~0.81 (its Figure 3)", "exit_end", "end"),
    ("stick: share of the cycle with the original's velocity 0", "(shaded, no number)",
     "stick_fraction", None),
    ("suction under the plate in the slip (A; the top fluid layer)", "", None, "suction_top"),
]


def ensemble_of(work, folder, count):
    """{member: metrics over cycles 2-4} of the complete members of work/folder"""
    runs = {"member%d" % k: run_metrics(work, os.path.join(folder, "member%d" % k))
            for k in range(count)}
    return {name: m for name, m in runs.items() if m}


def table_s1(work):
    """the Table S1 run by both estimators: ({metric: [cycle 2, cycle 3]}, pooled metrics over
    cycles 2-3), or None before it is complete"""
    keep = TABLE_S1_KEEP
    pooled = run_metrics(work, "table_s1", cycles=TABLE_S1_CYCLES, keep=keep)
    if pooled is None:
        return None
    per = [run_metrics(work, "table_s1", cycles=TABLE_S1_CYCLES, keep=(k,)) for k in keep]
    keys = set(pooled).union(*per)      # a fit that fails is a key missing: keep the others'
    return {key: [m.get(key) for m in per] for key in keys}, pooled


def data_file_cycles(keep=TABLE_S1_KEEP):
    """the original run's own data file (its count) over the cycles `keep`: {metric: values}"""
    m = original_data_file_metrics(DATA_FILE)
    at = [k - 2 for k in keep]             # its lists start at cycle 2
    return {"z_creep_original": [m["z_creep"][i] for i in at],
            "z_min_original": [m["z_min"][i] for i in at],
            "z_min_after_original": [m["z_min_phase"][i] for i in at]}


def missing(key):
    """what a run without a value of `key` shows: run_metrics drops n where the fit failed"""
    return "no fit" if key in ("n", "n_original") else "none"


def cell(values, key):
    _, scale, f = LABEL[key]
    return " / ".join(missing(key) if v is None else f % (scale * v) for v in values)


def front_table(s1, ensembles):
    """a row per paper number: the paper or the data file, Table S1's cycles 2 / 3 (n: pooled
    over both, then each), each ensemble's mean ± 95 % band of one more run; the original's
    estimator / ours"""
    data_file = data_file_cycles()
    head = ["the paper's number", "the paper / the original's data file, cycles 2 / 3",
            "Table S1, cycles 2 / 3: the original's estimator", "ours"]
    for label, ens in ensembles:
        head += ["%s (%d runs): the original's estimator" % (label, len(ens)), "ours"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    per, pooled = s1 if s1 else ({}, {})
    for label, reference, theirs, mine in PAPER_NUMBERS:
        cells = [label, cell(data_file[theirs], theirs) if reference is None else reference]
        for key in (theirs, mine):
            if key is None or key not in per:
                cells.append("")
            elif key.startswith("n"):
                cells.append("%s (%s)" % (cell([pooled.get(key)], key), cell(per[key], key)))
            else:
                cells.append(cell(per[key], key))
        for _, ens in ensembles:
            cells += [mean_band(ens, key) if key else "" for key in (theirs, mine)]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def band_table(coarse, fine, coarse_label, fine_label):
    """paper_scene.inside_band as a table"""
    lines = ["| metric | %s: mean ± 95 %% band of the mean of %d more (Bonferroni) | %s "
             "| their mean | inside |" % (coarse_label, len(fine), fine_label),
             "|---|---|---|---|---|"]
    for key, mean, half, values, inside in inside_band(coarse, fine):
        label, scale, f = LABEL[key]
        lines.append("| %s | %s ± %s | %s | %s | %s |" % (
            label, f % (scale * mean), f % (scale * half),
            ", ".join([f % (scale * v) for v in values] +
                      [missing(key)] * (len(fine) - len(values))), f % (scale * values.mean()),
            "yes" if inside else "**no**"))
    return lines


# ---- the original's creep fit: as its script runs it, and the minimum it seeks ----------

def fit_samples(d, cycles):
    """the original's creep-fit samples (tau/N, scaled rate, phase) of a run in each cycle of
    `cycles` and pooled over them: {cycle or "pooled": (friction, rate, phase)}"""
    params, _ = parameters(d)
    series = load(os.path.join(d, "timeseries.txt"))
    p = original.creep_samples(series, params["period"], params["tau"], params["rate_scale"])
    out = {}
    for k in list(cycles) + ["pooled"]:
        use = p["kept"] & (np.isin(p["cycle"], cycles) if k == "pooled" else p["cycle"] == k)
        out[k] = (p["friction"][use], p["rate"][use], p["time"][use] / params["period"])
    return out


def fit_row(friction, rate):
    """the script's fits (creep_fit_as_run), the least-squares minimum with its profile
    interval, and curve_fit from the default start on the rates in units of their median"""
    if len(rate) < 3:
        return None
    rescaled = original.curve_fit_as_called(original.creep_rheology2, friction,
                                            rate / np.median(rate))
    return {"samples": len(rate), "as_run": original.creep_fit_as_run(friction, rate),
            "minimum": original.creep_fit_minimum(friction, rate),
            "rescaled": float(rescaled["params"][0])}


def as_run_text(run):
    if run["second"] is None:
        return "the script stops in its first fit (%s)" % short_status(run["first"]["status"])
    if run["stopped"]:
        return "no n (%s)" % short_status(run["second"]["status"])
    return "%.2f" % run["n"]


def short_status(status):
    return "maxfev reached" if "maxfev" in status else status.split(".")[0][:60]


def interval_text(best):
    lo, hi = best["interval"]
    return "%s to %s" % ("< -20" if lo is None else "%.1f" % lo, "> 40" if hi is None else "%.1f" % hi)


def fit_study(runs):
    """runs: [(label, folder, cycles)]: (the per-run table's lines, {(label, cycle): row})"""
    lines = ["| run | cycles | samples | n as the script runs it (its first fit, A = 1) | n at "
             "the least-squares minimum | its profile interval (95 %, residuals independent) | "
             "SSR at n 6 / 11 over the minimum | curve_fit on the rates over their median | the "
             "5 fastest samples' share of the sum of squared rates (their phases) |",
             "|---|---|---|---|---|---|---|---|---|"]
    per_cycle = {}
    for label, d, cycles in runs:
        for k, (f, r, phases) in fit_samples(d, cycles).items():
            row = fit_row(f, r)
            if row is None:
                continue
            per_cycle[(label, k)] = row
            best = row["minimum"]
            ratio = original.least_squares_profile(f, r, list(PAPER_N))[1] / best["ssr"]
            first = row["as_run"]["first"]["params"][0]
            fastest = np.argsort(-r)[:5]
            lines.append("| %s | %s | %d | %s (%s) | %.2f | %s | %.2f / %.2f | %.2f | %.2f (%s) |" % (
                label, "%d-%d pooled" % (cycles[0], cycles[-1]) if k == "pooled" else k,
                row["samples"], as_run_text(row["as_run"]),
                "none" if np.isnan(first) else "%.1f" % first, best["n"], interval_text(best),
                ratio[0], ratio[1], row["rescaled"], np.sum(r[fastest] ** 2) / np.sum(r ** 2),
                ", ".join("%.2f" % (p % 1.0) for p in phases[fastest])))
    return lines, per_cycle


def share_inside(values):
    return np.mean((values >= PAPER_N[0]) & (values <= PAPER_N[1]))


def fit_distribution(per_cycle, prefix):
    """a line: the per-cycle n of the runs whose label starts with prefix, at the minimum and
    as run, and their share inside the paper's 6-11"""
    rows = [row for (label, k), row in per_cycle.items() if label.startswith(prefix) and
            k != "pooled"]
    if not rows:
        return "no runs"
    minima = np.array([row["minimum"]["n"] for row in rows])
    as_run = np.array([row["as_run"]["n"] for row in rows])
    got = as_run[~np.isnan(as_run)]
    return ("%d cycles: at the minimum %.2f ± %.2f (sd; %.2f-%.2f), %.0f %% inside 6-11; as the "
            "script runs it an n in %d (%.2f ± %.2f), %.0f %% of the %d inside 6-11" % (
                len(rows), minima.mean(), minima.std(ddof=1), minima.min(), minima.max(),
                100 * share_inside(minima), len(got), got.mean() if len(got) else np.nan,
                got.std(ddof=1) if len(got) > 1 else 0.0, 100 * share_inside(got) * len(got) /
                len(rows), len(rows)))


def bootstrap_minimum(units, draws=1000, seed=1):
    """the pooled least-squares minimum over units (run, cycle) drawn with replacement: the
    n of each draw"""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(draws):
        pick = [units[i] for i in rng.integers(0, len(units), len(units))]
        out.append(original.creep_fit_minimum(np.concatenate([u[0] for u in pick]),
                                              np.concatenate([u[1] for u in pick]),
                                              exponents=np.linspace(-20, 40, 601))["n"])
    return np.array(out)


# ---- the original's count on Table S1's dumps -------------------------------------------

def count_as_the_original(path, fixed_ids):
    """the mean count of a grain dump by the original's rules, recomputed from its positions:
    every pair of grains with the raw difference of their positions wrapped into the box, an
    overlap, neither fixed (src/sphere.cpp DEM::findOverlaps, python/sphere.py lines 4885-4906)"""
    from scipy.spatial import cKDTree
    _, g = read_dump(path)
    x = np.column_stack([g["x"], g["y"], g["z"]])
    for d, (lo, hi) in enumerate(box_bounds(path)[:2]):    # x, y periodic: wrapped as the original's
        x[:, d] = lo + np.mod(x[:, d] - lo, hi - lo)
    free = ~np.isin(g["id"], fixed_ids)
    r = g["radius"]
    count = np.zeros(len(r))
    for i, j in cKDTree(x).query_pairs(2 * r.max()):
        if free[i] and free[j] and np.sum((x[i] - x[j]) ** 2) < (r[i] + r[j]) ** 2:
            count[i] += 1
            count[j] += 1
    return count.mean(), np.mean(g["c_coordination_original"])


def fixed_ids(data):
    """the ids of the grains in.tidal_shear holds fixed, from the data file it starts from: the
    bottom layer (centres below 2 r) and the top layer (centres within 2 r of the highest)"""
    lines = open(data).read().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("Atoms")) + 2
    atoms = []
    for line in lines[start:]:
        if not line.strip():
            break
        v = line.split()
        atoms.append((int(v[0]), float(v[2]) / 2, float(v[6])))
    ids, radius, z = (np.array(c) for c in zip(*atoms))
    r = 0.01                                    # in.params' radius (the regions use it)
    return ids[(z < 2 * r) | (z > z.max() - 2 * r)]


def dump_check(d, data="bed.data"):
    """lines: each grain dump of the Table S1 run counted again from its positions against the
    time series' coordination_original at its step"""
    dumps = sorted(glob.glob(os.path.join(d, "grains_*.dump")),
                   key=lambda p: int(p.split("_")[-1].split(".")[0]))
    if not dumps:
        return []
    series = load(os.path.join(d, "timeseries.txt"))
    fixed = fixed_ids(os.path.join(d, data))
    dt = run_parameters(d)["dt"]
    lines = ["| step | time (s) | recounted from the dump's positions | the dump's per-grain "
             "column | the time series |", "|---|---|---|---|---|"]
    for path in dumps:
        step = int(path.split("_")[-1].split(".")[0])
        row = int(nearest_rows(series["time"], step * dt))
        if abs(series["time"][row] - step * dt) > 0.5 * dt:     # no row at that step (0)
            continue
        recount, column = count_as_the_original(path, fixed)
        lines.append("| %d | %.4f | %.4f | %.4f | %.4f |" % (
            step, series["time"][row], recount, column, series["coordination_original"][row]))
    return lines


# ---- the page ---------------------------------------------------------------------------------

def value_range(values, f="%.0f"):
    """'low-high' of values as f writes them, one value where they print alike"""
    low, high = f % min(values), f % max(values)
    return low if low == high else low + "-" + high


def cost_text(work, folders):
    """CPU s per run (its chunks over all its legs: common.runs.chunks_cpu) and µs per step of
    the runs of `folders` (the complete ones: the callers pass those)"""
    costs = [chunks_cpu(os.path.join(work, f)) for f in folders]
    costs = [c for c in costs if c[1]]
    if not costs:
        return "no runs"
    return "%s CPU s per run, %s µs per step" % (
        value_range([c[0] for c in costs]), value_range([1e6 * c[0] / c[1] for c in costs]))


def layout_cost_text(work):
    """the stiff preset's wall time per step on each of COST_RANKS, each run alone on the
    machine (paper_scene.py --only cost), and 4 cycles' wall time at that rate (the run's own
    time step and frequency, checkpoint_params.txt)"""
    cells = []
    for ranks in COST_RANKS:
        d = os.path.join(work, "stiff_cost", "np%d" % ranks)
        cost = read_cost(d)
        if cost is None:
            cells.append("%d rank(s): not measured" % ranks)
            continue
        loop, steps = map(sum, zip(*(loop_time(log, last=False) for log in run_logs(d)
                                     if os.path.exists(log))))
        run = run_parameters(d)
        us = 1e6 * loop / steps
        cells.append("%d rank(s) %.0f µs per step over its first %.3g cycle (4 cycles: %.0f min; "
                     "load %.2f before, %.2f after)" % (
                         ranks, us, steps * run["dt"] * run["freq"],
                         us * 4 / (run["freq"] * run["dt"]) / 6e7, cost[2], cost[3]))
    return "wall time of its chunks' loops: " + "; ".join(cells)


def plot(per_cycle, bootstrap, path):
    """the profile of the sum of squares over n of Table S1's cycles and the stiff members'
    cycles (each over its minimum), and the distribution of the per-cycle minima"""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for (label, k), row in sorted(per_cycle.items(), key=lambda kv: str(kv[0])):
        if k == "pooled" or not (label.startswith("Table S1") or label.startswith("stiff")):
            continue
        best = row["minimum"]
        style = dict(color="k", lw=1.5) if label.startswith("Table S1") else \
            dict(color="C0", lw=0.6, alpha=0.6)
        ax[0].plot(best["exponents"], best["profile"] / best["ssr"], **style)
    ax[0].axvspan(*PAPER_N, color="0.85")
    ax[0].set_xlim(0, 25)
    ax[0].set_ylim(0.9, 2.0)
    ax[0].set_xlabel("creep exponent n")
    ax[0].set_ylabel("SSR(n) / its minimum (A best at each n)")
    ax[0].set_title("the original's fit, per cycle: Table S1 (black), stiff preset (blue)",
                    fontsize=8)
    for x, prefix, colour in ((0, "stiff", "C0"), (1, "default", "C2"), (2, "Table S1", "k")):
        v = [row["minimum"]["n"] for (label, k), row in per_cycle.items()
             if label.startswith(prefix) and k != "pooled"]
        ax[1].plot(x + 0.1 * np.linspace(-1, 1, len(v)), v, "o", color=colour, ms=4)
    if len(bootstrap):
        lo, hi = np.percentile(bootstrap, [2.5, 97.5])
        ax[1].errorbar(0.3, np.median(bootstrap), yerr=[[np.median(bootstrap) - lo],
                                                        [hi - np.median(bootstrap)]],
                       fmt="s", color="C3", capsize=3, label="stiff, pooled: bootstrap 95 %")
        ax[1].legend(fontsize=7)
    ax[1].axhspan(*PAPER_N, color="0.85")
    ax[1].set_xticks([0, 1, 2])
    ax[1].set_xticklabels(["stiff preset", "default", "Table S1"])
    ax[1].set_ylabel("n at the least-squares minimum, per cycle")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def count_against_data_file(work, path):
    """lines and a figure: Table S1's count by the original's rules (coordination_original)
    against the original run's own data file, row by row over the time both cover (the data
    file's rows, every 0.01 s, matched to the nearest row of the run). Both are the original's
    count: pairs overlapping, none across a periodic boundary or with a fixed grain, over all
    grains (python/sphere.py lines 4885-4906; compute coordination/original, group all)"""
    series = os.path.join(work, "table_s1", "timeseries.txt")
    if not os.path.exists(series):
        return []
    c = load(series)
    t_data, _, z_data = np.loadtxt(DATA_FILE, unpack=True)
    inside = t_data <= c["time"][-1]
    t_data, z_data = t_data[inside], z_data[inside]
    z_run = c["coordination_original"][nearest_rows(c["time"], t_data)]
    lines = ["| cycle | rows | the run's mean | the data file's mean | mean difference | rms "
             "difference |", "|---|---|---|---|---|---|"]
    for k in range(1, int(np.ceil(t_data[-1] / TABLE_S1_PERIOD)) + 1):
        m = (t_data > (k - 1) * TABLE_S1_PERIOD) & (t_data <= k * TABLE_S1_PERIOD)
        d = z_run[m] - z_data[m]
        lines.append("| %d | %d | %.3f | %.3f | %+.3f | %.3f |" % (
            k, m.sum(), z_run[m].mean(), z_data[m].mean(), d.mean(), np.sqrt(np.mean(d ** 2))))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(11, 3.5))
    ax.plot(t_data, z_data, color="k", lw=0.8, label="the original run (its data file)")
    ax.plot(c["time"], c["coordination_original"], color="C0", lw=0.8,
            label="Table S1 here (coordination_original)")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("coordination, the original's count")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return lines


def bed_probes(work):
    """lines: the Table S1 beds packed with each friction (paper_scene.py table_s1_friction)
    and the original's count each starts at"""
    path = os.path.join(work, "table_s1_probes.txt")
    if not os.path.exists(path):
        return []
    rows = np.loadtxt(path, ndmin=2)
    return ["", "## The Table S1 bed: its friction while packing, at Table S1's k_n", "",
            "| mu_prep | the original's count at t = 0.01 s (the original run %.2f) | H (m) | phi |"
            % TARGET_Z,
            "|---|---|---|---|"] + ["| %.4f | %.3f | %.4f | %.4f |" % tuple(r) for r in rows]


def report(work, out):
    """bench/fidelity/paper_scene_results.md and paper_scene.png from the runs in work"""
    from common.runs import head_commit
    stiff = ensemble_of(work, "stiff", STIFF_MEMBERS)
    fine = ensemble_of(work, "stiff_eps0.07", STIFF_EPS_CHECK)
    numerics = ensemble_of(work, "stiff_original", ORIGINAL_MEMBERS)
    default = ensemble_of(work, "default", DEFAULT_MEMBERS)
    s1 = table_s1(work)
    lines = ["# The paper's numbers on its own scene: bench/fidelity/paper_scene.py --report", "",
             "Written at commit %s from the runs in `%s` (bench/fidelity/paper_scene.py: the "
             "plugin of the commit that started them, frozen in its plugin_paper_scene folder). "
             "Table S1: one run, cycles 2 and 3 (n pooled over both, each cycle's in brackets); "
             "the ensembles: mean ± the 95 %% prediction band of one more run over cycles 2-4 of "
             "4. The original run's own data file by its count, cycles 2 / 3. The paper's and the "
             "data file's values stand under the original's estimators only." % (
                 head_commit(), work), ""]
    lines += front_table(s1, [("the stiff preset", stiff), ("the default", default)])
    lines += ["", "## Costs (CPU s of each run's chunks as LAMMPS reports them: loop time x CPU use x "
              "MPI tasks, so a run on 2 ranks counts both; "
              "the runs shared the 2 cores with others)", "",
              "- the stiff preset, 4 cycles, 1 rank (two runs side by side): " +
              cost_text(work, ["stiff/" + m for m in stiff]),
              "- the stiff preset, each layout alone on the machine: " +
              layout_cost_text(work),
              "- the stiff preset at ε 0.07: " +
              cost_text(work, ["stiff_eps0.07/" + m for m in fine]),
              "- the stiff preset with the original's numerics: " +
              cost_text(work, ["stiff_original/" + m for m in numerics]),
              "- the default, 4 cycles, 1 rank: " +
              cost_text(work, ["default/" + m for m in default]),
              "- Table S1, %d cycles, 2 ranks: %s" % (TABLE_S1_CYCLES,
                                                      cost_text(work, ["table_s1"] if s1 else []))]
    lines += bed_probes(work)
    if len(stiff) >= 3 and fine:
        lines += ["", "## The stiff preset's time step: ε 0.07 against its band at ε 0.14", ""]
        lines += band_table(stiff, fine, "ε 0.14", "ε 0.07")
    if len(stiff) >= 3 and numerics:
        lines += ["", "## The original program's numerics at Table S1's stiffness (the stiff "
                  "preset, -var original 1) against the stiff ensemble's band", ""]
        lines += band_table(stiff, numerics, "the stiff preset", "`-var original 1`")
    runs = [("Table S1", os.path.join(work, "table_s1"), TABLE_S1_KEEP)] if s1 else []
    runs += [("stiff member%d" % k, os.path.join(work, "stiff", "member%d" % k), (2, 3, 4))
             for k in range(STIFF_MEMBERS) if "member%d" % k in stiff]
    runs += [("default member%d" % k, os.path.join(work, "default", "member%d" % k), (2, 3, 4))
             for k in range(DEFAULT_MEMBERS) if "member%d" % k in default]
    table, per_cycle = fit_study(runs)
    boot = np.array([])
    stiff_units = [fit_samples(os.path.join(work, "stiff", m), (2, 3, 4)) for m in stiff]
    units = [u[k][:2] for u in stiff_units for k in (2, 3, 4)]
    if len(units) >= 6:
        boot = bootstrap_minimum(units)
    lines += ["", "## The original's creep fit: as its script runs it, and the minimum it seeks", ""]
    for prefix in ("Table S1", "stiff", "default"):
        lines.append("- %s: %s" % (prefix, fit_distribution(per_cycle, prefix)))
    if len(boot):
        lo, hi = np.percentile(boot, [2.5, 97.5])
        lines.append("- the stiff preset pooled over its members' cycles 2-4, the (member, "
                     "cycle) units drawn with replacement %d times: n %.2f (95 %%: %.2f-%.2f), "
                     "%.0f %% of the draws inside 6-11" % (len(boot), np.median(boot), lo, hi,
                                                           100 * share_inside(boot)))
    lines += [""] + table
    count = count_against_data_file(work, os.path.join(out, "table_s1_count.png"))
    if count:
        lines += ["", "## Table S1's count by the original's rules against the original run's "
                  "data file, row by row", ""] + count + [
                  "", "![Table S1's count against the data file's](table_s1_count.png)"]
    if s1:
        lines += ["", "## The original's count on Table S1's dumps, counted again from the "
                  "positions", ""] + dump_check(os.path.join(work, "table_s1"))
    plot(per_cycle, boot, os.path.join(out, "paper_scene.png"))
    lines += ["", "![the original's fit: profiles and minima](paper_scene.png)"]
    with open(os.path.join(out, "paper_scene_results.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
