#!/usr/bin/python3
"""Time to solution of examples/tidal_shear: the chaotic spread of the outputs the paper
reports, each numerical knob's error against that spread, and what each costs.

Part "ensemble" (its sizes and metrics: bench/common/ensembles.py; bench/fidelity/ensemble.py
  --run default makes the same runs): the default run and ENSEMBLE - 1 copies whose sheared bed differs at the
  start by round-off: every grain of it moved by a random displacement of up to PERTURB
  along each axis (in.tidal_shear -var perturb, perturb_seed K), CYCLES cycles each, 1 rank.
Part "ensemble_np2": the default and NP2_ENSEMBLE - 1 of the same perturbed starts (seeds
  1, 2, ...: the same grains as the 1-rank members of those seeds) on 2 MPI ranks, one at a
  time on both cores: whether the decomposition shifts the outputs beyond the chaos.
  Per run, the metrics (SETTING_METRICS) averaged over cycles 2-4 (cycle 1 starts from the unsheared
  bed), and the creep exponent n pooled over the windows of cycles 2-4. The band of a metric:
  the 95 % prediction interval of one more run of the ensemble, mean +- t(0.975, N-1) s
  sqrt(1 + 1/N) over its N members: a run that differs from the default by round-off alone
  falls outside it once in 20.
Part "knobs": each knob of KNOBS alone, CYCLES cycles: its metrics against the band.
Part "layout": the default on the 2 cores as 2 MPI ranks, and as 1 rank x 2 OpenMP threads
  with /kk (each alone on the machine: wall time).
Part "fast": the preset -var fast 1 (in.params), likewise.
Part "table_s1": the Table S1 case (-var full 1, 9,600 grains, its bed prepared as the
  default's, common.beds.prepare_full) on both cores (2 MPI ranks) for TABLE_S1_BUDGET wall
  seconds with the default settings and with -var fast 1: the cost per step and per second of
  model time, and the 45 s of Table S1 projected; on a GPU projected from the Kokkos dispatches
  counted per step (bench/common/kokkos_dispatches.cpp) at assumed latencies.
Part "report" (no runs): the tables (time_to_solution_results.md) and the figure
  (time_to_solution.png) beside this script, from the runs in --work.

Costs: the CPU seconds of each 1-rank run (two run side by side, one per core, so CPU time
is the wall time a run takes on a core of its own), the wall seconds of the runs on both
cores; every run records the load average before and after (cost.txt).

Usage (after scripts/setup.sh; source scripts/env.sh):
    /usr/bin/python3 bench/time_to_solution/time_to_solution.py --part ensemble|knobs|layout|fast|report
        [--work DIR] [--jobs N] [--only NAME,...]
Runs complete in --work are not repeated. The short setting (bench/smoke.py): every run a few
thousand steps (none complete; the report says so); table_s1 needs the 9,600-grain bed's
preparation and is not part of it.
"""
import argparse
import os
import shutil
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import SMOKE, out_dir    # noqa: E402
from common.beds import CELL_Z, prepare_full    # noqa: E402
from common.ensembles import (CYCLES, KEEP, PERIOD, PERTURB, band, members, np2_members,    # noqa: E402
                              run_one)
from common.ensembles import SETTING_METRICS as METRICS    # noqa: E402
from common.runs import (COPY_US, HOST_FIX_COPIES, LAUNCH_US, TIDAL_SHEAR_TIMED, complete,    # noqa: E402
                         dispatches_per_step, freeze_plugin, head_commit, load, loop_time, prepare,
                         read_cost, timed_run)
from porewater_analysis.cycles import creep_points, cycle_metrics, factor_metrics, power_law    # noqa: E402
from porewater_analysis.timeseries import run_parameters    # noqa: E402

# the default's fluid grid is 3 x 2 x 4 cells of 0.087 x 0.065 x 0.082 m (4.3 x 3.3 x 4.1
# diameters, the original's ~4.4); the other two keep the active layers' top face where it is
# (3 x 0.08176 = 6 x 0.04088 = 2 x 0.12264 m, just under the plate)
GRID_FINE = {"grid_x": 6, "grid_y": 4, "grid_z": 7, "cell_z": CELL_Z / 2}
GRID_COARSE = {"grid_x": 2, "grid_y": 1, "grid_z": 3, "cell_z": CELL_Z * 1.5}

# name: (label, family, in.tidal_shear -var overrides, ranks, lmp arguments, OpenMP threads)
KNOBS = {
    # the default again, on the plugin of the knobs' runs: their cost's reference (its metrics
    # are member0's, bit for bit)
    "default": ("default (eps 0.07, every 10, 3x2x4 cells, skin 0.4 r)", "reference", {}, 1, (), 1),
    "eps0.035": ("eps 0.035", "time step", {"eps": 0.035}, 1, (), 1),
    "eps0.1": ("eps 0.1", "time step", {"eps": 0.1}, 1, (), 1),
    "eps0.14": ("eps 0.14", "time step", {"eps": 0.14}, 1, (), 1),
    "eps0.2": ("eps 0.2", "time step", {"eps": 0.2}, 1, (), 1),
    # the two time steps between the default's and one clearly outside, again with one grain
    # moved by 1e-12 m: is what puts a single run outside the band its own chaos or the step?
    "eps0.1_again": ("eps 0.1, again (perturbed)", "time step", {"eps": 0.1, "perturb": PERTURB},
                     1, (), 1),
    "eps0.14_again": ("eps 0.14, again (perturbed)", "time step",
                      {"eps": 0.14, "perturb": PERTURB}, 1, (), 1),
    "every1": ("fluid every 1", "fluid interval", {"fluid_every": 1}, 1, (), 1),
    "every50": ("fluid every 50", "fluid interval", {"fluid_every": 50}, 1, (), 1),
    "every200": ("fluid every 200", "fluid interval", {"fluid_every": 200}, 1, (), 1),
    "grid_fine": ("fluid cells half the size (6x4x7)", "fluid grid", GRID_FINE, 1, (), 1),
    "grid_coarse": ("fluid cells 1.5-2x (2x1x3)", "fluid grid", GRID_COARSE, 1, (), 1),
    "skin0.2": ("skin 0.2 r", "neighbours", {"skin": 0.2}, 1, (), 1),
    "skin0.8": ("skin 0.8 r", "neighbours", {"skin": 0.8}, 1, (), 1),
    "check10": ("skin 0.8 r, checked every 10", "neighbours", {"skin": 0.8, "neigh_every": 10},
                1, (), 1),
    "ty3": ("nve/sphere/ty3", "integrator", {"integrator": "nve/sphere/ty3"}, 1, (), 1),
}
LAYOUTS = {
    "np2": ("2 MPI ranks", "layout", {}, 2, (), 1),
    "kk2": ("1 rank x 2 threads, /kk", "layout", {}, 1, ("-k", "on", "t", "2", "-sf", "kk"), 2),
    # the creep of the 2-rank runs above the 1-rank ensemble's: another 2-rank run
    "np2_again": ("2 MPI ranks, again (perturbed)", "layout", {"perturb": PERTURB}, 2, (), 1),
}
FAST = {"fast": ("-var fast 1", "preset", {"fast": 1}, 2, (), 1),
        "fast_again": ("-var fast 1, again (perturbed)", "preset", {"fast": 1, "perturb": PERTURB},
                       2, (), 1),
        # the preset's settings on 1 rank: the settings apart from the layout
        "fast_1rank": ("-var fast 1 on 1 rank", "preset", {"fast": 1}, 1, (), 1)}
# the runs of one setting: their mean is judged against the ensemble's mean (replicated())
REPLICATES = {"eps0.1": ("eps0.1", "eps0.1_again"), "eps0.14": ("eps0.14", "eps0.14_again"),
              "fast": ("fast", "fast_again"), "np2": ("np2", "np2_again")}
# runs that change only the order in which forces are summed, i.e. differ from the default by
# round-off in another way than the ensemble's: a check of the band
ROUNDOFF_ONLY = ("skin0.2", "skin0.8", "check10", "np2", "kk2", "np2_again")

TABLE_S1_BUDGET = 600                   # wall s of each Table S1 run
TABLE_S1_TIME, TABLE_S1_KN = 45.0, 1.16e9   # s of model time (9 cycles of 5 s), k_n
GOAL_HOURS = 12.0


def table_s1(work, run=True):
    """the Table S1 case with the default settings and -var fast 1 on 2 ranks: lines"""
    bed = prepare_full(work, bed="original", folder="table_s1_bed") if run else None
    lines = ["| settings | steps in %d s | µs per step | Δt (s) | model s per wall hour | "
             "45 s of Table S1 (h) | load before/after |" % TABLE_S1_BUDGET, "|---|---|---|---|---|---|---|"]
    for name, variables in (("default", {}), ("fast", {"fast": 1})):
        d = os.path.join(work, "table_s1_" + name)
        if run and not read_cost(d):
            prepare(d, [TIDAL_SHEAR_TIMED])
            shutil.copy(os.path.join(bed, "consolidated_1.data"), d)
            left = TABLE_S1_BUDGET
            timed_run(d, "in.tidal_shear_timed", dict(variables, full=1, timeout="%02d:%02d:%02d" % (
                left // 3600, left // 60 % 60, left % 60)), ranks=2)
        if not read_cost(d):
            continue
        seconds, steps = loop_time(os.path.join(d, "log.lammps"), last=False)
        dt = run_parameters(d)["dt"]
        per_hour = 3600.0 * steps * dt / seconds
        cost = read_cost(d)
        lines.append("| %s | %d | %.0f | %.3g | %.4f | %.1f | %.1f/%.1f |" % (
            name, steps, 1e6 * seconds / steps, dt, per_hour, TABLE_S1_TIME / per_hour,
            cost[2] if len(cost) > 2 else float("nan"), cost[3] if len(cost) > 3 else float("nan")))
    # on a GPU: latency-bound at this size; the dispatches per step of each setting's /kk run
    lines += ["", "| settings | kernels per step | deep copies per step | GPU µs per step (%.0f µs "
              "a kernel, %.0f µs a copy, +%d host copies for fix wall/gran) | 45 s of Table S1 "
              "on a GPU (h) |" % (LAUNCH_US, COPY_US, HOST_FIX_COPIES), "|---|---|---|---|---|"]
    for name, variables in (("default", {}), ("fast", {"fast": 1})):
        kernels, copies = dispatches_per_step(work, variables, "dispatches_" + name)
        us = kernels * LAUNCH_US + (copies + HOST_FIX_COPIES) * COPY_US
        d = os.path.join(work, "table_s1_" + name)
        if read_cost(d):
            dt = run_parameters(d)["dt"]
            lines.append("| %s | %.1f | %.1f | %.0f | %.1f |" % (
                name, kernels, copies, us, TABLE_S1_TIME / dt * us * 1e-6 / 3600))
    return lines


def metrics(work, name):
    """{metric: value averaged over KEEP}, or None if the run is not complete"""
    path = os.path.join(work, name, "timeseries.txt")
    if not complete(path, CYCLES * PERIOD):
        return None
    c = load(path)
    per_cycle = factor_metrics(c, CYCLES)
    cycles = cycle_metrics(c, True, PERIOD, CYCLES, stuck_until=0.2)
    out = {}
    for key, _, _, _ in METRICS:
        if key == "n":
            pts = creep_points(c, cycles=CYCLES)
            fit = power_law(pts[np.isin(pts[:, 2], KEEP)])
            if fit:
                out["n"] = fit[0]
            continue
        source = cycles if key == "v_creep" else [per_cycle[k] for k in sorted(per_cycle)]
        vals = [r[key] for r in source if r["cycle"] in KEEP and key in r]
        if len(vals) == len(KEEP):    # a cycle without a slip has no slip metrics
            out[key] = float(np.mean(vals))
    return out


def bands_of(ens, k=1, family=False):
    """{metric: (mean, half-width, min, max, members)} of the runs ens {name: metrics}"""
    out = {}
    for key, _, _, _ in METRICS:
        vals = [m[key] for m in ens.values() if key in m]
        if len(vals) >= 3:
            out[key] = band(vals, k, len(METRICS) if family else 1) + (min(vals), max(vals), len(vals))
    return out


def outside(m, bands):
    """the metrics of run m outside the bands (a metric the run lacks counts as outside)"""
    return [k for k in bands if k not in m or abs(m[k] - bands[k][0]) > bands[k][1]]


def cells(m, bands):
    """table cells of run m: each metric with its error in band half-widths"""
    return " | ".join("%s (%+.1f)" % (f % (scale * m[key]), (m[key] - bands[key][0]) / bands[key][1])
                      if key in m and key in bands else "none" for key, _, scale, f in METRICS)


def cost_of(work, name):
    """(seconds, 'CPU' or 'wall', load before, after): CPU time of a 1-rank run, wall time of
    a run on both cores"""
    c = read_cost(os.path.join(work, name))
    if not c:
        return None
    spec = {**KNOBS, **LAYOUTS, **FAST}.get(name)
    both = spec and (spec[3] > 1 or spec[5] > 1)
    loads = (c[2], c[3]) if len(c) > 3 else (float("nan"), float("nan"))
    return (c[1], "wall") + loads if both else (c[0], "CPU") + loads


def report(work):
    ens = {n: metrics(work, n) for n in members()}
    ens = {n: m for n, m in ens.items() if m}
    if len(ens) < 3:
        if not SMOKE:
            sys.exit("the ensemble needs at least 3 complete runs in %s" % work)
        print("fewer than 3 complete runs in %s (the short setting): no tables" % work)
        return
    bands = bands_of(ens)
    commit = head_commit()
    lines = ["# Time to solution: bench/time_to_solution/time_to_solution.py", "",
             "Tables written at commit %s from the runs in `%s` (examples/tidal_shear, %d cycles "
             "each; metrics averaged over cycles %s, n pooled over their creep windows)." % (
                 commit, work, CYCLES, "-".join(map(str, (KEEP[0], KEEP[-1])))), "",
             "## The ensemble (%d runs: the default and one grain moved by %g m)" % (len(ens), PERTURB),
             "", "| metric | " + " | ".join(ens) + " | mean | band (95 % prediction) | range |",
             "|---|" + "---|" * (len(ens) + 3)]
    for key, label, scale, f in METRICS:
        if key not in bands:
            continue
        m, h, lo, hi, _ = bands[key]
        lines.append("| %s | %s | %s | ± %s | %s to %s |" % (
            label, " | ".join((f % (scale * e[key])) if key in e else "none" for e in ens.values()),
            f % (scale * m), f % (scale * h), f % (scale * lo), f % (scale * hi)))
    costs = [cost_of(work, n) for n in ens]
    costs = [c for c in costs if c]
    if costs:
        lines += ["", "Cost of a member (%d cycles, 1 rank): %.0f-%.0f CPU s (load before/after "
                  "%s)." % (CYCLES, min(c[0] for c in costs), max(c[0] for c in costs),
                            ", ".join("%.1f/%.1f" % c[2:] for c in costs))]
    lines += ["", "## Each knob against the band", "",
              "Error: (value - ensemble mean) / band half-width; |error| <= 1 is inside the band.", "",
              "| knob | cost (s) | " + " | ".join(l for _, l, _, _ in METRICS) +
              " | inside | inside, family-wise |", "|---|---|" + "---|" * (len(METRICS) + 2)]
    family = bands_of(ens, family=True)
    rows = {}
    for name, spec in {**KNOBS, **LAYOUTS, **FAST}.items():
        m = metrics(work, name)
        if not m:
            continue
        cost = cost_of(work, name)
        inside = not outside(m, bands)
        rows[name] = (spec, m, cost, inside)
        lines.append("| %s | %s | %s | %s | %s |" % (
            spec[0], "%.0f %s" % cost[:2] if cost else "", cells(m, bands), "yes" if inside else "no",
            "no" if outside(m, family) else "yes"))
    lines += roundoff_check(work, ens, bands) + replicated(work, ens)
    out = out_dir(HERE)
    plot(ens, bands, rows, work, os.path.join(out, "time_to_solution.png"))
    lines += ["", "![cost against each metric, the band shaded](time_to_solution.png)"]
    open(os.path.join(out, "time_to_solution_results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def roundoff_check(work, ens, bands):
    """how often a run that differs from the default by round-off alone has a metric outside
    the band: each member against the band of the others, and the summation-order runs"""
    lines = ["", "## The criterion on runs that differ by round-off alone", "",
             "| run | metrics outside the band | outside the family-wise band |", "|---|---|---|"]
    fails, family_fails, total = 0, 0, 0
    checks = [("%s (against the other %d members)" % (n, len(ens) - 1), ens[n],
               {o: m for o, m in ens.items() if o != n}) for n in ens]
    checks += [("%s (summation order)" % n, metrics(work, n), ens) for n in ROUNDOFF_ONLY]
    for label, m, against in checks:
        if not m:
            continue
        out, out_family = outside(m, bands_of(against)), outside(m, bands_of(against, family=True))
        lines.append("| %s | %s | %s |" % (label, ", ".join(out) or "none",
                                           ", ".join(out_family) or "none"))
        fails, family_fails, total = fails + bool(out), family_fails + bool(out_family), total + 1
    lines += ["", "Of %d runs that differ from the default by round-off alone, %d have a metric "
              "outside the band (the rate at which the every-metric criterion rejects a setting "
              "that changes nothing) and %d one outside the family-wise band." % (
                  total, fails, family_fails)]
    return lines


def replicated(work, ens):
    """settings run more than once: the mean of their k runs against the ensemble's mean,
    half-width t s sqrt(1/k + 1/N) (a bias of the setting, its own chaos averaged)"""
    lines = ["", "## Settings run more than once: the mean of k runs", "",
             "Error: (mean of the k runs - ensemble mean) / half-width t s sqrt(1/k + 1/N).", "",
             "| setting | k | " + " | ".join(l for _, l, _, _ in METRICS) +
             " | inside | inside, family-wise |", "|---|---|" + "---|" * (len(METRICS) + 2)]
    for setting, names in REPLICATES.items():
        runs = [m for m in (metrics(work, n) for n in names) if m]
        if len(runs) < 2:
            continue
        b = bands_of(ens, len(runs))
        mean = {k: float(np.mean([r[k] for r in runs])) for k in b if all(k in r for r in runs)}
        lines.append("| %s | %d | %s | %s | %s |" % (
            setting, len(runs), cells(mean, b), "yes" if not outside(mean, b) else "no",
            "yes" if not outside(mean, bands_of(ens, len(runs), family=True)) else "no"))
    return lines


def plot(ens, bands, rows, work, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 3, figsize=(13, 10))
    ens_costs = [cost_of(work, n) for n in ens]
    families = sorted({r[0][1] for r in rows.values()})
    colours = {f: "C%d" % k for k, f in enumerate(families)}
    for ax, (key, label, scale, _) in zip(axes.flat, METRICS):
        if key not in bands:
            ax.set_visible(False)
            continue
        m, h = bands[key][:2]
        ax.axhspan(scale * (m - h), scale * (m + h), color="0.88", label="band (95 %)")
        for name, c in zip(ens, ens_costs):
            if c and key in ens[name]:
                ax.plot(c[0], scale * ens[name][key], "o", color="0.4", ms=4)
        for name, (spec, mm, cost, inside) in rows.items():
            if cost and key in mm:
                ax.plot(cost[0], scale * mm[key], "s" if inside else "x", color=colours[spec[1]], ms=6)
                ax.annotate(name, (cost[0], scale * mm[key]), fontsize=6)
        ax.set_xscale("log")
        ax.set_title(label, fontsize=9)
        ax.set_xlabel("cost of %d cycles (s)" % CYCLES, fontsize=8)
    handles = [plt.Line2D([], [], marker="s", ls="", color=colours[f], label=f) for f in families]
    handles += [plt.Line2D([], [], marker="o", ls="", color="0.4", label="ensemble")]
    axes.flat[0].legend(handles=handles, fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=80)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--part", required=True,
                    choices=["ensemble", "ensemble_np2", "knobs", "layout", "fast", "table_s1",
                             "report"])
    ap.add_argument("--work", default="/tmp/pw_time_to_solution")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", default="", help="comma-separated run names of the part")
    args = ap.parse_args()
    if args.part == "report":
        return report(args.work)
    freeze_plugin(args.work, args.part)
    if args.part == "table_s1":
        print("\n".join(table_s1(args.work)))
        return None
    specs = {"ensemble": {n: ("", "", v, 1, (), 1) for n, v in members().items()},
             "ensemble_np2": {n: ("", "", v, 2, (), 1) for n, v in np2_members().items()},
             "knobs": KNOBS, "layout": LAYOUTS, "fast": FAST}[args.part]
    if args.only:
        specs = {n: s for n, s in specs.items() if n in args.only.split(",")}
    # runs on both cores one at a time; 1-rank runs --jobs at a time
    jobs = 1 if args.part in ("layout", "fast", "ensemble_np2") else args.jobs
    pool = ThreadPoolExecutor(jobs)
    todo = [(n, s) for n, s in specs.items()]
    for name, cpu in pool.map(lambda ns: run_one(args.work, ns[0], ns[1][2], ns[1][3], ns[1][4],
                                                 ns[1][5]), todo):
        print("%s: %s" % (name, "done before" if cpu is None else "%.0f s CPU" % cpu), flush=True)


if __name__ == "__main__":
    main()
