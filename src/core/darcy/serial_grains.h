// The grains' side of fix darcy/pressure on a CPU host whose per-atom arrays are double**
// rows (LAMMPS, LIGGGHTS): serial loops running the coupling's per-grain kernels
// (darcy/coupling.h). The KOKKOS fix runs the same kernels as Kokkos kernels instead.
#ifndef PW_DARCY_SERIAL_GRAINS_H
#define PW_DARCY_SERIAL_GRAINS_H

#include "darcy/coupling.h"
#include "darcy/fluid.h"
#include "grains/host_grains.h"

#include <vector>

namespace porewater {

template <class Image> class SerialGrains final : public GrainBackend {
 public:
  // the host's arrays now (they move when the host grows them); held[i] is grain i's fluid force
  void bind(const HostGrains<Image> &grains, int nlocal, int groupbit, double **held)
  {
    grains_ = grains;
    nlocal_ = nlocal;
    groupbit_ = groupbit;
    held_ = held;
  }

  void deposit(const CouplingGrid &grid, double interval, double *sums) override
  {
    if ((int) blocks_.size() < nlocal_) {    // grow with the atoms, never shrink
      blocks_.resize(nlocal_);
      weights_.resize(CORNERS * (size_t) nlocal_);
    }
    // local copies: the compiler may then keep them in registers across the stores
    const CouplingGrid g = grid;
    const Stencils stencils{blocks_.data(), weights_.data()};
    const auto add = [sums](int slot, double value) { sums[slot] += value; };
    for (int i = 0; i < nlocal_; ++i) deposit_grain(g, grains_, stencils, groupbit_, interval, i, add);
  }

  void apply_force(const CouplingGrid &grid, const FluidForceField &field, bool kept,
                   bool /*field_changed: read in place*/) override
  {
    const CouplingGrid g = grid;
    const FluidForceField f = field;
    const Stencils stencils{blocks_.data(), weights_.data()};
    const Held held{held_};
    for (int i = 0; i < nlocal_; ++i)
      apply_fluid_force(g, f, grains_, stencils, held, groupbit_, kept, i);
  }

  void add_held_force() override
  {
    const Held held{held_};
    for (int i = 0; i < nlocal_; ++i) add_held_fluid_force(grains_, held, i);
  }

  double bytes() const
  {
    return (double) blocks_.capacity() * sizeof(int) + (double) weights_.capacity() * sizeof(double);
  }

 private:
  struct Stencils {
    int *blocks;
    double *weight_rows;
    int &block(int i) const { return blocks[i]; }
    double *weights(int i) const { return weight_rows + CORNERS * i; }
  };
  struct Held {
    double **rows;
    double &operator()(int i, int d) const { return rows[i][d]; }
  };

  HostGrains<Image> grains_{};
  int nlocal_ = 0, groupbit_ = 0;
  double **held_ = nullptr;
  std::vector<int> blocks_;        // each grain's block at x from the last deposit (-1: none)
  std::vector<double> weights_;    // and its corner weights there
};

}    // namespace porewater

#endif
