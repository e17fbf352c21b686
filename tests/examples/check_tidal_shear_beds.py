#!/usr/bin/env python3
"""examples/tidal_shear starts from the bed and with the numerics its switches name.

Short runs (2 time-series rows, 2,340 steps) of:
- the default: the shipped bed prepared as the original program's (consolidated_0.data),
  velocity Verlet and the converged pressure solve;
- `-var original 1`: the same bed with the original's integrator (nve/sphere/ty3) and
  pressure iteration (relaxed; it ran: sweeps > 0);
- `-var bed frictionless`: the former default, consolidated_frictionless_0.data;
- `-var bed stiff`: the default's bed consolidated again at Table S1's grain stiffness
  (consolidated_stiff_0.data), run there (k_n 1.16e9, gamma_w x10) at eps 0.14: Delta t 0.2 of
  the default's (2 rows: 11,680 steps);
- `-var fast 1`: the default's bed and numerics at twice its time step (eps 0.14), the fluid
  every 25 steps (the default's fluid interval in seconds at every 50) and a skin of 0.2 r
  (2 rows: 1,150 steps, as a row is every 25 round(2.5 s / (1000 dt 25)) = 575 steps).
Each run's fluid cell height, mu_f and plate mass must be those that keep the reduced case's
groups for its bed's own H and phi (groups.py bed_parameters, to the 4 digits in.params
gives them: 5e-4), every value finite; the original's bed starts, by our count (compute
contact/atom), within 0.1 of 4.58, the target it was prepared for (4.53: the original run's
first row, which that run counted by its own rules; by those rules, compute
coordination/original, the bed starts lower, and no row's count by them may exceed ours,
whose pairs include theirs). `-var bed` with another value stops with an error naming the
allowed values. Grain dumps (`-var dump_every`) write positions at full precision (17
significant digits), and the mean of their per-grain count by the original's rules is the
time series' coordination_original of that step. The held base and the shear plate are the
grains within a diameter of the floor and of the highest centre, or, with groups.py --layers'
cuts, the original's (about a radius under the highest centre).

Usage: check_tidal_shear_beds.py --lmp LMP --plugin-dir DIR
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                       "tidal_shear")
sys.path.insert(0, EXAMPLE)
from groups import bed_geometry, bed_grains, bed_parameters, original_layer_cuts    # noqa: E402

# name: (-var switches, bed file, integrator, solver, coordination at the first row or None,
#        steps, {parameter: value} besides, where "dt" is relative to the default's)
CASES = {
    "default": ([], "consolidated_0.data", "nve/sphere", "converged", 4.58, 2340,
                {"fluid_every": 10, "skin": 0.4}),
    "original": (["original", "1"], "consolidated_0.data", "nve/sphere/ty3", "relaxed", 4.58, 2340,
                 {"dt": 1.0}),
    "frictionless": (["bed", "frictionless"], "consolidated_frictionless_0.data", "nve/sphere",
                     "converged", None, 2340, {}),
    "stiff": (["bed", "stiff"], "consolidated_stiff_0.data", "nve/sphere", "converged", None, 11680,
              {"dt": 0.2, "kn": 1.16e9, "gamma_w": 1000.0, "fluid_every": 10, "skin": 0.4}),
    "fast": (["fast", "1"], "consolidated_0.data", "nve/sphere", "converged", 4.58, 1150,
             {"dt": 2.0, "fluid_every": 25, "skin": 0.2}),
}
ok = True
default_dt = None


def check(cond, what):
    global ok
    print(("ok    " if cond else "FAIL  ") + what)
    ok &= bool(cond)


def run(lmp, work, env, switches, log, steps=2340):
    return subprocess.run([lmp, "-in", "in.tidal_shear", "-var", "run_steps", str(steps), "-log", log,
                           "-screen", "none"] + [a for i in range(0, len(switches), 2)
                                                 for a in ("-var", *switches[i:i + 2])],
                          cwd=work, env=env, capture_output=True, text=True)


def case(lmp, work, env, name):
    global default_dt
    switches, bed, integrator, solver, z_start, steps, besides = CASES[name]
    print("-- %s (%s)" % (name, " ".join(switches) or "no switches"))
    for f in ("timeseries.txt", "checkpoint_params.txt"):
        if os.path.exists(os.path.join(work, f)):
            os.remove(os.path.join(work, f))
    out = run(lmp, work, env, switches, "log." + name, steps)
    check(out.returncode == 0, "runs (exit %d)" % out.returncode)
    params = {}
    for line in open(os.path.join(work, "checkpoint_params.txt")):
        v = line.split()
        if len(v) == 4 and v[0] == "variable":
            params[v[1][3:]] = v[3]
    log = open(os.path.join(work, "log." + name)).read()
    names = open(os.path.join(work, "timeseries.txt")).readline().lstrip("# ").split()
    rows = [[float(x) for x in l.split()] for l in open(os.path.join(work, "timeseries.txt"))
            if not l.startswith("#")]
    col = {n: k for k, n in enumerate(names)}
    check("read_data %s" % bed in log, "starts from %s" % bed)
    check(params.get("integrator") == integrator, "integrator %s" % params.get("integrator"))
    check(params.get("solver") == solver, "solver %s" % params.get("solver"))
    if name == "default":
        default_dt = float(params["dt"])
    for key, value in besides.items():
        got = float(params[key]) / (default_dt if key == "dt" else 1.0)
        check(abs(got - value) < 1e-12 * value, "%s %s (%s%g)" % (
            key, params[key], "the default's x " if key == "dt" else "", value))
    height, phi = bed_geometry(os.path.join(EXAMPLE, bed))
    for key, value in bed_parameters(height, phi).items():
        got = float(params[key])
        check(abs(got / value - 1) < 5e-4, "%s %s keeps the groups for H %.4f, phi %.4f (%.6g)"
              % (key, params[key], height, phi, value))
    if z_start is not None:
        z0 = rows[0][col["coordination"]]
        check(abs(z0 - z_start) < 0.1, "starts at coordination %.3f by our count (prepared for "
              "%.2f in it)" % (z0, z_start))
    check(all(0 < r[col["coordination_original"]] <= r[col["coordination"]] for r in rows),
          "the original's count %s within ours %s" % (
              [r[col["coordination_original"]] for r in rows], [r[col["coordination"]] for r in rows]))
    check(len(rows) == 2 and all(math.isfinite(x) for r in rows for x in r), "2 finite rows")
    if solver == "relaxed":
        check(all(r[col["solver_iters"]] > 0 for r in rows), "relaxed sweeps %s" % (
            [r[col["solver_iters"]] for r in rows]))


def dumps(lmp, work, env):
    """a grain dump of the first time-series row's step: positions at 17 significant digits,
    the mean of its per-grain original count equal to that row's coordination_original"""
    print("-- dump_every 1170")
    out = run(lmp, work, env, ["dump_every", "1170"], "log.dump", 1170)
    check(out.returncode == 0, "runs (exit %d)" % out.returncode)
    lines = open(os.path.join(work, "grains_1170.dump")).read().splitlines()
    names = lines[8].split()[2:]
    grains = [dict(zip(names, l.split())) for l in lines[9:]]
    digits = sorted(len(g["x"].lstrip("-").split("e")[0].replace(".", "").lstrip("0"))
                    for g in grains)[len(grains) // 2]    # the median grain
    check(digits >= 15, "positions with %d significant digits (the median grain)" % digits)
    mean = sum(float(g["c_coordination_original"]) for g in grains) / len(grains)
    header, row = (l.lstrip("#").split() for l in
                   open(os.path.join(work, "timeseries.txt")).read().splitlines()[:2])
    series = row[header.index("coordination_original")]
    check(abs(mean - float(series)) < 1e-12, "the dump's original count %.6f is the time "
          "series' %s" % (mean, series))


def group_size(log, group):
    return int(next(l.split()[0] for l in log.splitlines() if l.endswith("atoms in group " + group)))


def layers(lmp, work, env):
    """the held base and the shear plate: by default the grains whose centres lie within a
    diameter of the floor and of the highest centre; with groups.py --layers' cuts the
    original's (sphere.py shear(): a diameter from the lowest and highest grain surfaces, the
    largest diameter of the lower and upper 30 %), on the shipped bed whose radii spread by
    0.9 %: the plate the grains above the highest centre less 0.9-1.1 radii"""
    radius, z = bed_grains(os.path.join(EXAMPLE, "consolidated_0.data"))
    r, top = 0.01, max(z)
    bottom_cut, top_cut = original_layer_cuts(os.path.join(EXAMPLE, "consolidated_0.data"))
    for name, switches, bottom, plate in (
            ("default", [], sum(zi < 2 * r for zi in z), sum(zi > top - 2 * r for zi in z)),
            ("original", ["bottom_cut", repr(bottom_cut), "top_cut", repr(top_cut)],
             sum(zi < bottom_cut for zi in z), sum(zi > top_cut for zi in z))):
        print("-- layers %s" % name)
        out = run(lmp, work, env, switches, "log.layers_" + name, 10)
        check(out.returncode == 0, "runs (exit %d)" % out.returncode)
        log = open(os.path.join(work, "log.layers_" + name)).read()
        got = group_size(log, "bottom"), group_size(log, "top")
        check(got == (bottom, plate), "held base and plate %s grains (the data file: %d, %d)"
              % (got, bottom, plate))
    check(top - 1.1 * r < top_cut < top - 0.9 * r and 1.9 * r < bottom_cut < 2.1 * r,
          "the original's plate from %.4f m (highest centre %.4f m), base under %.4f m"
          % (top_cut, top, bottom_cut))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--plugin-dir", required=True)
    args = ap.parse_args()
    work = tempfile.mkdtemp()
    try:
        for name in os.listdir(EXAMPLE):
            if name.startswith("in.") or name.endswith(".data"):
                shutil.copy(os.path.join(EXAMPLE, name), work)
        env = dict(os.environ, OMP_NUM_THREADS="1",
                   LD_LIBRARY_PATH=args.plugin_dir + ":" + os.environ.get("LD_LIBRARY_PATH", ""))
        for name in CASES:
            case(args.lmp, work, env, name)
        dumps(args.lmp, work, env)
        layers(args.lmp, work, env)
        print("-- bed packed")
        out = run(args.lmp, work, env, ["bed", "packed"], "log.bad")
        said = out.stdout + open(os.path.join(work, "log.bad")).read()
        check(out.returncode != 0, "-var bed packed stops (exit %d)" % out.returncode)
        check("ERROR: bed is packed: original (the default), stiff or frictionless" in said,
              "and says which values are allowed")
        return 0 if ok else 1
    finally:
        shutil.rmtree(work)


if __name__ == "__main__":
    sys.exit(main())
