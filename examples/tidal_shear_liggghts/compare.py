#!/usr/bin/env python3
"""Compares the time series of the LIGGGHTS run with the LAMMPS run of ../tidal_shear.

    python3 compare.py [LIGGGHTS_TIMESERIES [LAMMPS_TIMESERIES]]   (defaults: ./timeseries.txt,
                                                                      ../tidal_shear/timeseries.txt)

Prints, for each quantity of the time series (README.md of ../tidal_shear), both runs'
values at a few times and the largest difference over the common time span, relative to
the LAMMPS run's range of that quantity; writes comparison.png if matplotlib is there.
"""
import os
import sys

QUANTITIES = [  # column, what, scale for printing
    ("N_grains", "effective normal stress on the plate N (kPa)", 1e-3),
    ("N_applied", "applied stress S (kPa)", 1e-3),
    ("p_top", "top pore pressure (kPa)", 1e-3),
    ("p_mean", "mean pore pressure below the plate (kPa)", 1e-3),
    ("phi_mean", "mean porosity below the plate", 1.0),
    ("z_wall", "plate height (m)", 1.0),
    ("x_top", "top-layer displacement (mm)", 1e3),
    ("vx_top", "top-layer velocity (mm/s)", 1e3),
    ("tau_resist", "resisting shear stress (kPa)", 1e-3),
    ("coordination", "coordination number", 1.0),
    ("ke", "kinetic energy of the grains (J)", 1.0),
    ("solver_iters", "solver iterations", 1.0),
]


def read(path):
    with open(path) as f:
        header = f.readline().split()[1:]
        rows = [list(map(float, line.split())) for line in f if line.strip()]
    return {name: [r[i] for r in rows] for i, name in enumerate(header)}


def common_samples(a, b, tolerance=1e-7):
    """both series on the times they share, to `tolerance` s (LAMMPS' fix print also
    prints at step 0, LIGGGHTS' does not; LIGGGHTS' time accumulates over runs)"""
    pairs, j = [], 0
    for i, t in enumerate(a["time"]):
        while j < len(b["time"]) and b["time"][j] < t - tolerance:
            j += 1
        if j < len(b["time"]) and abs(b["time"][j] - t) <= tolerance:
            pairs.append((i, j))
    return ({k: [v[i] for i, _ in pairs] for k, v in a.items()},
            {k: [v[j] for _, j in pairs] for k, v in b.items()})


def nearest(times, t):
    return min(range(len(times)), key=lambda k: abs(times[k] - t))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    liggghts = read(sys.argv[1] if len(sys.argv) > 1 else "timeseries.txt")
    lammps = read(sys.argv[2] if len(sys.argv) > 2 else
                  os.path.join(here, "..", "tidal_shear", "timeseries.txt"))
    liggghts, lammps = common_samples(liggghts, lammps)
    n = len(liggghts["time"])
    span = liggghts["time"][-1]
    marks = [span * k / 4 for k in range(1, 5)]
    print(f"{n} common samples, t = {liggghts['time'][0]:.4g} ... {span:.4g} s")
    print(f"{'quantity':46s} {'t (s)':>7s} " + " ".join(f"{t:>17.3f}" for t in marks))
    for column, what, scale in QUANTITIES:
        a = [v * scale for v in liggghts[column]]
        b = [v * scale for v in lammps[column]]
        spread = max(b) - min(b)
        worst = max(abs(x - y) for x, y in zip(a, b))
        cells = " ".join(f"{a[nearest(liggghts['time'], t)]:8.4g}/{b[nearest(lammps['time'], t)]:<8.4g}"
                         for t in marks)
        relative = f"{worst / spread:.2f}" if spread > 0 else "-"
        print(f"{what:46s} {'LIGGGHTS/LAMMPS':>7s} {cells}   max|diff| {worst:.3g} "
              f"({relative} of the LAMMPS range)")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib (Debian: /usr/bin/python3 has it): no comparison.png")
        return 0
    fig, axes = plt.subplots(len(QUANTITIES) // 2, 2, figsize=(11, 13), sharex=True)
    for ax, (column, what, scale) in zip(axes.flat, QUANTITIES):
        ax.plot(lammps["time"], [v * scale for v in lammps[column]], label="LAMMPS")
        ax.plot(liggghts["time"], [v * scale for v in liggghts[column]], "--", label="LIGGGHTS")
        ax.set_ylabel(what, fontsize=8)
    axes.flat[0].legend()
    for ax in axes[-1]:
        ax.set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig("comparison.png", dpi=70)
    print("wrote comparison.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
