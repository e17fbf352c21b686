#!/usr/bin/python3
"""The paper's own scene and Table S1's grain stiffness on the reduced case: the runs, in
checkpointed chunks, each continued from its last checkpoint when the command is given again.

In this order (both cores busy throughout), parameters fixed before any of the runs:
  stiff       the stiff preset (examples/tidal_shear -var bed stiff: k_n 1.16e9, eps 0.14),
              STIFF_MEMBERS members x CYCLES cycles, 1 rank each, two side by side
  stiff_eps0.07  members 0 and 1 of it at eps 0.07: the whole cycles against its band
  table_s1    Table S1 itself (-var full 1: 9,600 grains), TABLE_S1_CYCLES cycles on 2 ranks,
              from a bed packed and consolidated as the original's (log-normal radii 0.009)
              with friction mu_prep while packing at the reduced case's k_n, consolidated
              again at Table S1's (mu_prep: MU_TALL, or the bisection's below it where that
              bed starts more than TARGET_TOL from the original run's count); eps 0.14
              where the stiff preset's rule (eps_rule) says so, else 0.07; grain dumps every DUMP_CYCLES (the original's count checked on them)
  original    the stiff preset with the original program's numerics (-var original 1: its
              integrator and its pressure iteration), members 0 and 1 (ORIGINAL_MEMBERS): the
              paper's numbers against the stiff ensemble's band (inside_band), the first of the
              differences from the original run that remain at Table S1's stiffness
  default     the default's ensemble again, DEFAULT_MEMBERS members (the original's count,
              coordination/original, is now rebuilt at each run's setup: compute
              coordination/original, doc)
  cost        (only when named in --only: each run alone on the machine) the stiff preset
              on 1 rank and on 2 ranks for COST_CYCLES of a cycle from its start: the wall
              time per step of each layout, side by side in one call

Usage (source scripts/env.sh first):
    /usr/bin/python3 bench/fidelity/paper_scene.py [--work DIR] [--only stiff,table_s1,...]
    /usr/bin/python3 bench/fidelity/paper_scene.py --only cost     # ~2 min, nothing else running
    /usr/bin/python3 bench/fidelity/paper_scene.py --archive       # Table S1's time series into
        bench/fidelity/table_s1/ (read: python3 -m porewater_analysis bench/fidelity/table_s1)
The short setting (bench/smoke.py): CYCLES and the members shortened; table_s1 needs the
9,600-grain bed's preparation and is not part of it.
"""
import argparse
import lzma
import os
import shutil
import sys
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from common import out_dir, short    # noqa: E402
from common.ensembles import AGAINST_PAPER, PERIOD, PERTURB, band, run_metrics, summary    # noqa: E402
from common.beds import bed_geometry, bisect_mu_prep, prepare_stiff_bed    # noqa: E402
from common.runs import (complete, freeze_plugin, load, prepare, run_example, run_lmp,    # noqa: E402
                         time_step)
from porewater_analysis.timeseries import nearest_rows    # noqa: E402

WORK = "/work/runs/paper_scene"
CYCLES = short(4, 0.002)
STIFF_MEMBERS, STIFF_EPS_CHECK, DEFAULT_MEMBERS = short((6, 2, 8), (2, 1, 2))
ORIGINAL_MEMBERS = short(2, 1)
TABLE_S1_CYCLES, TABLE_S1_PERIOD = 3, 5.0
MU_TALL = 0.0444                 # bench/creep_factors/creep_factors_bisect.md: 4.61 by the original's
                                 # count at the reduced case's k_n; the first probe of table_s1_friction
DUMP_CYCLES = 0.25
COST_CYCLES = short(0.05, 0.002)
COST_RANKS = (1, 2)


def member_variables(k):
    return {} if k == 0 else {"perturb": PERTURB, "perturb_seed": k}


def ensemble_runs(work):
    """[(folder, -var overrides)] of the 1-rank runs: the stiff eps check first (twice the
    steps), then the stiff ensemble"""
    runs = [("stiff_eps0.07/member%d" % k, dict(member_variables(k), bed="stiff", eps=0.07))
            for k in range(STIFF_EPS_CHECK)]
    runs += [("stiff/member%d" % k, dict(member_variables(k), bed="stiff"))
             for k in range(STIFF_MEMBERS)]
    return runs


def original_runs(work):
    """the stiff preset's members 0.. with the original program's numerics"""
    return [("stiff_original/member%d" % k, dict(member_variables(k), bed="stiff", original=1))
            for k in range(ORIGINAL_MEMBERS)]


def default_runs(work):
    return [("default/member%d" % k, member_variables(k)) for k in range(DEFAULT_MEMBERS)]


def run_pool(work, runs, jobs=2):
    pool = ThreadPoolExecutor(jobs)
    done = pool.map(lambda run: (run[0], run_example(os.path.join(work, run[0]),
                                                     dict(run[1], cycles=CYCLES),
                                                     CYCLES * PERIOD)), runs)
    for name, cpu in done:
        print("%s: %s" % (name, "done before" if cpu is None else "%.0f s CPU" % cpu), flush=True)


PAPER_KEYS = [k for _, _, ours, original in AGAINST_PAPER for k in (ours, original) if k]


def inside_band(coarse, fine):
    """[(metric, the ensemble's mean, the half-width of its 95 % prediction band of the mean of
    len(fine) more members, the other runs' values, inside)] for every
    metric of the paper's numbers (AGAINST_PAPER, both estimators) that both have;
    family-wise: Bonferroni over the metrics compared"""
    keys = [k for k in PAPER_KEYS if len(summary(coarse, k)) >= 3 and len(summary(fine, k))]
    rows = []
    for key in keys:
        b = summary(fine, key)
        mean, half = band(summary(coarse, key), k=len(b), metrics=len(keys))
        rows.append((key, mean, half, b, abs(b.mean() - mean) <= half))
    return rows


def stiff_ensembles(work):
    """({member: metrics} at eps 0.14, at eps 0.07), or None before all runs are complete"""
    coarse = {k: run_metrics(work, "stiff/member%d" % k) for k in range(STIFF_MEMBERS)}
    fine = {k: run_metrics(work, "stiff_eps0.07/member%d" % k) for k in range(STIFF_EPS_CHECK)}
    if not all(coarse.values()) or not all(fine.values()):
        return None
    return coarse, fine


def eps_rule(work):
    """(eps of the Table S1 run, why): 0.14 if the mean of the eps 0.07 members lies inside the
    stiff ensemble's band (inside_band) for every metric of the paper's numbers, else 0.07;
    before all runs are complete: 0.07"""
    both = stiff_ensembles(work)
    if both is None:
        return 0.07, "the stiff preset's runs are not all complete"
    rows = inside_band(*both)
    outside = ["%s %.3g against %.3g ± %.3g" % (k, b.mean(), a, h) for k, a, h, b, ok in rows
               if not ok]
    if outside:
        return 0.07, "eps 0.07 outside the band of eps 0.14: " + "; ".join(outside)
    return 0.14, "eps 0.07 inside the band of eps 0.14 for %s" % ", ".join(k for k, *_ in rows)


def bed_folder(mu, name):
    """work's folder of the Table S1 bed packed with mu (MU_TALL: the first, unsuffixed)"""
    return name if mu == MU_TALL else "%s_mu%.4f" % (name, mu)


def table_s1_bed(work, mu=MU_TALL, ranks=2):
    """the Table S1 bed packed with friction mu (common.beds.prepare_stiff_bed): its file"""
    return prepare_stiff_bed(os.path.join(work, bed_folder(mu, "table_s1_bed")),
                             {"full": 1, "mu_prep": mu}, ranks)


TARGET_Z, TARGET_TOL = 4.58, 0.15   # the original run's count at t = 0.01 s; bisect beyond
BISECT_ROUNDS = 2                   # of two probes each, 1 rank per probe, side by side


def table_s1_row_steps(eps):
    """in.tidal_shear's nout at Table S1's k_n: the steps between time-series rows"""
    dt = time_step(1.16e9, eps)
    return 10 * round(TABLE_S1_PERIOD / (1000 * dt * 10))


def table_s1_start(work, bed, eps, mu=MU_TALL, ranks=2):
    """the original's count on the Table S1 bed at t = 0.01 s (the original run's first row),
    from a run of two rows (its time series; Table S1's first rows are the same)"""
    d = os.path.join(work, bed_folder(mu, "table_s1_start"))
    path = os.path.join(d, "timeseries.txt")
    if not complete(path, 0.01):
        prepare(d)
        shutil.copy(bed, os.path.join(d, "bed.data"))
        run_lmp(d, "in.tidal_shear", {"full": 1, "data": "bed.data", "eps": eps,
                                      "run_steps": 2 * table_s1_row_steps(eps)}, ranks=ranks)
    c = load(path)
    return float(c["coordination_original"][nearest_rows(c["time"], 0.01)])


def table_s1_probe(work, eps, mu, ranks=2):
    """(mu, the original's count at t = 0.01 s, H, phi) of the Table S1 bed packed with mu"""
    bed = table_s1_bed(work, mu, ranks)
    height, phi = bed_geometry(bed)
    return mu, table_s1_start(work, bed, eps, mu, ranks), height, phi


def table_s1_friction(work, eps):
    """mu_prep of the Table S1 bed: MU_TALL (the tall bed's, found at the reduced case's k_n)
    if its bed starts within TARGET_TOL of the original run's count at Table S1's k_n, else
    the probe nearest it of a bisection below MU_TALL (common.beds.bisect_mu_prep: the
    count rises as the friction falls). Every probe is written to table_s1_probes.txt; None
    if none is within TARGET_TOL."""
    first = table_s1_probe(work, eps, MU_TALL)
    probes = [first]
    if abs(first[1] - TARGET_Z) > TARGET_TOL:
        pool = ThreadPoolExecutor(2)
        probes += bisect_mu_prep(work, lambda f, xs: list(pool.map(f, xs)), low=0.0,
                                 high=MU_TALL, rounds=BISECT_ROUNDS, tol=TARGET_TOL,
                                 target=TARGET_Z,
                                 probe=lambda mu: table_s1_probe(work, eps, mu, ranks=1))
    with open(os.path.join(work, "table_s1_probes.txt"), "w") as f:
        f.write("# mu_prep  the original's count at t = 0.01 s (the original run %.2f)  H (m)  "
                "phi\n" % TARGET_Z)
        for row in sorted(probes):
            f.write("%.4f %.4f %.4f %.4f\n" % row)
    best = min(probes, key=lambda p: abs(p[1] - TARGET_Z))
    for mu, z, _, _ in sorted(probes):
        print("table_s1: mu_prep %.4f: the original's count at t = 0.01 s %.3f (the original "
              "run %.2f)" % (mu, z, TARGET_Z), flush=True)
    return best[0] if abs(best[1] - TARGET_Z) <= TARGET_TOL else None


def table_s1(work, eps):
    mu = table_s1_friction(work, eps)
    if mu is None:
        print("table_s1: not run: no bed within %.2f of the original's count" % TARGET_TOL,
              flush=True)
        return
    print("table_s1: the bed packed with mu_prep %.4f" % mu, flush=True)
    bed = table_s1_bed(work, mu)
    d = os.path.join(work, "table_s1")
    nout = table_s1_row_steps(eps)
    variables = {"full": 1, "data": "bed.data", "eps": eps, "cycles": TABLE_S1_CYCLES,
                 "dump_every": int(nout * round(DUMP_CYCLES * 1000))}
    cpu = run_example(d, variables, TABLE_S1_CYCLES * TABLE_S1_PERIOD, ranks=2, data=bed)
    print("table_s1: %s" % ("done before" if cpu is None else "%.0f s CPU" % cpu), flush=True)


ARCHIVE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "table_s1")


def archive_table_s1(work, out=ARCHIVE):
    """Table S1's time series (xz) and run parameters into out, where
    `python3 -m porewater_analysis OUT` reads them (porewater_analysis.timeseries reads .xz)"""
    d = os.path.join(work, "table_s1")
    if not complete(os.path.join(d, "timeseries.txt"), TABLE_S1_CYCLES * TABLE_S1_PERIOD):
        sys.exit("archive: Table S1's run in %s is not complete" % d)
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(d, "timeseries.txt"), "rb") as src, \
            lzma.open(os.path.join(out, "timeseries.txt.xz"), "wb", preset=9) as dst:
        shutil.copyfileobj(src, dst)
    shutil.copy(os.path.join(d, "checkpoint_params.txt"), out)
    print("archive: %s" % ", ".join(sorted(os.listdir(out))), flush=True)


def stiff_cost(work):
    """the stiff preset from its start for COST_CYCLES of a cycle on each of COST_RANKS, one
    after the other (the machine otherwise idle: the load is in each run's cost.txt)"""
    for ranks in COST_RANKS:
        d = os.path.join(work, "stiff_cost", "np%d" % ranks)
        cpu = run_example(d, {"bed": "stiff", "cycles": COST_CYCLES}, COST_CYCLES * PERIOD,
                          ranks=ranks)
        print("stiff_cost/np%d: %s" % (ranks, "done before" if cpu is None else
                                       "%.0f s CPU" % cpu), flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", default=WORK)
    ap.add_argument("--only", default="stiff,table_s1,default")
    ap.add_argument("--report", action="store_true",
                    help="no runs: the tables from the runs in --work (paper_scene_results.md)")
    ap.add_argument("--archive", action="store_true",
                    help="no runs: Table S1's time series (xz) and parameters into %s" %
                    os.path.relpath(ARCHIVE, os.path.dirname(os.path.dirname(ARCHIVE))))
    args = ap.parse_args()
    if args.archive:
        return archive_table_s1(args.work)
    if args.report:
        from paper_scene_report import report
        report(args.work, out_dir(os.path.dirname(os.path.abspath(__file__))))
        return
    parts = args.only.split(",")
    freeze_plugin(args.work, "paper_scene")
    if "stiff" in parts:
        run_pool(args.work, ensemble_runs(args.work))
    if "table_s1" in parts:
        eps, why = eps_rule(args.work)
        print("table_s1: eps %g (%s)" % (eps, why), flush=True)
        table_s1(args.work, eps)
    if "original" in parts:
        run_pool(args.work, original_runs(args.work))
    if "default" in parts:
        run_pool(args.work, default_runs(args.work))
    if "cost" in parts:
        stiff_cost(args.work)


if __name__ == "__main__":
    sys.exit(main())
