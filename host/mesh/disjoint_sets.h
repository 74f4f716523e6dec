#pragma once
//! Union-find over 0..n-1 with path halving; the root of a set is its smallest member.

#include <cstdint>
#include <algorithm>
#include <numeric>
#include <vector>

namespace meshquilt {

class DisjointSets {
 public:
  explicit DisjointSets(size_t n) { reset(n); }

  //! Back to n singletons, keeping the storage (for many small sets in turn).
  void reset(size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0);
  }

  int32_t find(int32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];  // path halving keeps the trees shallow without recursion
      x = parent_[x];
    }
    return x;
  }

  void unite(int32_t a, int32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int32_t> parent_;
};

}  // namespace meshquilt
