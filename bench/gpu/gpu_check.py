#!/usr/bin/python3
"""The GPU check: examples/tidal_shear with the /kk styles on a GPU against the same binary's
CPU styles, and its cost per step: one command on a lent device machine, with the kit that
scripts/gpu_kit.sh builds here (carried); dry-run here, the same script, on KOKKOS' OpenMP
backend of the 2021 host. Every run (CPU and accel) uses -var neigh_every NEIGH_EVERY: the
neighbour list's distance check (a reduction the host waits for) every 25 steps instead of
every step (bench/gpu/neighbor_every.py: over a cycle of the reduced example as many builds, none
dangerous).

Parts (each run in its own folder under the work folder; lmp with and without ACCEL), in the
order they matter (the default order; the summary is written after each):
  roundoff  the reduced example, ROUNDOFF_STEPS steps, grains dumped every 100 steps: the
            largest |x_accel - x_cpu| of a grain at each dump, within the /kk equality tests'
            1e-10 m (tests/lammps/test_style_matrix.cpp, positions) or, once chaos has grown
            the CPU's own round-off past that, within 3 x the CPU's own spread (the CPU run
            against the CPU run with tau one ulp higher)
  table_s1  the Table S1-sized scene (common.beds.SCENES' table_s1: 9,600 grains, -var fast 1)
            as the example runs it, its outputs on: S1_STEPS steps with ACCEL (us per step:
            LAMMPS' loop time over steps; the goal: at most GOAL_S1_US), the kernels and deep
            copies per step on the device (bench/common/kokkos_dispatches.cpp counting, no waits: a
            2,000- less a 1,000-step run), ROUNDOFF_STEPS steps with the kernel timer
            (KTIMES_OUT: it waits for the device around each kernel), again without it, and
            on the CPU: |dx| every 100 steps as in roundoff, the accel runs' own difference a
            spread too
  growth    the reduced example tiled 1, 2, 4, 8 times per side (1,200 to 614,400 grains;
            common.beds.tiled) with ACCEL: us per step and grain-steps per second
            (the goal at 614,400: at least GOAL_GRAIN_STEPS)
  fluid_step  what a fluid step of fix darcy/pressure/kk asks of the host, on the reduced
            example and the Table S1-sized scene (-var fast 1, FLUID_STEPS steps with ACCEL):
            per fluid step, the deep copies between its deposit and force kernels (the grid's
            deposits up and force field down are expected; an atom array is not) and LAMMPS'
            atom syncs to the host there, by caller; and per kernel the host's time in its
            dispatch without waiting for the device (bench/common/kokkos_dispatches.cpp,
            KDISPATCH_OUT): on a GPU microseconds, unless the launch waits, as a launch object
            copied to constant memory does (the package's kernels are asserted to pass theirs
            as a kernel argument when the kit compiles: src/lammps/kokkos_grains.h); on a
            host backend the dispatch runs the kernel, so there it says nothing of launches
  cycle     the reduced example's first CYCLE_FRACTION cycle on the CPU, on the CPU with tau
            one ulp higher, on the CPU with the bed's grains displaced by up to DISPLACEMENT,
            and twice with ACCEL: the time series agree when max |accel - cpu| over it is at
            most 3 x the largest spread of round-off (cpu vs the other two, accel vs accel
            again; common.ensembles.spread_agreement); the cost per step of each
Writes OUT/summary.md (the tables), OUT/gpu_check.json (every number), OUT/kernel_times.txt,
OUT/logs.tar.gz (the runs' logs and time series) and OUT/machine.txt; exits 1 when a
round-off check fails. --time-limit S (default TIME_LIMIT): a run still going S seconds
after the start is killed, the parts after it are not started, and the summary says where
it stopped (exit 0 unless a check that ran failed): a device call keeps what ran. The
default parts take the Table S1-sized scene and the reduced example within it on an H200;
growth last. The short setting (bench/smoke.py): every part a few hundred steps, the
growth 1,200 and 9,600 grains only.

    tar -xJf gpu_kit.tar.xz && python3 bench/gpu/gpu_check.py --kit gpu_kit --out "$OUT"
                                                                   (on the device machine)
    source scripts/env.sh; /usr/bin/python3 bench/gpu/gpu_check.py --out DIR \\
        --accel "-k on t 2 -sf kk"                                   (dry run, OpenMP backend)
"""
import argparse
import json
import math
import os
import shlex
import subprocess
import sys
import tarfile
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import short    # noqa: E402
from common.beds import SCENES, prepare_scene, tiled    # noqa: E402
from common.ensembles import PERTURB as DISPLACEMENT    # noqa: E402  (the ensembles' perturbation, m)
from common.ensembles import SPREAD_FACTOR, perturbation, spread_agreement    # noqa: E402
from common.runs import KOKKOS_DISPATCHES, RunTimeout, loop_time, run_lmp    # noqa: E402
from kokkos_step_counts import per_step, read_run    # noqa: E402
from porewater_analysis.dump import read_dump    # noqa: E402
from porewater_analysis.timeseries import load as load_series    # noqa: E402

GPU_ACCEL = "-k on g 1 -sf kk -pk kokkos neigh half newton off"
KK_TEST_TOLERANCE = 1e-10      # m: |x| of /kk vs CPU in the style matrix (chute, 1,000 steps)
ROUNDOFF_STEPS, ROUNDOFF_EVERY = short((1000, 100), (200, 100))
CYCLE_FRACTION = short(0.05, 0.002)
S1_STEPS = short(10000, 200)
# the runs whose difference gives the dispatches per step
COUNT_STEPS = short((1000, 2000), (100, 200))
# whole fluid intervals (25 steps at -var fast 1)
GROWTH_STEPS = short({1: 2300, 2: 1150, 4: 575, 8: 250}, {1: 100, 2: 50})
NEIGH_EVERY = 25              # the neighbour list's distance check every N steps (--neigh-every)
EVERY_RUN = {"neigh_every": NEIGH_EVERY}    # -var settings of every run
GOAL_S1_US = 100.0            # us per step of the Table S1-sized scene, outputs on
GOAL_GRAIN_STEPS = 3e8        # grain-steps per second at 614,400 grains
FLUID_STEPS = short(1000, 100)    # steps of the fluid_step part (a fluid step every 25)
TIME_LIMIT = 480.0            # s: --time-limit, 8 minutes of a device call
DEADLINE = [None]             # time.time() at which runs are stopped (main sets it)
WAITED_US = 20.0              # us: a dispatch that long on a GPU's host waited for something


def use_kit(kit):
    """the kit's lmp and libraries first on this process' paths (its runs inherit them)"""
    os.environ["PATH"] = os.path.join(kit, "bin") + ":" + os.environ["PATH"]
    os.environ["LD_LIBRARY_PATH"] = os.path.join(kit, "lib") + ":" + os.environ.get("LD_LIBRARY_PATH", "")


def accel_threads(accel):
    """the OpenMP threads that lmp's accelerator arguments ask for (-k on t N), else 1"""
    words = shlex.split(accel)
    return int(words[words.index("t") + 1]) if "t" in words else 1


def run(work, name, variables, accel, extra_env=None, edits=()):
    """in.tidal_shear in work/name with -var `variables` (a scene's `data` and `copies`: the
    default bed tiled, common.beds) and its lines `edits` (old, new) replaced: its run
    loops' seconds, steps, us per step"""
    d = os.path.join(work, name)
    variables = prepare_scene(dict(EVERY_RUN, **variables), d, dict(os.environ))
    if edits:
        path = os.path.join(d, "in.tidal_shear")
        text = open(path).read()
        for old, new in edits:
            if old not in text:
                sys.exit("in.tidal_shear has no line %r to replace" % old)
            text = text.replace(old, new)
        open(path, "w").write(text)
    try:
        run_lmp(d, "in.tidal_shear", variables, args=shlex.split(accel), threads=accel_threads(accel),
                extra_env=extra_env, deadline=DEADLINE[0])
    except subprocess.CalledProcessError as e:
        log = os.path.join(d, "log.lammps")
        sys.exit("run %s failed (%s):\n%s" % (name, " ".join(e.cmd), open(log).read()[-3000:]
                                              if os.path.exists(log) else ""))
    seconds, steps = loop_time(os.path.join(d, "log.lammps"), last=False)
    return {"dir": d, "seconds": seconds, "steps": steps, "us_per_step": 1e6 * seconds / steps}


def largest_dx(dir_a, dir_b, step):
    """max over grains of |x_a - x_b| (nearest periodic image in x and y) at a dumped step"""
    name = "grains_%d.dump" % step
    length, a = read_dump(os.path.join(dir_a, name))
    _, b = read_dump(os.path.join(dir_b, name))
    if not np.array_equal(a["id"], b["id"]):
        return math.inf
    worst = 0.0
    for k, axis in enumerate("xyz"):
        d = a[axis] - b[axis]
        if k < 2:
            d -= length[k] * np.round(d / length[k])
        worst = max(worst, float(np.max(np.abs(d))))
    return worst


def cpu_pair(work, name, variables):
    """the CPU run and the CPU run with in.params' first PERTURBED value one ulp higher, side
    by side"""
    param, _, moved = perturbation()
    with ThreadPoolExecutor(2) as pool:
        cpu = pool.submit(run, work, name + "_cpu", variables, "")
        ulp = pool.submit(run, work, name + "_cpu_ulp", dict(variables, **{param: moved}), "")
        return cpu.result(), ulp.result(), "%s %s" % (param, moved)


def part_roundoff(work, accel, results):
    common = {"run_steps": ROUNDOFF_STEPS, "dump_every": ROUNDOFF_EVERY}
    cpu, ulp, perturbed = cpu_pair(work, "roundoff", common)
    acc = run(work, "roundoff_accel", common, accel)
    results["roundoff"] = dx_check(cpu["dir"], acc["dir"], ulp["dir"], perturbed)


def dx_check(cpu_dir, accel_dir, ulp_dir, perturbed, again_dir=None):
    """the largest |dx| of a grain at each dump, accel vs CPU, CPU vs CPU + 1 ulp and (given
    again_dir) accel vs accel run again: within the /kk tests' tolerance, or (once chaos has
    grown round-off past it) within SPREAD_FACTOR x the largest spread"""
    rows = []
    for step in range(ROUNDOFF_EVERY, ROUNDOFF_STEPS + 1, ROUNDOFF_EVERY):
        dx, spread = largest_dx(cpu_dir, accel_dir, step), largest_dx(cpu_dir, ulp_dir, step)
        again = largest_dx(accel_dir, again_dir, step) if again_dir else 0.0
        ok = dx <= max(KK_TEST_TOLERANCE, SPREAD_FACTOR * max(spread, again))
        rows.append((step, dx, spread, again, ok))
    return {"steps_dx": rows, "tolerance": KK_TEST_TOLERANCE, "perturbed": perturbed,
            "again": again_dir is not None, "passed": all(r[4] for r in rows)}


def part_cycle(work, accel, results):
    common = {"cycles": CYCLE_FRACTION}
    with ThreadPoolExecutor(1) as pool:    # the displaced CPU run beside the pair
        displaced = pool.submit(run, work, "cycle_cpu_displaced",
                                dict(common, perturb=DISPLACEMENT, perturb_seed=1), "")
        cpu, ulp, perturbed = cpu_pair(work, "cycle", common)
        runs = {"cpu": cpu, "cpu_ulp": ulp, "cpu_displaced": displaced.result()}
    runs["accel"] = run(work, "cycle_accel", common, accel)
    runs["accel_again"] = run(work, "cycle_accel_again", common, accel)
    series = {k: load_series(os.path.join(r["dir"], "timeseries.txt")) for k, r in runs.items()}
    n = min(len(s["time"]) for s in series.values())
    compared, agree = spread_agreement(series, ("accel", "cpu"), [("cpu_ulp", "cpu"), (
        "cpu_displaced", "cpu"), ("accel_again", "accel")])
    rows = [(q, what, float(series["cpu"][q][n - 1]), float(series["accel"][q][n - 1]), diff)
            + tuple(spreads) + (ratio,) for q, what, diff, spreads, ratio in compared]
    results["cycle"] = {"rows": rows, "samples": n, "t_end": float(series["cpu"]["time"][n - 1]),
                        "perturbed": perturbed, "passed": agree,
                        "us_per_step": {k: r["us_per_step"] for k, r in runs.items()},
                        "steps": runs["cpu"]["steps"]}


def dispatches_per_step(work, scene, accel, hook):
    """the Kokkos dispatches and deep copies per step of `scene` with ACCEL, counted by the
    hook without waits (the difference of two runs), and per kernel; LAMMPS' atom syncs per
    caller where the hook could be preloaded into lmp"""
    runs = []
    for steps in COUNT_STEPS:
        counts = {"KOKKOS_PROFILE_LIBRARY": hook, "LD_PRELOAD": hook,
                  "KCOUNT_OUT": os.path.join(work, "count_%d.txt" % steps),
                  "KSYNC_OUT": os.path.join(work, "sync_%d.txt" % steps)}
        run(work, "count_%d" % steps, dict(scene, run_steps=steps), accel, extra_env=counts)
        runs.append(read_run(counts["KCOUNT_OUT"], counts["KSYNC_OUT"]))
    return per_step(runs, COUNT_STEPS)


def part_table_s1(work, accel, hook, out, results):
    grains, scene = SCENES["table_s1"]
    timed = run(work, "s1_accel", dict(scene, run_steps=S1_STEPS), accel)
    counts = dispatches_per_step(work, scene, accel, hook)
    check = dict(scene, run_steps=ROUNDOFF_STEPS, dump_every=ROUNDOFF_EVERY)
    timer = {"KOKKOS_PROFILE_LIBRARY": hook, "KTIMES_OUT": os.path.join(out, "kernel_times.txt"),
             "KCOUNT_OUT": os.path.join(work, "kernel_counts.txt")}
    acc = run(work, "s1_accel_check", check, accel, extra_env=timer)
    again = run(work, "s1_accel_check_again", check, accel)
    cpu, ulp, perturbed = cpu_pair(work, "s1_check", check)
    results["table_s1"] = {"grains": grains, "steps": timed["steps"], "us_per_step": timed["us_per_step"],
                           "goal_met": timed["us_per_step"] <= GOAL_S1_US, "counts": counts,
                           "us_per_step_timed_kernels": acc["us_per_step"],
                           "cpu_us_per_step": cpu["us_per_step"], "check_steps": ROUNDOFF_STEPS,
                           "roundoff": dx_check(cpu["dir"], acc["dir"], ulp["dir"], perturbed, again["dir"])}


def read_counts(path):
    """{key: count} of a hook file's 'COUNT KEY' lines"""
    rows = {}
    for line in open(path) if os.path.exists(path) else ():
        count, _, key = line.rstrip("\n").partition(" ")
        if count.isdigit():
            rows[key] = rows.get(key, 0) + int(count)
    return rows


def fluid_step_counts(work, name, scene, accel, hook):
    """per fluid step: deep copies and atom syncs to the host during it; per kernel: the
    host's time in its dispatch (us per call)"""
    d = os.path.join(work, name)
    files = {k: os.path.join(work, "%s_%s.txt" % (name, k)) for k in ("count", "sync", "dispatch")}
    env = {"KOKKOS_PROFILE_LIBRARY": hook, "LD_PRELOAD": hook, "KCOUNT_OUT": files["count"],
           "KSYNC_OUT": files["sync"], "KDISPATCH_OUT": files["dispatch"]}
    r = run(work, name, dict(scene, run_steps=FLUID_STEPS, fast=1), accel, extra_env=env)
    counts, syncs = read_counts(files["count"]), read_counts(files["sync"])
    fluid_steps = counts.get("darcy/pressure:deposit", 0)
    per = max(fluid_steps, 1)
    copies = {k[len("fluid deep_copy "):]: n / per for k, n in counts.items()
              if k.startswith("fluid deep_copy ")}
    host_syncs = {}
    for key, n in syncs.items():
        words = key.split(" ")
        if words[0] == "fluid" and words[1] == "sync" and words[2] == "Host" and int(words[3], 16):
            caller = " ".join(words[4:])
            host_syncs[caller] = host_syncs.get(caller, 0.0) + n / per
    dispatch = [(name_, 1e6 * float(sec) / int(calls), int(calls)) for sec, calls, name_ in
                (line.rstrip("\n").split(" ", 2) for line in open(files["dispatch"])
                 if not line.startswith("#"))] if os.path.exists(files["dispatch"]) else []
    return {"steps": r["steps"], "fluid_steps": fluid_steps, "copies": copies,
            "host_syncs": host_syncs, "dispatch_us": sorted(dispatch, key=lambda t: -t[1])}


def part_fluid_step(work, accel, hook, results):
    results["fluid_step"] = {
        "reduced example": fluid_step_counts(work, "fluid_reduced", {}, accel, hook),
        "Table S1-sized scene": fluid_step_counts(work, "fluid_table_s1", SCENES["table_s1"][1],
                                                  accel, hook)}


def part_growth(work, accel, results):
    rows = []
    for copies, steps in GROWTH_STEPS.items():
        grains, scene = tiled(copies)
        r = run(work, "growth_x%d" % copies, dict(scene, run_steps=steps), accel)
        rows.append((grains, r["steps"], r["us_per_step"], r["us_per_step"] / grains,
                     1e6 * grains / r["us_per_step"]))
    results["growth"] = rows
    largest = rows[-1]
    results["growth_goal"] = {"grains": largest[0], "grain_steps_per_s": largest[4],
                              "goal_met": largest[4] >= GOAL_GRAIN_STEPS}


def cpu_model():
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            return line.split(":", 1)[1].strip()
    return "?"


def machine_record(kit):
    lines = ["date %s" % time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
             "cpus %d (%s), load %s" % (os.cpu_count(), cpu_model(), open("/proc/loadavg").read().strip())]
    for cmd in (["nvidia-smi", "--query-gpu=name,driver_version,memory.total,clocks.sm,clocks.max.sm",
                 "--format=csv"], ["lmp", "-h"]):
        try:
            text = subprocess.run(cmd, capture_output=True, text=True, timeout=60).stdout
            lines += text.splitlines()[:40] if cmd[0] == "nvidia-smi" else [
                l for l in text.splitlines() if "LAMMPS" in l or "KOKKOS" in l or "Kokkos" in l][:6]
        except (OSError, subprocess.TimeoutExpired) as e:
            lines.append("%s: %s" % (cmd[0], e))
    if kit and os.path.exists(os.path.join(kit, "BUILD_INFO")):
        lines += open(os.path.join(kit, "BUILD_INFO")).read().splitlines()
    return lines


def dx_table(check):
    lines = ["| step | max over grains of abs(x_accel - x_cpu) (m) | CPU vs CPU with %s | %s within |"
             % (check["perturbed"], "accel vs accel again |" if check["again"] else ""),
             "|---|---|---|%s---|" % ("---|" if check["again"] else "")]
    for step, dx, spread, again, ok in check["steps_dx"]:
        lines.append("| %d | %.3g | %.3g | %s%s |" % (step, dx, spread, "%.3g | " % again if check["again"]
                                                      else "", "yes" if ok else "NO"))
    return lines + ["", "within the /kk tests' %.0e m, or %g x the largest spread, at every dump: "
                    "**%s**" % (check["tolerance"], SPREAD_FACTOR, "yes" if check["passed"] else "NO"), ""]


def summary(results, accel):
    out = ["# GPU check: /kk with `%s` against the CPU styles of the same binary" % accel, ""]
    out += ["```"] + results["machine"] + ["```", ""]
    out += ["Every run with -var neigh_every %d. Seconds per part: %s." % (
        results.get("neigh_every", NEIGH_EVERY), ", ".join(
            "%s %.0f" % kv for kv in results.get("seconds", {}).items()) or "none yet"), ""]
    if "roundoff" in results:
        out += ["## Round-off: the reduced example, grains dumped every %d steps" % ROUNDOFF_EVERY, ""]
        out += dx_table(results["roundoff"])
    if "cycle" in results:
        c = results["cycle"]
        out += ["## The reduced example's first %.2f cycle (%d steps, %d samples to t = %.4g s)" % (
            CYCLE_FRACTION, c["steps"], c["samples"], c["t_end"]), "",
            "Spreads of round-off (max abs difference over the time series): the CPU run against "
            "the CPU run with %s (one ulp), against the CPU run with every grain of the bed "
            "displaced by up to %g m (the ensembles' perturbation), and the accel run against "
            "itself run again. Agreement: max abs(accel - CPU) at most %g x the largest "
            "spread." % (c["perturbed"], DISPLACEMENT, SPREAD_FACTOR), "",
            "| quantity | CPU at the end | accel at the end | max abs(accel - CPU) | CPU, 1 ulp "
            "| CPU, displaced | accel, again | ratio |", "|---|---|---|---|---|---|---|---|"]
        out += ["| %s: %s | %.6g | %.6g | %.3g | %.3g | %.3g | %.3g | %.2f |" % row
                for row in c["rows"]]
        out += ["", "agrees to the chaotic spread: **%s**; us per step: %s" % (
            "yes" if c["passed"] else "NO",
            ", ".join("%s %.1f" % kv for kv in c["us_per_step"].items())), ""]
    if "table_s1" in results:
        s = results["table_s1"]
        out += ["## Table S1-sized scene (%d grains, -var fast 1), its outputs on" % s["grains"], "",
                "| | us per step |", "|---|---|",
                "| accel, %d steps | %.1f |" % (s["steps"], s["us_per_step"]),
                "| accel with the kernel timer (waits for the device around each kernel), %d steps "
                "| %.1f |" % (s["check_steps"], s["us_per_step_timed_kernels"]),
                "| CPU styles, 1 core of this machine, %d steps | %.1f |" % (
                    s["check_steps"], s["cpu_us_per_step"]), "",
                "at most %.0f us per step: **%s**" % (GOAL_S1_US, "yes" if s["goal_met"] else "NO"), ""]
        out += counts_table(s["counts"])
        out += ["Round-off, as above, on this scene:", ""] + dx_table(s["roundoff"])
    if "fluid_step" in results:
        out += ["## A fluid step (-var fast 1: one every 25 steps), with `%s`" % accel, "",
                "Per fluid step, between fix darcy/pressure/kk's deposit and force kernels: the "
                "deep copies (the grid's deposits up and its force field down are expected), and "
                "LAMMPS' atom syncs to the host by caller (on a GPU each copies atom arrays down; "
                "on a host backend the kernels' own syncs are to the host too). Then each kernel's "
                "dispatch as the host spends it, without waiting: on a GPU above %.0f us it waited "
                "(a launch object through constant memory, a reduction into a host value); on a "
                "host backend the dispatch runs the kernel." % WAITED_US, ""]
        for label, f in results["fluid_step"].items():
            out += ["**%s**: %d fluid steps in %d steps." % (label, f["fluid_steps"], f["steps"]), "",
                    "| per fluid step | deep copy (to <- from) |", "|---|---|"]
            out += ["| %.2f | %s |" % (n, k[:110]) for k, n in sorted(f["copies"].items())] or ["| 0 | none |"]
            out += ["", "| per fluid step | atom sync to the host, by caller |", "|---|---|"]
            out += ["| %.2f | %s |" % (n, k[:110]) for k, n in sorted(f["host_syncs"].items())] or \
                ["| 0 | none |"]
            out += ["", "| us per dispatch | calls | kernel (those of every fluid step or more) |",
                    "|---|---|---|"]
            out += ["| %.1f | %d | %s |" % (us, n, k[:100]) for k, us, n in f["dispatch_us"]
                    if n >= f["fluid_steps"]][:15]
            out.append("")
    if results.get("stopped"):
        out += ["**Stopped at the time limit**: %s" % results["stopped"], ""]
    if "growth" in results:
        g = results["growth_goal"]
        out += ["## Growth (the reduced example tiled; -var fast 1)", "",
                "| grains | steps | us per step | us per grain-step | grain-steps per s |",
                "|---|---|---|---|---|"]
        out += ["| %d | %d | %.1f | %.4f | %.3g |" % row for row in results["growth"]]
        out += ["", "at least %.0e grain-steps per second at %d grains: **%s**" % (
            GOAL_GRAIN_STEPS, g["grains"], "yes" if g["goal_met"] else "NO"), ""]
    if results.get("kernels"):
        out += ["## Kernels of the Table S1-sized scene (kernel timer, top 15 by time)", "",
                "| seconds | calls | us per call | kernel |", "|---|---|---|---|"]
        out += ["| %.4f | %d | %.1f | %s |" % (s, c, 1e6 * s / max(c, 1), n[:110]) for s, c, n in
                results["kernels"][:15]]
        out.append("")
    return "\n".join(out)


def counts_table(c):
    t = c["totals"]
    out = ["Per step on the device, counted without waits (%d- less %d-step runs): %.2f kernels "
           "(for %.2f, reduce %.2f, scan %.2f), %.2f deep copies, %.2f fences." % (
               COUNT_STEPS[1], COUNT_STEPS[0], c["dispatches"], t.get("for", 0), t.get("reduce", 0), t.get("scan", 0), t.get("deep_copy", 0),
               t.get("fence", 0)), "", "| per step | kernel |", "|---|---|"]
    out += ["| %.3f | %s |" % (n, k[:110]) for k, n in sorted(c["kernels"].items(), key=lambda kv: -kv[1])]
    if c["atom"]:
        out += ["", "| per step | LAMMPS atom sync (space, mask, caller) |", "|---|---|"]
        out += ["| %.3f | %s |" % (n, k[:120]) for k, n in sorted(c["atom"].items(), key=lambda kv: -kv[1])]
    return out + [""]


def write_outputs(results, accel, out, work):
    """summary.md, gpu_check.json, machine.txt and logs.tar.gz of what has run so far"""
    results["kernels"] = read_kernel_times(os.path.join(out, "kernel_times.txt"))
    with open(os.path.join(out, "gpu_check.json"), "w") as f:
        json.dump(results, f, indent=1)
    text = summary(results, accel)
    open(os.path.join(out, "summary.md"), "w").write(text + "\n")
    open(os.path.join(out, "machine.txt"), "w").write("\n".join(results["machine"]) + "\n")
    with tarfile.open(os.path.join(out, "logs.tar.gz"), "w:gz") as tar:
        for root, _, files in os.walk(work):
            for f in files:
                if f in ("log.lammps", "timeseries.txt") or f.startswith(("count_", "sync_")):
                    path = os.path.join(root, f)
                    tar.add(path, arcname=os.path.relpath(path, work))
    return text


def read_kernel_times(path):
    if not os.path.exists(path):
        return []
    rows = []
    for line in open(path):
        if not line.startswith("#"):
            s, c, name = line.rstrip("\n").split(" ", 2)
            rows.append((float(s), int(c), name))
    return sorted(rows, reverse=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--kit", help="the kit folder (bin/lmp, lib/): scripts/gpu_kit.sh")
    ap.add_argument("--out", required=True, help="where summary.md and the rest go")
    ap.add_argument("--work", help="the runs' folder (default OUT/../gpu_check_runs)")
    ap.add_argument("--accel", default=GPU_ACCEL, help="lmp's accelerator arguments (%(default)s)")
    ap.add_argument("--parts", default="roundoff,table_s1,fluid_step,cycle,growth")
    ap.add_argument("--time-limit", type=float, default=TIME_LIMIT,
                    help="seconds after which runs stop and the summary is written (%(default)s)")
    ap.add_argument("--neigh-every", type=int, default=NEIGH_EVERY,
                    help="-var neigh_every of every run (%(default)s)")
    args = ap.parse_args()
    DEADLINE[0] = time.time() + args.time_limit
    EVERY_RUN["neigh_every"] = args.neigh_every
    kit = os.path.abspath(args.kit) if args.kit else None
    out = os.path.abspath(args.out)
    work = os.path.abspath(args.work or os.path.join(os.path.dirname(out), "gpu_check_runs"))
    os.makedirs(out, exist_ok=True)
    os.makedirs(work, exist_ok=True)
    if kit:
        use_kit(kit)
    hook = os.path.join(kit, "lib", "kokkos_dispatches.so") if kit else os.path.join(work, "kokkos_dispatches.so")
    if not kit:
        subprocess.run(["g++", "-O2", "-shared", "-fPIC", "-o", hook, KOKKOS_DISPATCHES, "-ldl"],
                       check=True)
    results = {"accel": args.accel, "neigh_every": args.neigh_every, "machine": machine_record(kit),
               "seconds": {}}
    print("\n".join(results["machine"]), flush=True)
    parts = {"roundoff": lambda: part_roundoff(work, args.accel, results),
             "cycle": lambda: part_cycle(work, args.accel, results),
             "table_s1": lambda: part_table_s1(work, args.accel, hook, out, results),
             "fluid_step": lambda: part_fluid_step(work, args.accel, hook, results),
             "growth": lambda: part_growth(work, args.accel, results)}
    for name in args.parts.split(","):
        t0 = time.time()
        try:
            parts[name]()
        except RunTimeout as e:
            results["stopped"] = "in part %s, %.0f s after the start (--time-limit %.0f): %s" % (
                name, time.time() - DEADLINE[0] + args.time_limit, args.time_limit, e)
            print(results["stopped"], flush=True)
            break
        results["seconds"][name] = time.time() - t0
        print("part %s: %.0f s" % (name, results["seconds"][name]), flush=True)
        write_outputs(results, args.accel, out, work)    # a run cut short keeps what it has
    print(write_outputs(results, args.accel, out, work), flush=True)
    ok = all(results.get(p, {}).get("passed", True) for p in ("roundoff", "cycle")) and \
        results.get("table_s1", {}).get("roundoff", {}).get("passed", True)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
