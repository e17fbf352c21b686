#!/usr/bin/python3
"""fix darcy/pressure: accuracy against run time, and its share of a Table S1 step.

Part 1 (accuracy): grain-free runs of in.darcy_accuracy through lmp + the plugin,
  against the analytic solutions, sweeping one setting at a time around a base case:
  grid layers nz, time step dt, `every N` (fluid step N*dt at a fixed LAMMPS dt) and the
  relative solver tolerance `tol`.
    Terzaghi: p(z,0) = 1, drained top z = H = 1, no-flow bottom, D = 1:
      p = sum_m (-1)^m 4/((2m+1) pi) cos(M z) exp(-M^2 t),  M = (2m+1) pi / 2
      error = max over the profiles at t = 0.05, 0.1, 0.15, 0.2 and the layers of |p - exact|
    Sinusoidal top: p_top = sin(omega t), omega = 2 (skin depth sqrt(2D/omega) = H), p = 0
      at t = 0; after two periods the start-up transient is below 1e-6 and
      p = Im[cosh(kappa z)/cosh(kappa H) e^{i omega t}], kappa = sqrt(i omega / D)
      error = max over 16 (8 at n < 192) profiles in the third period and the layers
  Errors are relative to the pressure scale (1). Time: LAMMPS' loop time (median).
Part 2 (share): two 9,600-grain scenes, grid 6x3x6, pair linear/coulomb, each run
  without the fix, with `every 1` and with `every 10`, interleaved; share of the fix =
  (t_fix - t_none) / t_fix. "columns": in.darcy_share (grains stacked in columns,
  2 contacts a grain: an upper bound of the share); "bed": bench/common/in.darcy_share_bed (the
  consolidated packing of examples/tidal_shear replicated 2x2x2 to the Table S1 box).
  Time = loop CPU time (LAMMPS' loop time x its "% CPU use"), less sensitive than wall
  time to other jobs on a shared machine. With --baseline DIR also the plugin in DIR
  (before/after). With --instructions also callgrind instruction counts per grain and
  step (load-independent; 100 steps each, about a minute a run).

Usage (after building the plugin, e.g. into build-bench/plugin):
    source scripts/env.sh
    /usr/bin/python3 bench/darcy/darcy_bench.py [--plugin build-bench/plugin] [--baseline DIR]
        [--repeat 3] [--part accuracy|share|all]
Writes darcy_bench_results.md (--out) and darcy_bench.png beside it. The short setting
(bench/smoke.py): each sweep's first value.
"""
import argparse, cmath, math, os, re, statistics, subprocess, sys, tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import COMMON, EXAMPLE, REPO, out_dir, short    # noqa: E402
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMP_NUM_THREADS="1")
PHI, KC = 0.4, 2.25
D = KC * PHI ** 3 / (1 - PHI) ** 2 / PHI      # k / (beta phi mu) with beta = mu = 1: 1.0
OMEGA = 2.0
TEND_TERZAGHI = 0.2
PERIODS = 3


def run_lmp(plugin, infile, variables, workdir, wrapper=()):
    cmd = list(wrapper) + ["lmp", "-in", infile, "-log", "none", "-echo", "none"]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    env = dict(ENV, LD_LIBRARY_PATH=os.path.abspath(plugin) + ":" + ENV.get("LD_LIBRARY_PATH", ""))
    out = subprocess.run(cmd, env=env, capture_output=True, text=True, cwd=workdir)
    loops = re.findall(r"Loop time of ([0-9.eE+-]+)", out.stdout)
    if out.returncode != 0 or not loops:
        sys.exit("failed: " + " ".join(cmd) + "\n" + out.stdout[-2000:] + out.stderr[-2000:])
    return float(loops[-1]), out.stdout


def loop_cpu_time(out):
    """CPU time of the last run's loop: wall time x LAMMPS' "% CPU use"."""
    wall = float(re.findall(r"Loop time of ([0-9.eE+-]+)", out)[-1])
    return wall * float(re.findall(r"([0-9.]+)% CPU use", out)[-1]) / 100


def read_profiles(path):
    """[(time, z array, p array)] from a fix darcy/pressure profile file."""
    blocks, lines = [], [l.split() for l in open(path) if not l.startswith("#")]
    i = 0
    while i < len(lines):
        _, time, nz, _ = lines[i]
        rows = np.array(lines[i + 1:i + 1 + int(nz)], dtype=float)
        blocks.append((float(time), rows[:, 1], rows[:, 2]))
        i += 1 + int(nz)
    return blocks


def terzaghi(z, t, terms=400):
    m = np.arange(terms)[:, None]
    M = (2 * m + 1) * math.pi / 2
    return np.sum((-1.0) ** m * 4 / ((2 * m + 1) * math.pi) * np.cos(M * z) *
                  np.exp(-M ** 2 * D * t), axis=0)


def tidal(z, t):
    kappa = cmath.sqrt(1j * OMEGA / D)
    return np.array([(cmath.cosh(kappa * zz) / cmath.cosh(kappa) * cmath.exp(1j * OMEGA * t)).imag
                     for zz in z])


# ---- part 1 -----------------------------------------------------------------------------
# base: nz 48, 400 fluid steps to t = 0.2 (Terzaghi) / 192 a period (tide), every 1, tol 1e-10
# (n = 400 LAMMPS steps to t = 0.2, or 192 a period; the fluid steps every `every` of them)
BASE = {1: dict(nz=48, n=400, every=1, tol=1e-10), 2: dict(nz=48, n=192, every=1, tol=1e-10)}
SWEEPS = {1: [("nz", [6, 12, 24, 48, 96, 192]),
              ("dt", [25, 50, 100, 200, 400, 800, 1600]),
              ("every", [1, 2, 4, 5, 10, 20]),
              ("tol", [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12])],
          2: [("nz", [6, 12, 24, 48, 96]),
              ("dt", [32, 64, 96, 192, 384, 768]),
              ("every", [1, 2, 3, 4, 6, 12]),
              ("tol", [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12])]}


def case_settings(case, nz, n, every, tol):
    """lmp variables; n = LAMMPS steps to t = 0.2 (Terzaghi) or a period (tide)."""
    if case == 1:
        return dict(case=1, nz=nz, dt=repr(TEND_TERZAGHI / n), steps=n, every=every, tol=tol,
                    pevery=n // 4)
    return dict(case=2, nz=nz, dt=repr(2 * math.pi / OMEGA / n), steps=PERIODS * n, every=every,
                tol=tol, pevery=n // 16 if n >= 192 else n // 8, omega=OMEGA)


def error_of(case, profile):
    err = 0.0
    for t, z, p in read_profiles(profile):
        if case == 1 and t > 1e-12:
            err = max(err, np.max(np.abs(p - terzaghi(z, t))))
        if case == 2 and t >= (PERIODS - 1) * 2 * math.pi / OMEGA * (1 - 1e-9):
            err = max(err, np.max(np.abs(p - tidal(z, t))))
    return err


def accuracy(plugin, repeat, workdir):
    configs = []
    for case in (1, 2):
        for name, values in SWEEPS[case]:
            for v in short(values, values[:1]):
                s = dict(BASE[case])
                s["n" if name == "dt" else name] = v
                configs.append((case, name, v, s))
    times = {i: [] for i in range(len(configs))}
    info = {}
    for r in range(repeat):          # interleaved repeats: load drift hits all alike
        for i, (case, name, v, s) in enumerate(configs):
            profile = os.path.join(workdir, f"acc_{i}.profile")
            var = case_settings(case, s["nz"], s["n"], s["every"], s["tol"])
            var["profile"] = profile
            t, out = run_lmp(plugin, os.path.join(HERE, "in.darcy_accuracy"), var, workdir)
            times[i].append(t)
            if r == 0:
                last = [l.split() for l in out.splitlines() if re.match(r"^\s+\d+\s+\S+\s+\S+\s+\S+\s*$", l)]
                info[i] = (error_of(case, profile), var, int(float(last[-1][2])))
        print(f"accuracy: repeat {r + 1}/{repeat} done", flush=True)
    rows = []
    for i, (case, name, v, s) in enumerate(configs):
        err, var, iters = info[i]
        fluid_steps = var["steps"] // var["every"]
        rows.append(dict(case="Terzaghi" if case == 1 else "sinusoidal top", sweep=name,
                         nz=s["nz"], dt_fluid=float(var["dt"]) * var["every"], every=var["every"],
                         tol=s["tol"], fluid_steps=fluid_steps, iters=iters, error=err,
                         seconds=statistics.median(times[i])))
    return rows


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, case in zip(axes, ("Terzaghi", "sinusoidal top")):
        for name, marker in (("nz", "o"), ("dt", "s"), ("every", "^"), ("tol", "x")):
            sel = [r for r in rows if r["case"] == case and r["sweep"] == name]
            ax.loglog([r["seconds"] for r in sel], [max(r["error"], 1e-16) for r in sel],
                      marker=marker, label=f"sweep {name}")
        ax.set_xlabel("loop time (s)")
        ax.set_ylabel("max |p - exact| / pressure scale")
        ax.set_title(f"fix darcy/pressure, {case} (grid 6x3xnz)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def accuracy_table(rows):
    out = ["| case | sweep | nz | fluid dt | every | tol | fluid steps | CG its (last) | max error | loop time (s) |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['case']} | {r['sweep']} | {r['nz']} | {r['dt_fluid']:.3g} | {r['every']} | "
                   f"{r['tol']:.0e} | {r['fluid_steps']} | {r['iters']} | {r['error']:.2e} | "
                   f"{r['seconds']:.3f} |")
    return out


# ---- part 2 -----------------------------------------------------------------------------
def breakdown(out):
    """Pair and Modify times of the last run's breakdown."""
    tail = out[out.rfind("Loop time of"):]
    get = lambda k: float(re.search(rf"^{k}\s+\|\s+([0-9.eE+-]+)", tail, re.M).group(1))
    return get("Pair"), get("Modify")


SCENES = (("columns", os.path.join(HERE, "in.darcy_share")),
          ("bed", os.path.join(COMMON, "in.darcy_share_bed")))
EXAMPLES = EXAMPLE
CASES = (dict(fluid=0), dict(fluid=1, every=1), dict(fluid=1, every=10))


def case_name(var):
    return "none" if not var["fluid"] else f"every {var['every']}"


def share(plugins, repeat, steps, workdir):
    configs = [(scene, infile, label, plugin, var) for scene, infile in SCENES
               for label, plugin in plugins for var in CASES]
    res = {i: [] for i in range(len(configs))}
    for r in range(repeat):          # interleaved repeats: load drift hits all alike
        for i, (scene, infile, label, plugin, var) in enumerate(configs):
            _, out = run_lmp(plugin, infile, dict(var, steps=steps, examples=EXAMPLES), workdir)
            res[i].append((loop_cpu_time(out),) + breakdown(out))
        print(f"share: repeat {r + 1}/{repeat} done", flush=True)
    med = {i: tuple(statistics.median(x[k] for x in res[i]) for k in range(3)) for i in res}
    lines = [f"{steps} steps, median of {repeat} interleaved repeats, 1 MPI rank; loop CPU time.", "",
             "| scene | plugin | fix | loop CPU (s) | CPU ms/step | Pair wall (s) | Modify wall (s) | fix share |",
             "|---|---|---|---|---|---|---|---|"]
    summary = {}
    for i, (scene, infile, label, plugin, var) in enumerate(configs):
        t, pair, modify = med[i]
        base = med[i - (i % len(CASES))][0]
        sh = (t - base) / t if var["fluid"] else None
        summary[(scene, label, case_name(var))] = t
        lines.append(f"| {scene} | {label} | {case_name(var)} | {t:.3f} | {1e3 * t / steps:.3f} | "
                     f"{pair:.3f} | {modify:.3f} | " + (f"{100 * sh:.1f}% |" if sh is not None else "- |"))
    if len(plugins) == 2:
        (a, _), (b, _) = plugins
        lines += ["", f"| scene | fix | fix time {a} / {b} |", "|---|---|---|"]
        for scene, _ in SCENES:
            for what in ("every 1", "every 10"):
                ca = summary[(scene, a, what)] - summary[(scene, a, "none")]
                cb = summary[(scene, b, what)] - summary[(scene, b, "none")]
                lines.append(f"| {scene} | {what} | {ca / cb:.2f} |")
    return lines


CALLGRIND_FUNCTIONS = ("Verlet::run", "FixDarcyPressure::post_force", "FixDarcyPressure::deposit_grains",
                       "FixDarcyPressure::apply_fluid_force", "PairLinearCoulomb::compute")


def instructions(plugins, workdir, steps=100, grains=9600):
    """callgrind instruction counts per grain and step (inclusive) of the main functions."""
    lines = [f"callgrind, instructions per grain and step (inclusive), over {steps} + 20 steps and 2 setups.", "",
             "| scene | plugin | fix | whole step | fix | deposit | force | pair | fix share |",
             "|---|---|---|---|---|---|---|---|---|"]
    for scene, infile in SCENES:
        for label, plugin in plugins:
            whole_none = None
            for var in CASES:
                cg = os.path.join(workdir, "callgrind.out")
                run_lmp(plugin, infile, dict(var, steps=steps, examples=EXAMPLES), workdir,
                        wrapper=("valgrind", "--tool=callgrind", "--callgrind-out-file=" + cg))
                text = subprocess.run(["callgrind_annotate", "--inclusive=yes", cg], capture_output=True,
                                      text=True).stdout
                count = {}
                for name in CALLGRIND_FUNCTIONS:
                    m = re.search(r"^\s*([\d,]+) .*?" + re.escape(name) + r"\(", text, re.M)
                    count[name] = int(m.group(1).replace(",", "")) / (steps + 22) / grains if m else 0.0
                whole = count["Verlet::run"]
                if not var["fluid"]:
                    whole_none = whole
                sh = f"{100 * (whole - whole_none) / whole:.1f}%" if var["fluid"] else "-"
                lines.append(f"| {scene} | {label} | {case_name(var)} | {whole:.0f} | "
                             f"{count['FixDarcyPressure::post_force']:.0f} | "
                             f"{count['FixDarcyPressure::deposit_grains']:.0f} | "
                             f"{count['FixDarcyPressure::apply_fluid_force']:.0f} | "
                             f"{count['PairLinearCoulomb::compute']:.0f} | {sh} |")
            print(f"instructions: {scene} {label} done", flush=True)
    return lines


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", default=os.path.join(REPO, "build-bench", "plugin"))
    ap.add_argument("--baseline", help="plugin dir of a previous build to compare (share part)")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--steps", type=int, default=300, help="steps of the share runs")
    ap.add_argument("--part", choices=("accuracy", "share", "all"), default="all")
    ap.add_argument("--instructions", action="store_true", help="share part: callgrind counts too")
    ap.add_argument("--out", default=os.path.join(out_dir(HERE), "darcy_bench_results.md"))
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as work:
        text = ["# fix darcy/pressure benchmark (generated by bench/darcy/darcy_bench.py)", ""]
        if args.part in ("accuracy", "all"):
            rows = accuracy(args.plugin, args.repeat, work)
            plot(rows, os.path.join(os.path.dirname(os.path.abspath(args.out)), "darcy_bench.png"))
            text += ["## Error against run time (grain-free, grid 6 x 3 x nz)", "",
                     "Plot: darcy_bench.png", ""] + accuracy_table(rows) + [""]
        if args.part in ("share", "all"):
            plugins = [("after", args.plugin)]
            if args.baseline:
                plugins = [("before", args.baseline)] + plugins
            text += ["## Share of the step, 9,600 grains, grid 6 x 3 x 6", ""]
            text += share(plugins, args.repeat, args.steps, work) + [""]
            if args.instructions:
                text += instructions(plugins, work) + [""]
    open(args.out, "w").write("\n".join(text))
    print("\n".join(text))


if __name__ == "__main__":
    main()
