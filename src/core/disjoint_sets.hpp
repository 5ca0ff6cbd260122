// Disjoint sets over 0..n-1 (union-find with path halving), for grouping faces into fans and
// pieces and points into copies of one another.
#pragma once

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace moa {

class DisjointSets {
 public:
  DisjointSets() = default;
  explicit DisjointSets(std::size_t n) { reset(n); }
  // n singletons; keeps the allocation when called again, for sets made in a loop.
  void reset(std::size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0u);
  }
  uint32_t root(uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // Joins a's set to b's: b's root becomes the root of both.
  void join(uint32_t a, uint32_t b) {
    const uint32_t rb = root(b);
    parent_[root(a)] = rb;
  }
  // Every element's root, indexed by element, handed over without a copy; the sets are empty
  // afterwards (reset them to use them again).
  std::vector<uint32_t> take_roots() {
    for (uint32_t x = 0; x < parent_.size(); ++x) parent_[x] = root(x);
    return std::move(parent_);
  }

 private:
  std::vector<uint32_t> parent_;
};

}  // namespace moa
