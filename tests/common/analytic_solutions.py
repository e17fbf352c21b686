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
