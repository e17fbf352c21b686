#!/usr/bin/python3
"""Deterministic cost of the package's kernels: callgrind instruction counts (inclusive) of
the pair style's compute() and of fix darcy/pressure's post_force(), CPU and KOKKOS (one
OpenMP thread), for one or more builds of the plugin side by side.

Scenes: the 3,044-grain cut of LAMMPS' chute (in.chute_cut, 300 steps) for the pair
style; the Table S1-sized bed (bench/common/in.darcy_share_bed, 9,600 grains, fluid every step,
100 + 20 steps) for the fix. Counts do not depend on the load of the machine (valgrind
counts instructions, not time), so two builds compare exactly.

Usage (after scripts/setup.sh; each PLUGIN_DIR holds a porewater.so):
    source scripts/env.sh
    /usr/bin/python3 bench/pair/instruction_counts.py [--only pair|darcy] LABEL=PLUGIN_DIR ...
"""
import argparse, os, re, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import COMMON, EXAMPLE, REPO, short    # noqa: E402

CHUTE_CUT = os.path.join(HERE, "in.chute_cut")
DARCY_BED = os.path.join(COMMON, "in.darcy_share_bed")
PAIR_STEPS, DARCY_STEPS = short((300, 100), (10, 10))

KOKKOS = ["-k", "on", "t", "1", "-sf", "kk"]
CASES = {
    "pair": [
        ("pair CPU", CHUTE_CUT, [], r"PairLinearCoulomb::compute\(int, int\)"),
        ("pair /kk", CHUTE_CUT, KOKKOS, r"PairLinearCoulombKokkos<Kokkos::OpenMP>::compute\(int, int\)"),
    ],
    "darcy": [
        ("darcy CPU", DARCY_BED, [], r"FixDarcyPressure::post_force\(int\)"),
        ("darcy /kk", DARCY_BED, KOKKOS, r"FixDarcyPressureKokkos<Kokkos::OpenMP>::post_force\(int\)|FixDarcyPressure::post_force\(int\)"),
    ],
}


def lammps_bench():
    lmp = subprocess.run(["which", "lmp"], capture_output=True, text=True).stdout.strip()
    # lmp lives in <prefix>/bin; the tree it was built from is recorded by scripts/versions.sh
    out = subprocess.run(["bash", "-c", f"source {REPO}/scripts/versions.sh && echo $LAMMPS_SRC"],
                         capture_output=True, text=True).stdout.strip()
    return os.path.join(out, "bench")


def count(plugin_dir, script, accel, pattern, workdir):
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false",
               LD_LIBRARY_PATH=plugin_dir + ":" + os.environ.get("LD_LIBRARY_PATH", ""))
    out = os.path.join(workdir, "callgrind.out")
    args = ["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out, "lmp", "-in",
            script, "-log", "none", "-screen", "none", "-var", "steps", str(PAIR_STEPS)]
    if script == CHUTE_CUT:
        args += ["-var", "pstyle", "linear/coulomb lever radius",
                 "-var", "pcoeff", "* * 200000.0 200000.0 0.5",
                 "-var", "data", os.path.join(lammps_bench(), "data.chute")]
    else:
        args += ["-var", "steps", str(DARCY_STEPS), "-var", "examples", EXAMPLE]
    subprocess.run(args + accel, cwd=workdir, env=env, check=True, capture_output=True)
    return inclusive_count(out, pattern)


def inclusive_count(profile, pattern):
    """the inclusive instructions of the function matching `pattern` in a callgrind profile"""
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", profile], capture_output=True,
                          text=True, check=True).stdout
    total = 0
    for line in text.splitlines():
        m = re.match(r"\s*([\d,]+)\s+(?:\([^)]*\)\s+)?[^:\s]*:(.*)", line)
        if m and re.search(pattern, m.group(2)):
            total = max(total, int(m.group(1).replace(",", "")))
    return total


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("builds", nargs="+", help="LABEL=PLUGIN_DIR")
    ap.add_argument("--only", choices=sorted(CASES), help="one part only")
    a = ap.parse_args()
    builds = [b.split("=", 1) for b in a.builds]
    parts = [a.only] if a.only else sorted(CASES)
    print("| kernel | " + " | ".join(label for label, _ in builds) + " |" +
          (" ratio |" if len(builds) == 2 else ""))
    print("|---|" + "---|" * (len(builds) + (1 if len(builds) == 2 else 0)))
    for part in parts:
        for name, script, accel, pattern in CASES[part]:
            counts = []
            for _, plugin in builds:
                with tempfile.TemporaryDirectory() as work:
                    counts.append(count(os.path.abspath(plugin), script, accel, pattern, work))
            row = f"| {name} | " + " | ".join(f"{c / 1e6:.1f} M" for c in counts) + " |"
            if len(counts) == 2 and counts[0]:
                row += f" {counts[1] / counts[0]:.3f} |"
            print(row, flush=True)


if __name__ == "__main__":
    sys.exit(main())
