// Spatial parts for the parallel first pass of Algorithm 1 (mesh_builder.cpp): the cloud is cut
// by axis-aligned planes at median coordinates until no part holds more than a given number of
// points. Each part is a box, half-open along every cut, so the triangles of different parts
// (each spanning points of one part only) lie in disjoint boxes and can never meet.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry.hpp"

namespace moa {

struct Partition {
  struct Box {
    Vec3 lo, hi;  // the part holds lo <= p < hi on each axis (infinite on the outer sides)
  };
  std::vector<Box> boxes;
  std::vector<uint16_t> part_of;  // per point

  std::size_t size() const { return boxes.size(); }
  // Whether the box [lo, hi] lies inside part `part`, at least `margin` from its cut planes.
  bool holds(uint32_t part, const Vec3 &lo, const Vec3 &hi, double margin) const;
};

// Cuts points into parts of at most max_points each (one part when there are no more than
// that). Deterministic: the result depends on the points alone.
Partition partition_points(const std::vector<Vec3> &points, std::size_t max_points);

}  // namespace moa
