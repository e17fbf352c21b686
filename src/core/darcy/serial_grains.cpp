#include "darcy/serial_grains.h"

#include "darcy/coupling.h"
#include "grains/host_grains.h"

namespace porewater {

namespace {
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
// the coupling reads no image flags
HostGrains<int> grains_of(const CouplingArrays &a)
{
  return HostGrains<int>{a.x, a.v, a.f, nullptr, nullptr, a.radius, nullptr, a.mask, nullptr};
}
}    // namespace

void SerialGrains::deposit(const CouplingGrid &grid, double interval, double *sums)
{
  const CouplingArrays a = arrays_;
  if ((int) blocks_.size() < a.nlocal) {    // grow with the atoms, never shrink
    blocks_.resize(a.nlocal);
    weights_.resize(CORNERS * (size_t) a.nlocal);
  }
  // local copies: the compiler may then keep them in registers across the stores
  const CouplingGrid g = grid;
  const HostGrains<int> grains = grains_of(a);
  const Stencils stencils{blocks_.data(), weights_.data()};
  const AddTo add{sums};
  for (int i = 0; i < a.nlocal; ++i) deposit_grain(g, grains, stencils, a.groupbit, interval, i, add);
}

void SerialGrains::apply_force(const CouplingGrid &grid, const FluidForceField &field, bool kept,
                               bool /*field_changed: read in place*/)
{
  const CouplingArrays a = arrays_;
  const CouplingGrid g = grid;
  const FluidForceField f = field;
  const HostGrains<int> grains = grains_of(a);
  const Stencils stencils{blocks_.data(), weights_.data()};
  const Held held{a.held};
  for (int i = 0; i < a.nlocal; ++i) apply_fluid_force(g, f, grains, stencils, held, a.groupbit, kept, i);
}

void SerialGrains::add_held_force()
{
  const CouplingArrays a = arrays_;
  const HostGrains<int> grains = grains_of(a);
  const Held held{a.held};
  for (int i = 0; i < a.nlocal; ++i) add_held_fluid_force(grains, held, i);
}

double SerialGrains::bytes() const
{
  return (double) blocks_.capacity() * sizeof(int) + (double) weights_.capacity() * sizeof(double);
}

}    // namespace porewater
