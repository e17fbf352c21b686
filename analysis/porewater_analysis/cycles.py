"""The package's own estimators of a tidal cycle (bench/fidelity and bench/paper_figures use
them): the slip of each cycle from the top layer's smoothed velocity, the creep exponent from
the slope of its displacement over windows of phases 0.2-0.6, the coordination while creeping
and at its minimum. Defaults are the reduced example's (examples/tidal_shear/in.params); pass a
run's own period, tau and amp (timeseries.run_parameters) where they differ."""
import numpy as np
from scipy import stats

from .original import ORIGINAL_CYCLES, ORIGINAL_PERIOD
from .timeseries import whole_cycles

PERIOD, AMP, TAU = 2.5, 70.0e3, 10.0e3    # s, Pa, Pa: examples/tidal_shear/in.params
DIAMETER, RHO = 0.02, 2600.0
SLIP_VELOCITY = 1e-2       # m/s: a slip, at least 10x any creep velocity (checked)
SMOOTH = 0.025             # s: velocity from the displacement over this window
LANDING = 0.1              # cycle after the slip's end


def smoothed_velocity(t, x):
    n = max(1, int(round(SMOOTH / np.median(np.diff(t)))))
    v = np.full_like(x, np.nan)
    v[n // 2:len(x) - (n - n // 2)] = (x[n:] - x[:-n]) / (t[n:] - t[:-n])
    return v


def cycle_metrics(c, wet, period=PERIOD, cycles=None, stuck_until=0.0, tau=TAU, amp=AMP):
    """per cycle (all the whole cycles by default); the slip: the first above SLIP_VELOCITY
    after phase `stuck_until` (the stuck part of the cycle: a blip as the last cycle's slip
    ends is not this one's)"""
    t, x, z = c["time"], c["x_top"], c["z_wall"]
    v = smoothed_velocity(t, x)
    rows = []
    for k in range(whole_cycles(t, period) if cycles is None else cycles):
        # (the sample at t = 0 precedes the first force evaluation: no grain force on the plate)
        inside = (t >= k * period) & (t < (k + 1) * period) & (t > 0)
        phase = t[inside] / period - k
        vi, xi, zi = v[inside], x[inside], z[inside]
        creep = (phase > 0.2) & (phase < 0.6)
        pc, = np.nonzero(creep)
        v_creep = (xi[pc[-1]] - xi[pc[0]]) / (period * (phase[pc[-1]] - phase[pc[0]]))
        r = {"cycle": k + 1, "v_creep": v_creep}
        # a slip of the cycle before that goes on into this one is not this cycle's
        slow = np.nonzero(vi <= SLIP_VELOCITY)[0]
        first_slow = slow[0] if len(slow) else len(vi)
        first_slow = max(first_slow, np.searchsorted(phase, stuck_until))
        fast = first_slow + np.nonzero(vi[first_slow:] > SLIP_VELOCITY)[0]
        if len(fast):
            i0 = fast[0]
            after = np.nonzero(vi[i0:] < SLIP_VELOCITY)[0]
            i1 = i0 + (after[0] if len(after) else len(vi) - 1 - i0)
            r.update(onset=phase[i0], end=phase[i1], peak=np.nanmax(vi[i0:i1 + 1]),
                     ratio=tau / c["N_applied"][inside][i0],
                     peak_phase=phase[i0 + int(np.nanargmax(vi[i0:i1 + 1]))],
                     mean=(xi[i1] - xi[i0]) / (period * (phase[i1] - phase[i0])),
                     slip=xi[i1] - xi[i0], dilation=np.max(zi[i0:i1 + 1]) - zi[i0])
        zc = c["coordination"][inside]
        r["z_min"], r["z_min_phase"] = zc.min(), phase[np.argmin(zc)]
        r["n_min_phase"] = phase[np.argmin(c["N_grains"][inside])]
        if wet:
            dp = (c["p_mean"] - c["p_top"])[inside] / amp
            r["dp_min"], r["dp_max"] = dp.min(), dp.max()
        rows.append(r)
    return rows


def fmt(r, key, f, scale=1.0):
    """a metric of a cycle's row formatted, "none" where the cycle has none (no slip)"""
    return f % (scale * r[key]) if key in r else "none"


def creep_points(c, window=0.05, period=PERIOD, cycles=None, tau=TAU):
    """(tau/N, gamma_dot, cycle, N) over phases 0.2-0.6 of each cycle: the slope of the top
    layer's displacement over windows of `window` cycles, over the plate's height"""
    t, x = c["time"], c["x_top"]
    out = []
    for k in range(whole_cycles(t, period) if cycles is None else cycles):
        for start in np.arange(0.2, 0.6 - 1e-9, window):
            w = (t >= (k + start) * period) & (t < (k + start + window) * period)
            if w.sum() < 5:
                continue
            slope = np.polyfit(t[w], x[w], 1)[0]
            n = np.mean(c["N_applied"][w])
            out.append((tau / n, slope / np.mean(c["z_wall"][w]), k + 1, n))
    return np.array(out)


def inertia_number(points):
    """I = gamma_dot d sqrt(rho/N) of each window with a positive rate"""
    p = points[points[:, 1] > 0]
    return p[:, 1] * DIAMETER * np.sqrt(RHO / p[:, 3])


def log_log_fit(x, y):
    """log y = n log x + c: n, its 95 % half-interval, r^2"""
    fit = stats.linregress(np.log(x), np.log(y))
    return fit.slope, stats.t.ppf(0.975, len(x) - 2) * fit.stderr, fit.rvalue ** 2


def power_law(points):
    """n, its 95 % half-interval, windows used and dropped (rate <= 0), r^2 of
    log gamma_dot = n log(tau/N) + c"""
    p = points[points[:, 1] > 0]
    if len(p) < 4:
        return None
    slope, half, r2 = log_log_fit(p[:, 0], p[:, 1])
    return slope, half, len(p), len(points) - len(p), r2


def phase_mask(t, period, cycle, lo, hi):
    return (t >= (cycle - 1 + lo) * period) & (t < (cycle - 1 + hi) * period)


def after_min_n(phase):
    """cycles after the minimum of N (phase 0.75), in [0, 1): a collapse in the landing
    just past the cycle's end stays next to one just before it"""
    return (phase - 0.75) % 1.0


def original_data_file_metrics(path):
    """coordination of the original run's own data file (bench/common/original_run_contacts.txt:
    t, n_heavy, coordination; already the original's count): start, while creeping (phases
    0.2-0.6), the minimum and its phase, over cycles 2-9 (the first dropped, as here)"""
    t, _, z = np.loadtxt(path, unpack=True)
    creep, mins = [], []
    for k in range(2, ORIGINAL_CYCLES + 1):
        creep.append(np.mean(z[phase_mask(t, ORIGINAL_PERIOD, k, 0.2, 0.6)]))
        inside = phase_mask(t, ORIGINAL_PERIOD, k, 0.0, 1.0)
        i = np.argmin(z[inside])
        mins.append((z[inside][i], after_min_n(t[inside][i] / ORIGINAL_PERIOD - (k - 1))))
    return {"z_start": z[0], "z_creep": creep, "z_min": [m[0] for m in mins],
            "z_min_phase": [m[1] for m in mins]}


def factor_metrics(c, cycles, period=PERIOD, tau=TAU, amp=AMP):
    """per cycle {cycle: metrics}: cycle_metrics' slip for the whole cycles, plus
    coordination while creeping (phases 0.2-0.6), suction during the slip (the bed's mean;
    right under the plate where the series has p_top_layer) and the plate's landing; n of
    each cycle's creep windows (a partial cycle: those it covers)"""
    t = c["time"]
    whole = int(np.floor(cycles + 1e-9))
    out = {r["cycle"]: r for r in cycle_metrics(c, True, period, whole, stuck_until=0.2,
                                                tau=tau, amp=amp)} if whole else {}
    pts = creep_points(c, period=period, cycles=int(np.ceil(cycles - 1e-9)), tau=tau)
    for k in range(1, int(np.ceil(cycles - 1e-9)) + 1):
        r = out.setdefault(k, {"cycle": k})
        creep = phase_mask(t, period, k, 0.2, 0.6)
        if t[creep].max() < (k - 1 + 0.59) * period:
            continue                      # the run ends before this cycle's creep does
        r["z_creep"] = np.mean(c["coordination"][creep])
        r["fit"] = power_law(pts[pts[:, 2] == k])
        if "onset" in r:
            slip = phase_mask(t, period, k, r["onset"], r["end"] + 1e-9)
            r["suction"] = np.min((c["p_mean"] - c["p_top"])[slip]) / amp
            if "p_top_layer" in c:    # right under the drained face (f_darcy[13])
                r["suction_top"] = np.min((c["p_top_layer"] - c["p_top"])[slip]) / amp
            # only where the run covers the whole window (a slip to the cycle's end: none)
            if t[-1] >= (k - 1 + r["end"] + LANDING) * period - 1e-9:
                land = phase_mask(t, period, k, r["end"], r["end"] + LANDING)
                excess = (c["N_grains"] - c["N_applied"])[land] / amp
                r["landing"] = np.sqrt(np.mean(excess ** 2))
    return out
