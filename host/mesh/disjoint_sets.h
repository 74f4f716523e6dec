#pragma once
//! Union-find over 0..n-1 with path halving; the root of a set is its smallest member.

#include <cstdint>
#include <algorithm>
#include <map>
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

//! The same over a few members of a large range (a map, not an array): for many small groups of
//! vertices of one large mesh. The root of a set is its smallest member.
class SparseDisjointSets {
 public:
  int32_t find(int32_t x) {
    for (auto it = parent_.find(x); it != parent_.end() && it->second != x; it = parent_.find(x)) x = it->second;
    return x;
  }

  void unite(int32_t a, int32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

  //! Every member joined to another, with the member it was joined to (in increasing order).
  const std::map<int32_t, int32_t>& joined() const { return parent_; }

 private:
  std::map<int32_t, int32_t> parent_;
};

}  // namespace meshquilt
