#!/usr/bin/python3
"""The dimensionless groups of the tidal shear experiment: Table S1, the reduced case used
before (1 Hz, beta_f x100) and the reduced case of in.params (README.md, "The reduced case
and its scaling").

    /usr/bin/python3 groups.py [--markdown]
    /usr/bin/python3 groups.py --bed FILE    (a bed of one's own: the -var values that keep
                                              the reduced case's groups for its H and phi)
    /usr/bin/python3 groups.py --layers FILE (the held base and the shear plate as the
                                              original marks them: their -var values)

H (top of the highest grain over the floor) and phi (1 - grain volume/(L_x L_y H)) of the
reduced cases come from their consolidated states; Table S1's are the supplement's 0.47 m at
phi 0.38. The groups of the plate mode use the bed's vertical stiffness under the plate,
K_v = m_w (2 pi f_p)^2, with the plate-mode frequency f_p measured by bench/wall_damping/wall_damping.py
(its ringdown) on each reduced bed: 110 Hz on the frictionless one, 93.3 Hz on the default
(the original's preparation, looser); as a constrained modulus M_s = K_v H/(L_x L_y) over
k_n/d, 0.79 and 0.567. Table S1's bed, prepared as the original's, takes the default's
(a packing of linear springs has its moduli proportional to k_n/d at a given geometry).
"""
import math
import sys

COMMON = dict(r=0.01, rho=2600.0, rho_f=1000.0, g=9.81, sigma0=80e3, amp=70e3, tau=10e3,
              kc=3.5e-13, eps=0.07)
# constrained modulus of the bed over k_n/d, from the plate mode measured on each reduced bed
MODULUS_FRICTIONLESS, MODULUS_ORIGINAL = 0.79, 0.567
CASES = {
    "Table S1": dict(COMMON, lx=0.52, ly=0.26, kn=1.16e9, beta=1.426e-8, mu_f=1.040e-7,
                     f=0.2, dz=0.55 / 6, H=0.47, phi=0.38, mass_factor=1.0, gamma_w=1e3,
                     gamma_p=0.0, modulus=MODULUS_ORIGINAL),
    # the case before the faithful reduced one (1 Hz, beta_f x100)
    "reduced before": dict(COMMON, lx=0.26, ly=0.13, kn=1.16e7, beta=1.426e-6, mu_f=8.3e-10,
                           f=1.0, dz=0.317 / 4, H=0.2567, phi=0.4206, mass_factor=1.0,
                           gamma_w=1e3, gamma_p=0.0, modulus=MODULUS_FRICTIONLESS),
    # in.params -var bed frictionless: consolidated_frictionless_0.data
    "reduced, frictionless bed": dict(COMMON, lx=0.26, ly=0.13, kn=1.16e7, beta=1.426e-8,
                                      mu_f=1.93e-7, f=0.4, dz=0.078, H=0.2383, phi=0.3759,
                                      mass_factor=0.493, gamma_w=100.0, gamma_p=0.0,
                                      modulus=MODULUS_FRICTIONLESS),
    # in.params (default): consolidated_0.data, the original's preparation
    "reduced": dict(COMMON, lx=0.26, ly=0.13, kn=1.16e7, beta=1.426e-8, mu_f=2.415e-7,
                    f=0.4, dz=0.08176, H=0.2498, phi=0.4049, mass_factor=0.4703,
                    gamma_w=100.0, gamma_p=0.0, modulus=MODULUS_ORIGINAL),
    # in.params -var bed stiff: consolidated_stiff_0.data, the default bed at Table S1's k_n
    "reduced, stiff bed": dict(COMMON, lx=0.26, ly=0.13, kn=1.16e9, beta=1.426e-8, mu_f=2.415e-7,
                               f=0.4, dz=0.08177, H=0.2498, phi=0.4050, mass_factor=0.4703,
                               gamma_w=1000.0, gamma_p=0.0, modulus=MODULUS_ORIGINAL, eps=0.14),
}


# the bed the reduced case's parameters were first chosen for (the frictionless one) and
# those values: bed_parameters keeps its groups for any other bed
FRICTIONLESS = CASES["reduced, frictionless bed"]
SHIPPED = dict(H=FRICTIONLESS["H"], phi=FRICTIONLESS["phi"], cell_z=0.078,
               mu_f=FRICTIONLESS["mu_f"], mass_factor=FRICTIONLESS["mass_factor"])


def bed_geometry(path):
    """H (top of the highest grain over the floor) and phi = 1 - grain volume/(L_x L_y H)
    of a LAMMPS data file of atom_style sphere (id type diameter density x y z)"""
    lines = open(path).read().splitlines()
    box = {}
    for line in lines[:40]:
        parts = line.split()
        if len(parts) == 4 and parts[2].endswith("lo"):
            box[parts[2][0]] = float(parts[1]) - float(parts[0])
    radius, z = bed_grains(path)
    top = max(0.0, max(zi + ri for zi, ri in zip(z, radius)))
    volume = sum(4.0 / 3.0 * math.pi * r ** 3 for r in radius)
    return top, 1 - volume / (box["x"] * box["y"] * top)


def bed_grains(path):
    """(radius, z) of every grain of a LAMMPS data file of atom_style sphere"""
    lines = open(path).read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("Atoms")) + 2
    radius, z = [], []
    for line in lines[start:]:
        if not line.strip():
            break
        v = line.split()
        radius.append(float(v[2]) / 2)
        z.append(float(v[6]))
    return radius, z


def original_layer_cuts(path):
    """(bottom_cut, top_cut) of in.tidal_shear: the held base and the shear plate as the
    original marks them (sphere.py shear(), lines 3115-3147 of klkkong/sphere): the grains
    whose centres lie within the largest diameter of the lower (upper) 30 % of the bed from
    the lowest (highest) grain surface"""
    radius, z = bed_grains(path)
    low = min(zi - ri for zi, ri in zip(z, radius))
    high = max(zi + ri for zi, ri in zip(z, radius))
    below = 2 * max(ri for zi, ri in zip(z, radius) if zi < (high - low) * 0.3)
    above = 2 * max(ri for zi, ri in zip(z, radius) if zi > (high - low) * 0.7)
    return low + below, high - above


def bed_parameters(height, phi):
    """cell_z, mu_f and mass_factor of the reduced case that keep its groups for a bed of
    height H and porosity phi: the fluid cells' top face at the same fraction of a cell under
    the plate, mu_f H^2/(k T sigma0) (Kozeny-Carman k) and m_w H/(A L_x L_y T^2)"""
    k = lambda p: p ** 3 / (1 - p) ** 2
    return {"cell_z": SHIPPED["cell_z"] * height / SHIPPED["H"],
            "mu_f": SHIPPED["mu_f"] * (k(phi) / k(SHIPPED["phi"])) * (SHIPPED["H"] / height) ** 2,
            "mass_factor": SHIPPED["mass_factor"] * SHIPPED["H"] / height}


def groups(c):
    d = 2 * c["r"]
    m = c["rho"] * 4.0 / 3.0 * math.pi * c["r"] ** 3
    dt = c["eps"] / math.sqrt(c["kn"] / m)
    T = 1.0 / c["f"]
    H, phi = c["H"], c["phi"]
    area = c["lx"] * c["ly"]
    mass_w = c["mass_factor"] * c["sigma0"] * area / c["g"]
    k = c["kc"] * phi ** 3 / (1 - phi) ** 2
    D = k / (c["beta"] * phi * c["mu_f"])
    smax = c["sigma0"] + c["amp"]
    Z = 4.5                                              # coordination of the loaded bed
    F_mean = math.pi * d * d * smax / (Z * (1 - phi))    # mean contact force at sigma_max
    M_s = c["modulus"] * c["kn"] / d
    K_v = M_s * area / H
    root = math.sqrt(K_v * mass_w)
    t_d = H * H / D
    rho_b = (1 - phi) * c["rho"] + phi * c["rho_f"]
    omega_p = math.sqrt(K_v / mass_w)
    g = {}
    g["eps = dt sqrt(k_n/m)"] = dt * math.sqrt(c["kn"] / m)
    g["kappa = k_n/(sigma_max d)"] = c["kn"] / (smax * d)
    g["delta/r at sigma_max (mean contact)"] = F_mean / c["kn"] / c["r"]
    g["D T/H^2"] = D * T / H ** 2
    g["mu_f H^2/(k T sigma0)"] = c["mu_f"] * H ** 2 / (k * T * c["sigma0"])
    g["1/(beta_f phi sigma0)"] = 1.0 / (c["beta"] * phi * c["sigma0"])
    g["beta_f k_n/d"] = c["beta"] * c["kn"] / d
    g["beta_f phi M_s (M_s: the bed's constrained modulus)"] = c["beta"] * phi * M_s
    g["t_i/T = d sqrt(rho/sigma0)/T"] = d * math.sqrt(c["rho"] / c["sigma0"]) / T
    g["Pi_w = m_w H/(A L_x L_y T^2)"] = mass_w * H / (c["amp"] * area * T * T)
    g["tau/sigma0"] = c["tau"] / c["sigma0"]
    g["A/sigma0"] = c["amp"] / c["sigma0"]
    g["(1-phi)(rho-rho_f) g H/sigma0"] = (1 - phi) * (c["rho"] - c["rho_f"]) * c["g"] * H / c["sigma0"]
    g["wall contact zeta = gamma_w/(2 sqrt(k_n m))"] = c["gamma_w"] / (2 * math.sqrt(c["kn"] * m))
    g["plate mode omega_p T"] = omega_p * T
    g["plate mode omega_p H^2/D"] = omega_p * t_d
    g["plate zeta = gamma_p/(2 sqrt(K_v m_w))"] = c["gamma_p"] / (2 * root)
    g["drained fluid zeta = mu_f L_x L_y H/(6 k sqrt(K_v m_w))"] = c["mu_f"] * area * H / (6 * k * root)
    g["elastic crossing/diffusion = H sqrt(rho_b/M_s) D/H^2"] = H * math.sqrt(rho_b / M_s) / t_d
    g["H/d"] = H / d
    g["L_x/d"] = c["lx"] / d
    g["cell dz/d"] = c["dz"] / d
    g["steps per cycle T/dt"] = T / dt
    return g


def main():
    if "--layers" in sys.argv:
        print("-var bottom_cut %.17g -var top_cut %.17g" % original_layer_cuts(
            sys.argv[sys.argv.index("--layers") + 1]))
        return
    if "--bed" in sys.argv:
        height, phi = bed_geometry(sys.argv[sys.argv.index("--bed") + 1])
        print("H %.4f m, phi %.4f; keeping the reduced case's groups: %s" % (height, phi, " ".join(
            "-var %s %.4g" % kv for kv in bed_parameters(height, phi).items())))
        return
    names = list(CASES)
    rows = {n: groups(CASES[n]) for n in names}
    keys = list(rows[names[0]])
    if "--markdown" in sys.argv:
        ratios = ("reduced", "reduced, stiff bed")
        print("| group | " + " | ".join(names) + " | " +
              " | ".join("%s / Table S1" % n for n in ratios) + " |")
        print("|---|" + "---|" * (len(names) + len(ratios)))
        for key in keys:
            vals = ["%.3g" % rows[n][key] for n in names]
            s1 = rows["Table S1"][key]
            print("| %s | %s | %s |" % (key, " | ".join(vals), " | ".join(
                "%.3g" % (rows[n][key] / s1 if s1 else float("nan")) for n in ratios)))
    else:
        print("%-58s" % "" + "".join("%16s" % n for n in names))
        for key in keys:
            print("%-58s" % key + "".join("%16.4g" % rows[n][key] for n in names))


if __name__ == "__main__":
    main()
