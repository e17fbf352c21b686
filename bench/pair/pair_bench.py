#!/usr/bin/python3
"""pair linear/coulomb against native gran/hooke/history, side by side, on two scenes:

  chute  LAMMPS' bench/in.chute (32,000 grains, frozen base, 26 degrees; a flow: few of the
         neighbours touch), damping off in both styles
  bed    the grains of examples/tidal_shear loaded under the example's stress-controlled plate
         (in.pair_bed; dry, not sheared): a dense bed, most neighbours in contact. Its
         data files: --data (e.g. the Table S1 bed of bench/time_to_solution/time_to_solution.py
         --part table_s1), or by default the two shipped beds (the default, coordination ~4.5,
         and the frictionless one, ~5.6) each replicated 2 x 2 in x and y to Table S1's
         footprint (4,800 grains; bench/common/in.replicate_bed -var nz 1)

Both styles identical in their trajectories (`linear/coulomb lever radius` against
`gran/hooke/history kn kt 0 0 mu 0`). Timings: every configuration `--repeat` times,
interleaved, the median loop time and Pair-section time, and the ratios native/ours (> 1:
ours is faster). --count instead: callgrind's instruction count of each style's compute()
(CPU and KOKKOS with one thread), which does not depend on the machine's load.
--mu 0 compares the frictionless case (native computes and resets the spring, ours skips it).
The short setting (bench/smoke.py): the default bed's scene only.
Usage (after scripts/setup.sh):
    source scripts/env.sh && /usr/bin/python3 bench/pair/pair_bench.py [--scene chute|bed]
        [--steps 300] [--repeat 3] [--mu 0.5] [--data FILE ...] [--count]
"""
import argparse, os, re, shutil, statistics, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import EXAMPLE, short    # noqa: E402
from common.runs import REPLICATE_BED    # noqa: E402
from instruction_counts import inclusive_count, lammps_bench    # noqa: E402  (this study's own)

# OpenMP threads are not pinned: on a shared machine a thread pinned to a busy core cannot
# move (one-thread KOKKOS runs were 1.6x slower pinned, and swung 2x between runs), and the
# CPU runs, compared with them, are not pinned either
ENV = {k: v for k, v in os.environ.items() if k not in ("OMP_PROC_BIND", "OMP_PLACES")}
ENV.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")

KOKKOS1 = ["-k", "on", "t", "1", "-sf", "kk"]
# (label, launcher prefix, lmp accelerator arguments, OMP threads)
CONFIGS = [
    ("CPU, 1 core", [], [], 1),
    ("CPU, MPI 2 ranks", ["mpirun", "--oversubscribe", "-np", "2"], [], 1),
    ("KOKKOS OpenMP, 1 thread", [], KOKKOS1, 1),
    ("KOKKOS OpenMP, 2 threads", [], ["-k", "on", "t", "2", "-sf", "kk"], 2),
]
COUNTED = {  # callgrind: the style's compute() (with what it calls)
    ("native", False): r"PairGranHookeHistory::compute\(int, int\)",
    ("ours", False): r"PairLinearCoulomb::compute\(int, int\)",
    ("native", True): r"PairGranHookeHistoryKokkos<Kokkos::OpenMP>::compute\(int, int\)",
    ("ours", True): r"PairLinearCoulombKokkos<Kokkos::OpenMP>::compute\(int, int\)",
}


def chute_args(name, mu, steps, data):
    style = (("gran/hooke/history 200000.0 200000.0 0.0 0.0 %g 0" % mu, "* *") if name == "native"
             else ("linear/coulomb lever radius", "* * 200000.0 200000.0 %g" % mu))
    return ["-in", os.path.join(HERE, "in.chute"), "-var", "pstyle", style[0], "-var", "pcoeff",
            style[1], "-var", "steps", str(steps), "-var", "data", data]


def bed_args(name, mu, steps, data):
    return ["-in", "in.pair_bed", "-var", "pair", name, "-var", "lever", "radius", "-var", "mu",
            str(mu), "-var", "steps", str(steps), "-var", "data", data]


def run(cwd, prefix, args, threads, log="none"):
    env = dict(ENV, OMP_NUM_THREADS=str(threads))
    cmd = prefix + ["lmp", "-log", log, "-echo", "none"] + args
    out = subprocess.run(cmd, env=env, capture_output=True, text=True, cwd=cwd)
    if out.returncode != 0:
        sys.exit("failed: " + " ".join(cmd) + "\n" + out.stdout[-2000:] + out.stderr[-2000:])
    return out.stdout


def times(stdout):
    """(loop time, Pair section time averaged over ranks) of one run"""
    m = re.search(r"Loop time of ([0-9.eE+-]+)", stdout)
    pair = re.search(r"^Pair +\| +\S+ +\| +([0-9.eE+-]+)", stdout, re.M)
    return float(m.group(1)), float(pair.group(1))


def coordination(stdout):
    """the mean coordination at the first and last thermo row (in.pair_bed prints it)"""
    rows = re.findall(r"^\s+\d+\s+\S+\s+([0-9.]+)\s", stdout, re.M)
    return float(rows[0]), float(rows[-1])


def count(cwd, args, kokkos, pattern):
    out = os.path.join(cwd, "callgrind.out")
    env = dict(ENV, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
    subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out, "lmp", "-log",
                    "none", "-screen", "none"] + args + (KOKKOS1 if kokkos else []),
                   cwd=cwd, env=env, check=True, capture_output=True)
    return inclusive_count(out, pattern)


def bed_scenes(work, data):
    """{label: data file} of the bed scene: the given files, or the shipped beds replicated"""
    for name in os.listdir(EXAMPLE):
        if name.startswith("in.") or name.startswith("consolidated_"):
            shutil.copy(os.path.join(EXAMPLE, name), work)
    for path in (os.path.join(HERE, "in.pair_bed"), REPLICATE_BED):
        shutil.copy(path, work)
    if data:
        return {os.path.basename(d): os.path.abspath(d) for d in data}
    scenes = {}
    beds = [("consolidated_0", "default bed x2x2 (4,800 grains)"),
            ("consolidated_frictionless_0", "frictionless bed x2x2 (4,800 grains)")]
    for bed, label in short(beds, beds[:1]):    # the short setting (bench/smoke.py): one
        out = os.path.join(work, bed + "_x2x2.data")
        run(work, [], ["-in", "in.replicate_bed", "-var", "in", bed + ".data", "-var", "out", out,
                       "-var", "nz", "1", "-screen", "none"], 1)
        scenes[label] = out
    return scenes


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scene", choices=["chute", "bed"], default="chute")
    ap.add_argument("--steps", type=int, default=300)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--mu", type=float, default=0.5, help="friction coefficient of both styles")
    ap.add_argument("--data", nargs="*", default=None,
                    help="chute: LAMMPS' data.chute (default in the LAMMPS tree's bench/); bed: "
                         "data files of the example's grains (default: the shipped beds replicated)")
    ap.add_argument("--count", action="store_true", help="instruction counts instead of times")
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="pw_pair_bench_")
    if args.scene == "chute":
        scenes = {"chute": (args.data or [os.path.join(lammps_bench(), "data.chute")])[0]}
        make_args = chute_args
    else:
        scenes = bed_scenes(work, args.data)
        make_args = bed_args
    print("%s, mu = %g, %d steps, %s" % (args.scene, args.mu, args.steps,
          "instruction counts" if args.count else "median of %d interleaved" % args.repeat), flush=True)
    for scene, data in scenes.items():
        if args.count:
            print("\n%s\n\n| kernel | native | ours | native/ours |\n|---|---|---|---|" % scene)
            for kokkos in (False, True):
                c = {n: count(work, make_args(n, args.mu, args.steps, data), kokkos, COUNTED[(n, kokkos)])
                     for n in ("native", "ours")}
                print("| %s | %.1f M | %.1f M | %.2f |" % ("KOKKOS, 1 thread" if kokkos else "CPU",
                      c["native"] / 1e6, c["ours"] / 1e6, c["native"] / c["ours"]), flush=True)
            continue
        rows = []
        for label, prefix, accel, threads in CONFIGS:
            t = {"native": [], "ours": []}
            for _ in range(args.repeat):    # interleaved: load drift hits both alike
                for name in ("native", "ours"):
                    stdout = run(work, prefix, make_args(name, args.mu, args.steps, data) + accel, threads)
                    t[name].append(times(stdout))
                    if args.scene == "bed" and not rows and len(t[name]) == 1 and name == "ours":
                        z0, z1 = coordination(stdout)
                        print("%s: coordination %.2f at the start, %.2f at the end" % (scene, z0, z1))
            (tn, pn), (to, po) = [tuple(statistics.median(x[k] for x in t[n]) for k in (0, 1))
                                  for n in ("native", "ours")]
            rows.append((label, tn, to, pn, po))
            print(f"{label:28s} loop: native {tn:7.3f} s ours {to:7.3f} s ratio {tn / to:5.2f}; "
                  f"Pair: native {pn:7.3f} s ours {po:7.3f} s ratio {pn / po:5.2f}", flush=True)
        print("\n%s (load average %.2f at the end)\n" % (scene, os.getloadavg()[0]))
        print("| configuration | native loop (s) | ours loop (s) | native/ours loop | "
              "native Pair (s) | ours Pair (s) | native/ours Pair |")
        print("|---|---|---|---|---|---|---|")
        for label, tn, to, pn, po in rows:
            print(f"| {label} | {tn:.3f} | {to:.3f} | {tn / to:.2f} | {pn:.3f} | {po:.3f} | {pn / po:.2f} |")
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
