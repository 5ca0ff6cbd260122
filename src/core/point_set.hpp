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
  std::vector<Vec3> work;          // centred and scaled to unit diagonal: floating geometry
  std::vector<uint32_t> original;  // internal index -> caller's index (first occurrence)
  std::size_t input_count = 0;
  std::size_t duplicates = 0;
  std::size_t size() const { return exact.size(); }
};

// Throws moa::Error(MOA_ERROR_INVALID_INPUT) with a message naming the problem.
PointSet prepare_points(const double *xyz, std::size_t count);

}  // namespace moa
