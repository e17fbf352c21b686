"""Table S1's landings, one by one (bench/fidelity/RESULTS.md): each landing's collapse of the
original's count at every row, on both grids of every second row (the original's 0.01 s) and
in the original run's data file (porewater_analysis.landings.landings), and what swings the
count after it: the count's swing against the plate's (z_wall about its trend, and the grains'
force on it, N_grains) over the rows after each landing (landings.swing). Writes
landings.md and landings.png beside this file; reads only committed data.

    PYTHONPATH=analysis /usr/bin/python3 bench/fidelity/table_s1/landings.py
"""
import os

import numpy as np

from porewater_analysis import landings
from porewater_analysis.original import sample_grid
from porewater_analysis.report import DATA_FILE, collapse_cell, parameters
from porewater_analysis.timeseries import load

HERE = os.path.dirname(os.path.abspath(__file__))
SIGNALS = (("the count", "coordination_original", 1.0, "%.2f"),
           ("z_wall (µm)", "z_wall", 1e6, "%.0f"),
           ("N_grains (kPa)", "N_grains", 1e-3, "%.0f"))
RUNNING = 5               # rows: the figure's running mean of z_wall (0.025 s)
WINDOWS = (landings.SWING_WINDOW, 0.1)     # cycle after each landing: 0.1 s and 0.5 s of 5 s


def longest_run(t, z, below):
    """(rows, first time) of the longest run of consecutive rows with z < below"""
    best, start, run = 0, None, 0
    for i, low in enumerate(z < below):
        run = run + 1 if low else 0
        if run > best:
            best, start = run, t[i - run + 1]
    return best, start


def main():
    series = load(os.path.join(HERE, "timeseries.txt"))
    period = parameters(HERE)[0]["period"]
    data = landings.read_data_file(DATA_FILE)
    t, z = series["time"], series["coordination_original"]
    grid, _ = sample_grid(t, period)
    rows = landings.landings(series, period, data)
    lines = ["# Table S1's landings (landings.py)", "",
             "Each landing's minimum of the original's count (t; cycles after the minimum of N) "
             "within %g cycle of the end of cycle k (porewater_analysis.landings): every row, each "
             "grid of every second row, the original run's data file." % landings.HALF_WIDTH, "",
             "| landing | every row | grid offset 0 (the original's samples) | grid offset 1 | "
             "the data file |", "|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %d | %s | %s |" % (r["landing"], collapse_cell(r["every_row"]), " | ".join(
            collapse_cell(c) for c in r["grid"] + [r["data_file"]])))
    lines += ["", "The swing after each landing (from its minimum at every row; the data file "
              "from its own): period by the spectrum's peak and by zero crossings, amplitude "
              "(half the 10-90 % span) of each signal about its quadratic trend; r: the "
              "correlation of the count with each signal's swing.", "",
              "| landing | rows after it | signal | period, spectrum (s) | period, crossings (s) "
              "| amplitude | r with the count |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        start = r["every_row"]["time"]
        for window in WINDOWS:
            m = landings.after_landing(t, start, period, window)
            count = landings.swing(t[m], z[m])["residual"]
            for name, column, scale, f in SIGNALS:
                s = landings.swing(t[m], series[column][m])
                lines.append("| %d | %.1f s, %d rows | %s | %.4f | %.4f | %s | %s |" % (
                    r["landing"], window * period, m.sum(), name, s["period_fft"],
                    s["period_crossings"], f % (scale * s["amplitude"]),
                    "" if column == "coordination_original" else
                    "%.2f" % np.corrcoef(count, s["residual"])[0, 1]))
        # at the original's cadence, over the longer window only (0.1 s: 10 samples)
        for j in (0, 1):
            g = landings.after_landing(t, start, period, WINDOWS[-1]) & (grid == j)
            s = landings.swing(t[g], z[g])
            lines.append("| %d | %.1f s, grid offset %d | the count | %.4f | %.4f | %.2f | |"
                         % (r["landing"], WINDOWS[-1] * period, j, s["period_fft"],
                            s["period_crossings"], s["amplitude"]))
        d = landings.after_landing(data[0], r["data_file"]["time"] - 1e-9, period, WINDOWS[-1])
        s = landings.swing(data[0][d], data[1][d])
        lines.append("| %d | %.1f s, the data file | the count | %.4f | %.4f | %.2f | |" % (
            r["landing"], WINDOWS[-1] * period, s["period_fft"], s["period_crossings"],
            s["amplitude"]))
    lines += ["", "Longest runs of consecutive rows in each landing's window with the count "
              "below 0.1 and below 0.5 (rows; first time):", "",
              "| landing | every row, < 0.1 | the data file, < 0.1 | every row, < 0.5 | the data "
              "file, < 0.5 |", "|---|---|---|---|---|"]
    for r in rows:
        lo, hi = r["window"]
        m, d = (t >= lo) & (t < hi), (data[0] >= lo) & (data[0] < hi)
        cells = [longest_run(tt, zz, b) for b in (0.1, 0.5)
                 for tt, zz in ((t[m], z[m]), (data[0][d], data[1][d]))]
        lines.append("| %d | " % r["landing"] + " | ".join("%d (%.3f s)" % c for c in cells) + " |")
    with open(os.path.join(HERE, "landings.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot(series, data, rows, grid, period, os.path.join(HERE, "landings.png"))


def plot(series, data, rows, grid, period, path):
    """per landing: the count at every row (both grids marked), the data file's, and the
    plate's height less its running mean over RUNNING rows (its fast swing), from 0.15 s
    before the landing to 0.35 s after it"""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t, z = series["time"], series["coordination_original"]
    fig, axes = plt.subplots(len(rows), 1, figsize=(9, 3.2 * len(rows)))
    for ax, r in zip(np.atleast_1d(axes), rows):
        t0 = r["every_row"]["time"]
        m = (t >= t0 - 0.15) & (t < t0 + 0.35)
        d = (data[0] >= t0 - 0.15) & (data[0] < t0 + 0.35)
        ax.plot(t[m], z[m], color="0.6", lw=0.8, label="Table S1, every row")
        for j, marker in ((0, "o"), (1, "s")):
            g = m & (grid == j)
            ax.plot(t[g], z[g], marker, ms=3, ls="none", label="grid offset %d" % j)
        ax.plot(data[0][d], data[1][d], "k^-", ms=3, lw=0.8, label="the data file")
        ax.set_ylabel("the original's count")
        ax.set_title("landing %d" % r["landing"], fontsize=9, loc="right")
        tw = ax.twinx()
        zw = series["z_wall"][m]
        fast = zw - np.convolve(zw, np.ones(RUNNING) / RUNNING, "same")
        edge = RUNNING // 2
        tw.plot(t[m][edge:-edge], 1e6 * fast[edge:-edge], color="C3", lw=0.8)
        tw.set_ylabel("z_wall less its %d-row running mean (µm)" % RUNNING, color="C3")
        ax.legend(fontsize=7, loc="lower left", ncol=4, bbox_to_anchor=(0, 1.0))
    np.atleast_1d(axes)[-1].set_xlabel("t (s)")
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    main()
