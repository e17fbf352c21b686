"""Analytic solutions the Python-driven tests compare against (the C++ tests' are in
analytic_solutions.h)."""
import cmath
import math


def tidal_column(z, t, height, diffusivity, amplitude, omega):
    """p(z, t) of dp/dt = D d2p/dz2 on [0, H] with no flow at z = 0, p(H, t) = A sin(omega t)
    and p(z, 0) = 0: the periodic solution Im[A e^(i omega t) cosh(kz)/cosh(kH)], k =
    sqrt(i omega/D), minus the decaying modes cos(m_n z), m_n = (n + 1/2) pi/H, that cancel
    its value at t = 0 (coefficients from the integral of cosh(kz) cos(m z) over [0, H]),
    summed until they have decayed below 1e-17 of their coefficient."""
    if t == 0.0:
        return 0.0    # the initial condition (the series converges slowly there)
    kappa = cmath.sqrt(1j * omega / diffusivity)
    p = (amplitude * cmath.exp(1j * omega * t) * cmath.cosh(kappa * z) /
         cmath.cosh(kappa * height)).imag
    n = 0
    while True:
        m = (n + 0.5) * math.pi / height
        decay = math.exp(-diffusivity * m * m * t)
        if decay < 1e-17:
            return p
        b = 2.0 / height * (amplitude * m * (-1) ** n / (1j * omega / diffusivity + m * m)).imag
        p -= b * decay * math.cos(m * z)
        n += 1


def undrained_pressure_change(phi0, phi1, compressibility):
    """Pressure change of a closed cell whose porosity goes from phi0 to phi1 with no flow:
    the integral of beta phi dp = -dphi/(1 - phi), -(1/beta) ln[phi1 (1 - phi0) / (phi0 (1 - phi1))];
    for a small change, -(phi1 - phi0)/(beta phi (1 - phi)) with phi at the midpoint."""
    return -math.log(phi1 * (1.0 - phi0) / (phi0 * (1.0 - phi1))) / compressibility


def consolidation(load, m_v, porosity, compressibility, permeability, viscosity, height,
                  solid_share):
    """One-dimensional consolidation of a linear skeleton in the pore water of fix
    darcy/pressure (doc/model.md, "Consolidation"): a load step `load` on the skeleton,
    constrained compressibility m_v, fluid compressibility beta, Darcy permeability k and
    viscosity mu over a layer of `height` H drained at its top and closed at its bottom, the
    grains taking `solid_share` alpha of the water's force per bulk volume -grad p (seepage
    pressure: 1 - phi; seepage full: 1). The fluid's storage is S = phi beta + alpha m_v:
    the undrained pressure is load m_v/S, the diffusivity c = k/(mu S), and the slowest
    mode decays at pi^2 c/(4 H^2). Returns a dict of them (and the inputs the series need)."""
    storage = porosity * compressibility + solid_share * m_v
    diffusivity = permeability / (viscosity * storage)
    return {"undrained_pressure": load * m_v / storage, "diffusivity": diffusivity,
            "storage": storage, "slowest_rate": math.pi ** 2 * diffusivity / (4.0 * height ** 2),
            "m_v": m_v, "solid_share": solid_share, "load": load, "height": height}


def consolidation_modes(c, t, terms=200):
    """The mode sums of a unit load step at time t >= 0 of consolidation(): the base
    pressure p(0, t)/p_u = sum 2 (-1)^m/M e^(-M^2 T) and the pressure integral
    int p dz/(p_u H) = sum 2/M^2 e^(-M^2 T), M = (2m + 1) pi/2, T = c t/H^2."""
    T = c["diffusivity"] * t / c["height"] ** 2
    base = mean = 0.0
    for m in range(terms):
        M = (2 * m + 1) * math.pi / 2
        decay = math.exp(-M * M * T)
        base += 2.0 * (-1) ** m / M * decay
        mean += 2.0 / (M * M) * decay
    return base, mean


def consolidation_step(c, t):
    """(base pressure, settlement) at time t of a load step at t = 0 of consolidation(); the
    settlement of the layer's top, m_v H (load - alpha p averaged over the layer); both 0
    before the step"""
    if t < 0.0:
        return 0.0, 0.0
    if t == 0.0:
        base, mean = 1.0, 1.0    # the series' limits (they converge slowly at T = 0)
    else:
        base, mean = consolidation_modes(c, t)
    p_u = c["undrained_pressure"]
    settlement = c["m_v"] * c["height"] * (c["load"] - c["solid_share"] * p_u * mean)
    return p_u * base, settlement
