// The maximum opposite point (paper §3.1, Fig. 2; §3.5.1 steps 3, 5 and 6): among the points
// inside the sphere of radius R around a target segment's midpoint, on the side being grown,
// the candidates ordered by the angle under which they see the segment, largest first.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry.hpp"
#include "core/marks.hpp"
#include "core/neighbors.hpp"
#include "core/parameters.hpp"
#include "core/point_set.hpp"

namespace moa {

struct Candidate {
  double cosine;  // cosine of the opposite angle ACB: the smaller, the larger the angle
  uint32_t vertex;
};

class OppositeAngleSearch {
 public:
  OppositeAngleSearch(const PointSet &points, const Neighborhood &nb, const Params &params);

  // Points of the k-NN lists of a and b that lie inside the sphere of segment ab, isolated
  // points left out.
  void sphere_points(uint32_t a, uint32_t b, std::vector<uint32_t> &out);
  // Candidates from `pool` other than a, b and `exclude`, strictly on the side `side` points
  // to (side = 0 accepts both sides; with `behind`, those on the other side or on the plane
  // between), largest angle first, ties broken by index.
  void rank(uint32_t a, uint32_t b, const std::vector<uint32_t> &pool, Vec3 side, uint32_t exclude,
            std::vector<Candidate> &out, bool behind = false) const;

 private:
  const PointSet &points_;
  const Neighborhood &nb_;
  double radius_factor_;
  IndexMarks listed_;  // points already looked at for the current segment
};

}  // namespace moa
