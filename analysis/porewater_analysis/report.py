"""Both estimators on one run, cycle by cycle: dicts for a benchmark's tables (analyse_run),
the markdown table and the figure of `python3 -m porewater_analysis`."""
import os

import numpy as np

from . import cycles as ours
from . import landings as landing
from . import original
from .timeseries import load, run_parameters, whole_cycles

MU_F = 2.415e-7            # Pa s: the reduced example's default bed (in.bed_original)
# the original run's own data file (its count every 0.01 s), read beside each landing
DATA_FILE = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                          "bench", "common", "original_run_contacts.txt"))
# what a run folder without checkpoint_params.txt (or without a key) is taken to have run
DEFAULTS = {"freq": 1.0 / ours.PERIOD, "tau": ours.TAU, "amp": ours.AMP, "mu_f": MU_F}


def parameters(run_dir):
    """(period, tau, amp, rate_scale) of the run, and a note for each value not recorded in
    checkpoint_params.txt (the reduced example's default taken instead)"""
    try:
        recorded = run_parameters(run_dir)
    except OSError:
        recorded = {}
    notes = ["%s not recorded in %s: the reduced example's %g taken" % (
        key, os.path.join(run_dir, "checkpoint_params.txt"), value)
        for key, value in DEFAULTS.items() if key not in recorded]
    p = dict(DEFAULTS, **{k: recorded[k] for k in DEFAULTS if k in recorded})
    return {"period": 1.0 / p["freq"], "tau": p["tau"], "amp": p["amp"],
            "rate_scale": p["mu_f"] / original.WATER_VISCOSITY}, notes


def ours_row(metrics):
    """a cycle of cycles.factor_metrics, its power law as n and n_half95 (95 %; None: too few
    windows)"""
    row = {key: value for key, value in metrics.items() if key != "fit"}
    fit = metrics.get("fit")
    row.update(n=fit[0] if fit else None, n_half95=fit[1] if fit else None)
    return row


def original_row(fit, stuck, counted):
    """a cycle of original.creep_fit_per_cycle, original.stick and the original's count of
    original.coordination (z_creep, z_min, z_min_phase: None where the run lacks it)"""
    z = counted["original"] or {}
    return dict(fit, **stuck, z_creep=z.get("creep"), z_min=z.get("min"),
                z_min_phase=z.get("min_phase"))


def leave_out(series, period, tau, rate_scale, count):
    """the original's fit of each whole cycle and pooled over cycles 2 to `count`, on each grid
    of original.sample_grid, its fastest samples left out (original.leave_fastest_out):
    [{fit ("cycle k" or "2-count pooled"), offset, count, rows}]"""
    _, stride = original.sample_grid(series["time"], period)
    fits = [("cycle %d" % k, k, k) for k in range(1, count + 1)]
    if count >= 2:
        fits.append(("%d-%d pooled" % (2, count), 2, count))
    out = []
    for name, first, last in fits:
        for j in range(stride):
            f = original.creep_fit(series, period, tau, rate_scale, first, last, j)
            out.append({"fit": name, "offset": j, "count": f["count"],
                        "rows": original.leave_fastest_out(f["friction"], f["rate"])})
    return out


def analyse_series(series, period, tau, amp, rate_scale, cycles=None, data=None):
    """{"cycles": [{"cycle", "ours", "original"} a whole cycle], "pooled": {"cycles",
    "ours", "original"} over cycles 2 to the last, "landings" (landings.landings, beside the
    original run's data file `data`, (t, z) of landings.read_data_file, where given),
    "leave_out" (leave_out), "fit_samples" (original.fit_samples of the pooled fit, every
    grid: each record with its offset)}, at most `cycles` cycles. Ours:
    cycles.factor_metrics and creep_points/power_law; the original's: original.creep_fit
    (per cycle, pooled), stick and coordination"""
    if cycles is not None:
        series = {k: v[series["time"] <= cycles * period] for k, v in series.items()}
    count = whole_cycles(series["time"], period)
    if count < 1:
        raise ValueError("the time series covers no whole forcing cycle of %g s" % period)
    mine = ours.factor_metrics(series, count, period, tau, amp)
    theirs = zip(original.creep_fit_per_cycle(series, period, tau, rate_scale),
                 original.stick(series, period, tau), original.coordination(series, period))
    rows = [{"cycle": k, "ours": ours_row(mine[k]), "original": original_row(*fit_stick_count)}
            for k, fit_stick_count in zip(range(1, count + 1), theirs)]
    points = ours.creep_points(series, period=period, cycles=count, tau=tau)
    later = points[points[:, 2] >= 2] if len(points) else points
    law = ours.power_law(later) if len(later) else None
    pooled = {"cycles": (2, count), "ours": dict(zip(
        ("n", "n_half95", "windows", "dropped", "r2"), law), points=later) if law else None,
        "original": original.creep_fit(series, period, tau, rate_scale, 2)}
    _, stride = original.sample_grid(series["time"], period)
    samples = [dict(r, offset=j) for j in range(stride)
               for r in original.fit_samples(series, period, tau, rate_scale, 2, offset=j)]
    return {"cycles": rows, "pooled": pooled,
            "landings": landing.landings(series, period, data),
            "leave_out": leave_out(series, period, tau, rate_scale, count),
            "fit_samples": samples}


def analyse_run(run_dir, cycles=None, data_file=DATA_FILE):
    """analyse_series on run_dir/timeseries.txt with the run's own parameters
    (checkpoint_params.txt), the landings beside the original run's data file (`data_file`;
    None or a missing file: without it), plus "parameters", "notes" (the values not recorded)
    and "data_file" (the one read, or None)"""
    params, notes = parameters(run_dir)
    if data_file is not None and not os.path.exists(data_file):
        data_file = None
    data = landing.read_data_file(data_file) if data_file else None
    result = analyse_series(load(os.path.join(run_dir, "timeseries.txt")), cycles=cycles,
                            data=data, **params)
    return dict(result, parameters=params, notes=notes, data_file=data_file)


def cell(value, f):
    return "none" if value is None or np.isnan(value) else f % value


def our_n(fit):
    return "%.2f ± %.2f" % (fit["n"], fit["n_half95"]) if fit and fit["n"] is not None \
        else "too few"


def original_n(fit):
    return "no fit (%d)" % fit["count"] if np.isnan(fit["n"]) else \
        "%.2f ± %.2f (%d)" % (fit["n"], fit["n_sigma"], fit["count"])


def intervals(spans, most=3):
    text = ", ".join("%.3f-%.3f" % s for s in spans[:most])
    return (text + (" +%d more" % (len(spans) - most) if len(spans) > most else "")) or "none"


def markdown(result, run_dir, samples_file="PREFIX_fit_samples.txt"):
    p = result["parameters"]
    lines = ["# porewater_analysis of `%s`" % run_dir, "",
             "Period %g s, tau %g Pa, A %g Pa, the original's rate scale mu_f/1.787e-3 = %.3g."
             % (p["period"], p["tau"], p["amp"], p["rate_scale"]), ""]
    lines += ["- " + note for note in result["notes"]] + ([""] if result["notes"] else [])
    lines += [
        "Phases within each cycle (0: N = sigma0 rising). Ours: n of log gamma_dot = n "
        "log(tau/N) + c over 0.05-cycle windows of phases 0.2-0.6 (95 %%); slip while the "
        "top layer's smoothed velocity is above %g m/s; Z over all rows. Original "
        "(analysis/README.md): n of curve_fit A (tau/N)^n on its samples (1 sigma; samples "
        "fitted); stick where max(vx_top, 0) <= 1e-8 m/s (fraction of the cycle, intervals); "
        "band exit (our reading of its figure): v above %g x the cycle's creep band, until "
        "back below it; Z of its count (coordination_original) on its samples."
        % (ours.SLIP_VELOCITY, original.BAND_EXIT_FACTOR), "",
        "| cycle | n ours | n original | slip onset, end (ours) | stick fraction | stick "
        "intervals | band exit onset, end | Z creeping ours | Z creeping original | min Z ours "
        "(phase) | min Z original (phase) |", "|" + "---|" * 11]
    for row in result["cycles"]:
        m, o = row["ours"], row["original"]
        lines.append("| %d | %s | %s | %s, %s | %s | %s | %s, %s | %s | %s | %s (%s) | %s (%s) |" % (
            row["cycle"], our_n(m), original_n(o), cell(m.get("onset"), "%.3f"),
            cell(m.get("end"), "%.3f"),
            cell(o["stick_fraction"], "%.3f"), intervals(o["stick_intervals"]),
            cell(o["exit_onset"], "%.3f"), cell(o["exit_end"], "%.3f"),
            cell(m.get("z_creep"), "%.2f"), cell(o["z_creep"], "%.2f"), cell(m["z_min"], "%.2f"),
            cell(m["z_min_phase"], "%.3f"), cell(o["z_min"], "%.2f"),
            cell(o["z_min_phase"], "%.3f")))
    first, last = result["pooled"]["cycles"]
    lines.append("| %d-%d pooled | %s | %s |" % (first, last, our_n(result["pooled"]["ours"]),
                                                 original_n(result["pooled"]["original"])) + " |" * 8)
    return lines + landing_lines(result) + leave_out_lines(result, samples_file)


def collapse_cell(c):
    return "none" if c is None else "%.3f (%.3f s; %.3f)" % (c["min"], c["time"], c["after_min_n"])


def landing_lines(result):
    """the table of landings.landings: every row, each grid, the data file"""
    rows = result.get("landings") or []
    if not rows:
        return []
    stride = rows[0]["stride"]
    data = result.get("data_file")
    lines = ["", "## The landings: the original's count at its collapse", "",
             "Landing k: the minimum of the original's count (coordination_original) within "
             "%g cycle of t = k T, a quarter cycle after the minimum of N (landings.py); a "
             "landing whose window the rows do not cover is left out. Its value (t; cycles "
             "after the minimum of N) over every row; on %s (original.sample_grid; offset 0: "
             "the original's samples, those of the table above); in the original run's data "
             "file (%s) at the same landing." % (
                 landing.HALF_WIDTH, "the rows at the original's cadence" if stride == 1 else
                 "each grid of every %s row at the original's cadence" % (
                     "second" if stride == 2 else "%d-th" % stride),
                 "`%s`" % os.path.relpath(data) if data else "not read"), "",
             "| landing | window (s) | every row | " +
             " | ".join("grid offset %d%s" % (j, " (the original's samples)" if j == 0 else "")
                        for j in range(stride)) + " | the data file |",
             "|" + "---|" * (4 + stride)]
    for r in rows:
        lines.append("| %d | %.2f-%.2f | %s | %s | %s |" % (
            r["landing"], r["window"][0], r["window"][1], collapse_cell(r["every_row"]),
            " | ".join(collapse_cell(c) for c in r["grid"]), collapse_cell(r["data_file"])))
    return lines


def leave_out_lines(result, samples_file="PREFIX_fit_samples.txt"):
    """the table of leave_out: n of the original's fit on each grid, its fastest left out"""
    rows = result.get("leave_out") or []
    if not rows:
        return []
    most = original.LEAVE_OUT
    lines = ["", "## The original's fit, its fastest samples left out", "",
             "n of the original's fit (curve_fit of A (tau/N)^n, original.fit_rheology2) on "
             "each grid of rows at its cadence (offset 0: the table's), again without its k "
             "fastest samples, k = 1-%d (original.leave_fastest_out), and the range of those. "
             "Every sample with the cut that drops it: `%s`." % (most, samples_file), "",
             "| fit | grid offset | samples | n | n without the k fastest, k = 1-%d | "
             "range k = 1-%d |" % (most, most), "|---|---|---|---|---|---|"]
    for r in rows:
        n = [cell(x["n"], "%.2f").replace("none", "no fit") for x in r["rows"]]
        lo, hi, failed = original.leave_out_range(r["rows"])
        span = "none" if lo is None else "%.2f-%.2f" % (lo, hi)
        if failed:
            span += " (%d no fit)" % failed
        lines.append("| %s | %d | %d | %s | %s | %s |" % (r["fit"], r["offset"], r["count"], n[0],
                                                       ", ".join(n[1:]), span))
    return lines


def fit_samples_lines(result):
    """the text of PREFIX_fit_samples.txt: every original sample of the pooled fit, each grid"""
    lines = ["# the original's samples of its creep fit pooled over cycles %d-%d, every grid of "
             "rows at its cadence (offset 0: the fit's; original.fit_samples): the cut that drops "
             "each, or kept. Cuts (python/halfshear-darcy-rate-dependence.py at 116df3b):"
             % tuple(result["pooled"]["cycles"])]
    lines += ["#   %s: %s" % cut for cut in original.CUTS]
    lines.append("# offset time_s cycle tau/N rate_scaled_1/s cut")
    for r in result["fit_samples"]:
        lines.append("%d %.5f %d %.6f %.5e %s" % (r["offset"], r["time"], r["cycle"],
                                                  r["friction"], r["rate"], r["cut"]))
    return lines


def plot(series, result, path):
    """per cycle against phase: the original's shear velocity (stick shaded), the coordination
    of both counts (ours on every row, the original's on its samples); the rate against tau/N
    of both fits (cycles 2 on) with the fitted lines"""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    p = result["parameters"]
    period = p["period"]
    s = original.original_samples(series, period)
    t, v = s["time"], original.shear_velocity(s["vx_top"])
    fig, ax = plt.subplots(3, 1, figsize=(7.5, 10))
    count = len(result["cycles"])
    for row in result["cycles"]:
        k = row["cycle"]
        inside = (t >= (k - 1) * period) & (t < k * period)
        phase = t[inside] / period - (k - 1)
        kw = dict(color="C%d" % ((k - 1) % 10), lw=0.8, label="cycle %d" % k)
        ax[0].semilogy(phase, np.where(v[inside] > 0, v[inside], np.nan), **kw)
        for a, b in row["original"]["stick_intervals"]:
            ax[0].axvspan(a, b, color="k", alpha=0.2 / count, lw=0)
        every = (series["time"] >= (k - 1) * period) & (series["time"] < k * period)
        ax[1].plot(series["time"][every] / period - (k - 1), series["coordination"][every], **kw)
        if "coordination_original" in s:
            ax[1].plot(phase, s["coordination_original"][inside], ls="--", **dict(kw, label=None))
    ax[0].set_ylabel("shearVelocity(): max(vx_top, 0) (m/s)\nstick shaded")
    ax[1].set_ylabel("coordination: ours (solid),\nthe original's count (dashed)")
    for a in ax[:2]:
        a.set_xlabel("phase of the forcing cycle")
        a.legend(fontsize=7, ncol=2)
    m, o = result["pooled"]["ours"], result["pooled"]["original"]
    first, last = result["pooled"]["cycles"]
    if m:
        x, y = m["points"][:, 0], m["points"][:, 1]
        ax[2].loglog(x[y > 0], y[y > 0], "o", ms=3, color="C0",
                     label="ours: 0.05-cycle windows, n %.2f" % m["n"])
        # the least-squares line passes through the means of the logs
        lx = np.log(x[y > 0])
        xs = np.exp(np.linspace(lx.min(), lx.max(), 50))
        ax[2].loglog(xs, np.exp(np.mean(np.log(y[y > 0])) + m["n"] * (np.log(xs) - lx.mean())),
                     color="C0")
    if o["count"]:
        ax[2].loglog(o["friction"], o["rate"] / p["rate_scale"], ".", ms=2, color="C3",
                     label="original: samples, n %.2f" % o["n"])
        if not np.isnan(o["n"]):
            xs = np.linspace(o["friction"].min(), o["friction"].max(), 50)
            ax[2].loglog(xs, original.creep_rheology2(xs, o["n"], o["A"]) / p["rate_scale"],
                         color="C3")
    ax[2].set_xlabel("tau/N (N applied), cycles %d-%d" % (first, last))
    ax[2].set_ylabel("shear strain rate v/H (1/s, the run's time)")
    ax[2].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
