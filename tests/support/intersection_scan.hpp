// C5 scan: every pair of faces whose bounding boxes touch, found with a uniform grid, is judged
// with the exact tests of triangle_intersection.hpp. Internal to the checker.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace moa::test {

// usable[f] != 0 for faces with three distinct in-range, non-collinear corners; other faces
// are skipped. on_hit(f, g, shared) is called once per offending pair, f < g, in a fixed order.
std::size_t scan_intersections(const double *xyz, const std::uint32_t *triangles,
                               const std::vector<std::uint8_t> &usable,
                               const std::function<void(std::size_t, std::size_t, int)> &on_hit);

}  // namespace moa::test
