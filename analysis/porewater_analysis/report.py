"""Both estimators on one run, cycle by cycle: dicts for a benchmark's tables (analyse_run),
the markdown table and the figure of `python3 -m porewater_analysis`."""
import os

import numpy as np

from . import cycles as ours
from . import original
from .timeseries import load, run_parameters, whole_cycles

MU_F = 2.415e-7            # Pa s: the reduced example's default bed (in.bed_original)
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


def analyse_series(series, period, tau, amp, rate_scale, cycles=None):
    """{"cycles": [{"cycle", "ours", "original"} a whole cycle], "pooled": {"cycles",
    "ours", "original"} over cycles 2 to the last}, at most `cycles` cycles. Ours:
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
    return {"cycles": rows, "pooled": pooled}


def analyse_run(run_dir, cycles=None):
    """analyse_series on run_dir/timeseries.txt with the run's own parameters
    (checkpoint_params.txt), plus "parameters" and "notes" (the values not recorded)"""
    params, notes = parameters(run_dir)
    result = analyse_series(load(os.path.join(run_dir, "timeseries.txt")), cycles=cycles,
                            **params)
    return dict(result, parameters=params, notes=notes)


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


def markdown(result, run_dir):
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
