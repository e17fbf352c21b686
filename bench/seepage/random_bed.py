#!/usr/bin/env python3
"""Consolidation of a random, settled grain bed under a load step with each seepage force of
fix darcy/pressure (bench/seepage/RESULTS.md, "A random bed"), against each force's closed form
and against a one-dimensional solution of the layered bed.

    random_bed.py [--case bench|ci] [--parts step20 step2 loose face] [--forces ...]
                  [--workdir DIR] [--prepare] [--check] [--analyse-only] [--set NAME=VALUE ...]
                  [--lmp LMP --plugin-dir DIR] [--table FILE --figure FILE]

Runs in.random_bed: once `prepare` (pour, settle and press the bed at sigma0; skipped when the
work folder holds its bed_ready.restart, unless --prepare or --check), then `load` once per
part and force (PARTS: the 40 -> 60 kPa step; a 2 kPa step; the 20 kPa step with the loose
grains, those with at most 3 contacts, out of the water; the drained face 1.5 cells under the
plate). From each load run it measures, as consolidation.py does for the column:

- the undrained base pressure p0: the bottom fluid layer's pressure averaged from the end of
  the ramp to 0.02 H^2/c after it, over the closed form's mean there (convolved with the ramp);
- the late decay rate: least squares of ln p_base over T = c t/H^2 in [0.3, 0.8] from the
  ramp's midpoint, over pi^2 c/(4 H^2).

The closed forms (tests/common/analytic_solutions.consolidation) take the bed's own numbers:
phi the mean porosity of the active layers before the step, k the harmonic mean of their
Kozeny-Carman permeabilities, H the active layers' height, m_v from the final settlement of
the layer under the drained face (its grains' strain at the end, summed over the layers, over
dsigma H less the part the pore pressure still holds: m_v = sum_l eps_l dz/(dsigma H -
alpha dz sum_l p_l,end)); "own" is the force's (alpha = 1 - phi for seepage pressure, the
paper's theory; alpha = 1 for seepage full, Terzaghi-Biot with compressible water), "other" the
other force's. The layered solution solves (phi_l beta + alpha m_v,l) dp/dt =
d/dz(k_l/mu dp/dz) + m_v,l dsigma/dt on the active layers (20 points a layer, drained face,
closed floor, the run's ramp), with each layer's porosity, Kozeny-Carman k and m_v measured in
the run (m_v,l: the layer's strain from the grains' heights at the start and the end, over its
effective-stress change dsigma - alpha p_l,end).

Runs with the grains' heights every 0.01 s (the step20 and step2 parts) are also measured for
what the loose grains do: the grains that rise more than 0.3 mm, and the fix's own grain
source (its output f_ID[10]) split into theirs and the rest's (each grain's hat weight in the
active layers, times its volume, over 1 - phi); and the skeleton's tangent m_v over the late
window (the active layers' compaction against the pressure they hold).

--check (the CI test, case ci: 400 grains, preloaded, a 2 kPa step) stops with status 1 unless
each force is within TOLERANCE of the layered solution and its p0 at least 15 % from the other
force's closed form. Without --check it writes the table (markdown) and the figure.
"""
import argparse
import glob
import math
import os
import sys
import textwrap

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "common"))
from common import out_dir, runs as example_runs  # noqa: E402
from analytic_solutions import consolidation  # noqa: E402
from consolidation import under_ramp, ramp  # noqa: E402

# in.random_bed's variables per case: the benchmark's bed (1,000 grains, 8 fluid layers of
# ~2.9 grain diameters, 2 x 2 cells across) and the CI test's (400 grains on 0.4 of the
# footprint, the same height, one cell across, twice the time step: the examples' `fast` eps,
# pressed at 50 kPa before 40 kPa, so that its 2 kPa step reloads it: no packing of it then
# collapses under the step, as one of the unpreloaded ones did, by 6 times its settlement)
CASES = {
    "bench": dict(grains=1000, lx=0.12, grid_xy=2),
    "ci": dict(grains=400, lx=0.076, grid_xy=1, pour_time=0.8, eps=0.14, sigma_pre=50.0e3),
}
DEFAULTS = dict(r_min=0.009, r_max=0.011, rho=2600.0, rho_f=1000.0, g=9.81, kn=1.0e6, mu=0.5,
                mu_prep=0.3, sigma0=40.0e3, dsigma=20.0e3, t_ramp=0.06, mass_w=1.0, seed=5281,
                layers=8, face_depth=0.5, beta=5.0e-8, mu_f=1.1e-3, kc=1.0e-10, fluid_every=1,
                nout=100, loose_contacts=-1, dump_every=0, pour_time=1.5, eps=0.07,
                sigma_pre=40.0e3)
# the load runs: (what they change, the forces, the grains' heights every dump_every steps)
PARTS = {
    "step20": (dict(), ("pressure", "full"), 1600),
    "step2": (dict(dsigma=2000.0), ("pressure", "full"), 1600),
    "loose": (dict(loose_contacts=3), ("pressure", "full"), 0),
    "face": (dict(face_depth=1.5), ("full",), 0),
}
PART_NAMES = {"step20": "40 -> 60 kPa", "step2": "40 -> 42 kPa",
              "loose": "40 -> 60 kPa, grains with <= 3 contacts out of the water",
              "face": "40 -> 60 kPa, the drained face 1.5 cells under the plate"}
CI_PARTS = {"ci": (dict(dsigma=2000.0), ("pressure", "full"), 0)}
LOAD_VARIABLES = ("grains", "r_min", "r_max", "lx", "rho", "rho_f", "g", "kn", "mu", "sigma0",
                  "dsigma", "t_ramp", "mass_w", "layers", "grid_xy", "beta", "mu_f", "kc",
                  "fluid_every", "nout", "seed", "mu_prep", "loose_contacts", "dump_every", "eps")
PREPARE_VARIABLES = ("grains", "r_min", "r_max", "lx", "rho", "rho_f", "g", "kn", "mu",
                     "mu_prep", "sigma0", "mass_w", "seed", "pour_time", "eps", "sigma_pre")
SHARE = {"pressure": lambda phi: 1.0 - phi, "full": lambda phi: 1.0}
OTHER = {"pressure": "full", "full": "pressure"}
UNDRAINED_WINDOW = 0.02    # H^2/c after the end of the ramp
RATE_WINDOW = (0.3, 0.8)   # T from the ramp's midpoint
RUN_T = 0.9                # run to this T after the ramp's midpoint (estimated before the run)
RISEN = 3.0e-4             # m: a grain that rose more than this
# CI tolerances, against the layered solution (RESULTS.md, "A random bed"): on the eight
# packings measured (seeds 5281, 11-14 on LAMMPS 29Sep2021, 5281, 11, 12 on 4Feb2025; both
# forces) p0 came to 0.979-1.020 of it, the late rate to 0.962-1.011; the uniform closed form
# to 0.958-1.008 and 0.899-1.050, these small beds' layers differing in m_v by up to 2x
TOLERANCE = {"undrained": 0.05, "rate": 0.07, "apart": 0.15}


def params(case, overrides=()):
    p = dict(DEFAULTS, **CASES[case])
    for item in overrides:
        key, value = item.split("=", 1)
        p[key] = type(p[key])(value) if key in p and not isinstance(p[key], str) else value
    return p


# ---------------------------------------------------------------------------- runs

def prepare(p, workdir):
    variables = {k: p[k] for k in PREPARE_VARIABLES}
    variables["stage"] = "prepare"
    example_runs.run_lmp(workdir, os.path.join(HERE, "in.random_bed"), variables,
                         log="log.prepare")


def plate_height(workdir):
    with open(os.path.join(workdir, "bed_ready.txt")) as f:
        return float(f.read().split()[0])


def cell_z(p, workdir):
    """the fluid cells' height: the plate face_depth cells above the drained face"""
    return plate_height(workdir) / (p["layers"] + p["face_depth"])


def estimated_run_time(p, workdir):
    """to T = RUN_T after the ramp's midpoint under the slower force's estimate (full), with
    m_v ~ 2.4 d/k_n and phi ~ 0.40 (the bench bed's: 4.6e-8/Pa and 0.401, H^2/c 0.89 s)"""
    phi, m_v = 0.40, 2.4 * (p["r_min"] + p["r_max"]) / p["kn"]
    k = p["kc"] * phi ** 3 / (1 - phi) ** 2
    c = k / (p["mu_f"] * (phi * p["beta"] + m_v))
    height = p["layers"] * cell_z(p, workdir)
    return 0.5 * p["t_ramp"] + RUN_T * height ** 2 / c


def load(p, seepage, workdir, name, args=(), extra_env=None, run_time=None):
    variables = {k: p[k] for k in LOAD_VARIABLES}
    variables.update(stage="load", seepage=seepage, name=name, cell_z=repr(cell_z(p, workdir)),
                     grid_z=p["layers"] + int(math.ceil(p["face_depth"] + 0.5)) + 1,
                     run_time=repr(run_time or estimated_run_time(p, workdir)))
    return example_runs.run_lmp(workdir, os.path.join(HERE, "in.random_bed"), variables,
                                log=f"log.{name}", args=args, extra_env=extra_env)


# ---------------------------------------------------------------------------- reading

def read_profile(path):
    """(times, active layers, p, phi, k): per block, the layers' x-y means (all layers)"""
    t, active, p, phi, k = [], [], [], [], []
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    i = 0
    while i < len(lines):
        head = lines[i].split()
        n = int(head[2])
        rows = np.array([[float(x) for x in lines[i + 1 + j].split()] for j in range(n)])
        t.append(float(head[1]))
        active.append(int(head[3]))
        p.append(rows[:, 2])
        phi.append(rows[:, 3])
        k.append(rows[:, 4])
        i += n + 1
    return np.array(t), np.array(active), np.array(p), np.array(phi), np.array(k)


def read_series(path):
    data = np.loadtxt(path, comments="#", ndmin=2)
    return data[:, 0], data[:, 1]


def read_grains(path):
    """id -> (radius, z) of a write_dump custom id radius z"""
    with open(path) as f:
        lines = f.readlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
    data = np.array([[float(x) for x in line.split()] for line in lines[start:]])
    order = np.argsort(data[:, 0])
    return data[order, 1], data[order, 2]


# ---------------------------------------------------------------------------- theory

def kozeny_carman(p, phi):
    return p["kc"] * phi ** 3 / (1.0 - phi) ** 2


def layered_solution(p, phi_l, k_l, mv_l, alpha_l, dz, times, sub=20):
    """base pressure (the bottom layer's mean) of the layered one-dimensional consolidation:
    (phi beta + alpha m_v) dp/dt = d/dz(k/mu dp/dz) + m_v dsigma/dt on len(phi_l) layers of
    height dz, p = 0 at the top face, no flow at the floor, the load ramped as the run's;
    finite volumes, `sub` per layer, harmonic face permeabilities; integrated exactly in time
    mode by mode (the load's rate held over steps of t_ramp/400)"""
    n_layers = len(phi_l)
    n = n_layers * sub
    h = dz / sub
    layer = np.repeat(np.arange(n_layers), sub)
    storage = phi_l[layer] * p["beta"] + alpha_l[layer] * mv_l[layer]
    mobility = k_l[layer] / p["mu_f"]
    face = 2 * mobility[:-1] * mobility[1:] / (mobility[:-1] + mobility[1:]) / h ** 2
    lap = np.diag(np.append(-face, 0.0) + np.append(0.0, -face)) + np.diag(face, 1) + \
        np.diag(face, -1)
    lap[-1, -1] -= 2 * mobility[-1] / h ** 2   # half a sub-cell to the drained face
    # q = S^(1/2) p: dq/dt = B q + S^(-1/2) m_v dsigma/dt, B symmetric
    root = np.sqrt(storage)
    rates, modes = np.linalg.eigh(lap / root[:, None] / root[None, :])
    forcing = modes.T @ (mv_l[layer] / root)
    dt = p["t_ramp"] / 400.0
    grid_t = np.arange(int(math.ceil(times[-1] / dt)) + 2) * dt
    sigma = p["dsigma"] * np.array([ramp(t / p["t_ramp"]) for t in grid_t])
    decay = np.exp(rates * dt)
    gain = np.expm1(rates * dt) / rates * forcing
    read = (modes[:sub, :] / root[:sub, None]).mean(axis=0)   # the bottom layer's mean p
    amplitude = np.zeros(n)
    base = np.zeros(len(grid_t))
    for j in range(len(grid_t) - 1):
        amplitude = decay * amplitude + gain * (sigma[j + 1] - sigma[j]) / dt
        base[j + 1] = read @ amplitude
    return np.interp(times, grid_t, base)


# ---------------------------------------------------------------------------- measuring

def windows(p, c, t):
    """the undrained window and the late-rate window of times t, for closed form c"""
    tc = c["height"] ** 2 / c["diffusivity"]
    undrained = (t >= p["t_ramp"]) & (t <= p["t_ramp"] + UNDRAINED_WINDOW * tc)
    late = (t >= 0.5 * p["t_ramp"] + RATE_WINDOW[0] * tc) & \
           (t <= 0.5 * p["t_ramp"] + RATE_WINDOW[1] * tc)
    return undrained, late


def layer_strains(z_start, z_end, dz, layers, z_plate):
    """each layer's compressive strain: the grains' vertical displacements fitted by least
    squares with a continuous function linear in each layer (knots at the layer faces and at
    the plate), minus its slope per layer; grains more than 5 robust deviations (1.4826 median
    absolute deviations) off the fit are left out and the fit repeated (the loose grains the
    seepage lifts by millimetres). Returns the strains and how many grains were left out."""
    knots = np.append(np.arange(layers + 1) * dz, z_plate)
    inside = z_start <= knots[-1]
    z, u = z_start[inside], (z_end - z_start)[inside]
    basis = np.array([np.interp(z, knots, np.eye(len(knots))[j]) for j in range(len(knots))]).T
    keep = np.ones(len(z), bool)
    for _ in range(5):
        nodal = np.linalg.lstsq(basis[keep], u[keep], rcond=None)[0]
        residual = u - basis @ nodal
        spread = 1.4826 * np.median(np.abs(residual[keep]))
        new_keep = np.abs(residual) <= 5 * spread
        if np.array_equal(new_keep, keep):
            break
        keep = new_keep
    return -(nodal[1:layers + 1] - nodal[:layers]) / dz, int((~keep).sum())


def late_rate(t, base, window):
    positive = window & (base > 0)
    return -np.polyfit(t[positive], np.log(base[positive]), 1)[0]


def read_heights(workdir, name, dt_run, t0_step):
    """(times, heights[time, grain]) of the dump every dump_every steps, if the run wrote one"""
    files = glob.glob(os.path.join(workdir, f"grains_{name}.*.txt"))
    files.sort(key=lambda f: int(f.split(".")[-2]))
    times, heights = [], []
    for path in files:
        data = np.loadtxt(path, skiprows=9, ndmin=2)
        heights.append(data[np.argsort(data[:, 0]), 1])
        times.append((int(path.split(".")[-2]) - t0_step) * dt_run)
    return np.array(times), np.array(heights)


def time_step(p):
    return p["eps"] * math.sqrt(p["rho"] * 4.0 / 3.0 * math.pi * p["r_min"] ** 3 / p["kn"])


def measure(p, seepage, workdir, name):
    t_abs, active, pl, phil, _ = read_profile(os.path.join(workdir, f"profile_{name}.txt"))
    series = np.loadtxt(os.path.join(workdir, f"series_{name}.txt"), comments="#", ndmin=2)
    ts, z_wall, source = series[:, 0], series[:, 1], series[:, 5]
    # the profile's times are LAMMPS' clock, the series' from the load's start; both are
    # written on the same steps (multiples of nout), the first at the first one after the start
    t = t_abs - t_abs[0] + ts[0]
    layers = int(active[0])
    dz = cell_z(p, workdir)
    height = layers * dz
    base = pl[:, 0]
    phi_l = phil[0, :layers]
    k_l = kozeny_carman(p, phi_l)
    phi = phi_l.mean()
    k_h = layers / np.sum(1.0 / k_l)
    alpha = SHARE[seepage](phi)
    z0 = z_wall[0]
    p_end = pl[-1, :layers]
    held_end = alpha * dz * p_end.sum()
    start = np.loadtxt(os.path.join(workdir, f"grains_{name}_start.txt"), skiprows=9, ndmin=2)
    start = start[np.argsort(start[:, 0])]
    radius, z_start, contacts = start[:, 1], start[:, 2], start[:, 3]
    _, z_end = read_grains(os.path.join(workdir, f"grains_{name}_end.txt"))
    strain_l, off_fit = layer_strains(z_start, z_end, dz, layers, z0)
    m_v = strain_l.sum() * dz / (p["dsigma"] * height - held_end)
    m_v_plate = (z0 - z_wall[-1]) / (p["dsigma"] * z0 - held_end)
    c = consolidation(p["dsigma"], m_v, phi, p["beta"], k_h, p["mu_f"], height, alpha)
    other = consolidation(p["dsigma"], m_v, phi, p["beta"], k_h, p["mu_f"], height,
                          SHARE[OTHER[seepage]](phi))
    undrained, late = windows(p, c, t)
    expected = np.array([under_ramp(c, p, x)[0] for x in t[undrained]]).mean()
    expected_other = np.array([under_ramp(other, p, x)[0] for x in t[undrained]]).mean()
    alpha_l = np.array([SHARE[seepage](x) for x in phi_l])
    mv_l = strain_l / (p["dsigma"] - alpha_l * p_end)
    layered = layered_solution(p, phi_l, k_l, mv_l, alpha_l, dz, t)
    r = dict(seepage=seepage, name=name, theory=c, other=other, t=t, base=base, phi=phi,
             phi_l=phi_l, k_h=k_h, m_v=m_v, m_v_plate=m_v_plate, mv_l=mv_l, off_fit=off_fit,
             undrained=base[undrained].mean(), undrained_expected=expected,
             undrained_other=expected_other, rate=late_rate(t, base, late), layered=layered,
             layered_undrained=layered[undrained].mean(),
             layered_rate=late_rate(t, layered, late),
             loose=int(np.sum(contacts <= 3)), risen_end=int(np.sum(z_end - z_start > RISEN)))
    # the grains' heights every dump_every steps: the risen grains, their share of the fix's
    # grain source, the tangent m_v over the late window
    t0_step = int(next(line for line in open(os.path.join(workdir, f"profile_{name}.txt"))
                       if not line.startswith("#")).split()[0]) - round(ts[0] / time_step(p))
    td, heights = read_heights(workdir, name, time_step(p), t0_step)
    if len(td):
        rise = np.max(heights - z_start, axis=0)
        risen = rise > RISEN
        volume = 4.0 / 3.0 * math.pi * radius ** 3

        def in_active(z):   # a grain's hat weight in the active layers (1-D, x-y summed)
            return np.clip(layers + 0.5 - z / dz, 0.0, 1.0)

        shares = []
        compaction = []
        for j, tt in enumerate(td):
            deposit = volume * (in_active(heights[j]) - in_active(z_start)) / (1.0 - phi)
            area = p["lx"] ** 2
            shares.append((tt, np.interp(tt, ts, source) / area, deposit.sum() / area,
                           deposit[risen].sum() / area, deposit[~risen].sum() / area,
                           int(np.sum(heights[j] - z_start > RISEN))))
            compaction.append(layer_strains(z_start, heights[j], dz, layers, z0)[0].sum() * dz)
        held = alpha * dz * np.array([np.interp(tt, t, pl[:, :layers].sum(axis=1)) for tt in td])
        window = (td >= 0.5 * p["t_ramp"] + RATE_WINDOW[0] * c["height"] ** 2 / c["diffusivity"]) & \
                 (td <= 0.5 * p["t_ramp"] + RATE_WINDOW[1] * c["height"] ** 2 / c["diffusivity"])
        tangent = -np.polyfit(held[window], np.array(compaction)[window], 1)[0]
        r.update(risen=int(risen.sum()), risen_contacts=np.bincount(contacts[risen].astype(int)),
                 largest_rise=float(rise.max()), shares=shares, m_v_tangent=tangent)
    return r


def report(r):
    c = r["theory"]
    print(f"[ report ] {r['name']} (seepage {r['seepage']}): phi {r['phi']:.4f}, k_h "
          f"{r['k_h']:.4g} m2, m_v {r['m_v']:.4g} 1/Pa (by the plate {r['m_v_plate']:.4g}), "
          f"H {c['height']:.4f} m, H^2/c {c['height'] ** 2 / c['diffusivity']:.4f} s; p0 "
          f"{r['undrained']:.1f} Pa: over its closed form {r['undrained'] / r['undrained_expected']:.4f}, "
          f"the other force's {r['undrained'] / r['undrained_other']:.4f}, the layered solution "
          f"{r['undrained'] / r['layered_undrained']:.4f}; late rate {r['rate']:.4f}/s: over its "
          f"closed form {r['rate'] / c['slowest_rate']:.4f}, the other force's "
          f"{r['rate'] / r['other']['slowest_rate']:.4f}, the layered solution "
          f"{r['rate'] / r['layered_rate']:.4f}")
    print("           per layer: phi " + " ".join("%.4f" % x for x in r["phi_l"]) + "; m_v " +
          " ".join("%.3g" % x for x in r["mv_l"]) + f" ({r['off_fit']} grains off the "
          f"displacement fit); {r['loose']} grains with <= 3 contacts, {r['risen_end']} "
          f"risen > {RISEN * 1e3:.1f} mm at the end")
    if "shares" in r:
        print(f"           {r['risen']} grains rose > {RISEN * 1e3:.1f} mm (contacts at the start: "
              f"{list(r['risen_contacts'])}), the most {r['largest_rise'] * 1e3:.1f} mm; tangent "
              f"m_v over the late window {r['m_v_tangent']:.4g} ({r['m_v_tangent'] / r['m_v']:.3f} "
              f"of the secant); the grain source per area (m): t, the fix's, the grains' hat "
              f"weights, of it the risen grains', the rest's, risen now:")
        for row in r["shares"][::10] + [r["shares"][-1]]:
            print("             %.2f  %.3e  %.3e  %.3e  %.3e  %d" % row)


def table(p, results):
    rows = ["| step | seepage | α | p0 measured (kPa) | / own closed form | / other force's | "
            "/ layered | late rate measured (1/s) | / own closed form | / other force's | "
            "/ layered | m_v (10⁻⁸/Pa) | H²/c (s) | grains risen > 0.3 mm |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for part, r in results:
        c = r["theory"]
        risen = f"{r['risen']} (end {r['risen_end']})" if "risen" in r else f"end {r['risen_end']}"
        rows.append(
            f"| {PART_NAMES.get(part, part)} | {r['seepage']} | {c['solid_share']:.3f} | "
            f"{r['undrained'] / 1e3:.3f} | {r['undrained'] / r['undrained_expected']:.3f} | "
            f"{r['undrained'] / r['undrained_other']:.3f} | "
            f"{r['undrained'] / r['layered_undrained']:.3f} | {r['rate']:.3f} | "
            f"{r['rate'] / c['slowest_rate']:.3f} | {r['rate'] / r['other']['slowest_rate']:.3f} | "
            f"{r['rate'] / r['layered_rate']:.3f} | {r['m_v'] * 1e8:.2f} | "
            f"{c['height'] ** 2 / c['diffusivity']:.3f} | {risen} |")
    return "\n".join(rows) + "\n"


def figure(p, results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    parts = list(dict.fromkeys(q for q, _ in results))
    fig, axes = plt.subplots(1, len(parts), figsize=(4.6 * len(parts), 4.2), squeeze=False)
    colours = {"pressure": "tab:blue", "full": "tab:red"}
    for ax, part in zip(axes[0], parts):
        for q, r in results:
            if q != part:
                continue
            c = r["theory"]
            tc = c["height"] ** 2 / c["diffusivity"]
            T = (r["t"] - 0.5 * p["t_ramp"]) / tc
            scale = c["undrained_pressure"]
            ax.semilogy(T, r["base"] / scale, color=colours[r["seepage"]], lw=2, alpha=0.5,
                        label=f"run, {r['seepage']}")
            coarse = np.linspace(0.0, r["t"][-1], 120)
            ax.semilogy((coarse - 0.5 * p["t_ramp"]) / tc,
                        np.array([under_ramp(c, p, x)[0] for x in coarse]) / scale, "--",
                        color=colours[r["seepage"]], lw=1,
                        label=f"closed form, {r['seepage']}")
            ax.semilogy(T, r["layered"] / scale, ":", color=colours[r["seepage"]], lw=1.5,
                        label=f"layered, {r['seepage']}")
        ax.axvspan(*RATE_WINDOW, color="0.9")
        ax.set_ylim(0.05, 1.5)
        ax.set_xlim(-0.05, 1.0)
        ax.set_xlabel("T = c (t - t_ramp/2)/H² (each force's own c)")
        ax.set_title(textwrap.fill(PART_NAMES.get(part, part), 42), fontsize=9)
    axes[0][0].set_ylabel("base pressure / closed form's p0")
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", choices=sorted(CASES), default="bench")
    parser.add_argument("--parts", nargs="+", default=None,
                        help=f"of {', '.join(PARTS)} (bench; default all)")
    parser.add_argument("--forces", nargs="+", choices=sorted(SHARE), default=None,
                        help="only these of each part's forces")
    parser.add_argument("--workdir", default=None)
    parser.add_argument("--prepare", action="store_true", help="prepare the bed even if it exists")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 unless within the tolerances (prepares the bed afresh)")
    parser.add_argument("--analyse-only", action="store_true",
                        help="measure the runs already in --workdir instead of running them")
    parser.add_argument("--set", nargs="*", default=[], help="NAME=VALUE: a variable of the runs")
    parser.add_argument("--lmp", default=None, help="lmp to run (default: the one on PATH)")
    parser.add_argument("--plugin-dir", default=None, help="folder of porewater.so")
    parser.add_argument("--table", default=None,
                        help="default: random_bed_table.md here (case bench), in the work folder (ci)")
    parser.add_argument("--figure", default=None, help="default: random_bed.png, as --table")
    args = parser.parse_args()
    if args.lmp:
        os.environ["PATH"] = os.path.dirname(os.path.abspath(args.lmp)) + os.pathsep + os.environ["PATH"]
    if args.plugin_dir:
        os.environ["LD_LIBRARY_PATH"] = (os.path.abspath(args.plugin_dir) + os.pathsep +
                                         os.environ.get("LD_LIBRARY_PATH", ""))
    base = params(args.case, args.set)
    workdir = args.workdir or os.path.join(HERE, "work", "random_" + args.case)
    os.makedirs(workdir, exist_ok=True)
    pages = out_dir(HERE) if args.case == "bench" else workdir
    args.table = args.table or os.path.join(pages, "random_bed_table.md")
    args.figure = args.figure or os.path.join(pages, "random_bed.png")
    parts = CI_PARTS if args.case == "ci" else {k: PARTS[k] for k in (args.parts or PARTS)}
    if not args.analyse_only and (args.prepare or args.check or
                                  not os.path.exists(os.path.join(workdir, "bed_ready.restart"))):
        prepare(base, workdir)
    results = []
    for part, (changes, forces, dump_every) in parts.items():
        p = dict(base, **changes)
        p["dump_every"] = dump_every
        for seepage in forces:
            if args.forces and seepage not in args.forces:
                continue
            name = f"{seepage}_{part}"
            if not args.analyse_only:
                load(p, seepage, workdir, name)
            results.append((part, measure(p, seepage, workdir, name)))
            report(results[-1][1])
    if args.check:
        failed = []
        for _, r in results:
            undrained = r["undrained"] / r["layered_undrained"]
            rate = r["rate"] / r["layered_rate"]
            apart = r["undrained"] / r["undrained_other"]
            if abs(undrained - 1.0) > TOLERANCE["undrained"]:
                failed.append(f"{r['name']}: p0 over the layered solution {undrained:.4f}")
            if abs(rate - 1.0) > TOLERANCE["rate"]:
                failed.append(f"{r['name']}: late rate over the layered solution {rate:.4f}")
            if abs(apart - 1.0) < TOLERANCE["apart"]:
                failed.append(f"{r['name']}: p0 only {apart:.4f} of the other force's closed form")
        if failed:
            print("FAILED: " + "; ".join(failed))
            return 1
        print(f"passed: each force within {TOLERANCE['undrained']:.0%} (p0) and "
              f"{TOLERANCE['rate']:.0%} (late rate) of the layered solution, p0 at least "
              f"{TOLERANCE['apart']:.0%} from the other force's closed form")
        return 0
    with open(args.table, "w") as f:
        f.write(table(base, results))
    figure(base, results, args.figure)
    return 0


if __name__ == "__main__":
    sys.exit(main())
