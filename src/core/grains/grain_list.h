// The local grains a CPU host's per-step loop visits, kept between re-neighborings: LAMMPS
// moves, sorts and exchanges grains only when it re-neighbors, so a list of their indices
// built then stays true until the next one. A fix builds it in pre_neighbor and setup, or
// invalidates it there and rebuilds it on its next use; the loops visit the listed grains in
// index order, so their sums add what a loop over every grain adds, in the same order.
#ifndef PW_GRAINS_GRAIN_LIST_H
#define PW_GRAINS_GRAIN_LIST_H

#include <vector>

namespace porewater {

class GrainList {
 public:
  bool valid() const { return valid_; }
  void invalidate() { valid_ = false; }
  // the grains i in [0, n) with keep(i)
  template <class Keep> void rebuild(int n, const Keep &keep)
  {
    indices_.clear();
    for (int i = 0; i < n; ++i)
      if (keep(i)) indices_.push_back(i);
    valid_ = true;
  }
  int size() const { return static_cast<int>(indices_.size()); }
  const int *indices() const { return indices_.data(); }

 private:
  std::vector<int> indices_;
  bool valid_ = false;
};

// body(i) for the listed grains
template <class Body> void for_each_listed(const GrainList &list, const Body &body)
{
  for (int k = 0; k < list.size(); ++k) body(list.indices()[k]);
}

// body(i, sums) for the listed grains, summing Body::count values into sums (zeroed here)
template <class Body> void sum_over_listed(const GrainList &list, const Body &body, double *sums)
{
  for (int k = 0; k < Body::count; ++k) sums[k] = 0.0;
  for (int k = 0; k < list.size(); ++k) body(list.indices()[k], sums);
}

}    // namespace porewater

#endif
