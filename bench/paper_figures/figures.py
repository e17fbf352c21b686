#!/usr/bin/python3
"""Does examples/tidal_shear reproduce Damsgaard et al. (2016)? The paper's results, measured
on the reduced case (examples/tidal_shear/README.md: the groups it keeps).

Part "cycle" (Figure 3): the example for 4 forcing cycles (10 s, 4,662,297 steps) with the
  pore water (k_c 3.5e-13, the default), dry (fluid 0), and with k_c 3.5e-14 and 3.5e-15
  (the paper's low-permeability twin). Per cycle: slip onset and end (the top layer's
  velocity, smoothed over 0.025 s, above / below 1 cm/s), peak and mean slip velocity, slip
  displacement, dilation during the slip, the smallest coordination number and its phase,
  the phase of the minimum of N on the grains, min and max of p_mean - p_top (/A); the
  stacked cycles against phase.
Part "permeability": from the same runs, slip displacement and onset phase against k_c (and
  dry) over cycles 2-4, with their cycle-to-cycle spread.
Part "creep" (Figure S1): (1) the paper's method, from the same tidal cycles: the shear
  strain rate (top-layer velocity / bed height, from the displacement over 0.05-cycle
  windows) against tau/N over phases 0.2-0.6 of each cycle while N falls;
  gamma_dot ~ (tau/N)^n fitted per cycle and pooled, with 95 % intervals. (2) Time scaling:
  the default forced 2x slower, every other group kept (SLOW below): the same windows.
  (3) Constant-stress shear tests (constant_stress.py): 8 tau/N x 2 bed states x 2 N, the
  creep rate of those that hold, n and the yield tau/N of each state.
Part "full" (table_s1_size.py): the example at Table S1 size on 2 ranks for --budget wall
  seconds (preparation included), its cost per step against the projection and its first
  part of the cycle against the reduced default's at the same phases.

Part "bisect": the friction while preparing that starts the original's bed (size spread
  0.009) at the original run's coordination (common.beds.bisect_mu_prep).
Part "factors" (factors.py): each difference from the original program alone from
  the default, then all together (2 cycles; k_n x10 1.6, x100 0.6); one table, one figure.
Part "factor_stress" --factor NAME: that factor's settings held at constant stress, two tau/N.

Usage (after scripts/setup.sh; source scripts/env.sh):
    /usr/bin/python3 bench/paper_figures/figures.py --part cycle|permeability|creep|full|bisect|factors|all
        [--work DIR] [--jobs N] [--budget S] [--analyse-only]
`--part all` is cycle, permeability and creep; full runs apart (it needs both cores alone).
Runs whose output is complete in --work are not repeated; the parameters were fixed before
any run (examples/tidal_shear/in.params). Each part writes bench/paper_figures/<part>_results.md
(the tables; RESULTS.md beside it discusses them) and its PNGs there. The short setting
(bench/smoke.py) runs each run a few thousand steps: none is complete, the tables are empty.
"""
import argparse
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import COMMON, SMOKE, out_dir, short    # noqa: E402
from common.beds import bisect_mu_prep    # noqa: E402
from common.runs import FRICTIONLESS, complete, head_commit, load, prepare, read_cost, timed_run    # noqa: E402
import factors    # noqa: E402
import table_s1_size    # noqa: E402
import constant_stress    # noqa: E402
from porewater_analysis.cycles import (AMP, PERIOD, SLIP_VELOCITY, SMOOTH, creep_points,
                                       cycle_metrics, fmt, inertia_number,
                                       original_data_file_metrics, power_law, smoothed_velocity)    # noqa: E402

OUT = out_dir(HERE)
CYCLES = 4
RUN_CYCLES = short(CYCLES, 0.002)       # what a run runs; a shorter one is never complete
SIGMA0 = 80.0e3            # Pa: examples/tidal_shear/in.params
VARIANTS = {  # name: (label, k_c or None for dry, -var overrides)
    "wet": ("k_c 3.5e-13 (default)", 3.5e-13, {}),
    "mid": ("k_c 3.5e-14", 3.5e-14, {"kc": 3.5e-14}),
    "twin": ("k_c 3.5e-15 (low-k twin)", 3.5e-15, {"kc": 3.5e-15}),
    "dry": ("dry (fluid 0)", None, {"fluid": 0}),
}


def run_variant(work, name):
    d = os.path.join(work, "cycle", name)
    out = os.path.join(d, "timeseries.txt")
    if complete(out, CYCLES * PERIOD):
        return name, None
    prepare(d)
    return name, timed_run(d, "in.tidal_shear", dict(FRICTIONLESS, **VARIANTS[name][2], cycles=RUN_CYCLES))


def cycle_table(data):
    lines = ["Per cycle of 2.5 s (phase 0 at the cycle's start, N = sigma0 and rising; its minimum "
             "at phase 0.75). Slip: the top layer's velocity, from its displacement over %.3f s, "
             "above %g m/s (onset; tau/N there) until it falls below it again (end; 1.000 when the "
             "slip goes on into the next cycle); creep v: its mean velocity "
             "over phases 0.2-0.6. Dilation: the plate's rise from the onset to its highest "
             "during the slip. Z: coordination number; N_g: the grains' force on the plate per "
             "area; dp: p_mean - p_top in the fluid cells below the plate, over A."
             % (SMOOTH, SLIP_VELOCITY), "",
             "| run | cycle | creep v (m/s) | onset (tau/N) | end | peak v (m/s) (phase) | mean v (m/s) "
             "| slip (mm) | dilation (mm) | min Z (phase) | phase of min N_g | dp min, max (A) |",
             "|" + "---|" * 12]
    for label, rows in data.values():
        for r in rows:
            dp = "%.3f, %.3f" % (r["dp_min"], r["dp_max"]) if "dp_min" in r else "dry"
            onset = "%.3f (%.2f)" % (r["onset"], r["ratio"]) if "onset" in r else "none"
            lines.append("| %s | %d | %.2e | %s | %s | %s | %s | %s | %s | %.2f (%.3f) | %.3f | %s |" % (
                label, r["cycle"], r["v_creep"], onset, fmt(r, "end", "%.3f"),
                "%.3f (%.3f)" % (r["peak"], r["peak_phase"]) if "peak" in r else "none", fmt(r, "mean", "%.3f"), fmt(r, "slip", "%.1f", 1e3),
                fmt(r, "dilation", "%.1f", 1e3), r["z_min"], r["z_min_phase"], r["n_min_phase"], dp))
    return lines


def spread_table(data, keep):
    """mean (min to max) over the cycles kept"""
    lines = ["| run | cycles | onset | tau/N at onset | slip (mm) | peak v (m/s) | dilation (mm) "
             "| min Z | dp min (A) |", "|" + "---|" * 9]
    for label, rows in data.values():
        kept = [r for r in rows if r["cycle"] in keep]

        def span(key, scale=1.0, f="%.3f"):
            vals = [scale * r[key] for r in kept if key in r]
            if not vals:
                return "none"
            return (f + " (" + f + " to " + f + ")") % (np.mean(vals), min(vals), max(vals))
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            label, ",".join(str(r["cycle"]) for r in kept), span("onset"), span("ratio", 1.0, "%.2f"),
            span("slip", 1e3, "%.1f"),
            span("peak"), span("dilation", 1e3, "%.1f"), span("z_min", 1.0, "%.2f"),
            span("dp_min") if any("dp_min" in r for r in kept) else "dry"))
    return lines


COLOURS = {"wet": "C0", "mid": "C2", "twin": "C3", "dry": "C7"}


def plot_cycles(series, path):
    fig, ax = plt.subplots(5, 1, figsize=(8, 12), sharex=True)
    for name, (label, c) in series.items():
        t = c["time"]
        v = smoothed_velocity(t, c["x_top"])
        for k in range(CYCLES):
            inside = (t >= k * PERIOD) & (t < (k + 1) * PERIOD)
            ph = t[inside] / PERIOD - k
            kw = dict(color=COLOURS[name], lw=0.8, alpha=0.4 + 0.15 * k,
                      label=label if k == CYCLES - 1 else None)
            ax[0].semilogy(ph, np.abs(v[inside]), **kw)
            ax[1].plot(ph, c["N_grains"][inside] / 1e3, **kw)
            if name != "dry":
                ax[2].plot(ph, (c["p_mean"] - c["p_top"])[inside] / AMP, **kw)
            ax[3].plot(ph, 1e3 * (c["z_wall"][inside] - c["z_wall"][inside][0]), **kw)
            ax[4].plot(ph, c["coordination"][inside], **kw)
    ph = np.linspace(0, 1, 200)
    ax[1].plot(ph, (SIGMA0 + AMP * np.sin(2 * np.pi * ph)) / 1e3, "k--", lw=0.8, label="applied N")
    ax[0].axhline(SLIP_VELOCITY, color="k", lw=0.5, ls=":")
    ax[0].set_ylim(1e-7, 1)
    labels = ["|v_x| top layer (m/s)", "N on the grains (kPa)", "(p_mean - p_top)/A",
              "plate rise in the cycle (mm)", "coordination"]
    for a, l in zip(ax, labels):
        a.set_ylabel(l)
    ax[0].legend(fontsize=7, loc="lower left")
    ax[1].legend(fontsize=7, loc="upper right")
    ax[-1].set_xlabel("phase of the forcing cycle (cycles 1-%d stacked, later ones darker)" % CYCLES)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def plot_permeability(data, keep, path):
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.5))
    for name, (label, rows) in data.items():
        kc = VARIANTS[name][1]
        x = kc if kc else 1e-11    # the dry bed, drawn at the right
        for r in rows:
            if r["cycle"] not in keep:
                continue
            ax[0].semilogx(x, 1e3 * r.get("slip", 0.0), "o", color=COLOURS[name])
            if "onset" in r:
                ax[1].semilogx(x, r["onset"], "o", color=COLOURS[name])
    ax[0].set_ylabel("slip displacement per cycle (mm)")
    ax[1].set_ylabel("slip onset (phase)")
    for a in ax:
        a.set_xlabel("k_c (m^2); at 1e-11: dry")
    fig.tight_layout()
    fig.savefig(path, dpi=90)


# ---------------------------------------------------------------- creep from the cycles

def save_rate_plot(fig, ax, path):
    ax.set_xlabel("tau/N (N: the applied normal stress)")
    ax.set_ylabel("shear strain rate v_x/H (1/s)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def creep_report(series, path):
    lines = ["| run | cycle | n (95 %) | windows used (dropped: rate <= 0) | r^2 | inertia number I |",
             "|---|---|---|---|---|---|"]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for name, (label, c) in series.items():
        pts = creep_points(c, cycles=CYCLES)
        cycles = sorted(set(pts[:, 2].astype(int)))
        sets = [(str(k), pts[pts[:, 2] == k]) for k in cycles]
        sets += [("%d-%d pooled" % (cycles[1], cycles[-1]), pts[pts[:, 2] >= cycles[1]])] if len(cycles) > 2 else []
        sets += [("all pooled", pts)]
        for which, sel in sets:
            fit = power_law(sel)
            if fit:
                i = inertia_number(sel)
                lines.append("| %s | %s | %.1f ± %.1f | %d (%d) | %.2f | %.1e to %.1e |" % (
                    (label, which) + fit + (i.min(), i.max())))
            else:
                lines.append("| %s | %s | too few positive rates | | | |" % (label, which))
        good = pts[pts[:, 1] > 0]
        ax.loglog(good[:, 0], good[:, 1], "o", ms=3, color=COLOURS[name], label=label)
    save_rate_plot(fig, ax, path)
    return lines


# ---------------------------------------------------------------- time scaling

# 2x slower forcing of the same bed, every group of the example's README kept but the
# grains' own time scale: mu_f x2 (mu_f H^2/(k T sigma0), D T/H^2), plate mass x4
# (m_w H/(A Lx Ly T^2)); t_contact/T and the inertia number halve
SLOW = {"freq": 0.2, "mu_f": 3.86e-7, "mass_factor": 1.972, "cycles": 1.6}
SLOW_RUN_CYCLES = short(SLOW["cycles"], 0.001)
SLOW_CYCLES = 2        # the creep windows (phases 0.2-0.6) of cycles 1 and 2


def load_slow(work):
    """the 2x slower run's time series, or None before it is complete"""
    out = os.path.join(work, "slow", "timeseries.txt")
    return load(out) if complete(out, SLOW["cycles"] / SLOW["freq"]) else None


def run_slow(work):
    d = os.path.join(work, "slow")
    if load_slow(work) is None:
        prepare(d)
        timed_run(d, "in.tidal_shear", dict(FRICTIONLESS, **dict(SLOW, cycles=SLOW_RUN_CYCLES)))
    return load_slow(work)


def time_scaling_report(fast, slow, path):
    """creep windows of the default and of the 2x slower forcing, cycle by cycle"""
    pf = creep_points(fast, period=PERIOD, cycles=SLOW_CYCLES)
    ps = creep_points(slow, period=1.0 / SLOW["freq"], cycles=SLOW_CYCLES)
    lines = ["Resolved windows: both rates above 3x the noise floor, the largest |rate| of a "
             "window with a negative rate in either run (the plate's shear vibration).", "",
             "| cycle | n at f (95 %) | n at f/2 | gamma_dot(f/2) / gamma_dot(f) at the same "
             "phase, resolved windows (tau/N) | shear strain over phases 0.2-0.6, f and f/2 "
             "| largest I, f and f/2 | slip (mm) and its onset phase, f and f/2 |",
             "|---|---|---|---|---|---|---|"]
    slips = [cycle_metrics(fast, True, PERIOD, CYCLES), cycle_metrics(slow, True, 1.0 / SLOW["freq"], SLOW_CYCLES)]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for k in range(1, SLOW_CYCLES + 1):
        f, sl = pf[pf[:, 2] == k], ps[ps[:, 2] == k]
        negative = np.concatenate([f[f[:, 1] < 0, 1], sl[sl[:, 1] < 0, 1]])
        floor = 3 * np.abs(negative).max() if len(negative) else 0.0
        both = (f[:, 1] > floor) & (sl[:, 1] > floor)
        ratios = ", ".join("%.2f (%.2f)" % (b / a, x) for x, a, b in
                           zip(f[both, 0], f[both, 1], sl[both, 1]))
        strain = [PERIOD * 0.05 * f[:, 1].sum(), 0.05 / SLOW["freq"] * sl[:, 1].sum()]
        fits = [power_law(f), power_law(sl)]
        lines.append("| %d | %s | %s | %s | %.2e, %.2e | %.1e, %.1e | %s |" % (
            k, *["%.1f ± %.1f" % x[:2] if x else "too few" for x in fits], ratios or "none",
            strain[0], strain[1], inertia_number(f).max(), inertia_number(sl).max(),
            ", ".join("%.1f (%.3f)" % (1e3 * r["slip"], r["onset"]) if "slip" in r else "none"
                      for r in (slips[0][k - 1], slips[1][k - 1]))
            if k <= SLOW["cycles"] else "f/2: the run ends before (phase %.1f)" % (SLOW["cycles"] % 1)))
        for pts, col, lab in [(f, "C0", "f = 0.4 Hz"), (sl, "C3", "f = 0.2 Hz")]:
            good = pts[pts[:, 1] > 0]
            ax.loglog(good[:, 0], good[:, 1], "o" if k == 1 else "s", ms=4, color=col,
                      mfc="none" if k == 1 else col, label="%s, cycle %d" % (lab, k))
    save_rate_plot(fig, ax, path)
    return lines


def load_cycles(work):
    series, costs = {}, {}
    for name, (label, _, _) in VARIANTS.items():
        d = os.path.join(work, "cycle", name)
        if complete(os.path.join(d, "timeseries.txt"), CYCLES * PERIOD):
            series[name] = (label, load(os.path.join(d, "timeseries.txt")))
            if read_cost(d):
                costs[name] = read_cost(d)
    return series, costs


def header(part, costs):
    commit = head_commit()
    lines = ["# Measured by bench/paper_figures/figures.py --part %s" % part, "",
             "`/usr/bin/python3 bench/paper_figures/figures.py --part %s`, tables written at commit %s from the runs "
             "in --work, on the 2-core "
             "development machine, shared with other jobs (CPU times below)." % (part, commit), ""]
    if costs:
        lines += ["| run | CPU s | wall s |", "|---|---|---|"]
        lines += ["| %s | %.0f | %.0f |" % (n, c[0], c[1]) for n, c in costs.items()]
        lines.append("")
    return lines


def write(part, lines):
    open(os.path.join(OUT, "%s_results.md" % part), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--part", default="all",
                    choices=["cycle", "permeability", "creep", "full", "bisect", "factors",
                             "factor_stress", "all"])
    ap.add_argument("--factor", default="all",
                    help="--part factor_stress: the factor run whose settings are held at "
                         "constant stress (factors.FACTORS)")
    ap.add_argument("--work", default="/tmp/pw_fidelity")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--budget", type=float, default=3600.0,
                    help="--part full: wall seconds of the run (the preparation apart)")
    ap.add_argument("--analyse-only", action="store_true")
    args = ap.parse_args()
    pool = ThreadPoolExecutor(args.jobs)
    jobs_map = lambda f, xs: list(pool.map(f, xs))
    if args.part == "bisect":
        probes = bisect_mu_prep(args.work, jobs_map, rounds=short(3, 1))
        write("bisect", header("bisect", {}) + factors.bisect_table(probes))
        return
    if args.part == "factor_stress":
        results = factors.held(args.work, args.factor, jobs_map)
        write("factor_stress", header("factor_stress", {}) + factors.stress_table(
            args.factor, results))
        return
    if args.part == "factors":
        if not args.analyse_only:
            factors.run_all(args.work, jobs_map)
        original = original_data_file_metrics(os.path.join(COMMON, "original_run_contacts.txt"))
        lines, results = factors.table(args.work, original, 2)
        first, _ = factors.table(args.work, original, 1)
        factors.plot(results, os.path.join(OUT, "factors.png"))
        costs = {label: read_cost(os.path.join(args.work, "factors", n))
                 for n, (label, _, _, _) in factors.FACTORS.items()}
        write("factors", header("factors", {k: v for k, v in costs.items() if v}) + [
            "## Beds", ""] + factors.beds_table(args.work) + [
            "", "## Each factor alone, then all together: cycle 2", ""] + lines + [
            "", "## Cycle 1 (from the unsheared bed)", ""] + first + [
            "", "![n and the minimum coordination per factor](factors.png)"])
        return
    if args.part == "full":
        if not args.analyse_only:
            table_s1_size.run_full(args.work, args.budget)
        series, _ = load_cycles(args.work)
        d = os.path.join(args.work, "full")
        lines, full = table_s1_size.compare(d, series["wet"][1], PERIOD)
        write("full", header("full", {"Table S1 size, 2 ranks (the run)": read_cost(d)}) + [
            "## Table S1 size", ""] + lines)
        return
    if not args.analyse_only:
        for name, cpu in jobs_map(lambda n: run_variant(args.work, n), VARIANTS):
            print("%s: %s" % (name, "done before" if cpu is None else "%.0f s CPU" % cpu),
                  flush=True)
    if args.part in ("creep", "all"):
        slow = run_slow(args.work) if not args.analyse_only else load_slow(args.work)
        stress = constant_stress.series(args.work, jobs_map, run=not args.analyse_only)
    series, costs = load_cycles(args.work)
    if not series:
        if not SMOKE:
            sys.exit("no complete run in " + args.work)
        print("no complete run in %s (the short setting): no tables" % args.work)
        return
    costs = {VARIANTS[n][0]: c for n, c in costs.items()}
    keep = list(range(2, CYCLES + 1))    # cycle 1 starts from the consolidated, unsheared bed
    data = {n: (label, cycle_metrics(c, VARIANTS[n][1] is not None, PERIOD, CYCLES))
            for n, (label, c) in series.items()}
    if args.part in ("cycle", "all"):
        plot_cycles(series, os.path.join(OUT, "cycle.png"))
        write("cycle", header("cycle", costs) + ["## Figure 3: the tidal cycle", ""] +
              cycle_table(data) + ["", "![stacked cycles](cycle.png)"])
    if args.part in ("permeability", "all"):
        plot_permeability(data, keep, os.path.join(OUT, "permeability.png"))
        write("permeability", header("permeability", costs) + [
            "## What the pore water changes", "",
            "Over cycles %s (cycle 1 starts from the consolidated, never sheared bed), "
            "mean (min to max):" % ",".join(map(str, keep)), ""] + spread_table(data, keep) + [
            "", "![slip against permeability](permeability.png)"])
    if args.part in ("creep", "all"):
        costs["2x slower forcing"] = read_cost(os.path.join(args.work, "slow"))
        lines = header("creep", costs) + [
            "## Figure S1 from the tidal cycles", "",
            "Windows of 0.05 cycle over phases 0.2-0.6 of each cycle (N falling from 150 "
            "to 52 kPa; the paper: 1-3 s into each 5 s cycle); gamma_dot: the slope of the "
            "top layer's displacement over the window, over the plate's height; fitted "
            "log gamma_dot = n log(tau/N) + c over the windows with a positive rate.", ""]
        lines += creep_report(series, os.path.join(OUT, "creep_cycles.png"))
        lines += ["", "![creep from the cycles](creep_cycles.png)", "",
                  "## Time scaling: the same bed forced 2x slower", "",
                  "The default (f = 0.4 Hz) against f = 0.2 Hz with %s (every group of the "
                  "example's README but t_contact/T and I kept), cycles 1-%d; windows as above."
                  % (", ".join("%s %s" % kv for kv in SLOW.items()), SLOW_CYCLES), ""]
        if slow is not None and "wet" in series:
            lines += time_scaling_report(series["wet"][1], slow,
                                         os.path.join(OUT, "time_scaling.png"))
            lines += ["", "![time scaling](time_scaling.png)"]
        else:
            lines += ["(the default's or the slower run is not complete)"]
        lines += ["", "## Figure S1 at constant stress", ""]
        lines += constant_stress.report(stress)
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        constant_stress.plot(stress, ax)
        fig.tight_layout()
        fig.savefig(os.path.join(OUT, "creep_stress.png"), dpi=90)
        write("creep", lines + ["", "![creep at constant stress](creep_stress.png)"])


if __name__ == "__main__":
    main()
