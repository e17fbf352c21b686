"""Ensembles of examples/tidal_shear: runs that differ from the default by round-off alone
(every grain of the sheared bed moved at random by up to PERTURB), each read over cycles 2-4 by
the package's estimators and by the original program's (analysis/porewater_analysis), and the
band such runs fall in; and the agreement of two runs' time series against that chaotic spread.

A metric's band: the 95 % prediction interval of one more run, mean +- t(0.975, N-1) s
sqrt(1 + 1/N) over the N members: a run that differs by round-off alone falls outside it once
in 20."""
import math
import os
import re

import numpy as np
from scipy import stats

from . import EXAMPLE, short
from .runs import complete, run_example
from porewater_analysis.cycles import after_min_n
from porewater_analysis.report import analyse_run, parameters

CYCLES, PERIOD = 4, 2.5                 # in.params (reduced case): f = 0.4 Hz
RUN_CYCLES = short(CYCLES, 0.002)       # what a run runs; a shorter one is never complete
KEEP = (2, 3, 4)                        # cycle 1 starts from the unsheared bed
ENSEMBLE, NP2_ENSEMBLE = 8, 6           # members on 1 rank, on 2 ranks
PERTURB = 1.0e-12                       # m: the largest random displacement of a bed grain

# key, label, scale, format. The nine every setting of time_to_solution is judged by (our
# estimators, porewater_analysis.cycles), then ours besides, then the original's
# (porewater_analysis.original)
SETTING_METRICS = [
    ("slip", "slip (mm)", 1e3, "%.0f"),
    ("onset", "onset (phase)", 1.0, "%.3f"),
    ("end", "end (phase)", 1.0, "%.3f"),
    ("peak", "peak velocity (m/s)", 1.0, "%.3f"),
    ("dilation", "dilation (mm)", 1e3, "%.1f"),
    ("z_min", "min coordination", 1.0, "%.2f"),
    ("suction", "suction in slip (A)", 1.0, "%.3f"),
    ("v_creep", "creep velocity 0.2-0.6 (um/s)", 1e6, "%.1f"),
    ("n", "creep exponent n, cycles 2-4", 1.0, "%.2f"),
]
OURS = SETTING_METRICS + [("z_creep", "Z creeping, our count", 1.0, "%.2f"),
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

# the paper's and the original data file's values (bench/fidelity/RESULTS.md says where
# from), and the metrics of both estimators that compare with each: label, reference, ours,
# the original's
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


def members(prefix="member", count=ENSEMBLE):
    """name: -var overrides of an ensemble's runs (member0 the unperturbed default; member K
    perturbed with seed K, so that the same K starts from the same grains on any layout)"""
    runs = {prefix + "0": {}}
    for k in range(1, count):
        runs["%s%d" % (prefix, k)] = {"perturb": PERTURB, "perturb_seed": k}
    return runs


def np2_members():
    return members("np2_member", NP2_ENSEMBLE)


def run_one(work, name, variables, ranks=1, args=(), threads=1):
    """in.tidal_shear for CYCLES cycles in work/name unless complete there, continued where it
    stopped (runs.run_example): (name, CPU s or None)"""
    return name, run_example(os.path.join(work, name), dict(variables, cycles=RUN_CYCLES),
                             CYCLES * PERIOD, ranks=ranks, args=args, threads=threads)


def band(values, k=1, metrics=1):
    """mean and the 95 % prediction interval's half-width of the mean of k more members;
    metrics > 1: 95 % for that many metrics at once (Bonferroni), the rate at which a run that
    differs by round-off alone has every one inside"""
    v = np.asarray(values, dtype=float)
    n = len(v)
    q = 1 - 0.025 / metrics
    return v.mean(), stats.t.ppf(q, n - 1) * v.std(ddof=1) * np.sqrt(1.0 / k + 1.0 / n)


def mean_over_kept(rows, key):
    values = [r[key] for r in rows if r.get(key) is not None]
    return float(np.mean(values)) if len(values) == len(rows) else None


def run_metrics(work, name, cycles=CYCLES, keep=KEEP):
    """{metric: value over the cycles `keep`} of a run complete to `cycles` cycles of its own
    period, by both estimators (n: pooled over them), or None"""
    d = os.path.join(work, name)
    if not complete(os.path.join(d, "timeseries.txt"), cycles * parameters(d)[0]["period"]):
        return None
    result = analyse_run(d, cycles=cycles)
    kept = [c for c in result["cycles"] if c["cycle"] in keep]
    ours = [dict(c["ours"]) for c in kept]
    original = [dict(c["original"]) for c in kept]
    for row in ours + original:    # a collapse in the landing just past the cycle's end
        row["z_min_after"] = after_min_n(row["z_min_phase"])    # stays next to one before it
    out = {key: mean_over_kept(ours, key) for key, _, _, _ in OURS if key != "n"}
    out.update({key: mean_over_kept(original, key.replace("_original", ""))
                for key, _, _, _ in ORIGINAL if key.endswith("_original") and key != "n_original"})
    out.update({key: mean_over_kept(original, key) for key in ("stick_fraction", "exit_onset",
                                                                "exit_end")})
    if len(keep) == 1:                  # n of that cycle's fits
        ours_n, original_n = ours[0].get("n"), original[0]["n"]
    elif tuple(keep) == tuple(range(2, cycles + 1)):    # n pooled, as the reports pool it
        pooled = result["pooled"]
        ours_n = pooled["ours"]["n"] if pooled["ours"] else None
        original_n = pooled["original"]["n"]
    else:
        raise ValueError("n is fitted per cycle or pooled over cycles 2-%d, not over %s"
                         % (cycles, keep))
    out["n"] = ours_n
    out["n_original"] = None if np.isnan(original_n) else original_n
    return {k: v for k, v in out.items() if v is not None}


def summary(ens, key):
    """the values of a metric over an ensemble {name: metrics} (the runs that have it)"""
    return np.array([m[key] for m in ens.values() if key in m])


def mean_band(ens, key):
    """a metric of an ensemble as a cell: mean ± the 95 % prediction band (3 runs or more),
    the mean of fewer, "none" without any"""
    scale, f = {k: (scale, f) for k, _, scale, f in METRICS}[key]
    v = summary(ens, key)
    if not len(v):
        return "none"
    return f % (scale * v.mean()) + (" ± " + f % (scale * band(v)[1]) if len(v) >= 3 else "")


def compare_ensembles(one, two, labels=("1 rank", "2 ranks", "2 - 1")):
    """lines: per metric of two ensembles {name: metrics}, the means, the difference two - one
    (by default 2 - 1 ranks) with its 95 % interval (Welch) and whether it is outside it
    family-wise (Bonferroni over the metrics compared); `labels` name one, two and the
    difference"""
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



# Two runs' time series against the chaotic spread (bench/hosts, bench/gpu): the columns
# compared (timeseries.txt of in.tidal_shear), and what they are
QUANTITIES = [
    ("x_top", "shear-plate displacement (m)"),
    ("vx_top", "shear-plate velocity (m/s)"),
    ("z_wall", "top-plate position (m)"),
    ("N_grains", "normal stress of the grains on the plate (Pa)"),
    ("p_mean", "mean pore pressure (Pa)"),
    ("phi_mean", "mean porosity"),
    ("coordination", "mean contacts per grain"),
    ("ke", "grains' kinetic energy (J)"),
]
# index variables of in.params one of which is moved by an ulp (the first one present)
PERTURBED = ["tau", "sigma0", "eps"]
SPREAD_FACTOR = 3.0    # two runs agree within this many times the largest chaotic spread


def spread_agreement(series, compared, spreads):
    """The time series of two runs against the chaotic spread: `series` {run: {column:
    array}}, `compared` a pair of runs, `spreads` the pairs of runs that differ by round-off
    alone. Rows (quantity, what, max |difference| of the compared pair over the series,
    that of each spread pair, the ratio to the largest spread) for QUANTITIES, and whether
    every ratio is at most SPREAD_FACTOR."""
    n = min(len(s["time"]) for s in series.values())
    worst = lambda a, b, q: float(np.max(np.abs(series[a][q][:n] - series[b][q][:n])))
    rows, agree = [], True
    for q, what in QUANTITIES:
        if q not in series[compared[0]]:
            continue
        diff = worst(*compared, q)
        spread = [worst(a, b, q) for a, b in spreads]
        ratio = diff / max(spread) if max(spread) > 0 else (0.0 if diff == 0 else math.inf)
        agree &= ratio <= SPREAD_FACTOR
        rows.append((q, what, diff, spread, ratio))
    return rows, agree


def perturbation():
    """(name, value, the value one ulp higher) of the first PERTURBED index variable of
    in.params"""
    text = open(os.path.join(EXAMPLE, "in.params")).read()
    for name in PERTURBED:
        m = re.search(rf"^\s*variable\s+{name}\s+index\s+(\S+)", text, re.M)
        if m:
            value = float(m.group(1))
            return name, m.group(1), repr(math.nextafter(value, math.inf))
    raise SystemExit(f"none of {PERTURBED} is an index variable of in.params")
