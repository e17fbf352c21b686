#!/usr/bin/python3
"""Figure-3-style summary of a tidal_shear run: N and tau/N, top-layer velocity (log),
displacement, dilation and coordination number against time.

    /usr/bin/python3 plot.py [timeseries.txt] [tidal_shear.png]
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

series = sys.argv[1] if len(sys.argv) > 1 else "timeseries.txt"
out = sys.argv[2] if len(sys.argv) > 2 else "tidal_shear.png"
names = open(series).readline().lstrip("# ").split()
data = np.loadtxt(series, ndmin=2)
col = {name: data[:, k] for k, name in enumerate(names)}
t = col["time"]
tau = float(sys.argv[3]) if len(sys.argv) > 3 else 10.0e3    # applied shear stress, Pa

fig, ax = plt.subplots(5, 1, sharex=True, figsize=(7, 10))
ax[0].plot(t, col["N_applied"] / 1e3, label="N applied (plate)")
ax[0].plot(t, col["N_grains"] / 1e3, lw=0.8, label="N on grains")
ax[0].set_ylabel("N [kPa]")
twin = ax[0].twinx()
twin.plot(t, tau / col["N_applied"], color="C3", lw=0.8)
twin.set_ylabel(r"$\tau/N$", color="C3")
ax[0].legend(loc="upper right", fontsize=8)
ax[1].semilogy(t, np.maximum(np.abs(col["vx_top"]), 1e-12))
ax[1].set_ylabel("top-layer $v_x$ [m/s]")
ax[2].plot(t, col["x_top"])
ax[2].set_ylabel("displacement [m]")
ax[3].plot(t, (col["z_wall"] - col["z_wall"][0]) * 1e3)
ax[3].set_ylabel("dilation [mm]")
ax[4].plot(t, col["coordination"])
ax[4].set_ylabel("coordination")
ax[4].set_xlabel("time [s]")
for a in ax:
    a.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(out, dpi=110)
print("wrote", out)
