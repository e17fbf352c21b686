"""Runs of examples/tidal_shear for the benchmarks (bench/wall_damping.py, bench/fidelity.py):
a work folder with the example's inputs, lmp with -var overrides, the time series."""
import os
import resource
import shutil
import subprocess

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "examples", "tidal_shear")


def run_lmp(workdir, infile, variables, ranks=1, plugin_dir=None, log="log.lammps"):
    """lmp -in infile in workdir (niced, one OpenMP thread); returns its CPU seconds."""
    # OMP_PROC_BIND (scripts/env.sh: spread) pins a 1-thread run to core 0: concurrent runs
    # would share that core
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if plugin_dir:
        env["LD_LIBRARY_PATH"] = plugin_dir + ":" + env.get("LD_LIBRARY_PATH", "")
    cmd = ["nice", "-n", "10"]
    if ranks > 1:
        cmd += ["mpirun", "--oversubscribe", "-np", str(ranks), "-x", "LD_LIBRARY_PATH", "-x", "OMP_PROC_BIND"]
    cmd += ["lmp", "-in", infile, "-log", log, "-screen", "none"]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    proc = subprocess.Popen(cmd, cwd=workdir, env=env)
    _, status, usage = os.wait4(proc.pid, 0)
    if status != 0:
        raise subprocess.CalledProcessError(status, cmd)
    return usage.ru_utime + usage.ru_stime


def prepare(workdir, extra=()):
    os.makedirs(workdir, exist_ok=True)
    for name in ["in.params", "in.tidal_shear", "consolidated_0.data"]:
        shutil.copy(os.path.join(EXAMPLE, name), workdir)
    for name in extra:
        shutil.copy(os.path.join(HERE, name), workdir)


def load(path):
    names = open(path).readline().lstrip("# ").split()
    data = np.loadtxt(path, ndmin=2)
    return {n: data[:, k] for k, n in enumerate(names)}


def complete(path, t_end):
    try:
        return load(path)["time"][-1] >= t_end - 0.01
    except (OSError, ValueError, IndexError):
        return False
