#!/usr/bin/python3
"""pair linear/coulomb against native gran/hooke/history on the 32k-grain chute, side by side.

Runs every configuration `--repeat` times, interleaved, and reports the median loop time
and the ratio native/ours (> 1: ours is faster). Usage (after scripts/setup.sh):
    source scripts/env.sh && /usr/bin/python3 bench/pair_bench.py [--steps 300] [--repeat 3]
"""
import argparse, os, re, statistics, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
NATIVE = ("gran/hooke/history 200000.0 200000.0 0.0 0.0 0.5 0", "* *")
OURS = ("linear/coulomb lever radius", "* * 200000.0 200000.0 0.5")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_PROC_BIND="spread", OMP_PLACES="threads")

# (label, launcher prefix, lmp accelerator arguments, OMP threads)
CONFIGS = [
    ("CPU, 1 core", [], [], 1),
    ("CPU, MPI 2 ranks", ["mpirun", "--oversubscribe", "-np", "2"], [], 1),
    ("KOKKOS OpenMP, 1 thread", [], ["-k", "on", "t", "1", "-sf", "kk"], 1),
    ("KOKKOS OpenMP, 2 threads", [], ["-k", "on", "t", "2", "-sf", "kk"], 2),
]


def loop_time(prefix, accel, threads, style, steps, data):
    cmd = prefix + ["lmp", "-in", os.path.join(HERE, "in.chute"), "-log", "none", "-echo", "none",
                    "-var", "pstyle", style[0], "-var", "pcoeff", style[1],
                    "-var", "steps", str(steps), "-var", "data", data] + accel
    env = dict(ENV, OMP_NUM_THREADS=str(threads))
    out = subprocess.run(cmd, env=env, capture_output=True, text=True, cwd="/tmp")
    m = re.search(r"Loop time of ([0-9.eE+-]+)", out.stdout)
    if out.returncode != 0 or not m:
        sys.exit("failed: " + " ".join(cmd) + "\n" + out.stdout[-2000:] + out.stderr[-2000:])
    return float(m.group(1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=300)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--data", default=os.path.expanduser(
        "~/.cache/lammps-porewater/lammps-29Sep2021u2/bench/data.chute"))
    args = ap.parse_args()
    rows = []
    for label, prefix, accel, threads in CONFIGS:
        t = {"native": [], "ours": []}
        for _ in range(args.repeat):    # interleaved: load drift hits both alike
            for name, style in (("native", NATIVE), ("ours", OURS)):
                t[name].append(loop_time(prefix, accel, threads, style, args.steps, args.data))
        tn, to = statistics.median(t["native"]), statistics.median(t["ours"])
        rows.append((label, tn, to, tn / to))
        print(f"{label:28s} native {tn:7.3f} s  ours {to:7.3f} s  native/ours {tn / to:5.2f}",
              flush=True)
    kk1 = next(r for r in rows if r[0].startswith("KOKKOS OpenMP, 1"))
    cpu1 = rows[0]
    print(f"native gran/hooke/history/kk (1 thread) vs native CPU: {cpu1[1] / kk1[1]:.2f}x")
    print(f"ours linear/coulomb/kk (1 thread) vs native /kk (1 thread): {kk1[1] / kk1[2]:.2f}x")
    print("| configuration | native gran/hooke/history (s) | linear/coulomb (s) | native/ours |")
    print("|---|---|---|---|")
    for label, tn, to, r in rows:
        print(f"| {label} | {tn:.3f} | {to:.3f} | {r:.2f} |")


if __name__ == "__main__":
    main()
