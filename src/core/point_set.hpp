// Stage 1 (DESIGN.md §2.1; paper §3.5.1 step 1): validate the caller's points, merge exact
// duplicates and order the rest along a Morton curve.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geometry.hpp"

namespace moa {

struct PointSet {
  // The caller's array, which outlives the run: the exact predicates read the caller's own
  // coordinates (scaled by 2^shift, which is exact) rather than a copy, 24 bytes per point.
  // While an InternalOrder lives it holds them in the internal order, the duplicates last.
  const double *input = nullptr;
  int shift = 0;
  std::vector<Vec3> work;  // centred and scaled to unit diagonal: the judgment's geometry
  // The caller's points in work units when `work` holds a smoothed copy (noisy clouds, see
  // smoothing.hpp); empty otherwise.
  std::vector<Vec3> raw_work;
  // Internal index -> caller's index (first occurrence); after the size() internal points, the
  // caller's indices of the duplicates (exact, or merged near ones): a permutation of all the
  // caller's points.
  std::vector<uint32_t> original;
  std::size_t input_count = 0;
  std::size_t duplicates = 0;
  std::size_t size() const { return input_count - duplicates; }
  // Point i's coordinates for the exact predicates, valid while an InternalOrder lives.
  Vec3 exact(uint32_t i) const {
    const double *p = input + 3 * std::size_t(i);
    if (shift == 0) return {p[0], p[1], p[2]};
    return {std::ldexp(p[0], shift), std::ldexp(p[1], shift), std::ldexp(p[2], shift)};
  }
  // Where the vertices really are, in work units: what crossing tests and output measure.
  const std::vector<Vec3> &placed() const { return raw_work.empty() ? work : raw_work; }
};

// Throws moa::Error(MOA_ERROR_INVALID_INPUT) with a message naming the problem. xyz must stay
// valid and unchanged as long as the PointSet is used, except by an InternalOrder. The caller's
// points listed in `merged` (near_duplicates.hpp) are left out like exact duplicates.
PointSet prepare_points(const double *xyz, std::size_t count,
                        const std::vector<uint32_t> &merged = {});

// Moves the caller's points into the internal (Morton) order for its lifetime, and back into
// the caller's order when it ends, on unwinding too: the way back allocates nothing. The exact
// predicates then read neighbouring points from neighbouring memory; in the caller's order (a
// shuffled scan) nearly every read was a cache miss, a tenth of the run at a million points.
// The caller's copy stays the only one: a second, ordered one would cost 24 bytes per point.
class InternalOrder {
 public:
  // xyz: the array the points were prepared from, writable.
  InternalOrder(const PointSet &points, double *xyz);
  ~InternalOrder();
  InternalOrder(const InternalOrder &) = delete;
  InternalOrder &operator=(const InternalOrder &) = delete;

 private:
  const std::vector<uint32_t> &from_;  // position k takes the caller's point from_[k]
  double *xyz_;
  std::vector<bool> moved_;  // allocated up front, so that restoring needs no memory
};

}  // namespace moa
