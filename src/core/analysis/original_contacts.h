// The contact count of the original program (sphere), whose coordination numbers the paper
// and the original run's data file report: src/sphere.cpp DEM::findOverlaps (lines 677-722)
// tests every pair i < j with the raw difference x_j - x_i of the stored (wrapped) positions,
// counts it if delta_n = |x_ij| - (r_i + r_j) < 0 and neither grain is fixed
// (`k.vel[i].w == 0 && k.vel[j].w == 0`); python/sphere.py findCoordinationNumber and
// findMeanCoordinationNumber (lines 4885-4906) give each grain of a pair one contact and
// average over all grains, the fixed ones included. No wall contacts are counted.
#ifndef PW_CORE_ANALYSIS_ORIGINAL_CONTACTS_H
#define PW_CORE_ANALYSIS_ORIGINAL_CONTACTS_H

#include <cmath>

namespace porewater {

// The box the positions are wrapped into along each periodic axis, [lo, lo + length).
struct PeriodicBox {
  double lo[3];
  double length[3];
  bool periodic[3];
};

// Which copy of the box along one axis a coordinate lies in (0: the box itself).
inline long box_image(double x, double lo, double length)
{
  return static_cast<long>(std::floor((x - lo) / length));
}

// Whether the original counts the contact of grains i and j, j given as the host's
// neighbour (possibly a periodic image): both free, overlapping strictly, and in the same
// copy of the box along every periodic axis, since the raw difference of the wrapped
// positions of a pair that touches across a periodic boundary is about a box length.
inline bool counted_by_original(const double *xi, const double *xj, double radius_sum,
                                bool fixed_i, bool fixed_j, const PeriodicBox &box)
{
  if (fixed_i || fixed_j) return false;
  const double dx = xj[0] - xi[0], dy = xj[1] - xi[1], dz = xj[2] - xi[2];
  if (!(dx * dx + dy * dy + dz * dz < radius_sum * radius_sum)) return false;
  for (int d = 0; d < 3; ++d)
    if (box.periodic[d] &&
        box_image(xi[d], box.lo[d], box.length[d]) != box_image(xj[d], box.lo[d], box.length[d]))
      return false;
  return true;
}

}    // namespace porewater

#endif
