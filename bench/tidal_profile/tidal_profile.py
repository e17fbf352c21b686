#!/usr/bin/python3
"""examples/tidal_shear: what each part of the scene costs, and what `every N` costs in error.

Part "profile": loop time of the same grains run four ways, interleaved, median of --repeat:
  granular  in.tidal_granular: pair, floor, gravity, nve/sphere only (what a plain
            LAMMPS granular script does)
  dry       in.tidal_shear -var fluid 0: plate, shear layer, held bottom, outputs, no water
  wet1      -var fluid_every 1 -var interpolate step: the fluid stepped every grain step
  wet10     -var interpolate step: the fluid stepped every 10th grain step
  wet10held in.tidal_shear as it is: every 10th, grain forces interpolated on fluid steps
            only (`interpolate fluid`), the example's default
  on two scenes: the reduced example (1,200 grains, grid 3x2x4) and a Table S1-sized bed
  (9,600 grains, grid 6x3x6, `-var full 1`; bench/common/in.replicate_bed builds it from the
  reduced bed, so it runs at the reduced stiffness: the cost of a step does not depend on
  k_n, only the number of steps does). The Table S1 scene also runs on 2 MPI ranks, and
  its per-step time projects the wall time of Table S1's 2.1e8 steps (45 s analysed) and
  2.76e8 steps (the 59 s the original ran).
Part "every": error of the tidal_shear time series against the fluid stepped every grain
  step, for every N = 2 ... 50 over --horizon grain steps from the shipped state: top-layer
  velocity and displacement, plate position, mean pore pressure (also every 10 and 50 with
  `interpolate fluid`). A second every-1 run with
  a 100x tighter solver tolerance gives the floor below which differences are the
  chaotic growth of round-off, not the fluid step.

Part "long": one long run of the reduced example (--long-steps, default 1e6 grain steps)
  on --ranks MPI ranks: every sampled value finite, the grains' kinetic
  energy bounded (largest value in each forcing cycle), the plate within the bed's range,
  and fix darcy/pressure's fluid balance (stored = inflow + grain source) closing: its
  residual against the allowance the solver tolerance permits. --closed: the same with a
  closed box (`top noflow`) and tol 1e-13, where the residual is round-off.

Usage (after scripts/setup.sh):  source scripts/env.sh
    /usr/bin/python3 bench/tidal_profile/tidal_profile.py [--part profile|every|all] [--repeat 3]
        [--steps 10000] [--horizon 47000]
Writes tidal_profile_results.md beside this script (--out).
"""
import argparse, os, re, shutil, statistics, subprocess, sys, tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import EXAMPLE, out_dir  # noqa: E402
from common.runs import REPLICATE_BED  # noqa: E402
from porewater_analysis.timeseries import load as read_series, run_parameters  # noqa: E402
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_NUM_THREADS="1")
STEPS_S1 = {"45 s analysed": 45.0 / 2.14e-7, "59 s run": 59.0 / 2.14e-7}
VARIANTS = {  # name: (input, extra variables)
    "granular": ("in.tidal_granular", {}),
    "dry": ("in.tidal_shear", {"fluid": 0}),
    "wet10": ("in.tidal_shear", {"fluid_every": 10, "interpolate": "step"}),
    "wet10held": ("in.tidal_shear", {"fluid_every": 10, "interpolate": "fluid"}),
    "wet1": ("in.tidal_shear", {"fluid_every": 1, "interpolate": "step"}),
}


def run_lmp(workdir, infile, variables, ranks=1, timed=True):
    cmd = ["lmp", "-in", infile, "-log", "none", "-echo", "none"]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    if ranks > 1:
        cmd = ["mpirun", "--oversubscribe", "-np", str(ranks)] + cmd
    out = subprocess.run(cmd, env=ENV, capture_output=True, text=True, cwd=workdir)
    loops = re.findall(r"Loop time of ([0-9.eE+-]+)", out.stdout)
    if out.returncode != 0 or (timed and not loops):
        sys.exit("failed: " + " ".join(cmd) + "\n" + out.stdout[-2000:] + out.stderr[-2000:])
    return sum(float(t) for t in loops) if timed else None    # in.tidal_shear: one run per chunk


def prepare(workdir):
    for name in os.listdir(EXAMPLE):
        if name.startswith("in.") or name.endswith(".data"):
            shutil.copy(os.path.join(EXAMPLE, name), workdir)
    for path in (os.path.join(HERE, "in.tidal_granular"), REPLICATE_BED):
        shutil.copy(path, workdir)
    run_lmp(workdir, "in.replicate_bed", {"in": "consolidated_frictionless_0.data", "out": "bed_9600.data"},
            timed=False)


def profile(workdir, steps, repeat, report):
    scenes = [  # name, grains, variables, ranks
        ("reduced example", 1200, {}, 1),
        ("Table S1 size", 9600, {"full": 1, "kn": 1.16e7, "data": "bed_9600.data"}, 1),
        ("Table S1 size", 9600, {"full": 1, "kn": 1.16e7, "data": "bed_9600.data"}, 2),
    ]
    report.append("## Part 1: cost of each part of the scene\n")
    report.append(f"{steps} steps per run (Table S1 scene: {steps // 4}), median of {repeat} "
                  "interleaved repeats; ratio = loop time / loop time of `granular`.\n")
    report.append("| scene | ranks | variant | loop (s) | µs/step | ns per grain-step per core | ratio to granular |")
    report.append("|---|---|---|---|---|---|---|")
    per_step = {}
    for scene, grains, scene_vars, ranks in scenes:
        n = steps if grains == 1200 else steps // 4
        times = {v: [] for v in VARIANTS}
        for _ in range(repeat):
            for v, (infile, extra) in VARIANTS.items():
                times[v].append(run_lmp(workdir, infile, dict(scene_vars, **extra, run_steps=n), ranks))
        base = statistics.median(times["granular"])
        for v in VARIANTS:
            t = statistics.median(times[v])
            per_step[(scene, ranks, v)] = t / n
            report.append(f"| {scene} | {ranks} | {v} | {t:.3f} | {1e6 * t / n:.1f} | "
                          f"{1e9 * t * ranks / (n * grains):.0f} | {t / base:.2f} |")
        print("\n".join(report[-len(VARIANTS):]), flush=True)
    report.append("\nProjected wall time of Table S1 (Δt = 2.14e-7 s) from the Table S1-sized "
                  "scene's time per step:\n")
    report.append("| ranks | variant | " + " | ".join(STEPS_S1) + " |")
    report.append("|---|---|" + "---|" * len(STEPS_S1))
    for ranks in (1, 2):
        for v in ("wet1", "wet10", "wet10held", "granular"):
            days = [per_step[("Table S1 size", ranks, v)] * n / 86400 for n in STEPS_S1.values()]
            report.append(f"| {ranks} | {v} | " + " | ".join(f"{d:.1f} days" for d in days) + " |")
    report.append("")


def edited(text, old, new):
    """text with old replaced by new; stops if the example no longer contains old."""
    if old not in text:
        sys.exit(f"examples/tidal_shear/in.tidal_shear no longer contains {old!r}")
    return text.replace(old, new)


def every_sweep(workdir, horizon, ranks, report):
    cases = [("every 1 (reference)", {"fluid_every": 1, "interpolate": "step"})]
    cases += [(f"every {n}", {"fluid_every": n, "interpolate": "step"}) for n in (2, 5, 10, 20, 50)]
    cases += [(f"every {n}, interpolate fluid", {"fluid_every": n, "interpolate": "fluid"})
              for n in (10, 50)]
    results = {}
    floor = ("every 1, tol 1e-12 (chaos floor)", {"fluid_every": 1, "interpolate": "step"})
    for name, variables in cases + [floor]:
        run_dir = os.path.join(workdir, re.sub(r"\W+", "_", name))
        os.makedirs(run_dir)
        for f in os.listdir(workdir):
            if f.startswith("in.") or f.endswith(".data"):
                shutil.copy(os.path.join(workdir, f), run_dir)
        if "1e-12" in name:  # the example's fix line gains a tighter tolerance
            src = open(os.path.join(run_dir, "in.tidal_shear")).read()
            src = edited(src, "solver ${solver_args} seepage ${seepage} &",
                         "solver ${solver_args} seepage ${seepage} tol 1e-12 &")
            open(os.path.join(run_dir, "in.tidal_shear"), "w").write(src)
        t = run_lmp(run_dir, "in.tidal_shear", dict(variables, run_steps=horizon, samples=2000), ranks)
        results[name] = (t, read_series(os.path.join(run_dir, "timeseries.txt")))
        print(name, f"{t:.1f} s", flush=True)
    t_ref, ref = results[cases[0][0]]
    amp = 70.0e3
    report.append("## Part 2: error of `every N` on the tidal_shear time series\n")
    report.append(f"{horizon} grain steps on {ranks} MPI rank(s) from the shipped state (t = 0 to "
                  f"{ref['time'][-1]:.3f} s), 2,000 samples per cycle. Errors are the maximum "
                  "over the samples of the difference to `every 1`: top-layer velocity relative "
                  "to the maximum |vx_top| of the reference, displacement relative to the "
                  "reference's final displacement, plate position in grain radii, mean pore "
                  "pressure relative to the forcing amplitude A = 70 kPa.\n")
    report.append("| run | loop (s) | cost / every 1 | vx_top | x_top | z_wall (radii) | p_mean / A |")
    report.append("|---|---|---|---|---|---|---|")
    for name, (t, s) in results.items():
        n = min(len(s["time"]), len(ref["time"]))
        err = lambda key: np.max(np.abs(s[key][:n] - ref[key][:n]))
        report.append(f"| {name} | {t:.1f} | {t / t_ref:.2f} | "
                      f"{err('vx_top') / np.max(np.abs(ref['vx_top'])):.2e} | "
                      f"{err('x_top') / abs(ref['x_top'][-1]):.2e} | {err('z_wall') / 0.01:.2e} | "
                      f"{err('p_mean') / amp:.2e} |")
    print("\n".join(report[-len(results):]), flush=True)
    report.append("")


def balance_ratio(s, m):
    """Largest |fluid balance residual| / allowance over the samples m (none before a solve)."""
    m = m & (s["balance_allowance"] > 0)
    return np.max(np.abs(s["fluid_balance"][m]) / s["balance_allowance"][m]) if m.any() else 0.0


def long_run(workdir, steps, ranks, closed, report):
    if closed:  # no flow through the top either, and a solve converged to round-off
        src = open(os.path.join(workdir, "in.tidal_shear")).read()
        src = edited(src, "top v_ptop ztop v_zwall", "top noflow tol 1e-13")
        open(os.path.join(workdir, "in.tidal_shear"), "w").write(src)
    t = run_lmp(workdir, "in.tidal_shear", {"run_steps": steps}, ranks)
    s = read_series(os.path.join(workdir, "timeseries.txt"))
    values = np.column_stack(list(s.values()))
    cycle = np.floor(s["time"] * run_parameters(workdir)["freq"]).astype(int)
    report.append("## Part 3: a long run" + (" in a closed box (top noflow, tol 1e-13)" if closed else "") + "\n")
    report.append(f"{steps} grain steps of the reduced example (t = 0 to {s['time'][-1]:.3f} s) "
                  f"on {ranks} MPI rank(s): loop time {t:.0f} s, {len(s['time'])} samples, "
                  f"all finite: {bool(np.all(np.isfinite(values)))}.\n")
    report.append("| forcing cycle | max kinetic energy (J) | plate z min–max (m) | max abs(p_mean) / A | max solver iterations | max abs(balance residual) / allowance |")
    report.append("|---|---|---|---|---|---|")
    for c in np.unique(cycle):
        m = cycle == c
        report.append(f"| {c} | {np.max(s['ke'][m]):.3e} | {np.min(s['z_wall'][m]):.4f}–"
                      f"{np.max(s['z_wall'][m]):.4f} | {np.max(np.abs(s['p_mean'][m])) / 70e3:.3f} | "
                      f"{np.max(s['solver_iters'][m]):.0f} | "
                      f"{balance_ratio(s, m):.1e} |")
    stored = np.max(np.abs(s["fluid_stored"]))
    report.append(f"\nAt the end: balance residual {s['fluid_balance'][-1]:.3e} m³, "
                  f"{abs(s['fluid_balance'][-1]) / stored:.1e} of the largest stored change "
                  f"({stored:.3e} m³).\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--part", choices=["profile", "every", "long", "all"], default="all")
    ap.add_argument("--long-steps", type=int, default=1000000)
    ap.add_argument("--closed", action="store_true", help="part long in a closed box")
    ap.add_argument("--ranks", type=int, default=2, help="MPI ranks of parts every and long")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--steps", type=int, default=10000)
    ap.add_argument("--horizon", type=int, default=47000)
    ap.add_argument("--out", default=os.path.join(out_dir(HERE), "tidal_profile_results.md"))
    args = ap.parse_args()
    report = ["# bench/tidal_profile/tidal_profile.py results\n", f"`{' '.join(sys.argv[1:])}`, "
              f"{os.cpu_count()} cores, load average before the run "
              f"{os.getloadavg()[0]:.2f}.\n"]
    with tempfile.TemporaryDirectory() as workdir:
        prepare(workdir)
        if args.part in ("profile", "all"):
            profile(workdir, args.steps, args.repeat, report)
        if args.part in ("every", "all"):
            every_sweep(workdir, args.horizon, args.ranks, report)
        if args.part == "long":
            long_run(workdir, args.long_steps, args.ranks, args.closed, report)
    open(args.out, "w").write("\n".join(report) + "\n")
    print("wrote", args.out)


if __name__ == "__main__":
    main()
