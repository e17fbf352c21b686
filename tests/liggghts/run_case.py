#!/usr/bin/env python3
"""Runs one LIGGGHTS test case through our launcher and checks its thermo output.

    run_case.py CASE --launcher BIN [--np N --mpiexec mpirun] --workdir DIR

The inputs are in inputs/, the meshes in meshes/ (next to this file). The cases here run
LIGGGHTS' own models through the launcher: each names its input, its -var settings and a
check of the thermo table(s) of the log. The cases of the package's styles are in
porewater_cases.py. The tolerances are explained where they are set.
"""
import argparse
import math
import os
import sys

from harness import CheckFailed, Launch, close, expect, run, run_input
import porewater_cases


# ---- checks -------------------------------------------------------------------------------

GRAIN_MASS = 2000 * 4 / 3 * math.pi * 0.005**3    # d = 10 mm, 2000 kg/m^3


def check_addforce(tables, log):
    rows = tables[-1]
    expect("porewater styles: fix darcy/pressure, fix wall/stress, fix shear/stress, "
           "fix pwtest/addforce" in log, "registered styles not reported")
    expect("pwtest/addforce: fix push pushes group pushed" in log, "fix init() not reached")
    expect(len(rows) == 11, f"{len(rows)} thermo rows")
    a = 2e-3 / GRAIN_MASS
    for r in rows:
        t = r["Step"] * 1e-4
        # f_push and f_push[3] are sums over ranks: 3 grains, 3 * 2e-3 N
        close(r["push"], 3.0, 0.0, "grains pushed (sum over ranks)")
        close(r["push[3]"], 6e-3, 1e-18, "force added (sum over ranks)")
        # constant force: velocity Verlet is exact up to rounding (1e-12 of 0.05 m)
        close(r["z1"], 0.05 + 0.5 * a * t * t, 1e-12, f"z of a pushed grain at t={t:g}")
        close(r["z4"], r["z1"], 0.0, "the two pushed grains")
        close(r["z3"], 0.05, 0.0, "the grain outside the group")


def check_undamped(tables, log):
    rows = tables[-1]
    first, last = rows[0], rows[-1]
    # head-on collision of equal grains, no damping: velocities swap; the symplectic
    # integrator's error at the end of a contact (kn dt^2 / m ~ 0.2 % of one contact's
    # 70 steps) leaves |v| within 1e-3
    close(last["vx1"], -first["vx1"], 1e-3 * abs(first["vx1"]), "left grain after the collision")
    close(last["vx2"], -first["vx2"], 1e-3 * abs(first["vx2"]), "right grain after the collision")
    close(last["vz1"], 0.0, 0.0, "no gravity on the colliding grains")
    # frictionless mesh floor: the bouncing grain keeps its horizontal velocity exactly
    for r in rows:
        close(r["vx3"], 0.05, 1e-14, f"horizontal velocity at step {r['Step']:g}")
    # ... and its energy: sampled out of contact (z > radius), within 1e-3 (three bounces)
    energy = lambda r: 0.5 * (r["vx3"]**2 + r["vz3"]**2) + 9.81 * r["z3"]
    free = [r for r in rows if r["z3"] > 0.0051]
    bounces = sum(1 for a, b in zip(free, free[1:]) if a["vz3"] < 0 < b["vz3"])
    expect(bounces >= 2, f"{bounces} bounces")
    e0 = energy(first)
    for r in free:
        close(energy(r), e0, 1e-3 * e0, f"energy per mass at step {r['Step']:g}")


def check_settle(tables, log):
    expect(len(tables) == 2, f"{len(tables)} runs")
    rows = tables[0] + tables[1]
    expect(all(r["Atoms"] == 108 for r in rows), "grains lost")
    last = rows[-1]
    # the stack collapses onto the floor: no grain sinks by more than 10 % of its radius
    expect(last["zmax"] < rows[0]["zmax"] - 0.005, f"stack did not collapse: {last['zmax']}")
    expect(min(r["zmin"] for r in rows) > 0.0045, "a grain sank into the mesh floor")
    # restitution 0.3: most of the potential energy released is dissipated (an undamped
    # stack would turn all of it into kinetic energy)
    released = 2500 / 2000 * GRAIN_MASS * 9.81 * (rows[0]["zsum"] - last["zsum"])
    expect(last["KinEng"] < 0.25 * released,
           f"kinetic energy {last['KinEng']:g} J of {released:g} J released: not damped")


def check_move(tables, log):
    rows = tables[-1]
    expect(all(r["Atoms"] == 48 for r in rows), "grains lost")
    for r in rows:
        t = r["Step"] * 1e-5
        # prescribed motion is exact up to the rounding of x0 + v t
        close(r["x1"], 0.02 * t, 1e-12, f"fix move x at t={t:g}")
        close(r["y1"], 0.0, 1e-15, "fix move y")
        close(r["z1"], 0.01, 1e-15, "fix move z")
        close(r["lid[9]"], 0.0355 - 0.02 * t, 1e-12, f"fix move/mesh lid at t={t:g}")
    # the weight of the 32 free grains is 0.41 N; the compacted stack pushes harder
    expect(max(r["lid[3]"] for r in rows) > 1.0, "the lid never pressed on the grains")


def check_servo(tables, log):
    rows = tables[-1]
    last = rows[-1]
    # the servo (kp 0.5) settles within 0.03 % of the target in these 15000 steps; 2 %
    # leaves room for the contact oscillations of another decomposition
    close(last["plate[3]"], 5.0, 0.1, "force of the grains on the servo plate")
    expect(last["plate[9]"] < 0.036 - 0.001, "the plate did not move down")


def check_settle_restart(tables, log, first_tables):
    # LIGGGHTS restores grains, velocities and contact histories bit for bit: the
    # continuation repeats the second run of in.settle (same decomposition) to every digit
    # printed. (A single uninterrupted run differs from both after a few thousand steps:
    # the set-up of each run re-sorts the grains and rebuilds the neighbour lists, which
    # changes the order of the force sums.)
    expect(len(tables) == 1, f"{len(tables)} runs")
    expect(tables[0] == first_tables[1], "restart continuation differs from the second run:\n"
           f"{tables[0][-1]}\n{first_tables[1][-1]}")


CASES = {
    "addforce": dict(input="in.addforce", vars={}, check=check_addforce,
                     convert=("addforce.restart", "\n4 atoms\n")),
    "undamped_hooke_stiffness": dict(input="in.undamped", vars={"model": "hooke_stiffness"},
                                     check=check_undamped),
    "undamped_hooke": dict(input="in.undamped", vars={"model": "hooke"}, check=check_undamped),
    "settle_hooke": dict(input="in.settle", vars={"model": "hooke"}, check=check_settle,
                         restart=("in.settle_restart", check_settle_restart)),
    "settle_hertz": dict(input="in.settle", vars={"model": "hertz"}, check=check_settle,
                         restart=("in.settle_restart", check_settle_restart)),
    "move": dict(input="in.move", vars={}, check=check_move),
    "servo": dict(input="in.servo", vars={"force": "5"}, check=check_servo),
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", choices=sorted(CASES) + sorted(porewater_cases.CASES) + ["help"])
    parser.add_argument("--launcher", required=True)
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--mpiexec", default="mpirun")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    args.launcher = os.path.abspath(args.launcher)

    os.makedirs(args.workdir, exist_ok=True)
    mpi = [args.mpiexec, "--oversubscribe", "-np", str(args.np)] if args.np > 1 else []
    try:
        if args.case == "help":
            # -help lists the package's styles before LIGGGHTS' own list (LIGGGHTS exits
            # with status 1 after its help text)
            out = run([args.launcher, "-help"], args.workdir, "liggghts -help", (0, 1))
            expect("Styles added by porewater: fix darcy/pressure, fix wall/stress, "
                   "fix shear/stress, fix pwtest/addforce" in out, "styles not listed")
            expect("Style options compiled with this executable" in out, "LIGGGHTS' help missing")
        elif args.case in porewater_cases.CASES:
            porewater_cases.CASES[args.case](Launch(mpi + [args.launcher], args.workdir, args.np))
        else:
            case = CASES[args.case]
            tables = run_input(mpi + [args.launcher], case["input"], case["vars"], args.workdir)
            case["check"](*tables)
            if "restart" in case:
                restart_input, check = case["restart"]
                check(*run_input(mpi + [args.launcher], restart_input, case["vars"],
                                 args.workdir), tables[0])
            if "convert" in case:
                # liggghts -restart RESTART DATA: converted after the styles are added
                restart_file, expected = case["convert"]
                run(mpi + [args.launcher, "-restart", restart_file, "converted.data",
                           "-log", "log.convert"], args.workdir, "liggghts -restart")
                with open(os.path.join(args.workdir, "converted.data")) as f:
                    expect(expected in f.read(), f"the data file lacks {expected!r}")
    except CheckFailed as failure:
        print(f"FAILED {args.case} (np {args.np}): {failure}")
        return 1
    print(f"passed {args.case} (np {args.np})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
