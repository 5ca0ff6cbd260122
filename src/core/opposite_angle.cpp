#include "core/opposite_angle.hpp"

#include <algorithm>
#include <cmath>

namespace moa {

OppositeAngleSearch::OppositeAngleSearch(const PointSet &points, const Neighborhood &nb,
                                         const Params &params)
    : points_(points), nb_(nb), radius_factor_(params.sphere_radius) {}

void OppositeAngleSearch::sphere_points(uint32_t a, uint32_t b, std::vector<uint32_t> &out) {
  out.clear();
  listed_.clear();
  const Vec3 &A = points_.work[a], &B = points_.work[b];
  Vec3 m = midpoint(A, B);
  double spacing = 0.5 * (double(nb_.spacing[a]) + double(nb_.spacing[b]));
  double r = std::max(radius_factor_ * spacing, 0.55 * dist(A, B));
  double r2 = r * r;
  for (uint32_t s : {a, b}) {
    const uint32_t *list = nb_.of(s);
    for (unsigned j = 0; j < nb_.k; ++j) {
      uint32_t p = list[j];
      if (listed_.has(p)) continue;
      listed_.set(p);
      if (norm2(points_.work[p] - m) < r2 && !nb_.alone(p)) out.push_back(p);
    }
  }
}

void OppositeAngleSearch::rank(uint32_t a, uint32_t b, const std::vector<uint32_t> &pool, Vec3 side,
                               uint32_t exclude, std::vector<Candidate> &out, bool behind) const {
  out.clear();
  const Vec3 &A = points_.work[a], &B = points_.work[b];
  bool any_side = norm2(side) == 0;
  for (uint32_t c : pool) {
    if (c == a || c == b || c == exclude) continue;
    const Vec3 &C = points_.work[c];
    if (!any_side && (dot(C - A, side) > 0) == behind) continue;
    Vec3 ca = A - C, cb = B - C;
    out.push_back({dot(ca, cb) / std::sqrt(norm2(ca) * norm2(cb)), c});
  }
  std::sort(out.begin(), out.end(), [](const Candidate &x, const Candidate &y) {
    return x.cosine != y.cosine ? x.cosine < y.cosine : x.vertex < y.vertex;
  });
}

}  // namespace moa
