#!/usr/bin/python3
"""Figure-3-style summary of a tidal_shear run: N and tau/N, top-layer velocity (log),
displacement, dilation, pore pressure below the plate against the top pressure, and
coordination number against time.

    /usr/bin/python3 plot.py [timeseries.txt] [tidal_shear.png] [tau] [title]
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

series = sys.argv[1] if len(sys.argv) > 1 else "timeseries.txt"
out = sys.argv[2] if len(sys.argv) > 2 else "tidal_shear.png"
tau = float(sys.argv[3]) if len(sys.argv) > 3 else 10.0e3    # applied shear stress, Pa
title = sys.argv[4] if len(sys.argv) > 4 else None
names = open(series).readline().lstrip("# ").split()
data = np.loadtxt(series, ndmin=2)
col = {name: data[:, k] for k, name in enumerate(names)}
t = col["time"]

fig, ax = plt.subplots(6, 1, sharex=True, figsize=(7, 11.5))
ax[0].plot(t, col["N_grains"] / 1e3, lw=0.5, color="C1", label="N on the grains")
ax[0].plot(t, col["N_applied"] / 1e3, color="C0", label="N applied (plate)")
ax[0].set_ylabel("N [kPa]")
twin = ax[0].twinx()
twin.plot(t, tau / col["N_applied"], color="C3", lw=0.8)
twin.set_ylabel(r"$\tau/N$", color="C3")
ax[0].legend(loc="upper right", fontsize=8)
ax[1].semilogy(t, np.maximum(np.abs(col["vx_top"]), 1e-7), lw=0.7)
ax[1].set_ylabel("top-layer $|v_x|$ [m/s]")
ax[2].plot(t, col["x_top"] * 1e3)
ax[2].set_ylabel("displacement [mm]")
ax[3].plot(t, (col["z_wall"] - col["z_wall"][0]) * 1e3)
ax[3].set_ylabel("dilation [mm]")
ax[4].plot(t, (col["p_mean"] - col["p_top"]) / 1e3, lw=0.7)
ax[4].set_ylabel(r"$\bar p - p_{top}$ [kPa]")
ax[5].plot(t, col["coordination"], lw=0.7)
ax[5].set_ylabel("coordination")
ax[5].set_xlabel("time [s]")
for a in ax:
    a.grid(alpha=0.3)
if title:
    ax[0].set_title(title, fontsize=10)
fig.tight_layout()
fig.savefig(out, dpi=100)
print("wrote", out)
