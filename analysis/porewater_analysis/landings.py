"""The plate's landings one by one: where the original's count collapses after each slip, at
every row and on each grid of rows at the original's 0.01 s cadence, beside the original
run's own data file at the same landing; and how the count swings after it.

A landing: the plate, lifted by the slip's dilation, comes down onto the bed; the bed's
contacts collapse (the original run's count to ~0.04 per grain) and then swing. It lies
about a quarter cycle after the minimum of the applied normal stress N (phase 0.75): the
collapse of the original's count is 0.23-0.28 cycle after it on average wherever the bed
collapses (bench/fidelity/RESULTS.md: Table S1, the original run's data file, the stiff and
the default presets' ensembles), that is where cycle k's forcing ends. So landing k is the
minimum of the count within HALF_WIDTH cycle of t = k T (the minimum of N at (k - 0.25) T
plus a quarter cycle): a window that holds the widest band measured (the stiff preset's
0.280 +- 0.057 cycle after the minimum of N) with 0.06 cycle to spare and stays clear of the
creep (phases 0.2-0.6) and the slip's onset (~0.6). A landing is measured only where the rows
cover its whole window. On Table S1 the minima are the same for half-widths 0.05-0.3.

After the landing the count swings row to row between ~0.05-1 and ~2-3; a grid of every
second row (the original's 0.01 s) then reads one side of the swing or the other, so its
minimum depends on the grid's offset (original.sample_grid): `landings` reports every row and
each offset.
"""
import numpy as np

from .cycles import after_min_n
from .original import ORIGINAL_PERIOD, sample_grid

HALF_WIDTH = 0.15          # cycle: the window of a landing either side of k T
SWING_WINDOW = 0.02        # cycle: the rows after a landing that `swing` reads (0.1 s of 5 s)
COLUMN = "coordination_original"    # the original's count (compute coordination/original)


def windows(t, period, half_width=HALF_WIDTH):
    """[(k, lo, hi)] for each landing k = 1, 2, ... whose window [k T - h T, k T + h T) the
    times t cover wholly (to half a row's spacing)"""
    tol = 0.5 * np.median(np.diff(t))
    out = []
    k = 1
    while (k + half_width) * period <= t[-1] + tol:
        lo, hi = (k - half_width) * period, (k + half_width) * period
        if lo >= t[0] - tol:
            out.append((k, lo, hi))
        k += 1
    return out


def collapse(t, z, lo, hi, period):
    """the minimum of z over lo <= t < hi: {min, time, phase (of its cycle), after_min_n
    (cycles after the minimum of N, cycles.after_min_n)}; None without a row there"""
    inside = np.nonzero((t >= lo) & (t < hi))[0]
    if not len(inside):
        return None
    i = inside[int(np.argmin(z[inside]))]
    phase = (t[i] / period) % 1.0
    return {"min": float(z[i]), "time": float(t[i]), "phase": float(phase),
            "after_min_n": float(after_min_n(phase))}


def read_data_file(path):
    """(t, coordination) of the original run's data file (bench/common/original_run_contacts.txt:
    t, n_heavy, coordination, its rows every 0.01 s)"""
    t, _, z = np.loadtxt(path, unpack=True)
    return t, z


def landings(series, period, data=None, data_period=ORIGINAL_PERIOD, half_width=HALF_WIDTH,
             column=COLUMN):
    """each landing the series covers: [{landing k, window (lo, hi), every_row, grid: [one per
    offset of original.sample_grid, 0 the original's samples], stride, data_file}], each a
    `collapse` of the original's count (column) in the window; data_file the same landing k of
    `data` ((t, z) of read_data_file, its window (k +- half_width) data_period: the same times
    where the run's period is the original's 5 s), None without data or where data does not
    cover it. [] for a series without the column"""
    if column not in series or len(series["time"]) < 2:
        return []
    t, z = series["time"], series[column]
    grid, stride = sample_grid(t, period)
    covered = {k for k, _, _ in windows(data[0], data_period, half_width)} if data else set()
    rows = []
    for k, lo, hi in windows(t, period, half_width):
        row = {"landing": k, "window": (lo, hi), "stride": stride,
               "every_row": collapse(t, z, lo, hi, period),
               "grid": [collapse(t[grid == j], z[grid == j], lo, hi, period)
                        for j in range(stride)],
               "data_file": None}
        if k in covered:
            row["data_file"] = collapse(data[0], data[1], (k - half_width) * data_period,
                                        (k + half_width) * data_period, data_period)
        rows.append(row)
    return rows


def swing(t, x, degree=2):
    """the oscillation of x(t) about a polynomial trend of `degree` (rows evenly spaced):
    {period_fft (s, the peak of the Hann-windowed spectrum's non-zero frequencies),
    period_crossings (s: twice the mean time between the residual's sign changes, None with
    fewer than two), amplitude (half the span between the residual's 10th and 90th
    percentiles), residual}. A period of two rows is the rows' Nyquist limit: an oscillation
    faster than it reads there too (aliased)"""
    u = np.arange(len(x), dtype=float)
    residual = x - np.polyval(np.polyfit(u, x, degree), u)
    dt = float(np.median(np.diff(t)))
    spectrum = np.abs(np.fft.rfft(residual * np.hanning(len(x))))
    freq = np.fft.rfftfreq(len(x), dt)
    peak = 1 + int(np.argmax(spectrum[1:]))
    change = np.nonzero(np.diff(np.sign(residual)) != 0)[0]
    crossings = (2 * (change[-1] - change[0]) * dt / (len(change) - 1)
                 if len(change) > 1 else None)
    lo, hi = np.percentile(residual, [10, 90])
    return {"period_fft": 1.0 / freq[peak], "period_crossings": crossings,
            "amplitude": 0.5 * (hi - lo), "residual": residual}


def after_landing(t, start, period, window=SWING_WINDOW):
    """the rows from a landing's time `start` over the next `window` cycle"""
    return (t >= start) & (t < start + window * period)
