// The grains' side of fix darcy/pressure on a CPU host whose per-atom arrays are double**
// rows (LAMMPS, LIGGGHTS): serial loops running the coupling's per-grain kernels
// (darcy/coupling.h). The KOKKOS fix runs the same kernels as Kokkos kernels instead.
#ifndef PW_DARCY_SERIAL_GRAINS_H
#define PW_DARCY_SERIAL_GRAINS_H

#include "darcy/fluid.h"

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
