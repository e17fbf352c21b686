#!/usr/bin/env python3
"""The same input in our LAMMPS (lmp + the plugin) and in our LIGGGHTS must give the same
results: both run the same core on the same grains.

    cross_host.py CASE --liggghts BIN --lmp BIN --plugin-dir DIR [--np N --mpiexec mpirun]
                  --workdir DIR

CASE darcy: fix darcy/pressure on grains moved by fix move (inputs/in.cross_darcy),
darcy_relaxed: the same with `solver relaxed 0.05 1e-3`, darcy_seepage: with `seepage full`; walls:
fix wall/stress and shear/stress on grains moved by fix move and by nve/sphere
(inputs/in.cross_walls); messages: every bad input of porewater_cases.py, whose error
messages must be the same text in both hosts. Exits 77 (skipped) when lmp or the plugin is
not there (a build without the LAMMPS host).

Tolerance: none. The grains are read from the same data file in the same order and not
sorted (atom_modify sort 0 0), fix move computes their positions with the same arithmetic
in both hosts, nve/sphere integrates them with the same arithmetic, and every number of our
fixes comes from the same core code compiled the same way; the deposits are summed over the
grains in the same order and over the ranks by the same MPI (the same decomposition on both
hosts). So the thermo output (17 digits), the fluid grid (VTK, 16 digits) and every grain's
position, velocity and force (17 digits) must agree to the last digit, serial and on 2
ranks. (A 1- and a 2-rank run differ by round-off, about 1e-15 relative: another order of
the sums.)
"""
import argparse
import os
import sys

from harness import CheckFailed, Launch, expect, read_rows, read_vtk
import porewater_cases

SKIPPED = 77


def lammps_text(text):
    """A LIGGGHTS input of porewater_cases.py as the same input for LAMMPS."""
    return ("plugin load porewater.so\n" + text
            .replace("atom_style granular", "atom_style sphere")
            .replace("communicate single vel yes", "comm_modify vel yes"))


def same_tables(liggghts, lammps, what):
    """thermo tables of both hosts: the LIGGGHTS header drops the c_/f_/v_ prefixes, so the
    rows are compared by position"""
    expect(len(liggghts) == len(lammps), f"{what}: {len(liggghts)} vs {len(lammps)} runs")
    for a, b in zip(liggghts, lammps):
        rows = [list(r.values()) for r in a], [list(r.values()) for r in b]
        expect(rows[0] == rows[1], f"{what}: thermo output differs:\n{a[-1]}\n{b[-1]}")
        expect(rows[0], f"{what}: no thermo rows")


def scene(hosts, input_name, files, variables=None):
    """runs input_name in both hosts; compares thermo output, then each of `files` (VTK or
    grain dumps) across the hosts"""
    tables = {}
    for host, launch in hosts.items():
        tables[host], _ = launch.run(input_name, dict(variables or {}, host=host), f"log.{host}")
    same_tables(tables["liggghts"], tables["lammps"], input_name)
    for name in files:
        reader = read_vtk if name.endswith(".vtk") else read_rows
        data = {host: reader(launch.path(name)) for host, launch in hosts.items()}
        expect(data["liggghts"], f"{name}: empty")
        expect(data["liggghts"] == data["lammps"], f"{name} differs between LIGGGHTS and LAMMPS")
    return tables


def darcy(hosts):
    tables = scene(hosts, "in.cross_darcy", ["cross_500.vtk", "cross_grains.txt"])
    last = tables["liggghts"][-1][-1]
    # the scene exercises the fluid: grains move (dphi/dt), a tidal top, a Dirichlet bottom
    expect(abs(last["fl[1]"]) > 1.0 and last["fl[4]"] > 0, f"no fluid dynamics: {last}")
    forces = read_rows(hosts["liggghts"].path("cross_grains.txt"))
    expect(max(abs(r[8]) for r in forces.values()) > 1e-3, "no fluid force on the grains")
    print(f"[ report ] cross-host darcy (np {hosts['liggghts'].np}): thermo, grid and 192 grains' "
          "fluid forces identical to the last digit")


def darcy_relaxed(hosts):
    """the same scene with the original program's iteration (solver relaxed 0.05 1e-3), 100x
    less permeable: at the scene's own permeability the sweeps diverge (measured: the
    pressure overflows at step 6, and the run stops saying so)"""
    tables = scene(hosts, "in.cross_darcy", ["cross_500.vtk", "cross_grains.txt"], {"relaxed": 1, "kc": 1e-11})
    last = tables["liggghts"][-1][-1]
    # 500 Pa of tide against a 1e-3 relative change: the sweeps go on where p passes 0
    expect(abs(last["fl[1]"]) > 1.0 and last["fl[4]"] >= 1, f"no fluid dynamics: {last}")
    print(f"[ report ] cross-host darcy, solver relaxed (np {hosts['liggghts'].np}): thermo, "
          f"grid and grains identical to the last digit; {last['fl[4]']:.0f} sweeps at the last step")


def darcy_seepage(hosts):
    """the same scene with `seepage full`: identical in both hosts, and on the same pressure
    field as the default force (the grains' motion is prescribed) a different force: each
    cell's gradient over its own solid fraction, 1/(1 - phi_c) within the porosity clamp's
    1/(1 - 0.1) to 1/(1 - 0.9), interpolated to the grain. Where the gradients of a grain's
    corner cells share a sign the ratio to the default's force lies in that range; where
    they differ in sign it has no bound, so the check counts the components in the range
    and that the forces differ (the sums the factors conserve: darcy_seepage_sums)"""
    liggghts = hosts["liggghts"]
    liggghts.run("in.cross_darcy", {"host": "liggghts"}, "log.pressure")
    pressure = read_rows(liggghts.path("cross_grains.txt"))
    scene(hosts, "in.cross_darcy", ["cross_500.vtk", "cross_grains.txt"], {"seepage": "full"})
    full = read_rows(liggghts.path("cross_grains.txt"))
    ratios = [full[i][d] / pressure[i][d] for i in pressure for d in (6, 7)
              if abs(pressure[i][d]) > 1e-9]
    expect(len(ratios) > 100, f"only {len(ratios)} horizontal fluid forces to compare")
    inside = sum(1.0 / 0.9 <= r <= 1.0 / 0.1 for r in ratios)
    expect(inside > 0.5 * len(ratios), f"seepage full / pressure within [1/0.9, 1/0.1] for only "
           f"{inside} of {len(ratios)} components")
    expect(all(abs(r - 1.0) > 1e-9 for r in ratios), "seepage full left a force unchanged")
    print(f"[ report ] cross-host darcy, seepage full (np {liggghts.np}): thermo, grid and grains "
          f"identical to the last digit; horizontal force / the default's within [1/0.9, 1/0.1] "
          f"for {inside} of {len(ratios)} components ({min(ratios):.4f} .. {max(ratios):.4f})")


def walls(hosts):
    tables = scene(hosts, "in.cross_walls", ["walls_grains.txt"])
    last = tables["liggghts"][-1][-1]
    expect(last["w[3]"] > 1.0 and last["s[1]"] > 0.0, f"the wall and the plate did not act: {last}")
    print(f"[ report ] cross-host walls (np {hosts['liggghts'].np}): wall, plate and 192 grains "
          "identical to the last digit")


def messages(hosts):
    cases = porewater_cases.DARCY_BAD_INPUT + porewater_cases.WALL_BAD_INPUT
    for name, text, expected in cases:
        got = {"liggghts": hosts["liggghts"].error(text + "\n", name),
               "lammps": hosts["lammps"].error(lammps_text(text) + "\n", name)}
        expect(expected in got["liggghts"], f"{name}: {got['liggghts']!r} lacks {expected!r}")
        expect(got["liggghts"] == got["lammps"],
               f"{name}: LIGGGHTS says {got['liggghts']!r}, LAMMPS {got['lammps']!r}")
    print(f"[ report ] cross-host messages: {len(cases)} bad inputs, the same message in both hosts")


CASES = {"darcy": darcy, "darcy_relaxed": darcy_relaxed, "darcy_seepage": darcy_seepage,
         "walls": walls, "messages": messages}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("case", choices=sorted(CASES))
    parser.add_argument("--liggghts", required=True)
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--plugin-dir", required=True)
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--mpiexec", default="mpirun")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    plugin = os.path.join(args.plugin_dir, "porewater.so")
    if not (os.access(args.lmp, os.X_OK) and os.path.exists(plugin)):
        print(f"skipped: no LAMMPS host here ({args.lmp}, {plugin}): build the plugin first")
        return SKIPPED
    # lmp resolves `plugin load porewater.so` through LD_LIBRARY_PATH
    os.environ["LD_LIBRARY_PATH"] = os.pathsep.join(
        [os.path.abspath(args.plugin_dir), os.environ.get("LD_LIBRARY_PATH", "")])
    mpi = [args.mpiexec, "--oversubscribe", "-np", str(args.np)] if args.np > 1 else []
    hosts = {}
    for host, binary in (("liggghts", args.liggghts), ("lammps", args.lmp)):
        workdir = os.path.join(args.workdir, host)
        os.makedirs(workdir, exist_ok=True)
        hosts[host] = Launch(mpi + [os.path.abspath(binary)], workdir, args.np)
    try:
        CASES[args.case](hosts)
    except CheckFailed as failure:
        print(f"FAILED cross-host {args.case} (np {args.np}): {failure}")
        return 1
    print(f"passed cross-host {args.case} (np {args.np})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
