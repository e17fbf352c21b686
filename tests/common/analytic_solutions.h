// Analytic solutions the Darcy tests compare against, shared by the unit tests and the
// tests through LAMMPS.
#ifndef PW_TEST_ANALYTIC_SOLUTIONS_H
#define PW_TEST_ANALYTIC_SOLUTIONS_H

#include <cmath>

namespace pwtest {

// Terzaghi: uniform p0, drained top at z = H, no-flow bottom (z from the bottom); the
// series to 400 terms
inline double terzaghi(double p0, double z, double height, double diffusivity, double t)
{
  const double pi = 3.14159265358979323846;
  double p = 0.0;
  for (int m = 0; m < 400; ++m) {
    const double M = (2 * m + 1) * pi / 2;
    p += 2 * p0 / M * std::sin(M) * std::cos(M * z / height) *
        std::exp(-M * M * diffusivity * t / (height * height));
  }
  return p;
}

}    // namespace pwtest

#endif
