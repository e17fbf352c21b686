"""Runs of examples/tidal_shear for the benchmarks (bench/wall_damping.py, bench/fidelity.py):
a work folder with the example's inputs, lmp with -var overrides; the time series through
analysis/porewater_analysis, which importing this module puts on the path."""
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "examples", "tidal_shear")
sys.path.insert(0, os.path.join(HERE, "..", "analysis"))
from porewater_analysis.timeseries import complete, load  # noqa: E402,F401  (the benchmarks' import)


# the example's bed before the original's preparation became the default (in.params `bed`):
# fidelity.py's cycle, permeability, creep and full parts and the factors' "former default"
# were measured on it, and name it to run as they did
FRICTIONLESS = {"bed": "frictionless"}


def run_lmp(workdir, infile, variables, ranks=1, plugin_dir=None, log="log.lammps", args=(),
            threads=1, extra_env=None, launcher=()):
    """lmp -in infile in workdir (niced; `threads` OpenMP threads, extra lmp `args` such as
    KOKKOS' -k on t 2 -sf kk, `extra_env` added to its environment, `launcher` a command it
    runs under, such as a profiler); returns its CPU seconds."""
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
    proc = subprocess.Popen(cmd, cwd=workdir, env=env,
                            preexec_fn=lambda: os.sched_setaffinity(0, range(os.cpu_count())))
    _, status, usage = os.wait4(proc.pid, 0)
    if status != 0:
        raise subprocess.CalledProcessError(status, cmd)
    return usage.ru_utime + usage.ru_stime


def time_step(kn, eps=0.07, radius=0.01, rho=2600.0):
    """examples/tidal_shear/in.params: dt = eps / sqrt(k_n / m)"""
    return eps / np.sqrt(kn / (rho * 4.0 / 3.0 * np.pi * radius ** 3))


def timed_run(workdir, infile, variables, ranks=1, args=(), threads=1):
    """run_lmp, its CPU and wall seconds written to workdir/cost.txt (with the load average
    of the last minute before and after)"""
    load_before = os.getloadavg()[0]
    start = time.time()
    cpu = run_lmp(workdir, infile, variables, ranks=ranks, args=args, threads=threads)
    with open(os.path.join(workdir, "cost.txt"), "w") as f:
        f.write("%.1f %.1f %.2f %.2f\n" % (cpu, time.time() - start, load_before, os.getloadavg()[0]))
    return cpu


def read_cost(workdir):
    """[CPU s, wall s] of timed_run (and the load before and after where recorded), or None"""
    path = os.path.join(workdir, "cost.txt")
    return [float(v) for v in open(path).read().split()] if os.path.exists(path) else None


def loop_time(log, last=True):
    """(seconds, steps) of the last run in a LAMMPS log, or of all its runs (in.tidal_shear
    runs in chunks, one run each: all of them)"""
    found = re.findall(r"Loop time of ([0-9.eE+]+) on \d+ procs for (\d+) steps", open(log).read())
    if last:
        return float(found[-1][0]), int(found[-1][1])
    return sum(float(f[0]) for f in found), sum(int(f[1]) for f in found)


def head_commit():
    """the short hash of the commit the benchmarks run from (their results pages name it)"""
    return subprocess.run(["git", "-C", HERE, "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True).stdout.strip()


def prepare(workdir, extra=()):
    os.makedirs(workdir, exist_ok=True)
    for name in os.listdir(EXAMPLE):
        if name.startswith("in.") or name.startswith("consolidated_"):
            shutil.copy(os.path.join(EXAMPLE, name), workdir)
    for name in extra:
        shutil.copy(os.path.join(HERE, name), workdir)
