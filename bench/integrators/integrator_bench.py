#!/usr/bin/python3
"""Grain integrators: error against cost, energy drift, and the stability map.

Compares LAMMPS' fix nve/sphere (velocity Verlet), fix nve/sphere/ty3 (sphere's Taylor step)
and fix nve/sphere/ty3 corrector yes, with pair linear/coulomb (no damping), over
eps = dt*sqrt(kn/m). Writes integrator_*.png and integrator_results.md into --out
(default: this folder); RESULTS.md beside it discusses them. Usage:
    source scripts/env.sh && nice /usr/bin/python3 bench/integrators/integrator_bench.py [--quick]
The short setting (bench/smoke.py): --quick with two eps, two integrators and every run a few
hundred steps.
"""
import argparse, math, os, re, shutil, statistics, subprocess, sys, tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import SMOKE, out_dir, short  # noqa: E402
from porewater_analysis.dump import read_dump  # noqa: E402

INTEGRATORS = short([("nve/sphere", "nve/sphere"), ("nve/sphere/ty3", "nve/sphere/ty3"),
                     ("ty3 corrector yes", "nve/sphere/ty3 corrector yes")],
                    [("nve/sphere", "nve/sphere"), ("nve/sphere/ty3", "nve/sphere/ty3")])
KN_PAIR, KN_GAS = 1.0e4, 2000.0    # stiffness of the two-grain and gas inputs; m = 1
# the errors a run that blows up stops with
BLOWUP = ("overlap_limit", "Out of range atoms", "Lost atoms", "Neighbor list overflow")
WORK = tempfile.mkdtemp(prefix="pw_integrator_")


def lmp(inp, **var):
    """Runs bench/integrators/<inp> with -var name value; returns (thermo rows, loop time, whether a
    blow-up error stopped it, e.g. the overlap_limit of pair linear/coulomb)."""
    # stdout line-buffered: the message of an error that aborts MPI is not lost
    cmd = ["stdbuf", "-oL", "lmp", "-in", os.path.join(HERE, inp), "-log", "none", "-echo", "none"]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    out = subprocess.run(cmd, capture_output=True, text=True, cwd=WORK)
    stopped = out.returncode != 0 or "ERROR" in out.stdout
    if stopped and not any(s in out.stdout for s in BLOWUP):
        sys.exit("failed: " + " ".join(cmd) + "\n" + out.stdout[-3000:] + out.stderr[-2000:])
    rows, loop, header = [], 0.0, None
    for line in out.stdout.splitlines():
        w = line.split()
        if w and w[0] == "Step":
            header = w
        elif header and len(w) == len(header) and re.match(r"^\d+$", w[0]):
            rows.append([float(s) for s in w])
        elif line.startswith("Loop time of"):
            loop += float(line.split()[3])
            header = None
    return np.array(rows), loop, stopped


STATE = ("xu", "yu", "zu", "vx", "vy", "vz", "omegax", "omegay", "omegaz")


def read_state(path):
    """id-sorted array of xu yu zu vx vy vz omegax omegay omegaz"""
    _, columns = read_dump(path)
    return np.column_stack([columns[n] for n in STATE])


# ------------------------------------------------------------------------------------------
# accuracy: two grains and a dense gas, against the exact solution or a tiny-step reference

def pair_state(fixargs, eps, b, mu, t_end):
    """final state of the two-grain collision, positions moved on freely to t_end (the grains
    have separated, so that is exact) to compare runs whose step counts round differently"""
    dt = eps / math.sqrt(KN_PAIR)
    steps = math.ceil(t_end / dt - 1e-9)
    dump = os.path.join(WORK, "pair.dump")
    lmp("in.integrator_pair", fixargs=fixargs, dt=repr(dt), steps=steps, b=b, mu=mu, lx=10,
        every=steps, dump=dump)
    s = read_state(dump)
    s[:, 0:3] += s[:, 3:6] * (t_end - steps * dt)
    return s, steps


def head_on_errors(fixargs, eps):
    """|x2 - exact| (diameters) and |v2 - v_exact|/v of the frictionless head-on collision:
    contact at t0 = 0.1 for T_c = pi/sqrt(2 kn), rebound velocity exactly the reverse"""
    t_end, t0, tc = 0.2, 0.1, math.pi / math.sqrt(2 * KN_PAIR)
    s, steps = pair_state(fixargs, eps, 0, 0, t_end)
    x2 = 0.5 + 0.5 * (t_end - t0 - tc)
    return abs(s[1, 0] - x2), abs(s[1, 3] - 0.5) / 0.5, steps


def oblique_errors(state, ref):
    """largest position error (diameters) and largest velocity error over v, r*omega, per v"""
    return (np.abs(state[:, 0:3] - ref[:, 0:3]).max(),
            max(np.abs(state[:, 3:6] - ref[:, 3:6]).max(),
                0.5 * np.abs(state[:, 6:9] - ref[:, 6:9]).max()) / 0.5)


def gas_state(fixargs, steps, horizon, mu, nside=7):
    dump = os.path.join(WORK, "gas.dump")
    lmp("in.integrator_gas", fixargs=fixargs, dt=repr(horizon / steps), steps=steps, nside=nside,
        mu=mu, every=steps, dump=dump)
    return read_state(dump)


def gas_errors(state, ref):
    """rms position error (diameters) and rms velocity error per rms speed"""
    dx = np.sqrt(((state[:, 0:3] - ref[:, 0:3]) ** 2).sum(1).mean())
    dv = np.sqrt(((state[:, 3:6] - ref[:, 3:6]) ** 2).sum(1).mean())
    return dx, dv / np.sqrt((ref[:, 3:6] ** 2).sum(1).mean())


def order(eps, err):
    """least-squares slope of log err against log eps"""
    return np.polyfit(np.log(eps), np.log(err), 1)[0]


# ------------------------------------------------------------------------------------------
# stability: does the energy stay bounded for `steps` steps?

def energy_series(scene, fixargs, eps, steps):
    """total energy per thermo sample and its scale, or None when the run stopped"""
    every = max(steps // 100, 1)
    if scene == "bounce":    # two grains colliding head-on again and again (box length 2.5)
        r = lmp("in.integrator_pair", fixargs=fixargs, dt=repr(eps / math.sqrt(KN_PAIR)),
                steps=steps, b=0, mu=0, lx=2.5, every=every, dump=os.path.join(WORK, "d"))
    elif scene == "gas":     # frictionless dense gas, 125 grains
        r = lmp("in.integrator_gas", fixargs=fixargs, dt=repr(eps / math.sqrt(KN_GAS)),
                steps=steps, nside=5, mu=0, every=every, dump=os.path.join(WORK, "d"))
    else:                    # the frictional bed at rest under gravity
        r = lmp("in.integrator_bed", fixargs=fixargs, dt=repr(eps / math.sqrt(KN_PAIR)),
                steps=steps, every=every, data=os.path.join(WORK, "bed.data"))
    rows, _, stopped = r
    if stopped:
        return None
    e = rows[:, 1:].sum(1)    # ke + erot + pe (+ m g z of the bed, g = m = 1)
    scale = rows[0, 3] if scene == "bed" else e[0]    # bed: its elastic energy at rest
    return rows[:, 0], e, scale


def stability(scene, fixargs, eps, steps):
    """'stopped' (a LAMMPS error: overlap_limit), 'rises' (energy up by more than 10 % of its
    scale at some sample; a loss is not an instability: the corrector and friction
    dissipate) or 'ok'"""
    s = energy_series(scene, fixargs, eps, steps)
    if s is None or not np.all(np.isfinite(s[1])):
        return "stopped"
    return "rises" if ((s[1] - s[1][0]) / s[2]).max() > 0.1 else "ok"


def linear_amplification(h, scheme):
    """spectral radius of one step on the harmonic oscillator a = -x at h = omega*dt, state
    (x, v, a_prev), as the fixes do it (taylor3.h)"""
    def step(s):
        x, v, ap = s
        a = -x
        if scheme == "nve/sphere":
            vh = v + 0.5 * h * a
            xn = x + h * vh
            return np.array([xn, vh - 0.5 * h * xn, a])
        xn = x + h * (v + h * (0.5 * a + (a - ap) / 6))
        vn = v + h * (a + 0.5 * (a - ap))
        if scheme != "nve/sphere/ty3":
            vn += 5 / 12 * h * (-xn - a - (a - ap))
        return np.array([xn, vn, a])
    return max(abs(np.linalg.eigvals(np.column_stack([step(e) for e in np.eye(3)]))))


def linear_limit(scheme):
    """largest h with spectral radius <= 1 + 1e-12"""
    lo, hi = 0.01, 4.0
    if linear_amplification(lo, scheme) > 1 + 1e-12:
        return 0.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if linear_amplification(mid, scheme) <= 1 + 1e-12 else (lo, mid)
    return lo


# ------------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="fewer eps, shorter runs (~2 min)")
    ap.add_argument("--out", default=out_dir(HERE))
    args = ap.parse_args()
    q = args.quick or bool(SMOKE)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    eps_list = [0.01, 0.02, 0.05, 0.1, 0.2] if q else [0.01, 0.014, 0.02, 0.03, 0.05, 0.07,
                                                       0.1, 0.14, 0.2]
    eps_list = short(eps_list, [0.07, 0.2])
    gas_ref = short((20000, 10000), (400, 200))    # steps of the gas' references
    md = ["# integrator_bench.py results" + (" (--quick)" if q else ""), ""]
    lines = {}    # (scene, integrator) -> (eps, steps per unit time, err_x, err_v)

    def table(title, scene):
        md.extend([f"### {title}", "", "| integrator | " + " | ".join(f"eps {e:g}" for e in
                   eps_list) + " | order |", "|---" * (len(eps_list) + 2) + "|"])
        for name, _ in INTEGRATORS:
            e, _, ex, ev = lines[(scene, name)]
            for label, err in (("x", ex), ("v", ev)):
                md.append(f"| {name} ({label}) | " + " | ".join(f"{v:.2e}" for v in err) +
                          f" | {order(e, err):.2f} |")
        md.append("")

    # cost per step, interleaved (frictional gas of 343 grains at eps 0.07)
    repeat, nsteps = short((1, 1000) if q else (3, 3000), (1, 100))
    times = {name: [] for name, _ in INTEGRATORS}
    for _ in range(repeat):
        for name, fixargs in INTEGRATORS:
            times[name].append(lmp("in.integrator_gas", fixargs=fixargs,
                                   dt=repr(0.07 / math.sqrt(KN_GAS)), steps=nsteps, nside=7,
                                   mu=0.5, every=nsteps, dump=os.path.join(WORK, "d"))[1])
    per_step = {n: statistics.median(t) / nsteps for n, t in times.items()}
    base = per_step["nve/sphere"]
    md += ["## Cost per step (343-grain frictional gas, eps 0.07, median of "
           f"{repeat} interleaved runs of {nsteps} steps, shared machine)", "",
           "| integrator | loop time per step (us) | relative to nve/sphere |", "|---|---|---|"]
    md += [f"| {n} | {1e6 * c:.1f} | {c / base:.3f} |" for n, c in per_step.items()] + [""]
    print("\n".join(md[-6:]), flush=True)

    # (a) head-on frictionless collision against the exact solution
    for name, fixargs in INTEGRATORS:
        r = [head_on_errors(fixargs, e) for e in eps_list]
        lines[("head-on", name)] = (np.array(eps_list), None, np.array([v[0] for v in r]),
                                    np.array([v[1] for v in r]))
    table("(a) head-on frictionless collision, exact solution (t = 0.2, after the rebound)",
          "head-on")
    # oblique collision with friction (b = 0.4 d, mu = 0.5, kt = kn) against a tiny step
    ref_eps = short(("1e-4", "2e-4"), ("1e-3", "2e-3"))
    ref, _ = pair_state("nve/sphere", float(ref_eps[0]), 0.4, 0.5, 0.3)
    ref2, _ = pair_state("nve/sphere", float(ref_eps[1]), 0.4, 0.5, 0.3)
    md.append("Reference of the oblique case: nve/sphere at eps %s; against eps %s: "
              "|dx| %%.1e, |dv|/v %%.1e." % ref_eps % oblique_errors(ref2, ref))
    md.append("")
    for name, fixargs in INTEGRATORS:
        r = [oblique_errors(pair_state(fixargs, e, 0.4, 0.5, 0.3)[0], ref) for e in eps_list]
        lines[("oblique", name)] = (np.array(eps_list), None, np.array([v[0] for v in r]),
                                    np.array([v[1] for v in r]))
    table("(a') oblique collision with friction (b = 0.4 d, mu = 0.5), reference eps %s" % ref_eps[0],
          "oblique")
    print("\n".join(md), flush=True)

    # (b) dense gas (343 grains), horizon 10/omega0 (about 4.5 pair contact times)
    w0 = math.sqrt(KN_GAS)
    horizon = 10.0 / w0
    for mu in (0.0, 0.5):
        scene = f"gas mu={mu:g}"
        ref = gas_state("nve/sphere", gas_ref[0], horizon, mu)
        ref2 = gas_state("nve/sphere", gas_ref[1], horizon, mu)
        md.append(f"Reference of the gas, mu = {mu:g}: nve/sphere at eps 5e-4; against eps 1e-3: "
                  "rms |dx| %.1e, rms |dv|/v_rms %.1e." % gas_errors(ref2, ref))
        md.append("")
        for name, fixargs in INTEGRATORS:
            steps = [round(10.0 / e) for e in eps_list]
            r = [gas_errors(gas_state(fixargs, n, horizon, mu), ref) for n in steps]
            lines[(scene, name)] = (10.0 / np.array(steps), None, np.array([v[0] for v in r]),
                                    np.array([v[1] for v in r]))
        table(f"(b) dense gas of 343 grains, mu = {mu:g}, at t = 10/omega0 (rms errors)", scene)
        print("\n".join(md[-8:]), flush=True)

    # chaos: the same error at longer horizons (nve/sphere, eps 0.07 and 0.035)
    if not q:
        md += ["### Chaos: nve/sphere on the frictional gas at longer horizons", "",
               "| horizon (1/omega0) | rms dx at eps 0.07 | at eps 0.035 | ratio (4 = order 2) |",
               "|---|---|---|---|"]
        for k in (1, 2, 4, 8):
            h = k * horizon
            ref = gas_state("nve/sphere", 20000 * k, h, 0.5)
            e1 = gas_errors(gas_state("nve/sphere", round(10 * k / 0.07), h, 0.5), ref)[0]
            e2 = gas_errors(gas_state("nve/sphere", round(10 * k / 0.035), h, 0.5), ref)[0]
            md.append(f"| {10 * k} | {e1:.2e} | {e2:.2e} | {e1 / e2:.2f} |")
        md.append("")
        print("\n".join(md[-8:]), flush=True)

    # error-vs-eps and error-vs-cost plots
    scenes = ["head-on", "oblique", "gas mu=0", "gas mu=0.5"]
    fig, axs = plt.subplots(2, 4, figsize=(17, 7.5))
    for col, scene in enumerate(scenes):
        for name, _ in INTEGRATORS:
            e, _, ex, ev = lines[(scene, name)]
            cost = per_step[name] / base / e    # Verlet-step equivalents per 1/sqrt(kn/m)
            axs[0, col].loglog(e, ev, "o-", label=name)
            axs[1, col].loglog(cost, ev, "o-", label=name)
        axs[0, col].set(title=scene, xlabel="eps = dt sqrt(kn/m)", ylabel="velocity error")
        axs[1, col].set(xlabel="cost: nve/sphere steps per 1/sqrt(kn/m)",
                        ylabel="velocity error")
        e = np.array(eps_list)
        axs[0, col].loglog(e, axs[0, col].lines[0].get_ydata()[-1] * (e / e[-1]) ** 2, "k:",
                           label="slope 2")
        axs[0, col].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "integrator_error.png"), dpi=90)

    # (c) energy drift of the frictionless gas (216 grains)
    nlong = short(20000 if q else 100000, 400)
    drift_eps = [0.07] if q else [0.07, 0.14]
    fig, axs = plt.subplots(1, len(drift_eps), figsize=(7 * len(drift_eps), 4.5), squeeze=False)
    md += [f"## (c) Energy drift, frictionless gas of 216 grains, {nlong} steps", "",
           "| integrator | eps | max abs(E-E0)/E0 | (E_end-E0)/E0 | loop time (s) |",
           "|---|---|---|---|---|"]
    for k, eps in enumerate(drift_eps):
        for name, fixargs in INTEGRATORS:
            rows, loop, stopped = lmp("in.integrator_gas", fixargs=fixargs, dt=repr(eps / w0),
                                      steps=nlong, nside=6, mu=0, every=nlong // 200,
                                      dump=os.path.join(WORK, "d"))
            e = rows[:, 1:].sum(1)
            rel = (e - e[0]) / e[0]
            axs[0, k].semilogy(rows[:, 0], np.abs(rel), label=name)
            end = f"stopped (overlap_limit) after step {rows[-1, 0]:.0f}" if stopped else \
                f"{rel[-1]:.2e}"
            md.append(f"| {name} | {eps:g} | {np.abs(rel).max():.2e} | {end} | " +
                      ("- |" if stopped else f"{loop:.1f} |"))
            print(md[-1], flush=True)
        axs[0, k].set(title=f"frictionless gas, eps {eps:g}", xlabel="step",
                      ylabel="|E - E0|/E0", ylim=(1e-6, None))
        axs[0, k].legend(fontsize=8)
    md.append("")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "integrator_drift.png"), dpi=90)

    # stability map: a scan of eps (stability need not be monotone in eps: see the bounce)
    lmp("in.integrator_bed_prep", data=os.path.join(WORK, "bed.data"))
    nmap = short(5000 if q else 20000, 200)
    grid = short([0.03, 0.07, 0.14, 0.3, 0.7, 1.4, 3.0] if q else
                 [0.02, 0.03, 0.05, 0.07, 0.1, 0.14, 0.2, 0.3, 0.5, 0.7, 1.0, 1.4, 2.0, 3.0],
                 [0.07])
    scenes = ("bounce", "gas", "bed")
    titles = {"bounce": "two-grain bounce", "gas": "frictionless gas (125)",
              "bed": "frictional bed under gravity (325 + 36 fixed)"}
    smap = {(n, sc): [stability(sc, fa, e, nmap) for e in grid]
            for n, fa in INTEGRATORS for sc in scenes}
    md += [f"## Stability map: eps scan, {nmap} steps per run", "",
           "Largest eps below the first failure (energy up by more than 10 %, or the run "
           "stopped by overlap_limit), and the eps above it (r: energy rises, s: stopped, "
           "o: ok again).",
           "", "| integrator | linear limit of omega dt | " + " | ".join(titles[sc] for sc in
                                                                 scenes) + " |",
           "|---|---|---|---|---|"]
    limits = {}
    for name, _ in INTEGRATORS:
        cells = []
        for sc in scenes:
            st = smap[(name, sc)]
            first = next((k for k, v in enumerate(st) if v != "ok"), len(grid))
            limits[(name, sc)] = grid[first - 1] if first > 0 else 0.0
            above = " ".join(f"{e:g}{v[0]}" for e, v in zip(grid[first:], st[first:]))
            cells.append(f"**{limits[(name, sc)]:g}**; " + (above or "none fails"))
        lim = linear_limit(name)
        md.append(f"| {name} | {lim:.3f} | " if lim > 0 else f"| {name} | none | ")
        md[-1] += " | ".join(cells) + " |"
        print(md[-1], flush=True)
    fig, ax = plt.subplots(figsize=(9, 4))
    colour = {"ok": 0, "rises": 1, "stopped": 2}
    rows = [(f"{n} / {sc}", [colour[v] for v in smap[(n, sc)]]) for sc in scenes
            for n, _ in INTEGRATORS]
    ax.imshow([r[1] for r in rows], cmap=matplotlib.colors.ListedColormap(
        ["#4c9a4c", "#e0a030", "#c03030"]), vmin=0, vmax=2, aspect="auto")
    ax.set_yticks(range(len(rows)), [r[0] for r in rows], fontsize=7)
    ax.set_xticks(range(len(grid)), [f"{e:g}" for e in grid], fontsize=7)
    ax.axvline(grid.index(0.07), color="k", ls=":")
    ax.set_xlabel("eps = dt sqrt(kn/m)")
    ax.set_title(f"green: energy within +10 % for {nmap} steps; orange: rises more; "
                 "red: stopped (overlap_limit)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "integrator_stability.png"), dpi=90)
    md += ["", "Linear growth per step of the harmonic oscillator (spectral radius - 1):", "",
           "| omega dt | " + " | ".join(n for n, _ in INTEGRATORS) + " |", "|---|---|---|---|"]
    for h in (0.05, 0.1, 0.2, 0.5, 1.0):
        md.append(f"| {h:g} | " + " | ".join(f"{linear_amplification(h, n) - 1:.2e}"
                                               for n, _ in INTEGRATORS) + " |")
    with open(os.path.join(args.out, "integrator_results.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))
    shutil.rmtree(WORK)


if __name__ == "__main__":
    main()
