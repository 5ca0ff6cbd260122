// Taking in left-out points (paper §3.5.2, step 1): a point that no triangle reached but that
// lies over a triangle of the finished surface becomes a vertex by splitting that triangle in
// three, when the three new triangles pass the same judgment as every other.
#include <algorithm>
#include <cmath>

#include "core/growth_state.hpp"

namespace moa {
namespace {

// Only the faces around this many of a point's nearest neighbours are considered.
constexpr unsigned kNearbyVertices = 8;
// A point farther from a face's plane than this many local spacings is not on that face.
constexpr double kMaxHeight = 1.0;

// Barycentric coordinates of p's projection onto triangle abc; false for a flat triangle.
bool barycentric(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &p, double (&l)[3]) {
  Vec3 n = cross(b - a, c - a);
  double area2 = norm2(n);
  if (area2 == 0) return false;
  l[0] = dot(cross(c - b, p - b), n) / area2;
  l[1] = dot(cross(a - c, p - c), n) / area2;
  l[2] = 1.0 - l[0] - l[1];
  return true;
}

class PointTaker {
 public:
  explicit PointTaker(GrowthState &g) : g_(g) {}

  std::size_t run() {
    std::size_t taken = 0;
    for (uint32_t p = 0; p < g_.points.size(); ++p)
      if (!g_.mesh.is_used(p) && take(p)) ++taken;
    return taken;
  }

 private:
  // Faces over which p lies, nearest plane first.
  void host_faces(uint32_t p) {
    const auto &w = g_.points.work;
    hosts_.clear();
    const uint32_t *nb = g_.nb.of(p);
    const double limit = kMaxHeight * g_.nb.spacing[p];
    for (unsigned j = 0; j < std::min(kNearbyVertices, g_.nb.k); ++j)
      for (uint32_t f : g_.mesh.faces_at(nb[j])) {
        const Tri &t = g_.mesh.stored(f);
        double l[3];
        if (!barycentric(w[t[0]], w[t[1]], w[t[2]], w[p], l)) continue;
        if (l[0] < 0 || l[1] < 0 || l[2] < 0) continue;
        Vec3 n = normalized(cross(w[t[1]] - w[t[0]], w[t[2]] - w[t[0]]));
        double h = std::fabs(dot(w[p] - w[t[0]], n));
        if (h <= limit) hosts_.push_back({h, f});
      }
    std::sort(hosts_.begin(), hosts_.end());
    hosts_.erase(std::unique(hosts_.begin(), hosts_.end()), hosts_.end());
  }

  bool take(uint32_t p) {
    host_faces(p);
    for (const auto &host : hosts_) {
      uint32_t f = host.second;
      if (!g_.mesh.alive(f)) continue;
      Tri o = g_.mesh.oriented(f);
      g_.mesh.remove(f);
      const Tri parts[3] = {{o[0], o[1], p}, {o[1], o[2], p}, {o[2], o[0], p}};
      uint32_t added[3];
      int n = 0;
      for (; n < 3; ++n) {
        Verdict v = g_.judge.judge(parts[n], nullptr, 0, true);
        TopologyJudge::count(v, g_.stats);
        if (v != Verdict::Accept) break;
        added[n] = g_.add_face(parts[n]);
      }
      if (n == 3) {
        g_.stats.triangles_loops += 2;  // three faces replace one
        return true;
      }
      // Undo: the host comes back as it was.
      for (int k = 0; k < n; ++k) g_.mesh.remove(added[k]);
      g_.add_face(o);
    }
    return false;
  }

  GrowthState &g_;
  std::vector<std::pair<double, uint32_t>> hosts_;
};

}  // namespace

std::size_t take_in_points(GrowthState &g) { return PointTaker(g).run(); }

}  // namespace moa
