"""What sets the creep exponent and the contact collapse (figures.py --part factors):
each way the reduced example differs from the original program, alone from the frictionless
bed (the example's default until the original's bed, factor 1, became it; in.params `bed`),
then all of them together (the example's `-var original 1`), 2 cycles each (CYCLES).

Beds (prepared once, before any tidal run; their targets fixed in advance; bench/common/beds.py):
  spread   in.pack/in.consolidate frictionless, log-normal radii of spread 0.009 (the
           original's packing scripts)
  original the same with friction mu_prep MU_PREP_ORIGINAL while packing and consolidating:
           the value that starts the tidal run at the original's coordination, 4.58 (the
           first row of the original run's contacts, bench/common/original_run_contacts.txt),
           found by bisection on beds alone
  kn10, kn100  the frictionless bed consolidated again (in.consolidate) at k_n x10, x100
Every bed runs with the groups of the example kept for its own H and phi (bed_groups):
the fluid cells' height, mu_f (mu_f H^2/(k T sigma0)) and the plate mass (m_w H/(A Lx Ly T^2)).
The short setting (bench/smoke.py): two beds (spread, kn10) and four factors, every run a few
thousand steps, never complete.
"""
import os
import shutil

import numpy as np

import constant_stress
from common import EXAMPLE, short
from common.beds import (MU_PREP_ORIGINAL, RESETTLE, SHIPPED_FRICTIONLESS, SPREAD, STIFF,
                         TARGET_Z, bed_geometry, bed_groups, prepare_bed)
from common.runs import FRICTIONLESS, complete, load, prepare, read_cost, run_lmp, timed_run
from porewater_analysis.cycles import PERIOD, after_min_n, factor_metrics, fmt
from porewater_analysis.original import ORIGINAL_CYCLES
from porewater_analysis.timeseries import run_parameters

# cycles per run: 2 (cycle 1 from the unsheared bed, cycle 2 kept); k_n x10 1.6 (cycle 2's
# creep, phases 0.2-0.6, not its slip), x100 0.6 (cycle 1's creep): 3.2x and 10x the steps
# of a cycle, at ~3,000 steps/s per run with two side by side on the development machine
CYCLES, KN10_CYCLES, KN100_CYCLES = 2, 1.6, 0.6
SHORT_CYCLES = 0.002                      # the short setting's runs
BEDS = {  # name: (in.pack / in.consolidate -var overrides, the shipped bed, or None: packed anew)
    "spread": ({"radius_spread": SPREAD, "mu_prep": 0.0}, None),
    "kn10": (dict(FRICTIONLESS, **STIFF["kn10"], settle_time=RESETTLE), SHIPPED_FRICTIONLESS),
    "kn100": (dict(FRICTIONLESS, **STIFF["kn100"], settle_time=RESETTLE), SHIPPED_FRICTIONLESS),
}


# name: (label, bed or None for the shipped one, in.tidal_shear -var overrides, cycles)
FACTORS = {
    "default": ("frictionless bed (the former default)", None, FRICTIONLESS, CYCLES),
    "bed": ("1. bed of the original (friction + spread)", "original", {}, CYCLES),
    "kn10": ("2. k_n x10", "kn10", STIFF["kn10"], KN10_CYCLES),
    "kn100": ("2. k_n x100 (Table S1's)", "kn100", STIFF["kn100"], KN100_CYCLES),
    "ty3": ("3. integrator nve/sphere/ty3", None, dict(FRICTIONLESS, integrator="nve/sphere/ty3"),
            CYCLES),
    "relaxed": ("4. pressure iteration relaxed", None, dict(FRICTIONLESS, solver="relaxed"), CYCLES),
    "spread": ("5. size spread alone", "spread", {}, CYCLES),
    "all": ("6. all together (-var original 1)", None, {"original": 1}, CYCLES),
}
# the order that keeps both cores busy: the longest first
RUN_ORDER = ["kn100", "kn10", "bed", "all", "default", "ty3", "relaxed", "spread"]
# the short setting: a bed packed anew, a shipped one consolidated again, and the factors on them
SHORT_BEDS, SHORT_RUNS = ("spread", "kn10"), ["kn10", "spread", "default", "ty3"]


def factor_variables(work, name):
    """the run's -var overrides: the factor's, with the bed's data file and its groups"""
    _, bed, overrides, cycles = FACTORS[name]
    variables = dict(overrides, cycles=cycles)
    if bed:
        data = os.path.join(work, "beds", bed, "bed.data")
        variables.update(bed_groups(*bed_geometry(data)), data="bed.data")
    return variables


def run_factor(work, name):
    d = os.path.join(work, "factors", name)
    cycles = FACTORS[name][3]
    if complete(os.path.join(d, "timeseries.txt"), cycles * PERIOD):
        return name, None
    prepare(d)
    variables = factor_variables(work, name)
    if "data" in variables:
        shutil.copy(os.path.join(work, "beds", FACTORS[name][1], "bed.data"), d)
    return name, timed_run(d, "in.tidal_shear", dict(variables, cycles=short(cycles, SHORT_CYCLES)))


def original_row(o, cycles):
    lo = lambda v, f: (f + " (" + f + "-" + f + ")") % (np.mean(v), min(v), max(v))
    phases = sorted(o["z_min_phase"])
    return ("| paper / the original's data file (cycles %s) | 6-11 | %s | %s (median %.3f, "
            "range %.3f-%.3f) | | ~0.61 | ~0.81 | 0.26-0.38 (yield) | | | ~70 days on a GPU |" % (
                cycles, lo(o["z_creep"], "%.2f"), lo(o["z_min"], "%.3f"), np.median(phases),
                phases[0], phases[-1]))


def table(work, original, cycle):
    """one row per factor, its metrics in the given cycle"""
    lines = ["| run | n (95 %) | Z creeping | min Z (cycles after the minimum of N) | slip (mm) | onset | end "
             "| tau/N at onset | suction in slip (A) | landing rms (A) | wall s (CPU s) |",
             "|" + "---|" * 11, original_row(original, "2-%d" % ORIGINAL_CYCLES)]
    results = {}
    for name, (label, _, _, cycles) in FACTORS.items():
        d = os.path.join(work, "factors", name)
        if not complete(os.path.join(d, "timeseries.txt"), cycles * PERIOD):
            lines.append("| %s | not run |" % label + " |" * 9)
            continue
        per_cycle = factor_metrics(load(os.path.join(d, "timeseries.txt")), cycles)
        results[name] = per_cycle
        r = per_cycle.get(cycle, {})
        if "z_creep" not in r:
            lines.append("| %s | the run ends before cycle %d's creep |" % (label, cycle) + " |" * 9)
            continue
        cost = read_cost(d)
        fit = r.get("fit")
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            label, "%.1f ± %.1f" % fit[:2] if fit else "too few", fmt(r, "z_creep", "%.2f"),
            "%s (%s)" % (fmt(r, "z_min", "%.2f"),
                         "%.3f" % after_min_n(r["z_min_phase"]) if "z_min" in r else "none"),
            fmt(r, "slip", "%.0f", 1e3), fmt(r, "onset", "%.3f"), fmt(r, "end", "%.3f"),
            fmt(r, "ratio", "%.2f"), fmt(r, "suction", "%.3f"), fmt(r, "landing", "%.2f"),
            "%.0f (%.0f)" % (cost[1], cost[0]) if cost else ""))
    return lines, results


def plot(results, path):
    import matplotlib.pyplot as plt
    names = [n for n in FACTORS if n in results]
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for i, name in enumerate(names):
        for k, style in ((1, dict(mfc="none")), (2, {})):
            r = results[name].get(k, {})
            if r.get("fit"):
                ax[0].errorbar(i + 0.1 * (k - 1.5), r["fit"][0], yerr=r["fit"][1], fmt="o",
                               color="C0", label="cycle %d" % k if i == 0 else None, **style)
            if "z_min" in r:
                ax[1].plot(i + 0.1 * (k - 1.5), r["z_min"], "o", color="C3",
                           label="cycle %d" % k if i == 0 else None, **style)
    ax[0].axhspan(6, 11, color="0.85", label="paper: 6-11")
    ax[1].axhspan(0.03, 0.05, color="0.85", label="original run: 0.03-0.05")
    ax[0].set_ylabel("creep exponent n of the cycle (95 %)")
    ax[1].set_ylabel("minimum coordination of the cycle")
    ax[1].set_yscale("log")
    for a in ax:
        a.set_xticks(range(len(names)))
        a.set_xticklabels([FACTORS[n][0].split(" (")[0] for n in names], rotation=35,
                          ha="right", fontsize=7)
        a.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


BED_RUN = {"shipped": "default", "original": "bed", "spread": "spread", "kn10": "kn10",
           "kn100": "kn100"}


def beds_table(work):
    """each bed's H, phi, the parameters that keep its groups, and its first coordination"""
    lines = ["| bed | H (m) | phi | coordination at 2.5 ms | cell_z, mu_f, mass_factor |",
             "|---|---|---|---|---|"]
    for name, run in BED_RUN.items():
        data = os.path.join(EXAMPLE, SHIPPED_FRICTIONLESS) if name == "shipped" else \
            os.path.join(work, "beds", name, "bed.data")
        series = os.path.join(work, "factors", run, "timeseries.txt")
        if not os.path.exists(data):
            continue
        h, phi = bed_geometry(data)
        g = bed_groups(h, phi)
        z0 = "%.3f" % load(series)["coordination"][0] if os.path.exists(series) else "-"
        lines.append("| %s | %.4f | %.4f | %s | %.4f, %.3e, %.3f |" % (
            name, h, phi, z0, g["cell_z"], g["mu_f"], g["mass_factor"]))
    return lines


def run_all(work, jobs_map):
    beds = dict(BEDS, original=({"radius_spread": SPREAD, "mu_prep": MU_PREP_ORIGINAL}, None))
    jobs_map(lambda n: prepare_bed(work, n, *beds[n]), short(list(beds), list(SHORT_BEDS)))
    for name, cpu in jobs_map(lambda n: run_factor(work, n), short(RUN_ORDER, SHORT_RUNS)):
        print("%s: %s" % (name, "done before" if cpu is None else "%.0f s CPU" % cpu), flush=True)


def bisect_table(probes):
    lines = ["Beds of spread %g packed and consolidated with friction mu_prep; the target: "
             "coordination %.2f at the tidal run's first sample (2.5 ms)." % (SPREAD, TARGET_Z), "",
             "| mu_prep | coordination at 2.5 ms | H (m) | phi |", "|---|---|---|---|"]
    lines += ["| %.4f | %.3f | %.4f | %.4f |" % p for p in probes]
    return lines


# constant-stress repeat for the run closest to the paper: the same protocol as
# constant_stress (N 25 kPa, no forcing, 2 s held, creep over 1-2 s), at two tau/N below the
# sheared default's yield (0.30-0.40 at 25 kPa), from that run's unsheared bed
STRESS_N, STRESS_RATIOS = 25.0e3, (0.2, 0.3)


def held(work, name, jobs_map):
    """the factor run's settings held at constant stress, STRESS_RATIOS: [(tau/N, result or
    None before the run is complete)]"""
    variables = factor_variables(work, name)
    variables.pop("cycles")
    recorded = run_parameters(os.path.join(work, "factors", name))
    mass_factor, dt = recorded["mass_factor"], recorded["dt"]

    def one(ratio):
        d = os.path.join(work, "stress_" + name, "r%.2f" % ratio)
        seconds = constant_stress.HOLD_TIME
        out = os.path.join(d, "timeseries.txt")
        if not complete(out, seconds):
            prepare(d)
            if "data" in variables:
                shutil.copy(os.path.join(work, "beds", FACTORS[name][1], "bed.data"), d)
            run_lmp(d, "in.tidal_shear", dict(
                variables, amp=0, sigma0=STRESS_N, tau=ratio * STRESS_N,
                mass_factor=mass_factor * constant_stress.SIGMA0 / STRESS_N,
                run_steps=int(round(short(seconds, 0.005) / dt))))
        if not complete(out, seconds):
            return ratio, None
        c = load(out)
        r = {"held": abs(np.polyfit(c["time"][-50:], c["x_top"][-50:], 1)[0]) < 1e-2}
        if r["held"]:
            r.update(constant_stress.measure(c))
        return ratio, r
    return jobs_map(one, STRESS_RATIOS)


def stress_table(name, results):
    lines = ["%s, N %.0f kPa held 2 s: gamma_dot over 1-2 s (95 %%), constant_stress.py's "
             "measure; the frictionless beds (the former default) did not creep (|gamma_dot| < 1e-8 1/s)."
             % (FACTORS[name][0], STRESS_N / 1e3), "",
             "| tau/N | holds | gamma_dot (1/s) | over 0.5-1 s | take-up (mm) |", "|---|---|---|---|---|"]
    for ratio, r in results:
        if r is None:
            lines.append("| %.2f | not complete | | | |" % ratio)
        elif not r["held"]:
            lines.append("| %.2f | fails | | | |" % ratio)
        else:
            lines.append("| %.2f | yes | %.1e ± %.1e | %.1e | %.3f |" % (
                ratio, r["rate"], r["half"], r["rate_early"], 1e3 * r["take_up"]))
    return lines
