"""The package's styles in LIGGGHTS, each case checked against an analytic answer: fix
darcy/pressure (tidal column, one grain, fluidisation under each seepage force, the grain
forces summed on a bed whose porosity steps, undrained compaction, restart, bad
input) and fix wall/stress and shear/stress (free wall, loaded stack, rigid plate). Every
tolerance is explained where it is set. A case is a function of a harness.Launch."""
import math
import os
import sys

from harness import CheckFailed, close, expect, read_profile, read_rows, read_vtk

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from analytic_solutions import tidal_column, undrained_pressure_change    # noqa: E402

# ---- fix darcy/pressure -------------------------------------------------------------------


def darcy_column(launch):
    """Tidal top over a grain-free column (D = 1, f = 10 Hz, skin depth 0.178, column 1 =
    5.6 skin depths) against the exact solution of the continuous problem, start-up
    transient included, at 60 and at 120 layers (time step halved with the spacing)."""
    amplitude, omega = 2.0, 2 * math.pi * 10
    worst = {}
    for layers, dt, steps in ((60, 5e-4, 2000), (120, 2.5e-4, 4000)):
        log = f"log.column{layers}"
        tables, _ = launch.run("in.darcy_column", {"layers": layers, "dt": dt, "steps": steps},
                               log)
        for r in tables[-1]:
            # the top value the fix applied is the variable's at the current time
            close(r["fl[6]"], amplitude * math.sin(omega * r["Time"]), 1e-12, "top pressure")
            close(r["fl[6]"], r["ptop"], 0.0, "top pressure vs the variable")
        blocks = read_profile(launch.path("profile.txt"))
        expect(len(blocks) == 101, f"{len(blocks)} profile blocks")    # every 0.01 s
        worst[layers] = max(abs(row[1] - tidal_column(row[0], time, 1.0, 1.0, amplitude, omega))
                            for time, rows in blocks.values() for row in rows)
        os.rename(launch.path("profile.txt"), launch.path(f"profile{layers}.txt"))
    print(f"[ report ] tidal column: max |p - exact| / A = {worst[60] / amplitude:.3e} (60 layers), "
          f"{worst[120] / amplitude:.3e} (120 layers), ratio {worst[60] / worst[120]:.2f}")
    # Crank-Nicolson on a cell-centred grid is second order in dz and dt: measured 2.05e-3 A
    # at 60 layers, 5.3e-4 A at 120 (ratio 3.9). 3e-3 A holds that; the top face half a cell
    # off, a one-step lag of the boundary value or a wrong diffusivity by 1 % each add more
    # (dz/delta = 9 %, omega dt = 3 %, 1 % of the phase lag of 5.6 rad)
    expect(worst[60] <= 3e-3 * amplitude, f"error {worst[60] / amplitude:.3e} A at 60 layers")
    expect(3.4 <= worst[60] / worst[120] <= 4.6,
           f"error ratio {worst[60] / worst[120]:.2f}: not second order")


GRAIN_VOLUME = 4.0 / 3.0 * math.pi * 0.01**3    # the grain of in.darcy_grain


def darcy_grain(launch):
    """One static grain: in a steady gradient it feels -V grad p, in still water rho_f V g."""
    tables, _ = launch.run("in.darcy_grain", {"fluid": "bottom 1000 top -500 tol 1e-13",
                                              "steps": 300}, "log.gradient")
    last = tables[-1][-1]
    # D = 1: the slowest mode decays as exp(-pi^2 t), 300 steps of 0.02: e^-59; p is then
    # linear, 1000 - 1500 z, to the CG tolerance 1e-13 * 1000 (LAMMPS measured 7e-10)
    p = read_vtk(launch.path("grid_300.vtk"))["pressure"]
    worst = max(abs(p[c] - (1000.0 - 1500.0 * ((c // 4) + 0.5) / 10)) for c in range(40))
    print(f"[ report ] linear profile: max |p - exact| = {worst:.2e} of 1000")
    expect(worst < 5e-9, f"p departs from the linear profile by {worst:.3g}")
    expected = GRAIN_VOLUME * 1500.0    # -V dp/dz, dp/dz = -1500
    # the interpolated gradient is exact for a linear p; error from the solve: 5e-9/0.1
    close(last["fz"], expected, 5e-8 * GRAIN_VOLUME, "-V dp/dz on the grain")
    close(last["fx"], 0.0, 1e-12 * expected, "x force (laterally uniform p)")
    close(last["fy"], 0.0, 1e-12 * expected, "y force")
    for d, name in enumerate(("fx", "fy", "fz")):
        close(last[f"fluid[{d + 1}]"], last[name], 0.0, "the fluid force is the only force")
    close(last["fl[6]"], -500.0, 0.0, "top pressure output")

    tables, _ = launch.run("in.darcy_grain", {"fluid": "density 1000 gravity 0 0 -9.81",
                                              "steps": 10}, "log.still")
    last = tables[-1][-1]
    close(last["fl[3]"], 0.0, 0.0, "still water: max |p|")
    # buoyancy rho_f V g, the grain's own arithmetic: to the last bits
    close(last["fz"], GRAIN_VOLUME * 1000.0 * 9.81, 4e-16 * GRAIN_VOLUME * 1000.0 * 9.81,
          "buoyancy")
    close(last["fx"], 0.0, 0.0, "no x force in still water")
    close(last["fy"], 0.0, 0.0, "no y force in still water")


CRITICAL_GRADIENT = (2600.0 - 1000.0) * 9.81    # (rho_s - rho_f) g, Pa/m: floats a grain


def darcy_fluidise(launch):
    """The bed under an upward gradient G stays at 0.9 G_c and lifts at 2 G_c."""
    rise = {}
    for factor in (0.9, 2.0):
        p_bottom = factor * CRITICAL_GRADIENT * 0.2
        tables, _ = launch.run("in.darcy_bed", {"pb": repr(p_bottom), "every": 1},
                               f"log.bed{factor}")
        held, moving = tables[0][-1], tables[1]
        # steady p with the grains held: linear, largest in the bottom cells (z = 0.01)
        close(held["fl[3]"], p_bottom * (1.0 - 0.01 / 0.2), 1e-6 * CRITICAL_GRADIENT,
              f"bottom-cell pressure at {factor} G_c")
        expect(all(r["Atoms"] == 320 for r in moving), "grains lost")
        rise[factor] = moving[-1]["zmean"] - held["zmean"]
    print(f"[ report ] fluidisation: mean rise {rise[0.9]:.3e} m at 0.9 G_c, {rise[2.0]:.3e} m "
          "at 2 G_c")
    # at rest: contacts carry the remaining 10 % of the buoyant weight (elastic, ~1e-7 m)
    expect(abs(rise[0.9]) < 1e-4, f"the bed moved {rise[0.9]:.3g} m below G_c")    # 1 % of d
    # lifted: the net upward force is the buoyant weight (G/G_c - 1), a = 6.04 m/s^2, 7.55 mm
    # in 0.05 s if the fluid let it; the dilating bed's suction holds it back (LAMMPS: same
    # bound). It can never rise faster than that free rise
    free_rise = 0.5 * (2.0 - 1.0) * CRITICAL_GRADIENT / 2600.0 * 0.05**2
    expect(3e-3 < rise[2.0] <= free_rise, f"rise {rise[2.0]:.4g} m at 2 G_c (free rise "
           f"{free_rise:.4g} m)")


def darcy_fluidise_full(launch):
    """Under seepage full the bed floats at (1 - phi)(rho_s - rho_f) g (in.darcy_bed_full, phi
    = 1 - pi/6 in every cell): it stays at 0.9 of that gradient and lifts at 2, as on LAMMPS
    (tests/lammps/test_fix_darcy_seepage.cpp)."""
    critical = (math.pi / 6.0) * CRITICAL_GRADIENT
    rise = {}
    for factor in (0.9, 2.0):
        tables, _ = launch.run("in.darcy_bed_full", {"pb": repr(factor * critical * 0.04)},
                               f"log.full{factor}")
        held, moving = tables[0][-1], tables[1]
        close(held["fl[2]"], 1.0 - math.pi / 6.0, 1e-12, "the bed's porosity, uniform")
        expect(all(r["Atoms"] == 256 for r in moving), "grains lost")
        rise[factor] = moving[-1]["zmean"] - held["zmean"]
    print(f"[ report ] seepage full, fluidisation: mean rise {rise[0.9]:.3e} m at 0.9x, "
          f"{rise[2.0]:.3e} m at 2x (1 - phi)(rho_s - rho_f) g")
    # as darcy_fluidise: at rest within 1 % of a diameter, lifted by more than 3 mm
    expect(abs(rise[0.9]) < 1e-4, f"the bed moved {rise[0.9]:.3g} m below its critical gradient")
    expect(rise[2.0] > 3e-3, f"rise {rise[2.0]:.4g} m at twice its critical gradient")


def darcy_seepage_sums(launch):
    """On a bed whose porosity steps (in.darcy_step), the grains' fluid forces sum to the
    water's force on the cells under seepage full, 1500 Pa x (8a)(6a) = 28.8 N, and to its
    solids' share -sum_c dp/dz_c (1 - phi_c) V_cell under seepage pressure (from the VTK
    file's cell pressures and porosities, the fix's central differences and Dirichlet
    ghosts), both to round-off, as on LAMMPS (tests/lammps/test_fix_darcy_seepage.cpp)."""
    a = 0.02
    nx, ny, nz, v_cell, dz = 4, 3, 4, 8 * a**3, 2 * a
    total = 1500.0 * (8 * a) * (6 * a)
    for seepage in ("full", "pressure"):
        tables, _ = launch.run("in.darcy_step", {"seepage": seepage}, f"log.step_{seepage}")
        last = tables[-1][-1]
        fields = read_vtk(launch.path(f"step_{seepage}_300.vtk"))
        p, phi = fields["pressure"], fields["porosity"]
        cells = 0.0
        for k in range(nz):
            for c in range(k * nx * ny, (k + 1) * nx * ny):
                below = p[c - nx * ny] if k > 0 else 2 * 1000.0 - p[c]
                above = p[c + nx * ny] if k < nz - 1 else 2 * -500.0 - p[c]
                share = 1.0 if seepage == "full" else 1.0 - phi[c]
                cells -= (above - below) / (2 * dz) * share * v_cell
        print(f"[ report ] seepage {seepage}: grains {last['fluid[3]']:.15g} N, cells "
              f"{cells:.15g} N, porosity {min(phi):.3f}-{max(phi):.3f}")
        expect(min(phi) < 0.5 and max(phi) > 0.7, "the porosity step is not there")
        # the VTK file's values are printed to 17 digits: 1e-12 of the total, as on LAMMPS
        close(last["fluid[3]"], cells, 1e-12 * total, f"{seepage}: the grains' sum")
        close(last["fluid[1]"], 0.0, 1e-12 * total, f"{seepage}: the x sum")
        close(last["fluid[2]"], 0.0, 1e-12 * total, f"{seepage}: the y sum")
        if seepage == "full":
            close(last["fluid[3]"], total, 1e-12 * total, "full: the water's force")


def darcy_mesh_floor(launch):
    """LIGGGHTS' own model (pair and wall gran model hertz, damped) and a mesh wall with the
    fix: grains dropped onto a mesh floor in still water come to rest carrying their buoyant
    weight on the floor, and the fluid pushes them up with rho_f V g."""
    tables, _ = launch.run("in.darcy_mesh_floor", log_name="log.mesh_floor")
    last = tables[-1][-1]
    volume = 4.0 / 3.0 * math.pi * 0.005**3
    weight, buoyancy = 36 * 2500.0 * volume * 9.81, 36 * 1000.0 * volume * 9.81
    # at rest (kinetic energy below 1e-20 J; measured 5e-30) the pore pressure has drained
    # to 1e-10 Pa: -V grad p is 1e-14 of the buoyancy, and the floor (fix
    # mesh/surface/stress, the force on the mesh: down) carries the rest of the weight
    # (measured to 2e-13)
    expect(last["KinEng"] < 1e-20, f"not at rest: {last['KinEng']} J")
    close(last["fluid"], buoyancy, 1e-9 * buoyancy, "fluid force on the grains (buoyancy)")
    close(-last["floor[3]"], weight - buoyancy, 1e-9 * weight, "force on the mesh floor")
    expect(abs(last["fl[3]"]) < 1e-6, f"pressure {last['fl[3]']} Pa left at rest")
    expect(last["zmin"] > 0.005 - 1e-4, "a grain sank into the mesh floor")


def darcy_undrained(launch):
    """Closed, impermeable box compacted by grains under fix move: each cell's pressure
    follows its porosity, beta phi dp = -dphi/(1 - phi)."""
    tables, _ = launch.run("in.darcy_undrained")
    expect(all(r["Atoms"] == 32 for r in tables[-1]), "grains lost")
    fields = read_vtk(launch.path("undrained_2000.vtk"))
    # porosity from the geometry: cell A holds the hat weights 1 - d/dx of the 32 grains at
    # distance d from its centre, cell B the rest (one cell in y and z: weight 1 there)
    solid = 32 * 4.0 / 3.0 * math.pi * 0.012**3 / 0.1**3
    def porosity(d):
        return 1.0 - solid * (1.0 - d / 0.1), 1.0 - solid * d / 0.1
    start, end = porosity(0.025), porosity(0.023)
    beta = 1e-6
    for c, name in enumerate(("A (compacted)", "B (dilated)")):
        close(fields["porosity"][c], end[c], 1e-14, f"porosity of cell {name}")
        p = fields["pressure"][c]
        exact = undrained_pressure_change(start[c], end[c], beta)
        middle = 0.5 * (start[c] + end[c])
        linear = -(end[c] - start[c]) / (beta * middle * (1.0 - middle))
        print(f"[ report ] undrained cell {name}: p = {p:.10g} Pa, exact {exact:.10g} "
              f"(rel. {(p - exact) / exact:.2e}), -dphi/(beta phi (1-phi)) {linear:.10g}")
        expect((p > 0) == (c == 0), f"cell {name}: pressure {p} of the wrong sign")
        # the fix's forcing is explicit with phi at the step's end (right-endpoint sum over
        # 2000 fluid steps): relative error |dphi per step| |g'/g| / 2 = 2e-5 in B (g =
        # 1/(phi (1-phi))); diffusion through k = 1e-24 m^2 is 1e-10 of it
        close(p, exact, 1e-4 * abs(exact), f"pressure of cell {name}")
        # the linearised form with phi at the midpoint: its own error (dphi)^2 g''/(24 g)
        # is 5e-4 in B
        close(p, linear, 1e-3 * abs(exact), f"pressure of cell {name}, linearised")


def darcy_restart(launch):
    """write_restart between two runs, read_restart: the continuation repeats the second run."""
    variables = {"pb": repr(2.0 * CRITICAL_GRADIENT * 0.2), "every": 3}
    whole, _ = launch.run("in.darcy_bed_split", dict(variables, prefix="whole"), "log.whole")
    split, _ = launch.run("in.darcy_bed_restart", dict(variables, prefix="split", initial=123),
                          "log.split")
    expect(len(whole) == 2 and len(split) == 1, "runs")
    expect(whole[1][-1]["KinEng"] > 0.0 and whole[1][-1]["zmean"] > whole[0][0]["zmean"] + 1e-4,
           "the bed is not lifting")
    # `every 3`: the split at step 200 falls between fluid steps (198, 201). LIGGGHTS
    # restores grains, velocities and contact histories bit for bit and the fix its fluid
    # (p, phi, the fluid clock); `initial 123` is ignored. Same decomposition, same order of
    # operations: every printed digit (17) and every cell must agree
    expect(split[0] == whole[1], "the continuation differs from the second run:\n"
           f"{split[0][-1]}\n{whole[1][-1]}")
    grains = (read_rows(launch.path("whole_grains.txt")), read_rows(launch.path("split_grains.txt")))
    expect(len(grains[0]) == 320 and grains[0] == grains[1], "grains differ after the restart")
    grids = (read_vtk(launch.path("whole_grid_400.vtk")), read_vtk(launch.path("split_grid_400.vtk")))
    expect(grids[0] == grids[1], "the fluid grids differ after the restart")
    expect(max(abs(p) for p in grids[0]["pressure"]) > 1000.0, "no pressure field")


# Bad input: (name, input text after the box, expected part of the message). The same
# inputs run through LAMMPS in the cross-host test, which compares the two messages.
COLUMN = ("atom_style granular\natom_modify map array sort 0 0\nboundary p p f\nnewton off\n"
          "communicate single vel yes\nunits si\nregion box block 0 1 0 1 0 1 units box\n"
          "create_box 1 box\n")
UNIT_FLUID = " viscosity 1 compressibility 1 density 1 permeability 1 kmax 0.9"
FIX = "fix bad all darcy/pressure grid 2 2 4"
DARCY_BAD_INPUT = [
    ("periodic_z", COLUMN.replace("boundary p p f", "boundary p p p") + FIX + UNIT_FLUID,
     "fix darcy/pressure requires boundaries periodic in x and y and non-periodic in z"),
    ("atomic", COLUMN.replace("atom_style granular", "atom_style atomic") + FIX + UNIT_FLUID,
     "fix darcy/pressure requires atom_style sphere"),
    ("missing", COLUMN + FIX + " viscosity 1 density 1 permeability 1",
     "missing required keyword(s): compressibility"),
    ("porosity", COLUMN + FIX + UNIT_FLUID + " porosity 0.2 1.0",
     "porosity MIN MAX needs 0 < MIN <= MAX < 1"),
    ("bottom", COLUMN + FIX + UNIT_FLUID + " bottom closed",
     "bottom expects noflow, a finite number or v_name, got 'closed'"),
    ("top", COLUMN + FIX + UNIT_FLUID + " top closed",
     "top expects noflow, a finite number or v_name, got 'closed'"),
    ("every", COLUMN + FIX + UNIT_FLUID + " every 0", "every expects an integer >= 1, got '0'"),
    ("seepage", COLUMN + FIX + UNIT_FLUID + " seepage drag",
     "seepage expects pressure or full, got 'drag'"),
    ("viscosity", COLUMN + FIX + UNIT_FLUID + " viscosity -1",
     "viscosity expects a finite number > 0, got '-1'"),
    ("gravity", COLUMN + FIX + UNIT_FLUID + " gravity 0 0",
     "gravity expects a finite number, but the command ends there"),
    ("keyword", COLUMN + FIX + UNIT_FLUID + " damping 1",
     "unknown keyword 'damping' (allowed: grid, viscosity,"),
    ("grid", COLUMN + "fix bad all darcy/pressure grid 2 0 4" + UNIT_FLUID,
     "grid expects an integer >= 1, got '0'"),
    ("no_variable", COLUMN + FIX + UNIT_FLUID + " top v_nowhere\nrun 0",
     "fix darcy/pressure: variable nowhere for top does not exist"),
    ("novertical_group", COLUMN + FIX + UNIT_FLUID + " novertical nope\nrun 0",
     "fix darcy/pressure bad: novertical group nope does not exist"),
    ("atom_variable", COLUMN + "variable atomic atom x\n" + FIX + UNIT_FLUID + " ztop v_atomic\nrun 0",
     "fix darcy/pressure: variable atomic for ztop is not equal-style"),
    ("not_converged", COLUMN + FIX + UNIT_FLUID + " initial 1.0 tol 1e-14 maxiter 1\n"
     "timestep 1e-3\nrun 1", "the pressure solve did not converge in 1 iterations"),
]


def darcy_bad_input(launch):
    for name, text, expected in DARCY_BAD_INPUT:
        message = launch.error(text + "\n", name)
        expect(expected in message, f"{name}: {message!r} lacks {expected!r}")
    # a restart of another grid: the fix says what differs
    launch.run_text(COLUMN + FIX + UNIT_FLUID + "\nrun 0\nwrite_restart other.restart\n",
                    "write_other")
    message = launch.error("atom_modify map array sort 0 0\nread_restart other.restart\n"
                           "fix bad all darcy/pressure grid 2 2 5" + UNIT_FLUID + "\n",
                           "read_other")
    expect("the grid of the restart file (2x2x4 cells of 0.5 x 0.5 x 0.25 from (0, 0, 0)) "
           "differs from this command's (2x2x5 cells of 0.5 x 0.5 x 0.2 from (0, 0, 0))" in message,
           message)
    # a restart of the other seepage force: refused, naming both
    launch.run_text(COLUMN + FIX + UNIT_FLUID + " seepage full\nrun 0\nwrite_restart full.restart\n",
                    "write_full")
    message = launch.error("atom_modify map array sort 0 0\nread_restart full.restart\n"
                           "fix bad all darcy/pressure grid 2 2 4" + UNIT_FLUID + "\n", "read_full")
    expect("the restart file's run had seepage full, this command has seepage pressure" in message,
           message)


# ---- fix wall/stress and shear/stress -----------------------------------------------------

def wall_free(launch):
    """No grains under the wall: M z'' = -S L_x L_y, exactly integrated by velocity Verlet."""
    tables, _ = launch.run("in.wall_free")
    # constant S = 0.5, a = -0.5 S A / M = -0.5 (A = 6, M = 6): z0 8, the state carries over
    # the six runs of 50 steps. Velocity Verlet is exact for a constant acceleration: only
    # round-off of ~300 additions of O(10) numbers remains, <= 1e-12
    expect(len(tables) == 7, f"{len(tables)} runs")
    for n, table in enumerate(tables[:6], start=1):
        t, r = 0.5 * n, table[-1]
        close(r["w[1]"], 8.0 - 0.25 * t * t, 1e-12, f"free wall z at t = {t}")
        close(r["w[2]"], -0.5 * t, 1e-12, f"free wall v at t = {t}")
        close(r["w[3]"], 0.0, 0.0, "no grain touches the wall")
        close(r["w[4]"], 0.5, 0.0, "applied stress")
    # S = c t (ramp, c = 2) from z0 9 for T = 2: velocity Verlet's velocity is exact, its
    # position lags the cubic by k T dt^2/6 exactly: z = z0 - k (T^3 - T dt^2)/6, k = c A/M.
    # S evaluated one step late would move z by O(k T^2 dt) = 1e-2
    # the restart file after the third run holds the wall: the continuation repeats runs 4-6
    continued, _ = launch.run("in.wall_restart")
    expect(continued == tables[3:6], "the wall continued from the restart file differs:\n"
           f"{continued[-1][-1]}\n{tables[5][-1]}")
    r = tables[6][-1]
    k, dt, big_t = 2.0, 0.01, 2.0
    close(r["r[1]"], 9.0 - k * (big_t**3 - big_t * dt * dt) / 6.0, 1e-12, "ramped wall z")
    close(r["r[2]"], -k * big_t * big_t / 2.0, 1e-12, "ramped wall v")
    close(r["r[4]"], 2.0 * big_t, 1e-12, "ramped stress at the current time")


def wall_stack(launch):
    """The wall on a 3 x 3 x 4 stack of touching grains (LIGGGHTS hooke/stiffness contacts,
    frictionless, kn = 1e4): at rest it carries S and sits 4 S/kn lower."""
    tables, _ = launch.run("in.wall_stack")
    first, last = tables[0][-1], tables[1][-1]
    close(first["w[1]"], 4.0, 1e-15, "z auto: on the highest grain's top")
    stress, kn = 10.0, 1.0e4
    delta = stress / kn
    # damped (fix viscous, the wall's dashpot): the residual falls ~300-fold per time unit,
    # ~1e-13 left at t = 5 (as measured on LAMMPS for the same stack)
    close(last["w[3]"], stress, 1e-8 * stress, "the grains carry the applied stress")
    close(last["w[1]"], 4.0 - 4.0 * delta, 1e-9, "4 springs in series under S")
    close(last["w[2]"], 0.0, 1e-9, "the wall at rest")
    close(last["w"], 9 * 0.5 * kn * delta * delta, 1e-9, "spring energy of the 9 contacts")
    # fix_modify w virial yes: the fixes' zz pressure is sum (z_i - z_w) f_z,i over the
    # grains touching the wall, over the volume 3 x 3 x 8 (nktv2p = 1 in SI); none without
    with_wall, without_wall = tables[2][-1]["press[3]"], tables[3][-1]["press[3]"]
    close(without_wall, 0.0, 0.0, "no fix virial with virial no")
    expected = 0.0
    for x, y, z in read_rows(launch.path("stack.txt")).values():
        overlap = z + 0.5 - last["w[1]"]
        if overlap > 0.0:
            expected += (z - last["w[1]"]) * (-kn * overlap)
    expect(expected > 0.0, "no grain under the wall")
    close((with_wall - without_wall) * 72.0, expected, 1e-9 * expected, "the wall's virial")


def shear_free(launch):
    """A layer without contacts as one rigid plate: a = tau L_x L_y / M; with resisting forces
    (fix addforce before it) a = (tau A + sum F_x)/M."""
    tables, _ = launch.run("in.shear_free")
    rows = read_rows(launch.path("plate_start.txt")), read_rows(launch.path("plate_end.txt"))
    free, pulled = tables[1][-1], tables[2][-1]
    t, a = 1.0, 0.5 * 24.0 / 12.0
    # constant acceleration: velocity Verlet exact up to round-off (1000 steps: 1e-12)
    close(free["s[1]"], a * t, 1e-12, "plate velocity")
    close(free["s[2]"], 0.5 * a * t * t, 1e-12, "plate displacement")
    close(free["s[3]"], 0.0, 0.0, "nothing resists")
    expect(len(rows[1]) == 6, "grains")
    for tag, (x0, y0, z0, vx0, vy0, vz0, *_rest) in rows[0].items():
        x, y, z, vx, vy, vz, wx, wy, wz = rows[1][tag]
        close(vx, a * t, 1e-12, f"grain {tag}: v_x of the plate")
        close(x - x0, 0.5 * a * t * t, 1e-12, f"grain {tag}: moved with the plate")
        close(vy, 0.0, 0.0, f"grain {tag}: y locked")
        close(y, y0, 0.0, f"grain {tag}: y locked")
        expect(wx == wy == wz == 0.0, f"grain {tag}: rotation locked")
        close(z - z0, vz0 * t, 1e-12, f"grain {tag}: vertical motion its own")
    # fix addforce -0.1 per grain in x: a = (12 - 0.6)/12 from rest (a new plate), resisting
    # stress 0.6/24
    a = (12.0 - 0.6) / 12.0
    close(pulled["p[1]"], a * t, 1e-12, "plate velocity against the pull")
    close(pulled["p[2]"], 0.5 * a * t * t, 1e-12, "plate displacement against the pull")
    close(pulled["p[3]"], 0.6 / 24.0, 1e-15, "resisting stress")


WALL_BOX = ("atom_style granular\natom_modify map array sort 0 0\nboundary p p f\nnewton off\n"
            "communicate single vel yes\nunits si\nregion box block 0 2 0 3 0 10 units box\n"
            "create_box 1 box\ntimestep 0.01\n")
WALL = "fix w all wall/stress "
WALL_BAD_INPUT = [
    ("wall_missing", WALL_BOX + WALL + "z 8 stress 0.5 mass 6", "missing required keyword(s): kn"),
    ("wall_mass", WALL_BOX + WALL + "z 8 stress 0.5 mass -6 kn 100",
     "mass expects a finite number > 0, got '-6'"),
    ("wall_z", WALL_BOX + WALL + "z top stress 0.5 mass 6 kn 100",
     "z expects auto or a finite number, got 'top'"),
    ("wall_keyword", WALL_BOX + WALL + "z 8 stress 0.5 mass 6 kn 100 wiggle 1",
     "unknown keyword 'wiggle' (allowed: z, stress, mass, kn, damping, damping_velocity, "
     "plate_damping, variables)"),
    ("wall_damping_velocity", WALL_BOX + WALL + "z 8 stress 0.5 mass 6 kn 100 damping_velocity lab",
     "damping_velocity expects relative or absolute, got 'lab'"),
    ("wall_variable", WALL_BOX + WALL + "z 8 stress v_nope mass 6 kn 100\nrun 0",
     "Fix wall/stress: variable nope for stress does not exist"),
    ("wall_auto", WALL_BOX + WALL + "z auto stress 1 mass 6 kn 100\nrun 0",
     "Fix wall/stress: z auto needs grains in group all"),
    # pulled up (S < 0) it leaves through the top: z = 8 + t^2/2 passes 10 at t = 2
    ("wall_top", WALL_BOX + WALL + "z 8 stress -1 mass 6 kn 100\nrun 300",
     ", above the box top 10"),
    ("wall_bottom", WALL_BOX + WALL + "z 1 stress 1 mass 6 kn 100\nrun 300",
     "below the box bottom 0 and so through every grain"),
    ("wall_periodic", WALL_BOX.replace("boundary p p f", "boundary p p p") + WALL +
     "z 8 stress 0.5 mass 6 kn 100", "needs a z-bounded box: boundary f, fm or fs in z"),
    ("shear_missing", WALL_BOX + "fix s all shear/stress tau 1", "missing required keyword(s): mass"),
    ("shear_empty", WALL_BOX + "region nowhere block 0 1 0 1 20 30 units box\n"
     "group none region nowhere\nfix s none shear/stress tau 1 mass 1\nrun 0",
     "Fix shear/stress s: group none has no grains"),
]


def walls_bad_input(launch):
    for name, text, expected in WALL_BAD_INPUT:
        message = launch.error(text + "\n", name)
        expect(expected in message, f"{name}: {message!r} lacks {expected!r}")


CASES = {
    "darcy_column": darcy_column,
    "darcy_grain": darcy_grain,
    "darcy_fluidise": darcy_fluidise,
    "darcy_seepage_sums": darcy_seepage_sums,
    "darcy_fluidise_full": darcy_fluidise_full,
    "darcy_mesh_floor": darcy_mesh_floor,
    "darcy_undrained": darcy_undrained,
    "darcy_restart": darcy_restart,
    "darcy_bad_input": darcy_bad_input,
    "wall_free": wall_free,
    "wall_stack": wall_stack,
    "shear_free": shear_free,
    "walls_bad_input": walls_bad_input,
}
