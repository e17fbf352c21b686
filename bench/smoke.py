#!/usr/bin/python3
"""Every study's regenerate command still runs: each study's entry point on its short setting
(PW_BENCH_SMOKE: every run a few hundred to a few thousand steps, bench/common/__init__.py) in
a temporary folder, its pages and figures written there too, never over the committed ones.
What it checks: the entry point starts, prepares its runs, runs lmp with the inputs and -var
settings it names and writes its pages from what it finds; not the numbers (runs that short
are not complete, the tables come out empty). Exits 1 if any entry point fails.

Not in it, and why (each says the same in its own docstring):
- the parts that prepare the 9,600-grain Table S1 bed (paper_figures --part full,
  time_to_solution --part table_s1, paper_scene's table_s1): in.pack and in.consolidate at
  that size take the better part of an hour before the first step of the run;
- host_compare needs both LAMMPS hosts (PW_LAMMPS=both scripts/setup.sh): run when the other
  host's lmp and plugin are there, said so otherwise;
- the GPU check on a GPU (it runs here on KOKKOS' host backend, as its dry run does);
- the parts that need valgrind or perf (step_cost.py, instruction_counts.py, fluid_share.py)
  run where those are installed and usable, said so otherwise;
- seepage/consolidation.py: ctest runs its CI case (lammps.seepage_consolidation, --check);
- pair_bench's chute scene (--scene chute): it differs from the bed scene only in the input
  and data file it names, and its 32,000-grain starts would add half a minute; the GPU
  check's roundoff and growth parts: the table_s1 part runs the same dump check and the same
  tiled scene.
The studies that take hours in full are named on bench/README.md.

    source scripts/env.sh && /usr/bin/python3 bench/smoke.py [--only NAME,...] [--keep DIR]
    /usr/bin/python3 bench/smoke.py --lmp LMP --plugin-dir DIR      (as ctest runs it)
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

BENCH = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(BENCH)
PYTHON = "/usr/bin/python3"


def host_has_kokkos():
    text = subprocess.run(["lmp", "-h"], capture_output=True, text=True).stdout
    return "KOKKOS" in text


def tool_missing(tool, probe=None):
    """why a tool cannot run here, or None"""
    if not shutil.which(tool):
        return "%s is not installed" % tool
    if probe and subprocess.run(probe, capture_output=True).returncode != 0:
        return "%s cannot run here (%s)" % (tool, " ".join(probe))
    return None


def other_host_missing():
    """why host_compare cannot run: the 2025 host's lmp and plugin (scripts/env.sh) absent"""
    check = subprocess.run(["bash", "-c", 'PW_LAMMPS=2025 source "%s/scripts/env.sh" && '
                            'command -v lmp >/dev/null && test -f "$PW_PLUGIN"' % REPO],
                           capture_output=True)
    return None if check.returncode == 0 else \
        "the 4Feb2025 host is not built (PW_LAMMPS=both scripts/setup.sh)"


def entries(plugin):
    """(name, script under bench/, arguments with {work} and {pages}, files it must write
    under {pages} or {work}, why it cannot run here or None)"""
    kk = None if host_has_kokkos() else "this lmp has no KOKKOS"
    valgrind = tool_missing("valgrind", ["valgrind", "--version"])
    perf = tool_missing("perf", ["perf", "stat", "-e", "task-clock", "true"])
    return [
        ("fidelity: ensembles by both estimators", "fidelity/ensemble.py",
         ["--work", "{work}", "--run", "twin", "--members", "2"],
         ["{pages}/fidelity/ensemble_results.md", "{work}/twin_member1/timeseries.txt"], None),
        ("fidelity: the paper's scene (stiff preset, its original numerics, default again)",
         "fidelity/paper_scene.py", ["--work", "{work}", "--only", "stiff,original,default,cost"],
         ["{work}/stiff/member1/timeseries.txt", "{work}/stiff_eps0.07/member0/cost.txt",
          "{work}/stiff_original/member0/timeseries.txt",
          "{work}/default/member1/timeseries.txt", "{work}/stiff_cost/np2/cost.txt"], None),
        ("fidelity: the paper's scene's tables", "fidelity/paper_scene.py",
         ["--work", "{work}", "--report"], ["{pages}/fidelity/paper_scene_results.md"], None),
        ("seepage: the paper's cycle on each force (dry run)", "seepage/ensembles.py",
         ["--work", "{work}", "--dry", "300"], ["{work}/dry/default_full/timeseries.txt"], None),
        ("paper_figures: cycle, permeability, creep", "paper_figures/figures.py",
         ["--work", "{work}", "--part", "all"],
         ["{work}/cycle/twin/timeseries.txt", "{work}/slow/timeseries.txt",
          "{work}/stress/check/sheared_N25_r0.10/timeseries.txt"], None),
        ("paper_figures: factors", "paper_figures/figures.py",
         ["--work", "{work}", "--part", "factors"],
         ["{pages}/paper_figures/factors_results.md", "{work}/factors/kn10/timeseries.txt"], None),
        ("paper_figures: factor at constant stress", "paper_figures/figures.py",
         ["--work", "{work}", "--part", "factor_stress", "--factor", "spread"],
         ["{pages}/paper_figures/factor_stress_results.md"], None),
        ("paper_figures: bisection of the bed's friction", "paper_figures/figures.py",
         ["--work", "{work}", "--part", "bisect"],
         ["{pages}/paper_figures/bisect_results.md"], None),
        ("creep_factors: cases as ensembles", "creep_factors/creep_factors.py",
         ["--work", "{work}", "--run", "kn10_eps0.14,tall", "--members", "2"],
         ["{pages}/creep_factors/creep_factors_results.md", "{work}/tall_member1/timeseries.txt"],
         None),
        ("creep_factors: the plateau after the first slip", "creep_factors/plateau.py",
         ["--work", "{work}", "--run", "control1,plate280"],
         ["{pages}/creep_factors/plateau_results.md", "{work}/control1/timeseries.txt"], None),
        ("creep_factors: counts on Table S1's geometry", "creep_factors/creep_factors.py",
         ["--work", "{work}", "--count"], ["{pages}/creep_factors/creep_factors_count.md"], None),
        ("time_to_solution: knobs", "time_to_solution/time_to_solution.py",
         ["--work", "{work}", "--part", "knobs", "--only", "default,eps0.14"],
         ["{work}/eps0.14/cost.txt"], None),
        ("time_to_solution: layout", "time_to_solution/time_to_solution.py",
         ["--work", "{work}", "--part", "layout", "--only", "np2"], ["{work}/np2/cost.txt"], None),
        ("time_to_solution: report", "time_to_solution/time_to_solution.py",
         ["--work", "{work}", "--part", "report"], [], None),
        ("step_cost: counts by section", "step_cost/step_cost.py",
         ["--scene", "reduced", "--steps", "25", "--markdown", "{pages}/step_cost.md",
          "now=" + plugin], ["{pages}/step_cost.md"], valgrind),
        ("step_cost: timer per rank", "step_cost/step_time.py",
         ["--scene", "reduced", "--steps", "200", "--repeat", "1", "--markdown",
          "{pages}/step_time.md", "now=" + plugin], ["{pages}/step_time.md"], None),
        ("step_cost: growth with the grain count", "step_cost/step_time.py",
         ["--growth", "--repeat", "1", "--markdown", "{pages}/step_growth.md", "--figure",
          "{pages}/step_growth.png", plugin], ["{pages}/step_growth.png"], None),
        ("step_cost: the fluid's share, sampled", "step_cost/fluid_share.py",
         ["--markdown", "{pages}/fluid_share.md", plugin], ["{pages}/fluid_share.md"], perf),
        ("checkpoint_cost", "checkpoint_cost/checkpoint_cost.py",
         ["--cycles", "0.002", "--work", "{work}"],
         ["{pages}/checkpoint_cost/checkpoint_cost_results.md"], None),
        ("gpu: the GPU check's dry run (KOKKOS host backend)", "gpu/gpu_check.py",
         ["--out", "{pages}/gpu", "--work", "{work}", "--accel", "-k on t 1 -sf kk",
          "--parts", "cycle,table_s1,fluid_step"],
         ["{pages}/gpu/summary.md", "{pages}/gpu/gpu_check.json"], kk),
        ("pair: against gran/hooke/history, dense beds", "pair/pair_bench.py",
         ["--scene", "bed", "--steps", "20", "--repeat", "1"], [], None),
        ("pair: instruction counts", "pair/instruction_counts.py", ["--only", "pair", "now=" + plugin],
         [], valgrind),
        ("darcy: accuracy and share of the step", "darcy/darcy_bench.py",
         ["--plugin", plugin, "--repeat", "1", "--steps", "20", "--out", "{pages}/darcy.md"],
         ["{pages}/darcy.md", "{pages}/darcy_bench.png"], None),
        ("integrators", "integrators/integrator_bench.py", ["--out", "{pages}"],
         ["{pages}/integrator_results.md", "{pages}/integrator_stability.png"], None),
        ("tidal_profile: cost of each part", "tidal_profile/tidal_profile.py",
         ["--part", "profile", "--repeat", "1", "--steps", "40", "--out", "{pages}/profile.md"],
         ["{pages}/profile.md"], None),
        ("tidal_profile: every N", "tidal_profile/tidal_profile.py",
         ["--part", "every", "--horizon", "1200", "--ranks", "1", "--out", "{pages}/every.md"],
         ["{pages}/every.md"], None),
        ("tidal_profile: long run", "tidal_profile/tidal_profile.py",
         ["--part", "long", "--long-steps", "2340", "--ranks", "1", "--out", "{pages}/long.md"],
         ["{pages}/long.md"], None),
        ("hosts: LAMMPS 4Feb2025 against 29Sep2021", "hosts/host_compare.py",
         ["--model-time", "0.006"], [], other_host_missing()),
        ("wall_damping", "wall_damping/wall_damping.py", ["--work", "{work}", "--part", "all"],
         ["{pages}/wall_damping/wall_damping_results.md"], None),
    ]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--lmp", help="the lmp to run (default: the one on PATH)")
    ap.add_argument("--plugin-dir", help="the folder of porewater.so (default: the first on "
                    "LD_LIBRARY_PATH that holds it)")
    ap.add_argument("--only", default="", help="comma-separated words: the entries whose name "
                    "contains one of them")
    ap.add_argument("--keep", help="run in this folder and keep it")
    args = ap.parse_args()
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    if args.lmp:
        lmp = os.path.abspath(args.lmp)
        env["PATH"] = os.path.dirname(lmp) + ":" + env.get("PATH", "")
        lib = os.path.join(os.path.dirname(os.path.dirname(lmp)), "lib")
        env["LD_LIBRARY_PATH"] = lib + ":" + env.get("LD_LIBRARY_PATH", "")
    if args.plugin_dir:
        env["LD_LIBRARY_PATH"] = os.path.abspath(args.plugin_dir) + ":" + env.get("LD_LIBRARY_PATH", "")
    plugin = next((p for p in env.get("LD_LIBRARY_PATH", "").split(":")
                   if p and os.path.exists(os.path.join(p, "porewater.so"))), None)
    if not plugin or not shutil.which("lmp", path=env.get("PATH")):
        sys.exit("no lmp on PATH or no porewater.so on LD_LIBRARY_PATH: source scripts/env.sh "
                 "or pass --lmp and --plugin-dir")
    os.environ.update(env)    # the probes below run the same lmp
    top = args.keep or tempfile.mkdtemp(prefix="pw_bench_smoke_")
    pages = os.path.join(top, "pages")
    os.makedirs(pages, exist_ok=True)
    env["PW_BENCH_SMOKE"] = pages
    only = [w for w in args.only.split(",") if w]
    failed, start = [], time.time()
    for index, (name, script, argv, expect, why_not) in enumerate(entries(plugin)):
        if only and not any(w in name for w in only):
            continue
        if why_not:
            print("skipped  %s: %s" % (name, why_not), flush=True)
            continue
        work = os.path.join(top, "work", script.replace("/", "_").replace(".py", ""))
        fill = lambda s: s.format(work=work, pages=pages)
        log = os.path.join(top, "logs", "%02d_%s.log" % (index, script.replace("/", "_")))
        os.makedirs(os.path.dirname(log), exist_ok=True)
        t0 = time.time()
        with open(log, "w") as out:
            rc = subprocess.run(["nice", "-n", "10", PYTHON, os.path.join(BENCH, script)] +
                                [fill(a) for a in argv], env=env, cwd=top, stdout=out,
                                stderr=subprocess.STDOUT).returncode
        missing = [fill(f) for f in expect if not os.path.exists(fill(f))]
        ok = rc == 0 and not missing
        print("%s %s (%.0f s)%s" % ("ok      " if ok else "FAILED  ", name, time.time() - t0,
                                    "" if ok else ": exit %d%s; log %s" % (
                                        rc, ", missing " + ", ".join(missing) if missing else "",
                                        log)), flush=True)
        if not ok:
            failed.append(name)
            print("".join(open(log).readlines()[-15:]), flush=True)
    print("bench smoke: %d failed, %.0f s in all%s" % (
        len(failed), time.time() - start, "" if args.keep else "; " + top + " removed"))
    if not args.keep:
        shutil.rmtree(top, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
