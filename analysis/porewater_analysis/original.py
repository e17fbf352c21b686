"""The original program's estimators: those of sphere's scripts, which define the paper's numbers
(Damsgaard et al. 2016), applied to a time series of examples/tidal_shear. Lines cited are
of sphere at commit 116df3b (github.com/klkkong/sphere, python/ and src/).

Our time series stands for the original's output files: `vx_top` for the fixed top grains'
x-velocity, `z_wall` for the top wall's position w_x (the floor at z = 0), `N_applied` for
the defined normal stress, and the tau of the run for the defined shear stress. The original
data file of the paper's run (bench/common/original_run_contacts.txt) is read by
cycles.original_data_file_metrics.
"""
import numpy as np
import scipy.optimize
import scipy.stats

from .timeseries import whole_cycles

ORIGINAL_PERIOD = 5.0      # s: Table S1's 0.2 Hz; the original scripts' times and rates are in it
ORIGINAL_CYCLES = 9        # Table S1: 45 s analysed
FILES_PER_CYCLE = 500      # the original wrote an output file every 0.01 s of its 5 s cycle
WATER_VISCOSITY = 1.787e-3  # Pa s: t_DEM_to_t_real = mu/1.787e-3 (rate-dependence.py line 71)
MAX_FRICTION = 0.38        # tau/N of the creep fit (rate-dependence.py line 99)
MAX_RATE = 0.1             # 1/s over a cycle of ORIGINAL_PERIOD (rate-dependence.py line 100)
CREEP_PHASES = (0.2, 0.6)  # 1-3 s of each 5 s cycle, open (rate-dependence.py lines 101-111)
BAND_EXIT_FACTOR = 10.0    # our reading of the slip: v above 10x the cycle's creep band


def shear_velocity(vx_top):
    """sphere.py `shearVelocity()` (python/sphere.py lines 4794-4808): numpy.max(vel[fixvel, 0])
    over ALL fixed grains (`shear()` lines 3131-3158 fix both the bottom and the top layer,
    fixvel = 1). The held bottom layer's x-velocity is exactly 0 and the top layer moves as
    one plate, so the maximum is max(vx_top, 0), elementwise."""
    return np.maximum(vx_top, 0.0)


def shear_strain_rate(vx_top, z_wall):
    """sphere.py `shearStrainRate()` (python/sphere.py lines 4837-4853): shearVelocity()/w_x[0],
    w_x the top wall's height above the floor at z = 0 (our z_wall)"""
    return shear_velocity(vx_top) / z_wall


def sample_grid(t, period):
    """(offset, stride) of rows at times t (t = k nout dt, k = 1, 2, ...): every stride-th row
    (the stride nearest to period/500, the original's 0.01 s of its 5 s cycle, over the rows'
    spacing) makes a grid at the original's cadence; offset = k mod stride says which of the
    stride grids a row belongs to (original_samples)"""
    spacing = np.median(np.diff(t))
    stride = max(1, int(round(period / FILES_PER_CYCLE / spacing)))
    return np.rint(t / spacing).astype(int) % stride, stride


def original_samples(series, period, offset=0):
    """the rows of the time series at the original's sampling: it wrote an output file every
    0.01 s of its 5 s cycle (period/500) and read them from the first on, never the initial
    state (rate-dependence.py line 70, readstep(i+1)). Each file holds the time it was
    written, which the scripts read as the sample's time (currentTime(), rate-dependence.py
    line 79; src/file_io.cpp line 443 writes time.current): src/device.cu adds dt to the time
    and to a file clock each step (lines 2543-2544), writes a file once that clock reaches
    0.01 s (line 2576) and zeroes it (line 2679), so file j stands at j m dt >= j 0.01 s (m
    the steps of a file, dt the original's time step). Our rows stand at t = k nout dt, k = 1,
    2, ..., ~1000 per cycle, nout dt ~ period/1000 (in.tidal_shear line 49 rounds it to whole
    fluid steps; Table S1: 0.0050018 s): every second row (generally every stride-th,
    sample_grid) is a grid at the original's cadence. `offset` 0 (k even: t ~ 0.01, 0.02, ...
    s on Table S1) is the grid that starts at the original's first file; 1 .. stride-1 the
    grids between, as much the original's cadence: which of them a fit or a minimum reads is
    no part of the original's code, and what it changes is measured (landings.landings,
    leave_fastest_out on each offset). The sample's time is its row's time, as the original's
    is its file's"""
    t = series["time"]
    grid, _ = sample_grid(t, period)
    keep = (grid == offset) & (t > 0)
    return {name: column[keep] for name, column in series.items()}


def creep_rheology2(friction, n, A):
    """python/halfshear-darcy-rate-dependence.py lines 47-49: the strain rate of tau/N"""
    return A * friction ** n


# the creep fit's cuts (python/halfshear-darcy-rate-dependence.py), in the script's order
CUTS = (
    ("rate 0", "line 88, numpy.nonzero(shearstrainrate): max(vx_top, 0) = 0"),
    ("tau/N >= 0.38", "line 99, tau/N < 0.38, strict"),
    ("rate >= 0.1", "line 100, rate < 0.1 t_DEM_to_t_real, strict (0.1 x 5 s/period here)"),
    ("outside 1-3 s", "lines 101-111, 6 < t < 8, 11 < t < 13, ...: open, on the sample's time"),
    ("cycle", "lines 101-111 start at 6 s: cycles before the fit's first (or after its last)"),
)


def creep_samples(series, period, tau, rate_scale=1.0, offset=0):
    """every original sample (original_samples at `offset`) with its time, cycle, phase,
    tau/N, scaled rate, shear velocity, the cuts of the creep fit it fails ({name of CUTS:
    mask}, the cycle cut left to the caller) and whether the fit keeps it ("kept": it fails
    none), as python/halfshear-darcy-rate-dependence.py lines 69-111: tau the DEFINED shear
    stress (line 73, w_tau_x), N the DEFINED normal stress (line 75, currentNormalStress()
    'defined', python/sphere.py lines 4121-4140: sigma0 + A sin(2 pi f t) at the file's time,
    our N_applied at the row's), rate shearStrainRate() * t_DEM_to_t_real (line 77;
    rate_scale = mu_f/1.787e-3, line 71), t the sample's time (line 79, currentTime(): the
    time its file was written, original_samples). The cuts: a zero rate (line 88,
    numpy.nonzero: a top layer at rest or moving backwards, shear_velocity), then (lines
    99-111) tau/N < 0.38, rate < 0.1 * t_DEM_to_t_real and t inside 1-3 s of a 5 s cycle,
    (6, 8), (11, 13), ...: all strict, so a sample exactly at tau/N 0.38, at the rate's
    threshold or at a window's end is cut, and a window's first sample is kept where it
    stands after the window opens (the original's file 600 at 600 m dt >= 6 s, our row at
    k nout dt). Here the window is 0.2 < phase < 0.6 of our period. The rate threshold is the
    unscaled rate < 0.1 1/s over Table S1's 5 s cycle; our reduced case runs the cycle in
    `period` (2.5 s), its rates larger by ORIGINAL_PERIOD/period for the same strain per
    cycle, so the threshold is 0.1 * ORIGINAL_PERIOD/period 1/s unscaled (rate * period <
    0.5)."""
    s = original_samples(series, period, offset)
    t = s["time"]
    cycle = np.floor(t / period).astype(int) + 1
    start = (cycle - 1) * period
    friction = tau / s["N_applied"]
    velocity = shear_velocity(s["vx_top"])
    rate = shear_strain_rate(s["vx_top"], s["z_wall"]) * rate_scale
    cuts = {"rate 0": rate == 0,
            "tau/N >= 0.38": ~(friction < MAX_FRICTION),
            "rate >= 0.1": ~(rate < MAX_RATE * ORIGINAL_PERIOD / period * rate_scale),
            "outside 1-3 s": ~((t > start + CREEP_PHASES[0] * period) &
                               (t < start + CREEP_PHASES[1] * period))}
    kept = ~np.any(list(cuts.values()), axis=0)
    return {"time": t, "cycle": cycle, "phase": t / period - (cycle - 1), "friction": friction,
            "rate": rate, "velocity": velocity, "cuts": cuts, "kept": kept}


def fit_samples(series, period, tau, rate_scale=1.0, first_cycle=2, last_cycle=None, offset=0):
    """the original's samples (at `offset`) as records {time, cycle, phase, friction, rate,
    velocity, cut}: cut "kept" for each sample the creep fit of cycles first_cycle ..
    last_cycle keeps (creep_fit), else the cuts of CUTS it fails, joined by ", " (a sample
    can fail several)"""
    p = creep_samples(series, period, tau, rate_scale, offset)
    outside = p["cycle"] < first_cycle
    if last_cycle is not None:
        outside |= p["cycle"] > last_cycle
    cuts = dict(p["cuts"], cycle=outside)
    names = [name for name, _ in CUTS]
    return [{"time": p["time"][i], "cycle": int(p["cycle"][i]), "phase": p["phase"][i],
             "friction": p["friction"][i], "rate": p["rate"][i],
             "velocity": p["velocity"][i],
             "cut": ", ".join(n for n in names if cuts[n][i]) or "kept"}
            for i in range(len(p["time"]))]


def fit_rheology2(friction, rate):
    """scipy.optimize.curve_fit(creep_rheology2, tau/N, rate) as
    python/halfshear-darcy-rate-dependence.py lines 118-120 call it (the default p0, linear
    space): {n, A, n_sigma, A_sigma (1 sigma: sqrt of pcov's diagonal)}, nan for fewer than 3
    samples or a fit that does not converge (RuntimeError)"""
    out = {"n": np.nan, "A": np.nan, "n_sigma": np.nan, "A_sigma": np.nan}
    if len(rate) < 3:
        return out
    try:
        popt, pcov = scipy.optimize.curve_fit(creep_rheology2, friction, rate)
    except RuntimeError:            # no convergence from the default p0
        return out
    sigma = np.sqrt(np.diag(pcov))
    return dict(n=popt[0], A=popt[1], n_sigma=sigma[0], A_sigma=sigma[1])


def creep_fit(series, period, tau, rate_scale=1.0, first_cycle=2, last_cycle=None, offset=0):
    """the original's creep exponent (python/halfshear-darcy-rate-dependence.py lines 69-120):
    fit_rheology2 on the samples of cycles first_cycle..last_cycle (all from the second by
    default, as lines 101-111) that creep_samples keeps (at `offset`, original_samples).
    Returns {n, A, n_sigma, A_sigma, count, time, friction, rate (the samples fitted)}"""
    p = creep_samples(series, period, tau, rate_scale, offset)
    use = p["kept"] & (p["cycle"] >= first_cycle)
    if last_cycle is not None:
        use &= p["cycle"] <= last_cycle
    out = {"count": int(use.sum()), "time": p["time"][use], "friction": p["friction"][use],
           "rate": p["rate"][use]}
    out.update(fit_rheology2(out["friction"], out["rate"]))
    return out


LEAVE_OUT = 5              # the fastest samples left out one by one (leave_fastest_out)


def leave_fastest_out(friction, rate, most=LEAVE_OUT):
    """fit_rheology2 again without the k fastest samples, k = 0 .. most: [{left_out, count, n,
    n_sigma, A}] (n nan: no fit). In linear space a few fastest samples decide the fit (see
    creep_fit_minimum); its n over k = 1 .. most says how far they alone move it"""
    order = np.argsort(rate, kind="stable")[::-1]
    rows = []
    for k in range(most + 1):
        keep = np.sort(order[k:])
        fit = fit_rheology2(friction[keep], rate[keep])
        rows.append(dict(fit, left_out=k, count=len(keep)))
    return rows


def leave_out_range(rows):
    """(lowest n, highest n, fits that failed) over the rows of leave_fastest_out with k >= 1
    (None, None where none converged)"""
    n = np.array([r["n"] for r in rows if r["left_out"] >= 1], dtype=float)
    good = n[~np.isnan(n)]
    return (float(good.min()) if len(good) else None, float(good.max()) if len(good) else None,
            int(np.isnan(n).sum()))


def least_squares_profile(friction, rate, exponents):
    """the sum of squared residuals of creep_rheology2 that curve_fit minimises, at each n of
    `exponents` minimised over A: A enters linearly, A(n) = sum(r f^n) / sum(f^2n); returns
    (A(n), SSR(n)) as arrays over `exponents`"""
    fn = friction[None, :] ** np.asarray(exponents, dtype=float)[:, None]
    a = (fn * rate[None, :]).sum(axis=1) / (fn * fn).sum(axis=1)
    return a, ((rate[None, :] - a[:, None] * fn) ** 2).sum(axis=1)


PROFILE_EXPONENTS = np.linspace(-20.0, 40.0, 6001)   # n of the profile: the paper's 6-11 well inside


def creep_fit_minimum(friction, rate, exponents=PROFILE_EXPONENTS, level=0.95):
    """the least-squares minimum that the original's curve_fit seeks (same model, same samples,
    same linear-space residuals), found on the profile of SSR over n (least_squares_profile)
    and refined between its neighbouring grid points; with the profile interval: the n whose
    SSR exceeds the minimum by less than F(level; 1, m - 2) SSR_min / (m - 2) (m samples,
    residuals taken as independent). Returns {n, A, ssr, interval (lo, hi; None at the
    grid's end), exponents, profile (SSR over exponents)}"""
    m = len(rate)
    a, ssr = least_squares_profile(friction, rate, exponents)
    i = int(np.argmin(ssr))
    lo, hi = exponents[max(i - 1, 0)], exponents[min(i + 1, len(exponents) - 1)]
    best = scipy.optimize.minimize_scalar(
        lambda n: least_squares_profile(friction, rate, [n])[1][0], bounds=(lo, hi),
        method="bounded", options={"xatol": 1e-8})
    n = float(best.x) if best.fun <= ssr[i] else float(exponents[i])
    a_n, ssr_n = (v[0] for v in least_squares_profile(friction, rate, [n]))
    inside = ssr <= ssr_n * (1 + scipy.stats.f.ppf(level, 1, m - 2) / (m - 2))
    first, last = np.nonzero(inside)[0][[0, -1]]
    interval = (None if first == 0 else float(exponents[first]),
                None if last == len(exponents) - 1 else float(exponents[last]))
    return {"n": n, "A": float(a_n), "ssr": float(ssr_n), "interval": interval,
            "exponents": exponents, "profile": ssr}


def creep_rheology1(friction, n):
    """python/halfshear-darcy-rate-dependence.py lines 43-45: the strain rate of tau/N, A = 1"""
    return friction ** n


def curve_fit_as_called(model, friction, rate):
    """scipy.optimize.curve_fit(model, tau/N, rate) with its defaults (p0 all ones, maxfev
    200 (k + 1)), as the original's script calls it: {params (nan where it raised), status
    ('converged: ...' or the RuntimeError's message), nfev}"""
    k = model.__code__.co_argcount - 1
    try:
        popt, _, info, mesg, _ = scipy.optimize.curve_fit(model, friction, rate, full_output=True)
    except RuntimeError as error:
        return {"params": np.full(k, np.nan), "status": str(error), "nfev": 200 * (k + 1)}
    return {"params": popt, "status": "converged: " + mesg, "nfev": int(info["nfev"])}


def creep_fit_as_run(friction, rate):
    """the two fits of python/halfshear-darcy-rate-dependence.py lines 114-120 in its order:
    creep_rheology1 (A = 1; its n printed, not used) then creep_rheology2, whose n is the
    paper's. A RuntimeError in the first stops the script before the second. Returns {n, A
    (nan where no value: raised, or never reached), stopped (the script stopped there),
    first, second (curve_fit_as_called of each)}"""
    first = curve_fit_as_called(creep_rheology1, friction, rate)
    if np.isnan(first["params"][0]):
        return {"n": np.nan, "A": np.nan, "stopped": True, "first": first, "second": None}
    second = curve_fit_as_called(creep_rheology2, friction, rate)
    return {"n": float(second["params"][0]), "A": float(second["params"][1]),
            "stopped": np.isnan(second["params"][0]), "first": first, "second": second}


def creep_fit_per_cycle(series, period, tau, rate_scale=1.0, offset=0):
    """creep_fit of each whole cycle alone, the first included: the commented-out block of
    python/halfshear-darcy-rate-dependence.py lines 136-253 (fits of 1-3 s, 6-8 s, ... at
    lines 137-220). That block compares the scaled rate with 0.1, without line 100's factor
    t_DEM_to_t_real (with the paper's 5.8e-5, a threshold that keeps every creeping sample);
    here the pooled fit's conditions, so that the cycles' samples are the pooled ones"""
    return [dict(creep_fit(series, period, tau, rate_scale, k, k, offset), cycle=k)
            for k in range(1, whole_cycles(series["time"], period) + 1)]


def stick(series, period, tau):
    """per whole cycle, the original's stick (python/halfshear-darcy-combined.py lines 235-241:
    shaded where numpy.isclose(v, 0.0), v = shearVelocity(), line 103; numpy's defaults atol
    1e-8, rtol 1e-5, i.e. max(vx_top, 0) <= 1e-8 m/s) on the original's samples:
    stick_fraction, the fraction of the cycle's samples stuck; stick_intervals, (start, end)
    phases of each run of stuck samples, first to last sample as span_where shades them.
    OUR reading of that figure (not the original's): the layer leaves and regains the creep
    band. band: the largest v among the cycle's creep-fit samples (creep_samples kept,
    rate_scale 1: the conditions do not depend on it); exit_onset: the first phase > 0.6
    with v > BAND_EXIT_FACTOR * band; exit_end: the first phase after it with v < band, 1.0
    if v stays above to the cycle's end. None where the cycle has no creep-fit sample or v
    never leaves the band."""
    s = original_samples(series, period)
    t, v = s["time"], shear_velocity(s["vx_top"])
    stuck = np.isclose(v, 0.0)
    kept = creep_samples(series, period, tau)["kept"]
    rows = []
    for k in range(1, whole_cycles(series["time"], period) + 1):
        inside = (t >= (k - 1) * period) & (t < k * period)
        phase, vi, si = t[inside] / period - (k - 1), v[inside], stuck[inside]
        edges = np.diff(np.concatenate([[0], si.astype(int), [0]]))
        starts, ends = np.nonzero(edges == 1)[0], np.nonzero(edges == -1)[0] - 1
        r = {"cycle": k, "stick_fraction": float(si.mean()) if len(si) else np.nan,
             "stick_intervals": [(phase[a], phase[b]) for a, b in zip(starts, ends)],
             "band": None, "exit_onset": None, "exit_end": None}
        creeping = vi[kept[inside]]
        if len(creeping):
            r["band"] = creeping.max()
            out = np.nonzero((phase > CREEP_PHASES[1]) & (vi > BAND_EXIT_FACTOR * r["band"]))[0]
            if len(out):
                back = out[0] + np.nonzero(vi[out[0]:] < r["band"])[0]
                r["exit_onset"] = phase[out[0]]
                r["exit_end"] = phase[back[0]] if len(back) else 1.0
        rows.append(r)
    return rows


def coordination(series, period):
    """per whole cycle, on the original's samples: the mean coordination over phases 0.2-0.6
    (creeping) and its minimum with its phase, of the original's count (column
    coordination_original; None where a run predates it) and of ours (coordination).
    The original's count: src/sphere.cpp DEM::findOverlaps (lines 677-725) takes every pair
    i < j, the raw difference x_j - x_i (no periodic image), an overlap delta_n < 0, counted
    only if BOTH grains have fixvel == 0 (line 712: neither grain is fixed; its comment says
    "both"); python/sphere.py findCoordinationNumber (lines 4885-4894) adds 1 to each grain
    of a pair, findMeanCoordinationNumber (lines 4896-4904) the mean over ALL grains, the
    fixed ones counting zero; called by python/halfshear-darcy-combined.py lines 130-131."""
    s = original_samples(series, period)
    t = s["time"]
    rows = []
    for k in range(1, whole_cycles(series["time"], period) + 1):
        inside = (t >= (k - 1) * period) & (t < k * period)
        phase = t[inside] / period - (k - 1)
        creeping = (phase > CREEP_PHASES[0]) & (phase < CREEP_PHASES[1])
        r = {"cycle": k}
        for key, column in (("original", "coordination_original"), ("ours", "coordination")):
            if column not in s:
                r[key] = None
                continue
            z = s[column][inside]
            i = int(np.argmin(z))
            r[key] = {"creep": float(np.mean(z[creeping])), "min": z[i], "min_phase": phase[i]}
        rows.append(r)
    return rows
