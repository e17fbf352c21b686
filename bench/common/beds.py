"""The beds and scenes the studies start from: beds packed and consolidated anew or the
shipped ones consolidated again at another stiffness, the friction while packing that starts a
bed at a target coordination, the Table S1 bed and beds prepared as it, and the shipped bed
tiled into the larger scenes the cost studies time (SCENES, tiled). Every bed runs with the
groups of the example kept for its own H and phi (examples/tidal_shear/groups.py: bed_groups)."""
import os
import shutil
import subprocess
import sys

from . import EXAMPLE, short
from .runs import REPLICATE_BED, load, prepare, run_lmp

sys.path.insert(0, EXAMPLE)
from groups import bed_geometry, bed_parameters as bed_groups    # noqa: E402,F401

KN = 1.16e7                               # examples/tidal_shear/in.params, reduced case
GAMMA_W = 100.0
SPREAD = 0.009                            # the original's log-normal spread of ln r
MU_PREP_ORIGINAL = 0.4 / 3                # paper_figures --part bisect: 4.53 at 0.4/3, 4.13 at 0.8/3
TARGET_Z = 4.58                           # the original run's first coordination (t = 0.01 s)
RESETTLE = 0.05                           # s: the shipped bed consolidated again at k_n x10,
                                          # x100 (as the Table S1 bed at Table S1's k_n)
# k_n x10, x100 with the wall dashpot's damping ratio gamma_w/(2 sqrt(k_n m)) kept
STIFF = {"kn10": {"kn": 10 * KN, "gamma_w": GAMMA_W * 10 ** 0.5},
         "kn100": {"kn": 100 * KN, "gamma_w": GAMMA_W * 10.0}}
SHIPPED_FRICTIONLESS = "consolidated_frictionless_0.data"
SMOKE_SETTLE = 1e-3                       # s: in.pack's and in.consolidate's settling, short setting


def prepare_bed(work, name, variables, shipped=None):
    """pack a bed (or take the shipped one, examples/tidal_shear's data file `shipped`) and
    consolidate it; the bed's data file"""
    d = os.path.join(work, "beds", name)
    out = os.path.join(d, "bed.data")
    if os.path.exists(out):
        return out
    prepare(d)
    variables = dict(variables, **short({}, {"settle_time": SMOKE_SETTLE}))
    source = shipped or "packed.data"
    if shipped is None:
        run_lmp(d, "in.pack", dict(variables, output=source), log="log.pack")
    run_lmp(d, "in.consolidate", dict(variables, input=source, output="bed.data"),
            log="log.consolidate")
    return out


def prepare_stiff_bed(d, variables, ranks=2):
    """a bed prepared as the Table S1 bed (in.pack and in.consolidate at the reduced case's
    k_n, in.consolidate again at Table S1's for RESETTLE s) in folder d, with the -var
    `variables` (its size, radii, mu_prep): its data file. Each stage's file is kept, so a
    preparation stopped midway goes on from the last."""
    out = os.path.join(d, "bed.data")
    if os.path.exists(out):
        return out
    prepare(d)
    soft = dict(variables, kn=KN, **short({}, {"settle_time": SMOKE_SETTLE}))
    if not os.path.exists(os.path.join(d, "packed.data")):
        run_lmp(d, "in.pack", dict(soft, output="packed.data"), ranks=ranks, log="log.pack")
    if not os.path.exists(os.path.join(d, "soft.data")):
        run_lmp(d, "in.consolidate", dict(soft, input="packed.data", output="soft.data"),
                ranks=ranks, log="log.consolidate_soft")
    run_lmp(d, "in.consolidate", dict(variables, **STIFF["kn100"], input="soft.data",
                                      output="bed.data.new",
                                      settle_time=short(RESETTLE, SMOKE_SETTLE)),
            ranks=ranks, log="log.consolidate")
    os.replace(os.path.join(d, "bed.data.new"), out)
    return out


def first_coordination(work, name, data, variables):
    """the coordination of the first time-series row (2.5 ms) of the tidal run on a bed"""
    d = os.path.join(work, "beds", name, "probe")
    prepare(d)
    shutil.copy(data, os.path.join(d, "bed.data"))
    run_lmp(d, "in.tidal_shear", dict(variables, data="bed.data", run_steps=1170))
    return load(os.path.join(d, "timeseries.txt"))["coordination"][0]


def bisect_mu_prep(work, jobs_map, low=0.0, high=0.4, rounds=3, tol=0.05, probe=None,
                   target=TARGET_Z):
    """mu_prep whose bed starts at target: two probes a round (both cores), the bracket cut
    to the third that holds the target; the probes (mu, z, H, phi) as rows. probe(mu): by
    default a bed of spread 0.009 and its first coordination by our count"""
    probes = []

    def first_ours(mu):
        name = "probe_mu%.4f" % mu
        data = prepare_bed(work, name, {"radius_spread": SPREAD, "mu_prep": mu})
        height, phi = bed_geometry(data)
        z = first_coordination(work, name, data, bed_groups(height, phi))
        return mu, z, height, phi

    for _ in range(rounds):
        mus = [low + (high - low) * f for f in (1.0 / 3.0, 2.0 / 3.0)]
        found = jobs_map(probe or first_ours, mus)
        probes += found
        best = min(found, key=lambda p: abs(p[1] - target))
        if abs(best[1] - target) < tol:
            break
        # coordination falls with friction: keep the third that brackets the target
        (m1, z1, _, _), (m2, z2, _, _) = found
        low, high = (low, m1) if target > z1 else ((m1, m2) if target > z2 else (m2, high))
    return sorted(probes)


# the Table S1 bed: in.pack and in.consolidate at the reduced case's k_n (10x the time step;
# preparation only, damped frictionless contacts), then in.consolidate at Table S1's from it
SOFT_KN = 1.16e7
SETTLE_TIME = 0.6                   # s: in.pack at most (its halt on the kinetic energy waits
                                    # for the slow compaction of frictionless grains: > 2 s)


def prepare_full(work, bed="frictionless", folder="full"):
    """the Table S1-sized bed (in.params -var bed BED: its preparation) in work/folder: in.pack
    and in.consolidate at the reduced case's k_n, then in.consolidate at Table S1's"""
    from .runs import TIDAL_SHEAR_TIMED
    d = os.path.join(work, folder)
    prepare(d, [TIDAL_SHEAR_TIMED])
    names = "_1.data" if bed == "original" else "_%s_1.data" % bed
    packed, final = "packed" + names, "consolidated" + names
    variables = {"bed": bed, "full": 1}
    steps = []
    if not os.path.exists(os.path.join(d, packed)):
        steps.append(("in.pack", dict(variables, kn=SOFT_KN, settle_time=SETTLE_TIME), 2, "log.pack"))
    if not os.path.exists(os.path.join(d, "consolidated_soft.data")):
        steps.append(("in.consolidate", dict(variables, kn=SOFT_KN, output="consolidated_soft.data"),
                      2, "log.consolidate_soft"))
    if not os.path.exists(os.path.join(d, final)):
        # at Table S1's k_n the plate and the grains settle in milliseconds (checked in the log)
        steps.append(("in.consolidate", dict(variables, input="consolidated_soft.data",
                                             settle_time=0.05), 2, "log.consolidate"))
    for infile, variables, ranks, log in steps:
        run_lmp(d, infile, variables, ranks=ranks, log=log)
    return d


# The scenes of the cost studies, -var fast 1 (scene: (grains, in.tidal_shear -var overrides)):
#   reduced   the reduced example (1,200 grains)
#   table_s1  the Table S1-sized scene: the default bed replicated 2 x 2 x 2 (in.replicate_bed:
#             9,600 grains in 0.52 x 0.26 x 0.5 m), -var full 1 at the reduced k_n it was
#             consolidated at (a step costs the same at any k_n; the bed stays at rest)
SCENES = {"reduced": (1200, {"fast": 1}),
          "table_s1": (9600, {"fast": 1, "full": 1, "kn": 1.16e7, "data": "bed_9600.data"})}
CELL_Z = 0.08176                # examples/tidal_shear/in.bed_original, the reduced case


def tiled(copies):
    """the reduced example tiled copies^3 times, its fluid cells with it: grains, -var
    overrides"""
    if copies == 1:
        return SCENES["reduced"]
    return (1200 * copies ** 3, {
        "fast": 1, "data": "bed_x%d.data" % copies, "copies": copies, "ngrains": 1200 * copies ** 3,
        "lx": 0.26 * copies, "ly": 0.13 * copies, "grid_x": 3 * copies, "grid_y": 2 * copies,
        "grid_z": 3 * copies + 1, "cell_z": CELL_Z})


def prepare_scene(variables, work, env, bed=None):
    """the example's inputs in work and a scene's bed (its `data`: the file `bed` if given,
    else the default bed tiled `copies` times per side, 2 unless given); the -var overrides
    for in.tidal_shear"""
    variables = dict(variables)
    copies = variables.pop("copies", 2)
    prepare(work, [REPLICATE_BED])
    if bed:
        shutil.copy(bed, os.path.join(work, variables["data"]))
    elif "data" in variables:
        subprocess.run(["lmp", "-in", "in.replicate_bed", "-log", "none", "-screen", "none",
                        "-var", "out", variables["data"]] + sum(
                            (["-var", n, str(copies)] for n in ("nx", "ny", "nz")), []),
                       cwd=work, env=env, check=True, capture_output=True)
    return variables
