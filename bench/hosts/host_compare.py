#!/usr/bin/python3
"""examples/tidal_shear on LAMMPS 29Sep2021 and 4Feb2025: the same input, side by side.

Runs the example as it is in the checkout (whatever examples/tidal_shear/in.params holds)
for --model-time seconds of model time, serially (one MPI rank, one thread), with
`scripts/env.sh` of each host, each run in a copy of the example folder:

  A  2021 and 2025 at the same time, one per core: their time series, and the cost per
     step of each (loop time / steps) in the same conditions
  B  the same pair again with one input parameter moved by one ulp (-var NAME VALUE with
     VALUE the next double after the example's): the chaotic spread of each host
  C  2021 on 2 MPI ranks (alone on the machine): the spread of another summation order

The chaotic spread of a quantity is the largest |difference| over the time series between
two runs of one host that differ only by round-off (A-B of each host, A-C for 2021); the
hosts agree on a quantity when max |2021 - 2025| (run A) is at most 3 times the largest
spread. Prints a markdown table, and the cost ratio 2025/2021 of pairs A and B.

  PW_LAMMPS=both scripts/setup.sh && bench/hosts/host_compare.py [--model-time 0.5] [--keep DIR]
  (with the PW_CACHE that setup used)
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import EXAMPLE, REPO  # noqa: E402
from common.ensembles import SPREAD_FACTOR, perturbation, spread_agreement  # noqa: E402
from porewater_analysis.timeseries import load as load_series  # noqa: E402


def shell(host, command, cwd, log):
    """`command` in bash with PW_LAMMPS=host scripts/env.sh sourced, output to `log`."""
    env = dict(os.environ, PW_LAMMPS=host, OMP_NUM_THREADS="1", OMP_PROC_BIND="false",
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    script = f'source "{REPO}/scripts/env.sh" && {command}'
    out = open(log, "w")
    return subprocess.Popen(["bash", "-c", script], cwd=cwd, env=env, stdout=out,
                            stderr=subprocess.STDOUT)


def check_hosts(work):
    """Both hosts' lmp and plugin exist (PW_LAMMPS=both scripts/setup.sh, the same PW_CACHE)."""
    for host in ("2021", "2025"):
        log = os.path.join(work, f"check{host}.out")
        if shell(host, 'command -v lmp && test -f "$PW_PLUGIN"', work, log).wait() != 0:
            sys.exit(f"no lmp or plugin of LAMMPS host {host} (PW_CACHE="
                     f"{os.environ.get('PW_CACHE', 'default')}): run PW_LAMMPS=both scripts/setup.sh")


def example_copy(parent, name):
    d = os.path.join(parent, name)
    os.makedirs(d)
    for f in os.listdir(EXAMPLE):
        if f.startswith("in.") or f.endswith(".data"):
            shutil.copy(os.path.join(EXAMPLE, f), d)
    return d


def timestep(work):
    """The example's timestep: in.params evaluated by LAMMPS itself."""
    d = example_copy(work, "dt")
    with open(os.path.join(d, "in.dt"), "w") as f:
        f.write('include in.params\nprint "PW_DT $(v_dt:%.17g)"\n')
    shell("2021", "lmp -in in.dt -log none -echo none", d, os.path.join(d, "shell.out")).wait()
    m = re.search(r"PW_DT (\S+)", open(os.path.join(d, "shell.out")).read())
    if not m:
        sys.exit(f"could not evaluate dt from in.params (see {d})")
    return float(m.group(1))


def start(work, name, host, steps, extra="", ranks=1):
    d = example_copy(work, name)
    lmp = "lmp" if ranks == 1 else f"mpirun --oversubscribe -np {ranks} lmp"
    cmd = f"{lmp} -in in.tidal_shear -var run_steps {steps} {extra} -log log.lammps -screen none"
    return d, shell(host, cmd, d, os.path.join(d, "shell.out"))


def finish(d, p):
    if p.wait() != 0:
        sys.exit(f"run in {d} failed:\n" + open(os.path.join(d, "shell.out")).read()[-2000:])
    log = open(os.path.join(d, "log.lammps")).read()
    loops = re.findall(r"Loop time of (\S+) on (\d+) procs for (\d+) steps", log)    # per chunk
    return dict(series=load_series(os.path.join(d, "timeseries.txt")),
                seconds=sum(float(m[0]) for m in loops), steps=sum(int(m[2]) for m in loops))


def load():
    return open("/proc/loadavg").read().split()[0]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--model-time", type=float, default=0.5, help="seconds of model time")
    ap.add_argument("--keep", help="run in this folder and keep it")
    args = ap.parse_args()
    work = args.keep or tempfile.mkdtemp(prefix="pw_hosts_")
    os.makedirs(work, exist_ok=True)
    loads = [load()]
    check_hosts(work)
    dt = timestep(work)
    steps = int(math.ceil(args.model_time / dt))
    name, value, moved = perturbation()
    print(f"dt {dt:.6g} s, {steps} steps ({steps * dt:.4g} s of model time); perturbed run: "
          f"-var {name} {moved} (in.params: {value}); load before {loads[0]}", flush=True)

    runs = {}
    t0 = time.time()
    pair = [start(work, "A2021", "2021", steps), start(work, "A2025", "2025", steps)]
    runs["A2021"], runs["A2025"] = [finish(*r) for r in pair]
    loads.append(load())
    pair = [start(work, "B2021", "2021", steps, f"-var {name} {moved}"),
            start(work, "B2025", "2025", steps, f"-var {name} {moved}")]
    runs["B2021"], runs["B2025"] = [finish(*r) for r in pair]
    loads.append(load())
    runs["C2021"] = finish(*start(work, "C2021", "2021", steps, ranks=2))
    loads.append(load())
    print(f"runs took {time.time() - t0:.0f} s; load average after each phase: {', '.join(loads[1:])}\n")

    n = min(len(r["series"]["time"]) for r in runs.values())
    s = {k: {q: r["series"][q][:n] for q in r["series"]} for k, r in runs.items()}
    assert np.array_equal(s["A2021"]["time"], s["A2025"]["time"])
    print(f"{n} samples to t = {s['A2021']['time'][-1]:.4g} s. max |difference| over the time series:\n")
    print("| quantity | 2021 at the end | 2025 at the end | 2021 vs 2025 | spread 2021 (1 ulp) "
          "| spread 2025 (1 ulp) | spread 2021 (1 vs 2 ranks) | hosts / largest spread |")
    print("|---|---|---|---|---|---|---|---|")
    rows, agree = spread_agreement(s, ("A2021", "A2025"),
                                   [("A2021", "B2021"), ("A2025", "B2025"), ("A2021", "C2021")])
    for q, what, hosts, spreads, ratio in rows:
        print(f"| {q}: {what} | {s['A2021'][q][-1]:.6g} | {s['A2025'][q][-1]:.6g} | {hosts:.3g} | "
              + " | ".join(f"{x:.3g}" for x in spreads) + f" | {ratio:.2f} |")
    print()
    for label in ("A", "B"):
        a, b = runs[label + "2021"], runs[label + "2025"]
        pa, pb = a["seconds"] / a["steps"], b["seconds"] / b["steps"]
        print(f"pair {label}: cost per step 2021 {pa * 1e6:.1f} us, 2025 {pb * 1e6:.1f} us: "
              f"2025/2021 = {pb / pa:.3f}")
    print(f"2 ranks (2021, alone): {runs['C2021']['seconds'] / runs['C2021']['steps'] * 1e6:.1f} us per step")
    print(f"\nhosts agree to the chaotic spread (max |2021 - 2025| <= {SPREAD_FACTOR:g} x largest spread): "
          + ("yes" if agree else "NO"))
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    return 0 if agree else 1


if __name__ == "__main__":
    sys.exit(main())
