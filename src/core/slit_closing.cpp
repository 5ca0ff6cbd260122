// Slits: holes of next to no area, one long edge with the rest of the loop lying along it.
// They appear where points sit in a row (a contour of a CT stack running straight across a
// face parallel to the cuts): the triangle over the row and the long edge would be a needle,
// so neither Algorithm 1 nor the patches can close them. The face on the other side of the
// long edge is split instead, into the fan from its third corner to the row, when every
// triangle of the fan passes the relaxed judgment.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/loop_filler.hpp"

namespace moa {
namespace {

// Longest loop looked at: the test of every edge against the rest is quadratic in its length.
constexpr std::size_t kMaxSlitLoop = 32;
// The rest of the loop must lie within this fraction of the long edge's length from the edge.
constexpr double kSlitThickness = 0.1;

// How far the loop's vertices other than loop[i] and loop[i + 1] stand off the segment
// between those two, over its length; infinity unless each projects strictly inside the
// segment, in order: the first after loop[i + 1] nearest to it, the last nearest to loop[i].
double slit_thickness(const std::vector<uint32_t> &loop, std::size_t i,
                      const std::vector<Vec3> &w) {
  const std::size_t n = loop.size();
  const Vec3 &a = w[loop[i]], &c = w[loop[(i + 1) % n]];
  const Vec3 d = c - a;
  const double length2 = norm2(d);
  constexpr double kNot = std::numeric_limits<double>::infinity();
  if (!(length2 > 0)) return kNot;
  double last = 1, thickest2 = 0;
  for (std::size_t k = 2; k < n; ++k) {
    const Vec3 p = w[loop[(i + k) % n]] - a;
    const double along = dot(p, d) / length2;
    if (!(along > 0 && along < last)) return kNot;
    last = along;
    thickest2 = std::max(thickest2, norm2(p - d * along));
  }
  return std::sqrt(thickest2 / length2);
}

}  // namespace

// Closes each slit whose fan passes the relaxed judgment; returns how many.
std::size_t LoopFiller::close_slits() {
  collect_hole_edges();
  loops_ = trace_loops();
  const auto &w = g_.points.work;
  std::size_t closed = 0;
  std::vector<uint32_t> sorted;
  std::vector<Tri> fan;
  for (const Loop &loop : loops_) {
    const std::vector<uint32_t> &v = loop.vertices;
    const std::size_t n = v.size();
    if (n < 3 || n > kMaxSlitLoop) continue;
    if (!simple_and_untangled(v, sorted)) continue;
    g_.poll();
    if (!still_open(v)) continue;
    std::size_t edge = n;
    double thinnest = kSlitThickness;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = slit_thickness(v, i, w);
      if (t <= thinnest) {
        thinnest = t;
        edge = i;
      }
    }
    if (edge == n) continue;
    // The hole runs a -> c along the long edge, so the face there runs c -> a; the rest of
    // the loop returns from c to a.
    const uint32_t a = v[edge], c = v[(edge + 1) % n];
    uint32_t fs[2];
    if (g_.mesh.edge_faces(c, a, fs) != 1) continue;
    const Tri old = g_.mesh.oriented(fs[0]);
    const uint32_t x = third_vertex(old, c, a);
    if (!has_directed(old, c, a) || std::binary_search(sorted.begin(), sorted.end(), x)) continue;
    fan.clear();
    for (std::size_t k = 1; k < n; ++k)
      fan.push_back(Tri{x, v[(edge + k) % n], v[(edge + k + 1) % n]});
    g_.mesh.remove(fs[0]);
    if (g_.add_all_or_none(fan)) {
      g_.stats.triangles_loops += fan.size() - 1;
      ++closed;
    } else {
      g_.add_face(old);
    }
  }
  return closed;
}

}  // namespace moa
