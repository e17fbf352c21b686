"""The example at Table S1 size (figures.py --part full): 9,600 grains, -var full 1,
on 2 MPI ranks, for as long as one benchmark command of at most an hour allows.

The bed (common.beds.prepare_full): in.pack and in.consolidate at Table S1 size, both with
the reduced case's k_n (1.16e7: 10x the time step; preparation only, damped frictionless
contacts), then in.consolidate again at Table S1's k_n from that bed (the contacts stiffen:
the bed rises by their overlap, ~1e-4 of a grain). Then in.tidal_shear -var full 1 from phase 0
until the wall-clock budget of the run is spent (LAMMPS' timer timeout); the preparation's
time is reported apart.
"""
import os

import numpy as np

from common.beds import prepare_full
from common.runs import (COPY_US, FRICTIONLESS, HOST_FIX_COPIES, LAUNCH_US, dispatches_per_step,
                         load, loop_time, prepare, run_lmp, time_step, timed_run)

PERIOD = 5.0                        # s: Table S1's forcing period
PROJECTED_US_PER_STEP = 430.0       # bench/tidal_profile: the Table S1-sized scene on 2 ranks
DT = time_step(1.16e9)              # Table S1's k_n


def run_full(work, budget_s):
    """the preparation (once), then the run for budget_s wall seconds; returns its folder"""
    d = prepare_full(work)
    if os.path.exists(os.path.join(d, "cost.txt")):
        return d
    left = int(budget_s - 60)    # the run's setup and output
    timeout = "%02d:%02d:%02d" % (left // 3600, left // 60 % 60, left % 60)
    timed_run(d, "in.tidal_shear_timed", {**FRICTIONLESS, "full": 1, "timeout": timeout,
                                          "write_state": "state_end"}, ranks=2)
    reference_runs(work)
    return d


REFERENCE_STEPS = 20000
REDUCED_PROJECTION_US = 145.0       # examples/tidal_shear/README.md: the shipped case, 1 rank, quiet


def reference_runs(work):
    """the reduced example right after, on the same machine: (µs per step on 1 and 2 ranks)"""
    d = os.path.join(work, "full_reference")
    prepare(d)
    out = []
    for ranks in (1, 2):
        log = "log.%drank" % ranks
        if not os.path.exists(os.path.join(d, log)):
            run_lmp(d, "in.tidal_shear", dict(FRICTIONLESS, run_steps=REFERENCE_STEPS), ranks=ranks, log=log)
        seconds, steps = loop_time(os.path.join(d, log), last=False)
        out.append(1e6 * seconds / steps)
    return out


def preparation_time(d):
    """wall seconds of the preparation's runs (their logs' loop times)"""
    return sum(loop_time(os.path.join(d, log), last=False)[0]
               for log in ["log.pack", "log.consolidate_soft", "log.consolidate"])


def end_of_preparation(d):
    """the last thermo line of the final consolidation: (plate velocity, N on the grains)"""
    rows = [line.split() for line in open(os.path.join(d, "log.consolidate"))]
    rows = [r for r in rows if len(r) == 7 and r[0].isdigit()]
    return float(rows[-1][3]), float(rows[-1][4])


def compare(d, reduced, reduced_period):
    """the Table S1-sized run against the reduced default's first cycle at the same phases"""
    full = load(os.path.join(d, "timeseries.txt"))
    seconds, steps = loop_time(os.path.join(d, "log.lammps"), last=False)
    us = 1e6 * seconds / steps
    reached = full["time"][-1] / PERIOD
    plate_v, plate_n = end_of_preparation(d)
    lines = ["Run: %d steps (%.3f s of model time, phase %.3f of the first cycle) in %.0f s on 2 "
             "ranks: **%.0f µs per step** against the %.0f µs projected (bench/tidal_profile, the "
             "9,600-grain scene on 2 ranks), %.2fx. The bed's preparation took %.0f s more "
             "(in.pack, in.consolidate twice: their loop times)."
             % (steps, full["time"][-1], reached, seconds, us, PROJECTED_US_PER_STEP,
                us / PROJECTED_US_PER_STEP, preparation_time(d)),
             "At the end of the preparation the plate moved at %.2g m/s with %.1f kPa on the "
             "grains (sigma0 80 kPa)." % (plate_v, plate_n / 1e3), ""]
    one, two = reference_runs(os.path.dirname(d))
    lines += ["The reduced example run right after on the same machine (%d steps of the shipped "
              "bed): %.0f µs per step on 1 rank (%.0f measured on a quiet machine before: %.2fx "
              "that now), %.0f on 2 ranks. Table S1 size "
              "per step against the reduced case on 2 ranks: %.1fx (%.1fx the grains)."
              % (REFERENCE_STEPS, one, REDUCED_PROJECTION_US, one / REDUCED_PROJECTION_US, two,
                 us / two, 9600 / 1200), ""]
    nine = 9 * PERIOD / DT
    kernels, copies = dispatches_per_step(os.path.dirname(d))
    floor = kernels * LAUNCH_US + (copies + HOST_FIX_COPIES) * COPY_US
    lines += ["A full 9-cycle run (45 s, %.2e steps of %.3g s) at this cost: %.1f days on these "
              "2 cores." % (nine, DT, nine * us * 1e-6 / 86400), "",
              "On a GPU (projected, not measured: no device was lent): the /kk run dispatches "
              "%.1f kernels and %.1f deep copies per step (counted on the host backend with "
              "bench/common/kokkos_dispatches.cpp, the same per step at any size), and fix wall/gran "
              "(no /kk in 29Sep2021) moves ~%d arrays between host and device each step. At "
              "%.0f µs per dispatch with its fence and %.0f µs per copy (assumed, typical of "
              "CUDA; 9,600 grains are too few to fill the device, so latency bounds the step): "
              "%.0f µs per step, %.1f hours for the 9 cycles (the original: ~70 days)."
              % (kernels, copies, HOST_FIX_COPIES, LAUNCH_US, COPY_US, floor,
                 nine * floor * 1e-6 / 3600), ""]
    lines += ["| phase window | quantity | Table S1 size | reduced (cycle 1) |", "|---|---|---|---|"]
    width = max(0.01, round(reached / 4, 2))    # phase: four windows over the run
    windows = [(a, min(a + width, reached)) for a in np.arange(0.0, reached - width / 2, width)]
    for a, b in windows:
        for name, (f_full, f_red) in {
                "creep velocity (m/s)": (velocity, velocity),
                "top layer displacement at the end (µm)": (displacement, displacement),
                "coordination (mean)": (mean_of("coordination"), mean_of("coordination")),
                "p_mean - p_top, min / A": (dp_of(np.min), dp_of(np.min)),
                "p_mean - p_top, max / A": (dp_of(np.max), dp_of(np.max)),
                "N on the grains / applied (mean)": (n_ratio, n_ratio)}.items():
            lines.append("| %.2f-%.2f | %s | %.3g | %.3g |" % (
                a, b, name, f_full(full, a * PERIOD, b * PERIOD),
                f_red(reduced, a * reduced_period, b * reduced_period)))
    return lines, full


def _window(c, t0, t1):
    return (c["time"] >= t0) & (c["time"] <= t1) & (c["time"] > 0)


def velocity(c, t0, t1):
    w = _window(c, t0, t1)
    return np.polyfit(c["time"][w], c["x_top"][w], 1)[0]


def displacement(c, t0, t1):
    return 1e6 * c["x_top"][_window(c, t0, t1)][-1]


def mean_of(key):
    return lambda c, t0, t1: np.mean(c[key][_window(c, t0, t1)])


def dp_of(f):
    return lambda c, t0, t1: f((c["p_mean"] - c["p_top"])[_window(c, t0, t1)]) / 70.0e3


def n_ratio(c, t0, t1):
    w = _window(c, t0, t1)
    return np.mean(c["N_grains"][w] / c["N_applied"][w])
