// The per-grain kernels of the fixes (walls/, integrate/, darcy/) are written once, as
// functors over a grain accessor G:
//   g.x(i, d), g.v(i, d), g.f(i, d), g.omega(i, d), g.torque(i, d)   (references)
//   g.radius(i), g.rmass(i), g.mask(i), g.image(i)
// HostGrains is that accessor over the per-atom arrays of a CPU host (LAMMPS and LIGGGHTS
// both keep double** rows of 3); the KOKKOS styles give the same functors an accessor over
// views. The loops over grains are the host's: the serial ones here, Kokkos kernels there.
#ifndef PW_GRAINS_HOST_GRAINS_H
#define PW_GRAINS_HOST_GRAINS_H

#include "pw_inline.h"

#include <type_traits>

namespace porewater {

template <class Image> struct HostGrains {
  double **xs, **vs, **fs, **omegas, **torques;
  const double *radii, *rmasses;
  const int *masks;
  const Image *images;

  double &x(int i, int d) const { return xs[i][d]; }
  double &v(int i, int d) const { return vs[i][d]; }
  double &f(int i, int d) const { return fs[i][d]; }
  double &omega(int i, int d) const { return omegas[i][d]; }
  double &torque(int i, int d) const { return torques[i][d]; }
  double radius(int i) const { return radii[i]; }
  double rmass(int i) const { return rmasses[i]; }
  int mask(int i) const { return masks[i]; }
  Image image(int i) const { return images[i]; }
};

// The accessor over a CPU host's Atom: LAMMPS and LIGGGHTS name their per-atom arrays alike
// (x, v, f, omega, torque, radius, rmass, mask, image).
template <class Atom>
auto grains_of_atom(const Atom *atom) -> HostGrains<typename std::remove_pointer<decltype(atom->image)>::type>
{
  using Image = typename std::remove_pointer<decltype(atom->image)>::type;
  return HostGrains<Image>{atom->x,      atom->v,      atom->f,     atom->omega, atom->torque,
                           atom->radius, atom->rmass,  atom->mask,  atom->image};
}

// body(i) for the grains [0, n)
template <class Body> void for_each_grain(int n, const Body &body)
{
  for (int i = 0; i < n; ++i) body(i);
}

// body(i, sums) for the grains [0, n), summing Body::count values into sums (zeroed here)
template <class Body> void sum_over_grains(int n, const Body &body, double *sums)
{
  for (int k = 0; k < Body::count; ++k) sums[k] = 0.0;
  for (int i = 0; i < n; ++i) body(i, sums);
}

}    // namespace porewater

#endif
