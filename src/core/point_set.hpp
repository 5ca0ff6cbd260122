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
  const double *input = nullptr;
  int shift = 0;
  std::vector<Vec3> work;  // centred and scaled to unit diagonal: the judgment's geometry
  // The caller's points in work units when `work` holds a smoothed copy (noisy clouds, see
  // smoothing.hpp); empty otherwise.
  std::vector<Vec3> raw_work;
  std::vector<uint32_t> original;  // internal index -> caller's index (first occurrence)
  std::size_t input_count = 0;
  std::size_t duplicates = 0;
  std::size_t size() const { return original.size(); }
  // Point i's coordinates for the exact predicates.
  Vec3 exact(uint32_t i) const {
    const double *p = input + 3 * std::size_t(original[i]);
    if (shift == 0) return {p[0], p[1], p[2]};
    return {std::ldexp(p[0], shift), std::ldexp(p[1], shift), std::ldexp(p[2], shift)};
  }
  // Where the vertices really are, in work units: what crossing tests and output measure.
  const std::vector<Vec3> &placed() const { return raw_work.empty() ? work : raw_work; }
};

// Throws moa::Error(MOA_ERROR_INVALID_INPUT) with a message naming the problem. xyz must stay
// valid and unchanged as long as the PointSet is used.
PointSet prepare_points(const double *xyz, std::size_t count);

}  // namespace moa
