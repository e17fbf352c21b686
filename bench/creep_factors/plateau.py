#!/usr/bin/python3
"""What sets the count a slip leaves: Table S1's height (2,400 grains on the reduced
footprint) at Table S1's grain stiffness, prepared as Table S1's bed, run through the first
slip and the creep after it, one factor changed at a time beside unchanged runs perturbed by
round-off (RESULTS.md beside this script, "The plateau after the first slip").

The bed, fixed before any run: prepared as the Table S1 bed (common.beds.prepare_stiff_bed:
packed and consolidated at the reduced case's k_n, consolidated again at Table S1's) with its
friction while packing (MU_PREP_S1), on 2,400 grains; the groups of the reduced case
kept for its H and phi with 6 fluid layers (creep_factors.tall_groups); the stiff preset's
k_n, gamma_w and eps 0.14. Each run RUN_CYCLES cycles on 1 rank, two side by side. The cases:

  control        member K (K = 0 unperturbed, else every sheared grain moved by up to
                 1e-12 m, seed K): the spread a run takes from round-off alone
  plate280       the plate's mass x 280/1100: Table S1 lists 280 kg (sigma0 Lx Ly/g at
                 20 kPa); the original's script (halfshear-darcy-stress-mod-starter.py line
                 69) and Table S1 as run take sigma0 80 kPa (1.1 t): how much the plateau
                 depends on the slip's size, not a difference from the original run
  original       the original program's numerics (-var original 1: its Taylor integrator and
                 its relaxed Jacobi pressure iteration)
  layers         the held base and the shear plate marked as the original marks them
                 (groups.py original_layer_cuts: a diameter from the extreme grains'
                 surfaces, about a radius under the highest centre; the example's: a diameter
                 under the highest centre): the plate's grains, and the grains the original's
                 count leaves out, 83 instead of 139 on this bed
  fluid1         the fluid stepped with every grain step, as the original's run: its
                 initFluid(cfd_solver = 1) sets ndem 1 (sphere.py line 3494), which
                 halfshear-darcy-stress-mod-starter.py keeps (its setDEMstepsPerCFDstep(10),
                 line 60, is commented out); Table S1 as run and the example: every 10th,
                 the force held between

Metrics by the original's count (coordination/original), from each time series: the first row
(t 0.01 s) and the mean over phases 0.2-0.6 of cycle 1 (before the first slip) and of cycle 2
(the creep after it), beside the original run's data file at the same phases of its cycles.

Usage (source scripts/env.sh first):
    /usr/bin/python3 bench/creep_factors/plateau.py --run control0,plate280   # both cores
    /usr/bin/python3 bench/creep_factors/plateau.py                            # the page
A run stopped midway is continued from its checkpoint when named again.
"""
import argparse
import glob
import json
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
from common import out_dir, short    # noqa: E402
from common.beds import SPREAD, STIFF, bed_geometry, prepare_stiff_bed    # noqa: E402
from common.ensembles import PERIOD, PERTURB, band    # noqa: E402
from common.runs import (complete, freeze_plugin, head_commit, load, read_cost,    # noqa: E402
                         run_example, time_step)
from creep_factors import TALL_GRAINS, tall_groups    # noqa: E402
from groups import original_layer_cuts    # noqa: E402
from porewater_analysis.cycles import phase_mask    # noqa: E402
from porewater_analysis.dump import read_dump    # noqa: E402
from porewater_analysis.landings import read_data_file    # noqa: E402

WORK = "/work/runs/plateau"
MU_PREP_S1 = 0.0148            # bench/fidelity/table_s1/README.md: Table S1's bed
RUN_CYCLES = short(1.65, 0.002)     # through cycle 2's phase 0.6
PHASES = (0.2, 0.6)
DUMP_CYCLES = 0.1
EPS = 0.14                          # the stiff preset's
PLATE_S1, PLATE_AS_RUN = 280.0, 1100.0
OUT = out_dir(HERE)
STORE = os.path.join(OUT, "plateau_runs.json")
DATA_FILE = os.path.join(os.path.dirname(HERE), "common", "original_run_contacts.txt")


def plateau_bed(work):
    """the 2,400-grain bed prepared as Table S1's: its data file"""
    return prepare_stiff_bed(os.path.join(work, "bed"), {
        "ngrains": TALL_GRAINS, "radius_spread": SPREAD, "mu_prep": MU_PREP_S1})


def run_dt():
    return time_step(STIFF["kn100"]["kn"], EPS)


def base_variables(bed):
    """the runs' -var values: the groups for the bed's H and phi, the stiff preset's k_n,
    gamma_w, eps, grain dumps every DUMP_CYCLES (the count by height)"""
    height, phi = bed_geometry(bed)
    return dict(tall_groups(height, phi), **STIFF["kn100"], eps=EPS, data="bed.data",
                cycles=RUN_CYCLES, dump_every=int(round(DUMP_CYCLES * PERIOD / run_dt())))


def case_variables(work, case, base):
    """-var overrides of a case (control0, control1, ..., plate280, ...; factors joined by
    "+" together)"""
    if case.startswith("control"):
        k = int(case[len("control"):])
        return dict(base, **({} if k == 0 else {"perturb": PERTURB, "perturb_seed": k}))
    variables = dict(base)
    for factor in case.split("+"):
        if factor == "plate280":
            variables["mass_factor"] = base["mass_factor"] * PLATE_S1 / PLATE_AS_RUN
        elif factor == "original":
            variables["original"] = 1
        elif factor == "layers":
            bottom, top = original_layer_cuts(os.path.join(work, "bed", "bed.data"))
            variables.update(bottom_cut=repr(bottom), top_cut=repr(top))
        elif factor == "fluid1":
            variables["fluid_every"] = 1
        else:
            raise SystemExit("unknown case %s: control<K>, or factors joined by +: plate280, "
                             "original, layers, fluid1" % case)
    return variables


def run_case(work, bed, case):
    variables = case_variables(work, case, base_variables(bed))
    cpu = run_example(os.path.join(work, case), variables, RUN_CYCLES * PERIOD, data=bed)
    return case, "done before" if cpu is None else "%.0f s CPU" % cpu


def phase_mean(time, count, cycle, period=PERIOD, phases=PHASES):
    """mean of count over phases of cycle (1-based) of a series of that period"""
    rows = phase_mask(time, period, cycle, *phases)
    return float(np.mean(count[rows])) if rows.any() else None


def first_row(time, count, period):
    """the count at the data file's first row, phase 0.002 (t 0.01 s of its 5 s)"""
    return float(count[int(np.argmin(abs(time / period - 0.01 / 5.0)))])


def metrics(work, case):
    path = os.path.join(work, case, "timeseries.txt")
    if not complete(path, RUN_CYCLES * PERIOD):
        return None
    m = series_metrics(load(path), PERIOD)
    return m if None not in m.values() else None    # the short setting: no cycle 2


def data_file():
    """the original run's count at the same phases (T 5 s)"""
    t, z = read_data_file(DATA_FILE)
    return {"first": first_row(t, z, 5.0), "cycle1": phase_mean(t, z, 1, 5.0),
            "cycle2": phase_mean(t, z, 2, 5.0), "cycle3": phase_mean(t, z, 3, 5.0)}


LABELS = {"plate280": "the plate 280 kg (Table S1's listed mass), not 1.1 t",
          "layers": "the held base and the shear plate as the original marks them",
          "original": "the original's numerics (integrator, pressure iteration)",
          "fluid1": "the fluid stepped with every grain step (the original's ndem 1)"}
TABLE_S1 = os.path.join(os.path.dirname(HERE), "fidelity", "table_s1", "timeseries.txt.xz")


def series_metrics(c, period):
    z = c["coordination_original"]
    return {"first": first_row(c["time"], z, period), "cycle1": phase_mean(c["time"], z, 1, period),
            "cycle2": phase_mean(c["time"], z, 2, period)}


PROFILE_BIN = 2                     # grain diameters a height bin


def profile(work, case):
    """{cycle: [(height of the bin's bottom in diameters, the mean count of the bed's moving
    grains there)]} over the run's grain dumps at phases PHASES of cycles 1 and 2 (the fixed
    layers: the grains within a diameter of the floor or the top at the first dump), or None
    without dumps"""
    dumps = sorted(glob.glob(os.path.join(work, case, "grains_*.dump")),
                   key=lambda p: int(p.rsplit("_", 1)[1].split(".")[0]))
    if not dumps:
        return None
    _, first = read_dump(dumps[0])
    d = 2 * np.median(first["radius"])
    moving = (first["z"] > first["z"].min() + d) & (first["z"] < first["z"].max() - d)
    out = {}
    steps_per_cycle = PERIOD / run_dt()
    for path in dumps:
        phase = int(path.rsplit("_", 1)[1].split(".")[0]) / steps_per_cycle
        cycle = int(phase) + 1
        if cycle not in (1, 2) or not PHASES[0] <= phase - (cycle - 1) < PHASES[1]:
            continue
        _, g = read_dump(path)
        out.setdefault(cycle, []).append((g["z"][moving] / d, g["c_coordination_original"][moving]))
    result = {}
    for cycle, snaps in out.items():
        z = np.concatenate([s[0] for s in snaps])
        count = np.concatenate([s[1] for s in snaps])
        bins = (z // PROFILE_BIN).astype(int)
        result[cycle] = [(b * PROFILE_BIN, float(count[bins == b].mean()))
                         for b in range(bins.min(), bins.max() + 1) if (bins == b).any()]
    return result


def profile_lines(work, case):
    """a table of the count by height before and after the first slip, or []"""
    p = profile(work, case)
    if not p or 1 not in p or 2 not in p:
        return []
    lines = ["", "The count by height in %s (its grain dumps every %.1f cycle at phases %.1f-%.1f; "
             "the moving grains, bins of %d diameters from the floor):" % (
                 case, DUMP_CYCLES, PHASES[0], PHASES[1], PROFILE_BIN), "",
             "| height (d) | cycle 1 | cycle 2 | change |", "|---|---|---|---|"]
    after = dict(p[2])
    for z, before in p[1]:
        if z in after:
            lines.append("| %d-%d | %.2f | %.2f | %+.2f |" % (z, z + PROFILE_BIN, before, after[z],
                                                             after[z] - before))
    return lines


def report(store, work=WORK):
    """the page's lines: every case's counts, each factor against the controls' spread"""
    controls = [m["cycle2"] for case, m in sorted(store.items()) if case.startswith("control")]
    lines = ["# The plateau after the first slip: bench/creep_factors/plateau.py", "",
             "Table S1's height (2,400 grains, 0.26 x 0.13 m) at Table S1's k_n, prepared as "
             "Table S1's bed (mu_prep %.4f), %.2f cycles a run on 1 rank, two side by side on the "
             "development machine (2 cores; the load in the last column); "
             "the original's count (coordination/original) at the data file's first row "
             "(phase 0.002) and over phases %.1f-%.1f of cycles 1 and 2. Written at commit %s "
             "from `plateau_runs.json` (each run's commit, CPU s and load in it)."
             % (MU_PREP_S1, RUN_CYCLES, PHASES[0], PHASES[1], head_commit()), "",
             "| run | first row | cycle 1 (before the first slip) | cycle 2 (creep after it) "
             "| cycle 2 / cycle 1 | cycle 2 minus the controls' mean | CPU s (load before, "
             "after) |", "|---|---|---|---|---|---|---|"]
    ref = data_file()
    lines.append("| the original run's data file (T 5 s) | %.2f | %.2f | %.2f | %.3f | | |"
                 % (ref["first"], ref["cycle1"], ref["cycle2"], ref["cycle2"] / ref["cycle1"]))
    s1 = series_metrics(load(TABLE_S1), 5.0)
    lines.append("| Table S1 as run (bench/fidelity/table_s1, 9,600 grains) | %.2f | %.2f | %.2f "
                 "| %.3f | | |" % (s1["first"], s1["cycle1"], s1["cycle2"],
                                   s1["cycle2"] / s1["cycle1"]))
    mean = np.mean(controls) if controls else float("nan")
    for case, m in sorted(store.items(), key=lambda kv: (not kv[0].startswith("control"), kv[0])):
        label = ("control, member %s" % case[len("control"):]) if case.startswith("control") \
            else "; ".join(LABELS[f] for f in case.split("+"))
        cost = m.get("cost")
        lines.append("| %s | %.2f | %.2f | %.2f | %.3f | %+.2f | %s |" % (
            label, m["first"], m["cycle1"], m["cycle2"], m["cycle2"] / m["cycle1"],
            m["cycle2"] - mean,
            "%.0f (%.2f, %.2f)" % (cost[0], cost[2], cost[3]) if cost and len(cost) > 3 else ""))
    if len(controls) > 2:
        centre, half = band(controls)
        lines += ["", "The controls' cycle-2 plateaus span %.2f (%d runs differing by "
                  "round-off): a run that differs from them by round-off alone lies within "
                  "%.2f ± %.2f (95 %% prediction band); outside it: %s." % (
                      max(controls) - min(controls), len(controls), centre, half,
                      ", ".join(c for c, m in sorted(store.items()) if not c.startswith("control")
                                and abs(m["cycle2"] - centre) > half) or "none")]
    for case in sorted(store):
        lines += profile_lines(work, case)
    return lines


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--work", default=WORK)
    ap.add_argument("--run", default="", help="cases, comma separated, two at a time")
    args = ap.parse_args()
    if args.run:
        bed = plateau_bed(args.work)
        freeze_plugin(args.work, "plateau")
        pool = ThreadPoolExecutor(2)
        for case, what in pool.map(lambda c: run_case(args.work, bed, c), args.run.split(",")):
            print("%s: %s" % (case, what), flush=True)
    store = json.load(open(STORE)) if os.path.exists(STORE) else {}
    for case in sorted(os.listdir(args.work)) if os.path.isdir(args.work) else []:
        m = metrics(args.work, case)
        if m:    # the commit a run ran from: the one stored when it was first read
            store[case] = dict(m, commit=store.get(case, {}).get("commit", head_commit()),
                               cost=read_cost(os.path.join(args.work, case)))
    json.dump(store, open(STORE, "w"), indent=1, sort_keys=True)
    lines = report(store, args.work)
    open(os.path.join(OUT, "plateau_results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))
