"""Runs of lmp for the studies: examples/tidal_shear's inputs copied into a work folder, lmp
with -var overrides (niced, each run free to use any core), its CPU and wall seconds and the
load around it, LAMMPS' loop times, the commit the runs come from, a copy of the plugin that a
rebuild does not touch, and the Kokkos dispatches a step makes."""
import glob
import os
import re
import shutil
import signal
import subprocess
import sys
import time

import numpy as np

from . import COMMON, EXAMPLE
from porewater_analysis.timeseries import complete, load    # noqa: F401  (the studies' import)

# the inputs that more than one study runs
REPLICATE_BED = os.path.join(COMMON, "in.replicate_bed")        # a bed tiled nx x ny x nz
TIDAL_SHEAR_TIMED = os.path.join(COMMON, "in.tidal_shear_timed")  # the example under a timeout
KOKKOS_DISPATCHES = os.path.join(COMMON, "kokkos_dispatches.cpp")  # Kokkos profiling hook

# the example's bed before the original's preparation became the default (in.params `bed`):
# the paper_figures study's cycle, permeability, creep and full parts and the factors' "former
# default" were measured on it, and name it to run as they did
FRICTIONLESS = {"bed": "frictionless"}


class RunTimeout(Exception):
    """a run stopped at its deadline (run_lmp's `deadline`)"""


def run_lmp(workdir, infile, variables, ranks=1, plugin_dir=None, log="log.lammps", args=(),
            threads=1, extra_env=None, launcher=(), deadline=None):
    """lmp -in infile in workdir (niced; `threads` OpenMP threads, extra lmp `args` such as
    KOKKOS' -k on t 2 -sf kk, `extra_env` added to its environment, `launcher` a command it
    runs under, such as a profiler); returns its CPU seconds. `deadline` (time.time()): the
    run is killed there and RunTimeout raised."""
    # OMP_PROC_BIND (scripts/env.sh: spread) pins a 1-thread run to core 0: concurrent runs
    # would share that core
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND="false",
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if plugin_dir:
        env["LD_LIBRARY_PATH"] = plugin_dir + ":" + env.get("LD_LIBRARY_PATH", "")
    env.update(extra_env or {})
    cmd = ["nice", "-n", "10"] + list(launcher)
    if ranks > 1:
        cmd += ["mpirun", "--oversubscribe", "-np", str(ranks), "-x", "LD_LIBRARY_PATH", "-x", "OMP_PROC_BIND"]
    cmd += ["lmp", "-in", infile, "-log", log, "-screen", "none"] + list(args)
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    # numpy's OpenMP runtime binds this very process under OMP_PROC_BIND=spread (to core 0),
    # and children inherit that mask: the runs of a pool would share one core
    proc = subprocess.Popen(cmd, cwd=workdir, env=env, start_new_session=deadline is not None,
                            preexec_fn=lambda: os.sched_setaffinity(0, range(os.cpu_count())))
    while True:
        pid, status, usage = os.wait4(proc.pid, os.WNOHANG if deadline else 0)
        if pid:
            break
        if time.time() > deadline:
            os.killpg(proc.pid, signal.SIGKILL)
            os.wait4(proc.pid, 0)
            raise RunTimeout(" ".join(cmd))
        time.sleep(0.2)
    if status != 0:
        raise subprocess.CalledProcessError(status, cmd)
    return usage.ru_utime + usage.ru_stime


def time_step(kn, eps=0.07, radius=0.01, rho=2600.0):
    """examples/tidal_shear/in.params: dt = eps / sqrt(k_n / m)"""
    return eps / np.sqrt(kn / (rho * 4.0 / 3.0 * np.pi * radius ** 3))


def timed_run(workdir, infile, variables, ranks=1, args=(), threads=1, log="log.lammps"):
    """run_lmp, its CPU and wall seconds added as a line to workdir/cost.txt (with the load
    average of the last minute before and after): a run continued in legs has a line a leg"""
    load_before = os.getloadavg()[0]
    start = time.time()
    cpu = run_lmp(workdir, infile, variables, ranks=ranks, args=args, threads=threads, log=log)
    with open(os.path.join(workdir, "cost.txt"), "a") as f:
        f.write("%.1f %.1f %.2f %.2f\n" % (cpu, time.time() - start, load_before, os.getloadavg()[0]))
    return cpu


def read_cost(workdir):
    """[CPU s, wall s, load before the first leg, load after the last] of timed_run's legs
    (summed), or None"""
    path = os.path.join(workdir, "cost.txt")
    if not os.path.exists(path):
        return None
    legs = np.loadtxt(path, ndmin=2)
    return [legs[:, 0].sum(), legs[:, 1].sum()] + list(legs[[0, -1], [2, 3]]) \
        if legs.shape[1] >= 4 else list(legs[:, :2].sum(axis=0))


def run_logs(workdir):
    """the logs of a run of the example in the order of its legs: log.lammps, then each
    continued leg's (run_example)"""
    legs = glob.glob(os.path.join(workdir, "log.continued*"))
    return [os.path.join(workdir, "log.lammps")] + sorted(
        legs, key=lambda p: int(p.rsplit(".", 1)[1]) if p[-1].isdigit() else 1)


def run_example(workdir, variables, t_end, ranks=1, args=(), threads=1, data=None):
    """in.tidal_shear in workdir until its time series reaches t_end s (timed_run): from the
    start, or continued from workdir's checkpoint where a run stopped before (-var continue 1,
    each leg's log its own: log.continued.K); `data`: a file to copy there first. The leg's
    CPU s, or None if the run was complete"""
    if complete(os.path.join(workdir, "timeseries.txt"), t_end):
        return None
    go_on = os.path.exists(os.path.join(workdir, "checkpoint.restart"))
    if not go_on:
        prepare(workdir)
        if data:
            shutil.copy(data, workdir)
    log = "log.continued.%d" % len(run_logs(workdir)) if go_on else "log.lammps"
    return timed_run(workdir, "in.tidal_shear", dict(variables, **({"continue": 1} if go_on else {})),
                     ranks=ranks, args=args, threads=threads, log=log)


CHUNK = re.compile(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps.*?\n"
                   r"\s*([0-9.]+)% CPU use with (\d+) MPI tasks", re.S)


def chunks_cpu(workdir):
    """(CPU s, steps) of a run of the example's completed chunks over all its legs' logs: each
    chunk's loop time x its CPU use x its MPI tasks, as LAMMPS reports them. A leg killed
    mid-chunk lost that chunk's work, which the next leg does again: counted once."""
    cpu, steps = 0.0, 0
    for log in run_logs(workdir):
        if os.path.exists(log):
            for loop, _, n, use, tasks in CHUNK.findall(open(log).read()):
                cpu += float(loop) * float(use) / 100.0 * int(tasks)
                steps += int(n)
    return cpu, steps


def loop_time(log, last=True):
    """(seconds, steps) of the last run in a LAMMPS log, or of all its runs (in.tidal_shear
    runs in chunks, one run each: all of them)"""
    found = re.findall(r"Loop time of ([0-9.eE+]+) on \d+ procs for (\d+) steps", open(log).read())
    if last:
        return float(found[-1][0]), int(found[-1][1])
    return sum(float(f[0]) for f in found), sum(int(f[1]) for f in found)


def head_commit():
    """the short hash of the commit the benchmarks run from (their results pages name it)"""
    return subprocess.run(["git", "-C", COMMON, "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True).stdout.strip()


def prepare(workdir, extra=()):
    """workdir with the example's inputs and shipped beds, and the files `extra` (paths)"""
    os.makedirs(workdir, exist_ok=True)
    for name in os.listdir(EXAMPLE):
        if name.startswith("in.") or name.startswith("consolidated_"):
            shutil.copy(os.path.join(EXAMPLE, name), workdir)
    for path in extra:
        shutil.copy(path, workdir)


def freeze_plugin(work, part):
    """the runs of this process load a copy of the plugin taken now (work/plugin_PART): a
    rebuild meanwhile does not touch them"""
    frozen = os.path.join(work, "plugin_" + part)
    os.makedirs(frozen, exist_ok=True)
    for path in os.environ.get("LD_LIBRARY_PATH", "").split(":"):
        if os.path.exists(os.path.join(path, "porewater.so")):
            for so in ("porewater.so", "porewater_styles.so"):    # a new file: runs of an
                shutil.copy(os.path.join(path, so), os.path.join(frozen, so + ".new"))  # earlier
                os.replace(os.path.join(frozen, so + ".new"), os.path.join(frozen, so))  # call keep theirs
            break
    else:
        sys.exit("no porewater.so on LD_LIBRARY_PATH: source scripts/env.sh first")
    os.environ["LD_LIBRARY_PATH"] = frozen + ":" + os.environ["LD_LIBRARY_PATH"]


# GPU latency assumed per dispatch (with its fence) and per copy, and the arrays LAMMPS' fix
# wall/gran (no /kk in 29Sep2021) moved between host and device each step (x v f omega torque
# up, f torque down): the projection made before any GPU was lent
LAUNCH_US, COPY_US = 5.0, 15.0
HOST_FIX_COPIES = 7


def read_count(path):
    words = open(path).readline().split()
    return {words[i]: int(words[i + 1]) for i in range(0, len(words), 2)}


def dispatches_per_step(work, variables=None, folder="dispatches", steps=(1000, 2000)):
    """Kokkos dispatches and deep copies per step of the reduced example with -sf kk (the
    same per step at any size) and -var `variables`: the difference of two runs of `steps`
    (1,000 and 2,000: whole fluid intervals for every N up to 200 that divides 1,000)"""
    d = os.path.join(work, folder)
    hook = os.path.join(d, "kokkos_dispatches.so")
    if not os.path.exists(hook):
        prepare(d)
        subprocess.run(["g++", "-O2", "-shared", "-fPIC", "-o", hook, KOKKOS_DISPATCHES],
                       check=True)
    totals = []
    for n in steps:
        out = os.path.join(d, "count_%d.txt" % n)
        if os.path.exists(out):
            totals.append(read_count(out))
            continue
        env = dict(os.environ, KOKKOS_PROFILE_LIBRARY=hook, KCOUNT_OUT=out, OMP_NUM_THREADS="1",
                   OMP_PROC_BIND="false")
        extra = [a for kv in (variables or {}).items() for a in ("-var", kv[0], str(kv[1]))]
        subprocess.run(["lmp", "-k", "on", "t", "1", "-sf", "kk", "-in", "in.tidal_shear",
                        "-var", "run_steps", str(n), "-screen", "none", "-log", "none"] + extra,
                       cwd=d, env=env, check=True)
        totals.append(read_count(out))
    span = float(steps[1] - steps[0])
    per = {k: (totals[1][k] - totals[0][k]) / span for k in totals[0]}
    return per["for"] + per["reduce"] + per["scan"], per["deep_copy"]
