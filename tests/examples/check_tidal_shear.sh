#!/usr/bin/env bash
# examples/tidal_shear behaves as the model says, from the shipped consolidated state:
#  1. body forces per group: the bed carries gravity and the fluid force, the held bottom
#     layer the fluid force only, the plate's grains (top) no gravity and no vertical fluid
#     force but their horizontal one;
#  2. loading (the first 0.3 s, N rising from 80 to 118 kPa): the bed compacts and the pore
#     pressure below the plate stays above p_top by what a drained column predicts: the
#     fluid the bed expels per unit volume and time, its compaction rate eps_dot and the
#     expansion of the water as p_top falls, -beta_f phi dp_top/dt, flows out through the
#     top, which takes a mean excess mu_f H_f^2/(3 k) (eps_dot - beta_f phi dp_top/dt) over
#     the column of height H_f (within a factor 2 for the column's non-uniform k and
#     compaction; 1.1e-3 A measured here); the top layer does not slip;
#  3. below yield the bed holds, above it it fails: at constant N (0.1 s from the shipped
#     state) with tau/N = 0.3 the top layer takes up the shear load (0.27 mm) and then holds
#     (within 25 um over the last 0.05 s, i.e. creeping at under 5e-4 m/s; measured 7.5 um,
#     the plate's own shear vibration); with tau/N = 0.5 it accelerates past 1 cm/s. (At 0.4
#     it moved 0.8 mm over the last 0.05 s: the unsheared bed yields between 0.3 and 0.4, as
#     the paper's 0.26-0.38.) The parameters (cell_z, mu_f, plate mass, ...) are read from
#     the run's checkpoint_params.txt.
# Usage: check_tidal_shear.sh LMP PLUGIN_DIR
set -euo pipefail
LMP=$1; PLUGIN_DIR=$2
EXAMPLE=$(cd "$(dirname "$0")/../../examples/tidal_shear" && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cp "$EXAMPLE"/in.* "$EXAMPLE"/consolidated_0.data "$work"/
cd "$work"
export LD_LIBRARY_PATH="$PLUGIN_DIR:${LD_LIBRARY_PATH:-}" OMP_NUM_THREADS=1

# 1. body forces: after 2000 steps of the example, the forces with the contacts, the walls,
#    the held bottom and the plate switched off are the body forces alone
cat > in.body_forces <<'EOF'
variable run_steps index 2000
include in.tidal_shear
neigh_modify exclude type 1 1
unfix grains
fix grains all nve/sphere/bed gravity ${g} bed
unfix wall
unfix shear
compute fz all property/atom fz
compute fx_top top reduce sum f_darcy[1]
compute fz_fluid_top top reduce sum f_darcy[3]
compute fz_fluid_bed bed reduce sum f_darcy[3]
compute fz_fluid_bottom bottom reduce sum f_darcy[3]
compute fz_top top reduce sum c_fz
compute fz_bed bed reduce sum c_fz
compute fz_bottom bottom reduce sum c_fz
thermo_style custom step c_fx_top c_fz_fluid_top c_fz_fluid_bed c_fz_fluid_bottom c_fz_top c_fz_bed c_fz_bottom
run 0
print "BODY $(c_fx_top:%.10e) $(c_fz_fluid_top:%.10e) $(c_fz_fluid_bed:%.10e) $(c_fz_fluid_bottom:%.10e) $(c_fz_top:%.10e) $(c_fz_bed:%.10e) $(c_fz_bottom:%.10e) $(mass(bed)*v_g:%.10e) $(count(top)) $(count(bed)) $(count(bottom))"
EOF
"$LMP" -in in.body_forces -log log.body -screen none
grep '^BODY' log.body > body.txt

# 2. loading: 0.3 s of the example
"$LMP" -in in.tidal_shear -var run_steps 140187 -log log.loading -screen none
mv timeseries.txt loading.txt
# the example's parameters as the run recorded them (in.checkpoint_params)
param() { awk -v k="ck_$1" '$1 == "variable" && $2 == k { print $4 }' checkpoint_params.txt; }
for p in cell_z mu_f beta_f kc mass_factor; do export "PW_$p=$(param $p)"; done

# 3. constant N (amp 0, p_top 0) below and above yield; the plate keeps its mass
for ratio in 0.3 0.5; do
  sigma=$(/usr/bin/python3 -c "print(10.0e3 / $ratio)")
  factor=$(/usr/bin/python3 -c "print($PW_mass_factor * 80.0e3 / $sigma)")
  "$LMP" -in in.tidal_shear -var amp 0 -var sigma0 "$sigma" -var mass_factor "$factor" \
    -var run_steps 46729 -log log.creep_$ratio -screen none
  mv timeseries.txt creep_$ratio.txt
done

/usr/bin/python3 - <<'PY'
import numpy as np, os, sys
ok = True
def check(cond, what):
    global ok
    print(("ok    " if cond else "FAIL  ") + what)
    ok &= bool(cond)
def load(path):
    names = open(path).readline().lstrip("# ").split()
    d = np.loadtxt(path, ndmin=2)
    return d, {n: d[:, k] for k, n in enumerate(names)}

A, s0, f, g = 70.0e3, 80.0e3, 0.4, 9.81
# -- 1. body forces
b = open("body.txt").read().split()[1:]
fx_top, fzf_top, fzf_bed, fzf_bottom, fz_top, fz_bed, fz_bottom, weight_bed = map(float, b[:8])
scale = abs(weight_bed)
check(fzf_top == 0.0 and fz_top == 0.0, "plate grains: no gravity, no vertical fluid force (%g, %g)" % (fzf_top, fz_top))
check(abs(fx_top) > 1e-9 * scale, "plate grains keep their horizontal fluid force (sum f_x %.3g N)" % fx_top)
check(abs(fz_bed - (fzf_bed - weight_bed)) < 1e-9 * scale, "bed: gravity + fluid force (%.6g = %.6g - %.6g)" % (fz_bed, fzf_bed, weight_bed))
check(fzf_bed > 0.3 * weight_bed * 1000 / 2600, "bed: the fluid force includes buoyancy (%.4g N of %.4g)" % (fzf_bed, weight_bed * 1000 / 2600))
check(abs(fz_bottom - fzf_bottom) < 1e-9 * scale and fzf_bottom != 0.0, "held bottom layer: fluid force only, no gravity (%.4g N)" % fz_bottom)

# -- 2. loading
d, c = load("loading.txt")
t = c["time"]
check(len(d) >= 100 and np.all(np.isfinite(d)), "%d finite samples over the loading" % len(d))
check(np.allclose(c["N_applied"], s0 + A * np.sin(2 * np.pi * f * t), rtol=0, atol=1.0), "plate stress follows sigma0 + A sin(2 pi f t)")
check(np.allclose(c["p_top"], A * np.sin(2 * np.pi * f * t + np.pi), rtol=0, atol=1.0), "top pressure follows A sin(2 pi f t + pi)")
w = (t > 0.1) & (t < 0.3)
excess = np.mean((c["p_mean"] - c["p_top"])[w])
v_wall = np.polyfit(t[w], c["z_wall"][w], 1)[0]          # the bed's compaction rate
p = {k: float(os.environ["PW_" + k]) for k in ("cell_z", "mu_f", "beta_f", "kc")}
H = np.mean(c["z_wall"][w]); H_f = 3 * p["cell_z"]       # bed height, drained column
phi = np.mean(c["phi_mean"][w]); k = p["kc"] * phi**3 / (1 - phi)**2; mu_f, beta_f = p["mu_f"], p["beta_f"]
dp_top = np.mean(np.gradient(c["p_top"], t)[w])
compaction, expansion = -v_wall / H, -beta_f * phi * dp_top
drained = mu_f * H_f**2 / (3 * k) * (compaction + expansion)
print("      loading: plate at %.3g mm/s, p_mean - p_top = %.4g Pa = %.2e A, drained column %.4g Pa "
      "(compaction %.3g /s, water expansion %.3g /s)" % (1e3 * v_wall, excess, excess / A, drained, compaction, expansion))
check(v_wall < 0, "the bed compacts while N rises")
check(0.5 * drained < excess < 2.0 * drained, "pore pressure below the plate above p_top by the drained column's excess (factor 2)")
check(excess > 2e-4 * A, "... which is more than 2e-4 A (the water is not passive)")
check(np.all(np.abs(c["vx_top"]) < 1e-2), "no slip while N rises (|v_x| < 1 cm/s)")

# -- 3. creep and yield
for ratio, slips in ((0.3, False), (0.5, True)):
    d, c = load("creep_%s.txt" % ratio)
    t, x, v = c["time"], c["x_top"], c["vx_top"]
    late = t > t[-1] - 0.02
    if slips:
        check(np.mean(v[late]) > 1e-2 and v[-1] > v[late][0], "tau/N = %s: the top layer accelerates past 1 cm/s (v_x %.3g m/s)" % (ratio, v[-1]))
    else:
        held = t > t[-1] - 0.05
        step = x[held].max() - x[held].min()
        check(x[-1] > 5e-5 and step < 25e-6 and np.all(np.abs(v[held]) < 1e-2), "tau/N = %s: the top layer takes up the load (%.3g mm) and holds (%.2g um over the last 0.05 s, |v_x| < 1 cm/s)" % (ratio, 1e3 * x[-1], 1e6 * step))
sys.exit(0 if ok else 1)
PY
