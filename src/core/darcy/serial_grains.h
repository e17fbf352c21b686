// The grains' side of fix darcy/pressure on a CPU host whose per-atom arrays are double**
// rows (LAMMPS, LIGGGHTS): serial loops running the coupling's per-grain kernels
// (darcy/coupling.h). The KOKKOS fix runs the same kernels as Kokkos kernels instead.
#ifndef PW_DARCY_SERIAL_GRAINS_H
#define PW_DARCY_SERIAL_GRAINS_H

#include "darcy/fluid.h"

#include <climits>
#include <cmath>
#include <vector>

namespace porewater {

// the per-atom arrays the coupling reads and writes
struct CouplingArrays {
  double **x, **v, **f;
  const double *radius;
  const int *mask;
  int nlocal, groupbit;
  double **held;    // held[i]: grain i's fluid force, kept for `interpolate fluid`
};

// The smallest ID of a local grain of the group with a non-finite position or velocity,
// LLONG_MAX if there is none (the host takes the minimum over its ranks); for the message
// of the run that stops on it.
template <class Tag> long long first_nonfinite_tag(const CouplingArrays &a, const Tag *tag)
{
  long long first = LLONG_MAX;
  for (int i = 0; i < a.nlocal; ++i) {
    if (!(a.mask[i] & a.groupbit)) continue;
    bool finite = true;
    for (int d = 0; d < 3; ++d) finite = finite && std::isfinite(a.x[i][d]) && std::isfinite(a.v[i][d]);
    if (!finite && (long long) tag[i] < first) first = (long long) tag[i];
  }
  return first;
}

// a CPU host's Atom (LAMMPS and LIGGGHTS name their per-atom arrays alike)
template <class Atom> CouplingArrays coupling_arrays_of(const Atom *atom, int groupbit, double **held)
{
  return CouplingArrays{atom->x, atom->v, atom->f, atom->radius, atom->mask, atom->nlocal, groupbit, held};
}

class SerialGrains final : public GrainBackend {
 public:
  // the host's arrays now (they move when the host grows them)
  void bind(const CouplingArrays &arrays) { arrays_ = arrays; }
  void deposit(const CouplingGrid &grid, double interval, double *sums) override;
  void apply_force(const CouplingGrid &grid, const FluidForceField &field, bool kept,
                   bool field_changed) override;
  void add_held_force() override;
  double bytes() const;

 private:
  CouplingArrays arrays_{};
  std::vector<int> blocks_;        // each grain's block at x from the last deposit (-1: none)
  std::vector<double> weights_;    // and its corner weights there
};

}    // namespace porewater

#endif
