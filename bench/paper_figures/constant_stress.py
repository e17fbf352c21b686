"""Constant-stress shear tests of the reduced bed (figures.py --part creep): Figure S1
measured as the supplement describes it, independently of the tidal cycles.

Each test: the plate at a constant N (no tidal forcing, p_top 0, the pore water on), a
constant shear stress tau on the top layer, the plate's mass that of the example. Two bed
states: the shipped consolidated bed (never sheared) and the bed after 1.2 tidal cycles of
the example (sheared once; written out at phase 0.2 of the second cycle, after it has
stuck again; write_data keeps positions, not the contacts' tangential springs, so those
restart from zero). First a 0.3 s check: the layer holds (|v_x| < 1 cm/s at its end) or
fails; a test that holds is run for 2 s and its creep rate measured over 1-2 s. The short
setting (bench/smoke.py) runs each check a few thousand steps (never complete: no test is
measured) on two of the tests.
"""
import os
import shutil

import numpy as np
from scipy import stats

from common import short
from common.runs import FRICTIONLESS, complete, load, prepare, run_lmp, time_step
from porewater_analysis.cycles import log_log_fit

SIGMA0 = 80.0e3
DIAMETER, RHO = 0.02, 2600.0
DT = time_step(1.16e7)                 # the reduced case's k_n (in.params)
SLIP_VELOCITY = 1e-2                   # m/s: failed (as the tidal cycles' slip)
RATIOS = short([0.1, 0.2, 0.3, 0.4, 0.45, 0.5, 0.6, 0.7], [0.1])
NORMAL = short([25.0e3, 50.0e3], [25.0e3])
CHECK_TIME, HOLD_TIME = 0.3, 2.0       # s
RATE_WINDOW = (1.0, 2.0)               # s: after the start-up transient (checked: 0.5-1 s)
BLOCK = 0.1                            # s: block means remove the plate's shear vibration
STATES = {
    "consolidated": ("consolidated, never sheared", "consolidated_frictionless_0.data"),
    "sheared": ("sheared 1.2 tidal cycles", "sheared_1.data"),
}


def sheared_state(work):
    """the bed after 1.2 cycles of the example (its default parameters)"""
    d = os.path.join(work, "sheared_state")
    path = os.path.join(d, "sheared_1.data")
    if not os.path.exists(path):
        prepare(d)
        run_lmp(d, "in.tidal_shear", dict(FRICTIONLESS, cycles=short(1.2, 0.002),
                                          write_state="sheared_1"))
    return path


# the suspected cause of a creep rate below resolution, tested: the water damps the bed's
# vibrations (no other damping acts at constant stress); the same tests dry
DRY = [("consolidated", 25.0e3, 0.4), ("sheared", 25.0e3, 0.3)]


def run_test(work, state, n, ratio, seconds, fluid=1, run=True):
    kind = "check" if seconds == CHECK_TIME else "hold"
    d = os.path.join(work, "stress", kind, "%s_N%.0f_r%.2f%s" % (state, n / 1e3, ratio,
                                                                 "" if fluid else "_dry"))
    out = os.path.join(d, "timeseries.txt")
    if not complete(out, seconds):
        if not run:
            return None
        prepare(d)
        data = STATES[state][1]
        if state == "sheared":
            shutil.copy(sheared_state(work), d)
        # the plate keeps the example's mass: mass_factor scales with 1/N
        run_lmp(d, "in.tidal_shear", {**FRICTIONLESS, "amp": 0, "sigma0": n, "tau": ratio * n, "data": data,
                                      "mass_factor": 0.493 * SIGMA0 / n, "fluid": fluid,
                                      "run_steps": int(round(short(seconds, 0.005) / DT))})
    return load(out) if complete(out, seconds) else None


def end_velocity(c):
    t, x = c["time"], c["x_top"]
    end = t > CHECK_TIME - 0.05
    return np.polyfit(t[end], x[end], 1)[0]


def block_rate(c, t0, t1):
    """slope of the top layer's block-mean displacement over [t0, t1], its standard error"""
    t, x = c["time"], c["x_top"]
    edges = np.arange(t0, t1 + 1e-9, BLOCK)
    tm = [t[(t >= a) & (t < a + BLOCK)].mean() for a in edges[:-1]]
    xm = [x[(t >= a) & (t < a + BLOCK)].mean() for a in edges[:-1]]
    fit = stats.linregress(tm, xm)
    return fit.slope, fit.stderr


def measure(c):
    """creep of a held test: gamma_dot over RATE_WINDOW (+- 95 %), the same over 0.5-1 s, I"""
    h = np.mean(c["z_wall"][c["time"] > RATE_WINDOW[0]])
    v, se = block_rate(c, *RATE_WINDOW)
    nblocks = int(round((RATE_WINDOW[1] - RATE_WINDOW[0]) / BLOCK))
    half = stats.t.ppf(0.975, nblocks - 2) * se
    v_early, _ = block_rate(c, 0.5, 1.0)
    n = np.mean(c["N_grains"][c["time"] > RATE_WINDOW[0]])
    last = c["time"] > RATE_WINDOW[1] - BLOCK
    wiggle = c["x_top"][last] - np.polyval(np.polyfit(c["time"][last], c["x_top"][last], 1),
                                           c["time"][last])
    return {"rate": v / h, "half": half / h, "rate_early": v_early / h, "height": h,
            "vibration": wiggle.std(),
            "inertia": abs(v / h) * DIAMETER * np.sqrt(RHO / n), "n_grains": n,
            "take_up": c["x_top"][c["time"] <= RATE_WINDOW[0]][-1]}


def series(work, jobs_map, states=tuple(STATES), run=True):
    """every test (checks, then holds of those that hold), dry ones last; with run False only
    those complete in work. Returns {point: result}; point (state, N, tau/N[, "dry"])"""
    def tests(points, seconds, fluid):
        got = jobs_map(lambda p: run_test(work, *p, seconds, fluid=fluid, run=run), points)
        return {p: c for p, c in zip(points, got) if c is not None}

    out = {}
    for points, fluid in [([(s, n, r) for s in states for n in NORMAL for r in RATIOS], 1),
                          ([p for p in DRY if p[0] in states], 0)]:
        checks = tests(points, CHECK_TIME, fluid)
        held = [p for p in checks if end_velocity(checks[p]) <= SLIP_VELOCITY]
        holds = tests(held, HOLD_TIME, fluid)
        for p in checks:
            late = checks[p]["time"] > CHECK_TIME - 0.05
            r = {"fails": p not in held, "v_end": end_velocity(checks[p]),
                 "unmeasured": p in held and p not in holds,
                 "resist": np.mean(checks[p]["tau_resist"][late]) / p[1]}
            if p in holds:
                r.update(measure(holds[p]))
            out[p if fluid else p + ("dry",)] = r
    return out


def power_law(rows):
    """n (95 %) of gamma_dot ~ (tau/N)^n over the held tests whose rate is resolved
    (positive and above its own 95 % interval)"""
    pts = [(ratio, r["rate"]) for ratio, r in rows if "rate" in r and r["rate"] > r["half"]]
    if len(pts) < 3:
        return None
    slope, half, r2 = log_log_fit([p[0] for p in pts], [p[1] for p in pts])
    return slope, half, len(pts), r2


def report(results):
    lines = ["Per test: gamma_dot = v_x/H over %.1f-%.1f s (the slope of the top layer's "
             "displacement averaged over %.1f s blocks, +- its 95 %% interval; H the plate's "
             "height) and over 0.5-1 s; the take-up: the layer's displacement in the first "
             "%.1f s; vibration: the rms of its displacement about a line over the last %.1f s. Fails: the layer above %g m/s after %.1f s (its velocity then)."
             % (RATE_WINDOW + (BLOCK, RATE_WINDOW[0], BLOCK, SLIP_VELOCITY, CHECK_TIME)), "",
             "| state | N (kPa) | tau/N | gamma_dot 1-2 s (1/s) | 0.5-1 s | take-up (mm) "
             "| vibration (µm) | I |", "|---|---|---|---|---|---|---|---|"]
    fits = ["", "| state | N (kPa) | n (95 %) | tests fitted | r^2 | yield tau/N (held, failed) |",
            "|---|---|---|---|---|---|"]
    for s, (label, _) in STATES.items():
        for n in NORMAL:
            rows = [(ratio, results[(s, n, ratio)]) for ratio in RATIOS if (s, n, ratio) in results]
            for ratio, r in rows:
                if r["unmeasured"]:
                    lines.append("| %s | %.0f | %.2f | holds at %.1f s; not run longer | | | | |"
                                 % (label, n / 1e3, ratio, CHECK_TIME))
                elif r["fails"]:
                    lines.append("| %s | %.0f | %.2f | fails (%.2g m/s at %.1f s; the bed "
                                 "resists with %.2f N) | | | | |"
                                 % (label, n / 1e3, ratio, r["v_end"], CHECK_TIME, r["resist"]))
                else:
                    lines.append("| %s | %.0f | %.2f | %.2e ± %.1e | %.2e | %.3f | %.2g | %.0e |" % (
                        label, n / 1e3, ratio, r["rate"], r["half"], r["rate_early"],
                        1e3 * r["take_up"], 1e6 * r["vibration"], r["inertia"]))
            held = [ratio for ratio, r in rows if not r["fails"]]
            failed = [ratio for ratio, r in rows if r["fails"]]
            fit = power_law(rows)
            fits.append("| %s | %.0f | %s | %s | %s | %s |" % (
                label, n / 1e3, "%.1f ± %.1f" % fit[:2] if fit else "too few resolved rates",
                fit[2] if fit else "", "%.2f" % fit[3] if fit else "",
                "%.2f-%.2f" % (max(held), min(failed)) if held and failed else "outside"))
    dry = ["", "The suspected cause tested, dry (`fluid 0`), the same tests:", "",
           "| state | N (kPa) | tau/N | gamma_dot 1-2 s, with water | dry | dry, 0.5-1 s "
           "| vibration with water, dry (µm) |", "|---|---|---|---|---|---|---|"]
    for key, r in results.items():
        if len(key) == 4:
            wet = results.get(key[:3], {"fails": False, "unmeasured": True})

            def cell(x):
                if x["unmeasured"]:
                    return "not run"
                return "fails (%.2g m/s)" % x["v_end"] if x["fails"] else "%.2e ± %.1e" % (
                    x["rate"], x["half"])
            dry.append("| %s | %.0f | %.2f | %s | %s | %s | %s |" % (
                STATES[key[0]][0], key[1] / 1e3, key[2], cell(wet), cell(r),
                "%.2e" % r["rate_early"] if "rate" in r else "",
                ", ".join("%.2g" % (1e6 * x["vibration"]) if "vibration" in x else "-"
                          for x in (wet, r))))
    return lines + fits + dry


def plot(results, ax):
    markers = {"consolidated": "o", "sheared": "s"}
    colours = {25.0e3: "C0", 50.0e3: "C1"}
    for key, r in results.items():
        if r["unmeasured"]:
            continue
        s, n, ratio = key[:3]
        kw = dict(color="C7" if len(key) == 4 else colours[n], marker=markers[s], ls="none")
        if r["fails"]:
            ax.plot(ratio, r["v_end"] / 0.24, mfc="none", **kw)
        elif r["rate"] > r["half"]:
            ax.errorbar(ratio, r["rate"], yerr=[[min(r["half"], 0.99 * r["rate"])], [r["half"]]], **kw)
        else:
            ax.plot(ratio, max(r["rate"] + r["half"], 1e-10), marker="v", color=kw["color"], ls="none")
    for s, m in markers.items():
        for n, col in colours.items():
            ax.plot([], [], marker=m, color=col, ls="none", label="%s, N %.0f kPa" % (STATES[s][0], n / 1e3))
    ax.plot([], [], marker="o", color="C7", ls="none", label="dry (fluid 0), N 25 kPa")
    ax.plot([], [], marker="v", color="k", ls="none", label="unresolved: upper bound")
    ax.plot([], [], marker="o", mfc="none", color="k", ls="none", label="fails: v/H at 0.3 s")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("tau/N")
    ax.set_ylabel("shear strain rate (1/s)")
    ax.legend(fontsize=6)
