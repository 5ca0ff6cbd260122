// The loop module's cap for a hole that lies in one cut of a contour stack: a face parallel to
// the slices (an object's flat top or bottom, or one cut off by the scan's field of view) gets
// no points but its rim, so greedy filling, which builds from the rim inwards by the widest
// angle, has nothing to build with but slivers and corners itself. The rim is planar there,
// and a triangulation of the polygon in its own plane closes it.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry.hpp"
#include "core/mesh_state.hpp"

namespace moa {

// Triangulates the loop's polygon in its least-squares plane by clipping ears, the ear with
// the largest smallest angle first. Each triangle keeps the loop's direction on the loop's
// edges (as a patch of the hole needs). Nothing when the polygon, seen in that plane, has no
// ear left to clip (it crosses itself there).
std::vector<Tri> flat_cap(const std::vector<Vec3> &points, const std::vector<uint32_t> &loop);

}  // namespace moa
