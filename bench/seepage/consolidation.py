#!/usr/bin/env python3
"""Consolidation of a column of grains under a load step with each seepage force of fix
darcy/pressure, against each force's closed form (bench/seepage/RESULTS.md).

    consolidation.py [--case bench|ci] [--forces pressure full] [--workdir DIR] [--kokkos]
                     [--check] [--lmp LMP --plugin-dir DIR] [--table FILE --figure FILE]
                     [--analyse-only]

Runs in.consolidation (a column of N grains under a plate, the stress ramped by dsigma) once
per force, reads the bottom layer's pressure (the base pressure) and the plate's settlement,
and compares them with tests/common/analytic_solutions.consolidation() for the column's own
m_v, porosity and permeability: the undrained base pressure (the mean over the window from
the end of the ramp to 0.02 H^2/c after it, over the closed form's mean there, the closed form
convolved with the ramp) and the late decay rate of the base pressure (least squares of its
log over T = c t/H^2 in [0.3, 0.8] from the ramp's midpoint, over pi^2 c/(4 H^2)).
--check (the CI test, case ci) stops with status 1 unless each force matches its own
closed form within the tolerances below. Without --check it writes the table (markdown) and
the figure: base pressure and settlement against time, both forces, both theories.
"""
import argparse
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "common"))
from common import out_dir, runs as example_runs  # noqa: E402
from analytic_solutions import consolidation, consolidation_step  # noqa: E402

# in.consolidation's variables per case: the CI case resolves the slowest mode with 8 fluid
# layers, the benchmark with 16 (twice the column, the viscosity for a similar H^2/c)
CASES = {
    "ci": dict(grains=20, layers=8, mu_f=2500.0, t_ramp=4.0),
    "bench": dict(grains=36, layers=16, mu_f=800.0, t_ramp=8.0),
}
DEFAULTS = dict(cells_per=2, k=1.0e4, sigma0=10.0, dsigma=1.0, beta=5.0e-5, kc=1.0, dt=5.0e-4,
                nout=200)
# The fraction of the water's force per bulk volume the grains take: seepage pressure puts
# -V grad p on a grain (1 - phi per bulk volume), seepage full -V grad p/(1 - phi) (all of it)
SHARE = {"pressure": lambda phi: 1.0 - phi, "full": lambda phi: 1.0}
UNDRAINED_WINDOW = 0.02    # H^2/c after the end of the ramp
RATE_WINDOW = (0.3, 0.8)   # T from the ramp's midpoint: the next mode has decayed to < 1e-3
# CI tolerances (README.md, "Tolerances"): the undrained column is uniform on the grid (its
# compaction and the hat weights exact), so the base pressure is off by the ringing of the
# ramp only (measured 0.03-0.05 %); the rate by the grid's resolution of the slowest mode,
# (dz/H)^2 terms: -0.3 % from the diffusion operator, about +1 % from the force <-> porosity
# loop at 8 layers (measured +0.5/+0.6 %; at 16 layers +0.1/+0.2 %)
TOLERANCE = {"undrained": 0.003, "rate": 0.015, "settlement": 0.005}
# the times after the ramp, in H^2/c, at which the settlement is compared with the closed
# forms: while the layer drains, where the two forces' settlements differ by 12-24 %
SETTLEMENT_T = (0.0, 0.02, 0.05, 0.1, 0.2, 0.4)


def params(case):
    p = dict(DEFAULTS, **CASES[case])
    p["a0"] = 1.0 - p["sigma0"] / p["k"]                 # spacing under sigma0 (area A = 1)
    p["height"] = p["layers"] * p["cells_per"] * p["a0"]  # the drained face, z_face
    return p


def theory(p, seepage):
    """consolidation() of the column: m_v = A/(k a0) of its springs, the porosity of its
    lattice on the grid, Kozeny-Carman's permeability of it"""
    phi = 1.0 - (math.pi / 6.0) / p["a0"]
    k = p["kc"] * phi ** 3 / (1.0 - phi) ** 2
    return consolidation(p["dsigma"], 1.0 / (p["k"] * p["a0"]), phi, p["beta"], k, p["mu_f"],
                         p["height"], SHARE[seepage](phi))


def ramp(s):
    """the applied load's share at s = t/t_ramp (in.consolidation's variable sigma)"""
    s = min(max(s, 0.0), 1.0)
    return s - math.sin(2 * math.pi * s) / (2 * math.pi)


def under_ramp(c, p, t, pieces=400):
    """(base pressure, settlement of the layer) at t under the ramped load: the step response
    of consolidation_step summed over the ramp's increments (at their midpoints)"""
    base = settle = 0.0
    for i in range(pieces):
        t0, t1 = p["t_ramp"] * i / pieces, p["t_ramp"] * (i + 1) / pieces
        share = ramp(t1 / p["t_ramp"]) - ramp(t0 / p["t_ramp"])
        b, s = consolidation_step(c, t - 0.5 * (t0 + t1))
        base += share * b
        settle += share * s
    return base, settle


def plate_settlement(c, p, t):
    """the plate's settlement at t: the layer's (under_ramp) and the drained column above the
    face, (N a0 - H) m_v times the load applied"""
    above = (p["grains"] * p["a0"] - p["height"]) * c["m_v"] * p["dsigma"]
    return under_ramp(c, p, t)[1] + above * ramp(t / p["t_ramp"])


def run_time(p, seepage):
    """to T = 0.85 after the ramp's midpoint: the rate's window and a bit"""
    c = theory(p, seepage)
    return 0.5 * p["t_ramp"] + 0.85 * c["height"] ** 2 / c["diffusivity"]


def read_profile(path):
    """(times, bottom layer pressure, bottom layer porosity) of a fix darcy/pressure profile file"""
    t, p, phi = [], [], []
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    i = 0
    while i < len(lines):
        head = lines[i].split()
        layers = int(head[2])
        bottom = lines[i + 1].split()
        t.append(float(head[1]))
        p.append(float(bottom[2]))
        phi.append(float(bottom[3]))
        i += layers + 1
    return np.array(t), np.array(p), np.array(phi)


def read_series(path):
    data = np.loadtxt(path, comments="#", ndmin=2)
    return data[:, 0], data[:, 1]


def measure(p, seepage, workdir):
    """the run's base pressure and settlement against time, the closed form's, and the two
    ratios to it"""
    c = theory(p, seepage)
    t, base, phi = read_profile(os.path.join(workdir, f"profile_{seepage}.txt"))
    ts, z_wall = read_series(os.path.join(workdir, f"series_{seepage}.txt"))
    settlement = z_wall[0] - z_wall
    tc = c["height"] ** 2 / c["diffusivity"]
    window = (t >= p["t_ramp"]) & (t <= p["t_ramp"] + UNDRAINED_WINDOW * tc)
    expected = np.array([under_ramp(c, p, x)[0] for x in t[window]])
    late = (t >= 0.5 * p["t_ramp"] + RATE_WINDOW[0] * tc) & (t <= 0.5 * p["t_ramp"] + RATE_WINDOW[1] * tc)
    rate = -np.polyfit(t[late], np.log(base[late]), 1)[0]
    settlement_expected = plate_settlement(c, p, ts[-1])
    other = theory(p, "full" if seepage == "pressure" else "pressure")
    own_ratios, other_ratios = [], []
    for T in SETTLEMENT_T:
        i = min(int(np.searchsorted(ts, p["t_ramp"] + T * tc)), len(ts) - 1)
        own_ratios.append(settlement[i] / plate_settlement(c, p, ts[i]))
        other_ratios.append(settlement[i] / plate_settlement(other, p, ts[i]))
    return dict(seepage=seepage, theory=c, t=t, base=base, ts=ts, settlement=settlement,
                porosity=phi[1], undrained=base[window].mean(),
                undrained_expected=expected.mean(), rate=rate, tc=tc,
                settlement_end=settlement[-1], settlement_expected=settlement_expected,
                settlement_own=own_ratios, settlement_other=other_ratios)


def run(p, seepage, workdir, kokkos):
    variables = {k: p[k] for k in ("grains", "layers", "cells_per", "k", "sigma0", "dsigma",
                                   "t_ramp", "beta", "mu_f", "kc", "dt", "nout")}
    variables.update(seepage=seepage, run_time=run_time(p, seepage))
    args = ["-k", "on", "t", "1", "-sf", "kk"] if kokkos else []
    example_runs.run_lmp(workdir, os.path.join(HERE, "in.consolidation"), variables,
                         log=f"log.{seepage}", args=args)


def classical(p):
    """Terzaghi's classical closed form: stiff water (beta = 0) and the full force"""
    return consolidation(p["dsigma"], 1.0 / (p["k"] * p["a0"]), 0.0, 0.0,
                         theory(p, "full")["diffusivity"] * theory(p, "full")["storage"],
                         1.0, p["height"], 1.0)


def table(p, results):
    """each run against its own closed form, the other force's and Terzaghi's classical one"""
    rows = ["| seepage | alpha = solid share | p_u closed form / dsigma | p_u measured / own | "
            "/ other force's | / classical | late rate closed form | measured / own | "
            "/ other force's | / classical | settlement at the end / own |",
            "|---|---|---|---|---|---|---|---|---|---|---|"]
    other = {"pressure": "full", "full": "pressure"}
    terzaghi = classical(p)
    for r in results:
        c, o = r["theory"], theory(p, other[r["seepage"]])
        own_u = r["undrained"] / r["undrained_expected"]
        rows.append(
            f"| {r['seepage']} | {c['solid_share']:.4f} | {c['undrained_pressure'] / p['dsigma']:.4f} "
            f"| {own_u:.5f} | {own_u * c['undrained_pressure'] / o['undrained_pressure']:.3f} "
            f"| {own_u * c['undrained_pressure'] / terzaghi['undrained_pressure']:.3f} "
            f"| {c['slowest_rate']:.5f} | {r['rate'] / c['slowest_rate']:.4f} "
            f"| {r['rate'] / o['slowest_rate']:.3f} | {r['rate'] / terzaghi['slowest_rate']:.3f} "
            f"| {r['settlement_end'] / r['settlement_expected']:.4f} |")
    return "\n".join(rows) + "\n"


def figure(p, results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax_p, ax_s) = plt.subplots(1, 2, figsize=(11, 4.2))
    colours = {"pressure": "tab:blue", "full": "tab:red"}
    names = {"pressure": "seepage pressure (the paper's)", "full": "seepage full (Terzaghi)"}
    t_end = max(r["t"][-1] for r in results)
    times = np.linspace(0.0, t_end, 400)
    drained = 1.0 / (p["k"] * p["a0"]) * p["grains"] * p["a0"] * p["dsigma"]
    for r in results:
        ax_p.plot(r["t"], r["base"] / p["dsigma"], color=colours[r["seepage"]], lw=2.5, alpha=0.5,
                  label=f"run, {names[r['seepage']]}")
        ax_s.plot(r["ts"], r["settlement"] / drained, color=colours[r["seepage"]], lw=2.5, alpha=0.5)
    for seepage, style in (("pressure", "--"), ("full", ":")):
        c = theory(p, seepage)
        ax_p.plot(times, [under_ramp(c, p, x)[0] / p["dsigma"] for x in times], "k" + style, lw=1,
                  label=f"closed form, alpha = {c['solid_share']:.3f}")
        ax_s.plot(times, [plate_settlement(c, p, x) / drained for x in times], "k" + style, lw=1)
    ax_p.set_xlabel("time")
    ax_p.set_ylabel("base pressure / load step")
    ax_p.legend(fontsize=8)
    ax_s.set_xlabel("time")
    ax_s.set_ylabel("plate settlement / drained settlement")
    fig.suptitle(f"{p['grains']} grains, {p['layers']} fluid layers under the drained face")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", choices=sorted(CASES), default="bench")
    parser.add_argument("--forces", nargs="+", choices=sorted(SHARE), default=["pressure", "full"])
    parser.add_argument("--workdir", default=None)
    parser.add_argument("--kokkos", action="store_true", help="fix darcy/pressure/kk (-sf kk)")
    parser.add_argument("--check", action="store_true", help="exit 1 unless within the tolerances")
    parser.add_argument("--analyse-only", action="store_true",
                        help="measure the runs already in --workdir instead of running them")
    parser.add_argument("--lmp", default=None, help="lmp to run (default: the one on PATH)")
    parser.add_argument("--plugin-dir", default=None, help="folder of porewater.so")
    parser.add_argument("--table", default=os.path.join(out_dir(HERE), "consolidation_table.md"))
    parser.add_argument("--figure", default=os.path.join(out_dir(HERE), "consolidation.png"))
    args = parser.parse_args()
    if args.lmp:
        os.environ["PATH"] = os.path.dirname(os.path.abspath(args.lmp)) + os.pathsep + os.environ["PATH"]
    if args.plugin_dir:
        os.environ["LD_LIBRARY_PATH"] = (os.path.abspath(args.plugin_dir) + os.pathsep +
                                         os.environ.get("LD_LIBRARY_PATH", ""))
    p = params(args.case)
    workdir = args.workdir or os.path.join(HERE, "work", args.case)
    os.makedirs(workdir, exist_ok=True)
    results = []
    for seepage in args.forces:
        if not args.analyse_only:
            run(p, seepage, workdir, args.kokkos)
        results.append(measure(p, seepage, workdir))
    failed = []
    for r in results:
        c = r["theory"]
        undrained = r["undrained"] / r["undrained_expected"]
        rate = r["rate"] / c["slowest_rate"]
        settled = max(r["settlement_own"], key=lambda x: abs(x - 1.0))
        apart = min(r["settlement_other"], key=lambda x: abs(x - 1.0))
        print(f"[ report ] seepage {r['seepage']}: undrained base pressure {r['undrained']:.6f} "
              f"(closed form {r['undrained_expected']:.6f}, ratio {undrained:.5f}); late rate "
              f"{r['rate']:.6f} (closed form {c['slowest_rate']:.6f}, ratio {rate:.5f}); "
              f"settlement over its closed form at T = {', '.join(map(str, SETTLEMENT_T))}: "
              f"{', '.join('%.5f' % x for x in r['settlement_own'])} (the other force's: "
              f"{', '.join('%.3f' % x for x in r['settlement_other'])}); grid "
              f"porosity {r['porosity']:.6f}, the column's {1.0 - math.pi / 6 / p['a0']:.6f}")
        if abs(settled - 1.0) > TOLERANCE["settlement"]:
            failed.append(f"{r['seepage']}: settlement ratio {settled:.5f}")
        if abs(apart - 1.0) < 4 * TOLERANCE["settlement"]:    # the test can tell the forces
            failed.append(f"{r['seepage']}: the other force's settlement as close as {apart:.5f}")
        if abs(undrained - 1.0) > TOLERANCE["undrained"]:
            failed.append(f"{r['seepage']}: undrained ratio {undrained:.5f}")
        if abs(rate - 1.0) > TOLERANCE["rate"]:
            failed.append(f"{r['seepage']}: rate ratio {rate:.5f}")
    if args.check:
        if failed:
            print("FAILED: " + "; ".join(failed))
            return 1
        print(f"passed: each force within {TOLERANCE['undrained']:.1%} (undrained), "
              f"{TOLERANCE['rate']:.1%} (rate) and {TOLERANCE['settlement']:.1%} (settlement) of "
              f"its own closed form")
        return 0
    with open(args.table, "w") as f:
        f.write(table(p, results))
    figure(p, results, args.figure)
    return 0


if __name__ == "__main__":
    sys.exit(main())
