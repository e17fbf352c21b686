#!/usr/bin/python3
"""pair linear/coulomb against native gran/hooke/history on the 32k-grain chute, side by side.

Runs every configuration `--repeat` times, interleaved, and reports the median loop time,
the median time of the Pair section, and the ratios native/ours (> 1: ours is faster).
--mu 0 compares the frictionless case (native computes and resets the spring, ours skips it).
Usage (after scripts/setup.sh):
    source scripts/env.sh && /usr/bin/python3 bench/pair_bench.py [--steps 300] [--repeat 3] [--mu 0.5]
"""
import argparse, os, re, statistics, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))

def styles(mu):
    """(native, ours) as (pair_style, pair_coeff) arguments, damping off in both."""
    return ((f"gran/hooke/history 200000.0 200000.0 0.0 0.0 {mu} 0", "* *"),
            ("linear/coulomb lever radius", f"* * 200000.0 200000.0 {mu}"))

# OpenMP threads are not pinned: on a shared machine a thread pinned to a busy core cannot
# move (one-thread KOKKOS runs were 1.6x slower pinned, and swung 2x between runs), and the
# CPU runs, compared with them, are not pinned either
ENV = {k: v for k, v in os.environ.items() if k not in ("OMP_PROC_BIND", "OMP_PLACES")}
ENV.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")

# (label, launcher prefix, lmp accelerator arguments, OMP threads)
CONFIGS = [
    ("CPU, 1 core", [], [], 1),
    ("CPU, MPI 2 ranks", ["mpirun", "--oversubscribe", "-np", "2"], [], 1),
    ("KOKKOS OpenMP, 1 thread", [], ["-k", "on", "t", "1", "-sf", "kk"], 1),
    ("KOKKOS OpenMP, 2 threads", [], ["-k", "on", "t", "2", "-sf", "kk"], 2),
]


def times(prefix, accel, threads, style, steps, data):
    """(loop time, Pair section time) of one run."""
    cmd = prefix + ["lmp", "-in", os.path.join(HERE, "in.chute"), "-log", "none", "-echo", "none",
                    "-var", "pstyle", style[0], "-var", "pcoeff", style[1],
                    "-var", "steps", str(steps), "-var", "data", data] + accel
    env = dict(ENV, OMP_NUM_THREADS=str(threads))
    out = subprocess.run(cmd, env=env, capture_output=True, text=True, cwd="/tmp")
    m = re.search(r"Loop time of ([0-9.eE+-]+)", out.stdout)
    pair = re.search(r"^Pair +\| +\S+ +\| +([0-9.eE+-]+)", out.stdout, re.M)    # avg over ranks
    if out.returncode != 0 or not m or not pair:
        sys.exit("failed: " + " ".join(cmd) + "\n" + out.stdout[-2000:] + out.stderr[-2000:])
    return float(m.group(1)), float(pair.group(1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=300)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--mu", type=float, default=0.5, help="friction coefficient of both styles")
    ap.add_argument("--data", default=os.path.expanduser(
        "~/.cache/lammps-porewater/lammps-29Sep2021u2/bench/data.chute"))
    args = ap.parse_args()
    native, ours = styles(args.mu)
    print(f"mu = {args.mu}, {args.steps} steps, median of {args.repeat}", flush=True)
    rows = []
    for label, prefix, accel, threads in CONFIGS:
        t = {"native": [], "ours": []}
        for _ in range(args.repeat):    # interleaved: load drift hits both alike
            for name, style in (("native", native), ("ours", ours)):
                t[name].append(times(prefix, accel, threads, style, args.steps, args.data))
        (tn, pn), (to, po) = [tuple(statistics.median(x[k] for x in t[n]) for k in (0, 1))
                              for n in ("native", "ours")]
        rows.append((label, tn, to, pn, po))
        print(f"{label:28s} loop: native {tn:7.3f} s ours {to:7.3f} s ratio {tn / to:5.2f}; "
              f"Pair: native {pn:7.3f} s ours {po:7.3f} s ratio {pn / po:5.2f}", flush=True)
    kk1 = next(r for r in rows if r[0].startswith("KOKKOS OpenMP, 1"))
    cpu1 = rows[0]
    print(f"native gran/hooke/history/kk (1 thread) vs native CPU: {cpu1[1] / kk1[1]:.2f}x")
    print(f"ours linear/coulomb/kk (1 thread) vs native /kk (1 thread): {kk1[1] / kk1[2]:.2f}x")
    print("| configuration | native loop (s) | ours loop (s) | native/ours loop | "
          "native Pair (s) | ours Pair (s) | native/ours Pair |")
    print("|---|---|---|---|---|---|---|")
    for label, tn, to, pn, po in rows:
        print(f"| {label} | {tn:.3f} | {to:.3f} | {tn / to:.2f} | {pn:.3f} | {po:.3f} | {pn / po:.2f} |")

if __name__ == "__main__":
    main()
