#!/usr/bin/python3
"""examples/tidal_shear after a slip: does the plate ring, and what damps it?

Part "ringdown" (in.plate_ringdown, 0.3 s each): the plate on the frictionless bed (the
  example's default before; `original_bed`: on today's default bed) under a
  stress step 80 -> 100 kPa, no shear: the plate-bed mode's frequency f_p (FFT peak of the
  grain force on the plate) and damping ratio zeta (slope of the log Hilbert envelope over
  the part of the record where the envelope lies between 1e-3 and 0.3 of its first value),
  for each wall damping form, dry and wet. K_v = m_w (2 pi f_p)^2 is the bed's vertical
  stiffness under the plate (examples/tidal_shear/groups.py uses it).
Part "cycle" (examples/tidal_shear/in.tidal_shear, 3.0 s = 1.2 forcing cycles each): the
  first slip and what follows, for each variant below. Per run: the creep displacement of
  the top layer before the slip (phases 0.30-0.60 of the first cycle, N falling from 150 to
  52 kPa), the slip (onset: v_x > 1 cm/s; end: v_x < 1 mm/s again), and after the slip end
  the grain force on the plate against the applied stress (range and rms of
  N_grains - N_applied over 0.25 s) with its spectrum, the coordination number's range,
  and whether the top layer sticks (v_x < 1e-3 m/s over the last 0.25 s).
  The spread of two identical runs: the default on 1 and on 2 MPI ranks (the same physics,
  sums in another order).

Usage (after scripts/setup.sh; source scripts/env.sh):
    /usr/bin/python3 bench/wall_damping/wall_damping.py [--work DIR] [--part ringdown|cycle|all]
        [--old-gradient-plugin DIR]     # a plugin built with the v.grad(phi) of before
        [--analyse-only]
Writes wall_damping.png and wall_damping_results.md beside this script. A run whose output
is complete in --work is not repeated. The short setting (bench/smoke.py): two runs of each
part, a few hundred steps each (none complete: no table rows).
"""
import argparse
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from scipy.signal import hilbert

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from common import out_dir, short    # noqa: E402
from common.runs import FRICTIONLESS, complete, head_commit, load, prepare, run_lmp, time_step    # noqa: E402

OUT = out_dir(HERE)
A, SIGMA0, T_CYCLE, DT = 70e3, 80e3, 2.5, time_step(1.16e7)
CYCLE_STEPS = int(round(short(3.0, 0.001) / DT))
RINGDOWN_TIME = 0.3                 # s: in.plate_ringdown's run_time

RINGDOWN = {  # name: (label, variables)
    "none": ("no dashpot", {"gamma_w": 0}),
    "relative": ("relative, gamma_w 100", {"damping_velocity": "relative"}),
    "relative1000": ("relative, gamma_w 1000", {"damping_velocity": "relative", "gamma_w": 1000}),
    "absolute": ("absolute, gamma_w 100", {}),
    "plate": ("absolute + plate 4e3", {"plate_damping": 4.0e3}),
    "wet_absolute": ("absolute, wet", {"fluid": 1}),
    # the example's default bed (the original's preparation): its plate mode for groups.py
    "original_bed": ("absolute, the original's bed (default)", {"bed": "original"}),
    "original_bed_wet": ("absolute, wet, the original's bed (default)", {"bed": "original", "fluid": 1}),
}
CYCLE = {  # name: (label, variables, ranks, plugin)
    "wet_absolute": ("wet, absolute (default)", {}, 1, None),
    "wet_absolute_np2": ("wet, absolute, 2 ranks", {}, 2, None),
    "dry_absolute": ("dry, absolute", {"fluid": 0}, 1, None),
    "wet_relative": ("wet, relative", {"damping_velocity": "relative"}, 1, None),
    "wet_none": ("wet, no dashpot", {"gamma_w": 0}, 1, None),
    "wet_absolute_old_gradient": ("wet, absolute, old grad phi", {}, 1, "old"),
    "dry_absolute_plate": ("dry, absolute + plate 4e3", {"fluid": 0, "plate_damping": 4.0e3}, 1,
                           None),
}


# ---------------------------------------------------------------- ringdown

# the short setting: two runs of each part
RINGDOWN = short(RINGDOWN, {k: RINGDOWN[k] for k in ("none", "absolute")})
CYCLE = short(CYCLE, {k: CYCLE[k] for k in ("wet_absolute", "wet_absolute_np2")})


def ringdown(path):
    c = load(path)
    t, n = c["time"], c["N_grains"]
    x = n - np.mean(n[len(n) // 2:])
    dt = t[1] - t[0]
    spectrum = np.abs(np.fft.rfft(x * np.hanning(len(x))))
    freq = np.fft.rfftfreq(len(x), dt)
    f_p = freq[1 + np.argmax(spectrum[1:])]
    env = np.abs(hilbert(x))
    first = np.max(env[t < 0.02])
    sel = (t > 0.01) & (env < 0.3 * first) & (env > 1e-3 * first)
    sel &= t < t[-1] - 0.01
    if sel.sum() < 20:        # barely damped: fit the whole record
        sel = (t > 0.01) & (t < t[-1] - 0.01)
    slope = np.polyfit(t[sel], np.log(env[sel]), 1)[0]
    return dict(t=t, x=x, env=env, f_p=f_p, zeta=-slope / (2 * np.pi * f_p))


# ---------------------------------------------------------------- cycle

T_MIN = 0.75 * T_CYCLE              # the first minimum of N
WINDOWS = [(T_MIN + 0.375, T_MIN + 0.625), (T_MIN + 0.625, T_MIN + 0.875),
           (T_MIN + 0.875, T_MIN + 1.125)]
SPECTRUM_WINDOW = (T_MIN + 0.125, T_MIN + 0.875)


def rolling_rms(t, y, width):
    n = max(1, int(round(width / (t[1] - t[0]))))
    kernel = np.ones(n) / n
    return np.sqrt(np.convolve(y * y, kernel, mode="same"))


def cycle_metrics(c):
    t, vx, x = c["time"], c["vx_top"], c["x_top"]
    out = {}
    phase = t / T_CYCLE
    # means over windows of 0.05 cycle: the plate's shear vibration (~1 um) averages out
    mean_x = lambda p: np.mean(x[(phase >= p - 0.025) & (phase < p + 0.025)])
    out["creep_displacement"] = mean_x(0.575) - mean_x(0.325)
    out["creep_late"] = mean_x(0.655) - mean_x(0.605)
    fast = np.nonzero(vx > 1e-2)[0]
    out["slips"] = len(fast) > 0
    excess = (c["N_grains"] - c["N_applied"]) / A
    out["excess"] = excess
    out["excess_rms"] = rolling_rms(t, excess, 0.05)
    if not out["slips"]:
        return out
    onset = fast[0]
    out["slip_onset"] = t[onset]
    out["slip_peak_velocity"] = vx[onset:].max()
    out["slip_displacement"] = x[-1] - x[onset]
    out["dilation"] = c["z_wall"][onset:].max() - c["z_wall"][onset]
    out["suction_min"] = (c["p_mean"] - c["p_top"])[onset:].min() / A
    out["windows"] = []
    for lo, hi in WINDOWS:
        w = (t >= lo) & (t < hi)
        out["windows"].append((np.sqrt(np.mean(excess[w] ** 2)), c["coordination"][w].min(),
                               np.abs(vx[w]).max()))
    landing = (t > T_MIN) & (t < T_MIN + 1.125)
    out["lift_off"] = np.mean(c["N_grains"][landing] < 0.1 * c["N_applied"][landing])
    w = (t >= SPECTRUM_WINDOW[0]) & (t < SPECTRUM_WINDOW[1])
    y = excess[w] * A
    out["spectrum_f"] = np.fft.rfftfreq(len(y), t[1] - t[0])
    hann = np.hanning(len(y))
    out["spectrum"] = 2 * np.abs(np.fft.rfft(y * hann)) / np.sum(hann)
    out["spectrum_peak"] = out["spectrum_f"][1 + np.argmax(out["spectrum"][1:])]
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--work", default="/tmp/pw_wall_damping")
    ap.add_argument("--part", default="all", choices=["ringdown", "cycle", "all"])
    ap.add_argument("--old-gradient-plugin", default=None)
    ap.add_argument("--analyse-only", action="store_true")
    args = ap.parse_args()

    rings, cycles = {}, {}
    if args.part in ("ringdown", "all"):
        for name, (label, variables) in RINGDOWN.items():
            d = os.path.join(args.work, "ringdown", name)
            out = os.path.join(d, "ringdown.txt")
            if not args.analyse_only and not complete(out, RINGDOWN_TIME):
                prepare(d, [os.path.join(HERE, "in.plate_ringdown")])
                run_lmp(d, "in.plate_ringdown", dict(FRICTIONLESS, **variables,
                                                     run_time=short(RINGDOWN_TIME, 0.002)))
            if complete(out, RINGDOWN_TIME):
                rings[name] = (label, ringdown(out))
    if args.part in ("cycle", "all"):
        for name, (label, variables, ranks, plugin) in CYCLE.items():
            d = os.path.join(args.work, "cycle", name)
            out = os.path.join(d, "timeseries.txt")
            plugin_dir = args.old_gradient_plugin if plugin == "old" else None
            if plugin == "old" and not plugin_dir and not os.path.exists(out):
                continue
            if not args.analyse_only and not complete(out, 3.0):
                prepare(d)
                run_lmp(d, "in.tidal_shear", dict(FRICTIONLESS, **variables, run_steps=CYCLE_STEPS), ranks,
                        plugin_dir)
            if complete(out, 3.0):
                cycles[name] = (label, load(out))
    report(rings, cycles)


def report(rings, cycles):
    commit = head_commit()
    lines = ["# The plate after a slip: ringing and wall damping (bench/wall_damping/wall_damping.py)", "",
             "`/usr/bin/python3 bench/wall_damping/wall_damping.py --part all` (after scripts/setup.sh; "
             "source scripts/env.sh), written at commit %s on the 2-core development machine, "
             "shared with other jobs. Runs already complete in --work are reused: the "
             "first-cycle runs below were made with the example's inputs of this commit by "
             "the build before the styles moved onto src/core, whose time series this commit "
             "reproduces bit for bit (compared over the first 1.4 s of the default run, and "
             "over the default's 2.25 cycles by bench/paper_figures' run); the ringdown runs "
             "by this commit's build." % commit, ""]
    if rings:
        lines += ["## Plate ringdown (in.plate_ringdown: stress step 80 -> 100 kPa, 0.3 s)", "",
                  "| wall damping | f_p (Hz) | zeta |", "|---|---|---|"]
        for name, (label, r) in rings.items():
            lines.append("| %s | %.1f | %.4f |" % (label, r["f_p"], r["zeta"]))
        lines.append("")
    metrics = {name: cycle_metrics(c) for name, (label, c) in cycles.items()}
    if cycles:
        head = " | ".join("%.2f-%.2f s: rms, min Z, max v_x" % w for w in WINDOWS)
        lines += ["## The first forcing cycle (in.tidal_shear, 3.0 s)", "",
                  "Creep: top-layer displacement from phase 0.325 to 0.575 (N falling from 149 to "
                  "59 kPa, tau/N 0.07-0.17) and from 0.605 to 0.655 (35 to 20 kPa, tau/N 0.29-0.50), "
                  "each position the mean over 0.05 cycle. Slip onset: v_x > 1 cm/s. After the minimum of N (t = %.3f s): rms "
                  "of (N_grains - N_applied)/A, the smallest coordination number and the largest "
                  "|v_x| (m/s) in three windows; lift-off: the fraction of samples from the "
                  "minimum of N to 1.125 s after it with N_grains < 0.1 N_applied; the peak of "
                  "the spectrum of N_grains - N_applied over %.2f-%.2f s." % ((T_MIN,) + SPECTRUM_WINDOW),
                  "",
                  "| run | creep (um) | late creep (um) | slip onset (s) | peak v_x (m/s) | slip (mm) | dilation (mm) "
                  "| min p_mean - p_top (A) | " + head + " | lift-off | spectrum peak (Hz) |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for name, (label, c) in cycles.items():
            m = metrics[name]
            if not m["slips"]:
                lines.append("| %s | %.2f | %.2f | none |  |  |  |  |  |  |  |  |  |" % (
                    label, 1e6 * m["creep_displacement"], 1e6 * m["creep_late"]))
                continue
            wins = " | ".join("%.3f, %.2f, %.1e" % w for w in m["windows"])
            lines.append("| %s | %.3f | %.2f | %.3f | %.3f | %.1f | %.2f | %.3f | %s | %.3f | %.1f |" % (
                label, 1e6 * m["creep_displacement"], 1e6 * m["creep_late"], m["slip_onset"], m["slip_peak_velocity"],
                1e3 * m["slip_displacement"], 1e3 * m["dilation"], m["suction_min"], wins,
                m["lift_off"], m["spectrum_peak"]))
        lines.append("")
    open(os.path.join(OUT, "wall_damping_results.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot(rings, cycles, metrics)


def plot(rings, cycles, metrics):
    fig, ax = plt.subplots(2, 2, figsize=(12, 8.5))
    for k, (name, (label, c)) in enumerate(cycles.items()):
        m = metrics[name]
        color = "C%d" % k
        t = c["time"]
        ax[0, 0].semilogy(t, np.maximum(np.abs(c["vx_top"]), 1e-7), color=color, lw=0.6,
                          label=label)
        sel = t > T_MIN - 0.4
        ax[0, 1].plot(t[sel], m["excess_rms"][sel], color=color, lw=0.8, label=label)
        if m["slips"]:
            ax[1, 0].semilogy(m["spectrum_f"], np.maximum(m["spectrum"] / 1e3, 1e-3), color=color,
                              lw=0.8, label=label)
    ax[0, 0].set_xlabel("time (s)")
    ax[0, 0].set_ylabel("top-layer $|v_x|$ (m/s)")
    ax[0, 0].set_title("stick and slip, first cycle (N minimum at %.3f s)" % T_MIN)
    ax[0, 0].legend(fontsize=7)
    ax[0, 1].set_xlabel("time (s)")
    ax[0, 1].set_ylabel("rms of $(N_{grains} - N_{applied})/A$ over 0.05 s")
    ax[0, 1].set_title("grain force on the plate against the applied stress")
    ax[0, 1].axvline(T_MIN, color="k", lw=0.5, ls=":")
    ax[1, 0].set_xlabel("frequency (Hz)")
    ax[1, 0].set_ylabel("amplitude of $N_{grains} - N_{applied}$ (kPa)")
    ax[1, 0].set_title("spectrum over %.2f-%.2f s" % SPECTRUM_WINDOW)
    ax[1, 0].set_xlim(0, 200)
    for name, (label, r) in rings.items():
        ax[1, 1].semilogy(r["t"], np.maximum(r["env"] / 1e3, 1e-3), lw=0.8,
                          label="%s: %.0f Hz, zeta %.3f" % (label, r["f_p"], r["zeta"]))
    ax[1, 1].set_xlabel("time after the stress step (s)")
    ax[1, 1].set_ylabel("envelope of the grain force (kPa)")
    ax[1, 1].set_title("plate ringdown, stress step 80 -> 100 kPa")
    if rings:
        ax[1, 1].legend(fontsize=7)
    for a in ax.flat:
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "wall_damping.png"), dpi=100)


if __name__ == "__main__":
    sys.exit(main())
