// Points standing alone off the surface (stray points, outliers): a point whose own spacing
// is many times that of the points around it is no sample of the surface they sample. Algorithm
// 1 and the loop module leave such points out of their candidates and seeds; the take-in
// (take_in.cpp) still offers each one to the finished surface, so that a point that does lie
// on it becomes a vertex after all.
#pragma once

#include <cstdint>
#include <vector>

#include "core/neighbors.hpp"
#include "core/point_set.hpp"

namespace moa {

// Marks the isolated points in nb.isolated (left empty when there are none). Parallel over
// points; the result does not depend on the number of threads.
void mark_isolated_points(const PointSet &points, Neighborhood &nb);

}  // namespace moa
