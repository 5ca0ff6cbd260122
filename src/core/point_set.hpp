// Stage 1 (DESIGN.md §2.1; paper §3.5.1 step 1): validate the caller's points, merge exact
// duplicates and order the rest along a Morton curve.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/geometry.hpp"

namespace moa {

struct PointSet {
  std::vector<Vec3> exact;         // caller's coordinates × 2^k, internal order: exact predicates
  std::vector<Vec3> work;          // centred and scaled to unit diagonal: the judgment's geometry
  // The caller's points in work units when `work` holds a smoothed copy (noisy clouds, see
  // smoothing.hpp); empty otherwise.
  std::vector<Vec3> raw_work;
  std::vector<uint32_t> original;  // internal index -> caller's index (first occurrence)
  std::size_t input_count = 0;
  std::size_t duplicates = 0;
  std::size_t size() const { return exact.size(); }
  // Where the vertices really are, in work units: what crossing tests and output measure.
  const std::vector<Vec3> &placed() const { return raw_work.empty() ? work : raw_work; }
};

// Throws moa::Error(MOA_ERROR_INVALID_INPUT) with a message naming the problem.
PointSet prepare_points(const double *xyz, std::size_t count);

}  // namespace moa
