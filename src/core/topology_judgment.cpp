// Topology judgment (paper §3.4). Cheap tests run first; the exact crossing test runs last.
#include "core/topology_judgment.hpp"

#include <cmath>

#include "core/predicates.hpp"

namespace moa {
namespace {

// A triangle whose largest angle exceeds this is a needle or a cap: its area is nearly zero
// and its normal meaningless.
const double kMaxCornerAngle = degrees_to_radians(175.0);

// A triangle whose normal is more than about 100 degrees from the mean normal of a fan it
// joins faces backwards.
constexpr double kBackwardsCosine = -0.17;

uint32_t third_vertex(const Tri &t, uint32_t u, uint32_t v) {
  for (uint32_t x : t)
    if (x != u && x != v) return x;
  return kNone;
}

}  // namespace

TopologyJudge::TopologyJudge(const PointSet &points, const Neighborhood &nb, const Params &params,
                             MeshState &mesh, CrossingIndex &crossings)
    : points_(points),
      nb_(nb),
      mesh_(mesh),
      crossings_(crossings),
      flatness_a_(params.flatness_a),
      flatness_c_(params.flatness_c),
      cos_edge_fold_(std::cos(degrees_to_radians(params.edge_fold_angle))),
      vertex_fold_(degrees_to_radians(params.vertex_fold_angle)),
      vertex_open_(degrees_to_radians(params.vertex_open_angle)),
      cos_normal_(std::cos(degrees_to_radians(params.max_normal_deviation))) {}

bool TopologyJudge::degenerate(const Tri &t) const {
  const Vec3 &a = points_.work[t[0]], &b = points_.work[t[1]], &c = points_.work[t[2]];
  if (angle_at(a, b, c) > kMaxCornerAngle || angle_at(b, c, a) > kMaxCornerAngle ||
      angle_at(c, a, b) > kMaxCornerAngle)
    return true;
  return collinear(points_.exact[t[0]], points_.exact[t[1]], points_.exact[t[2]]);
}

bool TopologyJudge::normal_deviates(const Tri &t) const {
  const Vec3 &a = points_.work[t[0]], &b = points_.work[t[1]], &c = points_.work[t[2]];
  Vec3 n = normalized(cross(b - a, c - a));
  for (uint32_t v : t)
    if (std::fabs(dot(n, nb_.normal[v])) < cos_normal_) return true;
  return false;
}

bool TopologyJudge::edge_folds(const Tri &t) const {
  // Fig. 8 (2): alpha is the angle between AB x BC and AB x BD; near 0 the two triangles lie
  // on the same side of AB, folded onto each other.
  for (int i = 0; i < 3; ++i) {
    uint32_t ia = t[i], ib = t[(i + 1) % 3];
    uint32_t fs[2];
    int n = mesh_.edge_faces(ia, ib, fs);
    for (int k = 0; k < n; ++k) {
      uint32_t id = third_vertex(mesh_.stored(fs[k]), ia, ib);
      const Vec3 &A = points_.work[ia], &B = points_.work[ib];
      const Vec3 &C = points_.work[t[(i + 2) % 3]], &D = points_.work[id];
      Vec3 ab = B - A;
      Vec3 u = normalized(cross(ab, C - B)), w = normalized(cross(ab, D - B));
      if (dot(u, w) > cos_edge_fold_) return true;
    }
  }
  return false;
}

bool TopologyJudge::vertex_folds(const Tri &t) const {
  // Fig. 8 (1): triangles PAB and PCD sharing only P. A small alpha between the directions to
  // their centres M and N, with both beta = AOB and gamma = COD large (O the centre of A, B,
  // C, D), marks a duplicated fan.
  for (int i = 0; i < 3; ++i) {
    uint32_t ip = t[i], ia = t[(i + 1) % 3], ib = t[(i + 2) % 3];
    const Vec3 &P = points_.work[ip], &A = points_.work[ia], &B = points_.work[ib];
    Vec3 M = centroid(P, A, B);
    for (uint32_t f : mesh_.faces_at(ip)) {
      const Tri &g = mesh_.stored(f);
      int shared = 0;
      for (uint32_t x : g) shared += (x == ia || x == ib || x == ip);
      if (shared != 1) continue;
      uint32_t ic = kNone, id = kNone;
      for (uint32_t x : g)
        if (x != ip) (ic == kNone ? ic : id) = x;
      const Vec3 &C = points_.work[ic], &D = points_.work[id];
      Vec3 N = centroid(P, C, D);
      if (angle_between(M - P, N - P) >= vertex_fold_) continue;
      Vec3 O = (A + B + C + D) * 0.25;
      if (angle_at(O, A, B) > vertex_open_ && angle_at(O, C, D) > vertex_open_) return true;
    }
  }
  return false;
}

bool TopologyJudge::faces_backwards(const Tri &t) const {
  // Where t joins faces whose orientation is tied to its own (a component it shares an edge
  // with), its normal must agree with theirs at each corner: a triangle whose normal turns
  // against the fan it joins wraps around to the far side of a thin part.
  uint32_t roots[3];
  double sign[3];
  int linked = 0;
  for (int i = 0; i < 3; ++i) {
    uint32_t u = t[i], v = t[(i + 1) % 3], fs[2];
    if (mesh_.edge_faces(u, v, fs) != 1) continue;
    Tri g = mesh_.oriented(fs[0]);
    bool same_direction = false;  // t and g both run u->v: g's class is flipped relative to t
    for (int k = 0; k < 3; ++k) same_direction |= (g[k] == u && g[(k + 1) % 3] == v);
    roots[linked] = mesh_.component(fs[0]);
    sign[linked++] = same_direction ? -1.0 : 1.0;
  }
  if (linked == 0) return false;
  const auto &w = points_.work;
  Vec3 nt = normalized(cross(w[t[1]] - w[t[0]], w[t[2]] - w[t[0]]));
  for (uint32_t v : t) {
    Vec3 sum{};
    for (uint32_t f : mesh_.faces_at(v)) {
      uint32_t root = mesh_.component(f);
      for (int k = 0; k < linked; ++k) {
        if (roots[k] != root) continue;
        Tri g = mesh_.oriented(f);
        sum = sum + normalized(cross(w[g[1]] - w[g[0]], w[g[2]] - w[g[0]])) * sign[k];
        break;
      }
    }
    if (norm2(sum) > 0 && dot(nt, normalized(sum)) < kBackwardsCosine) return true;
  }
  return false;
}

bool TopologyJudge::flatness_fails(const Tri &t, const uint32_t *sphere, std::size_t count) const {
  // Fig. 7: T = (|PD| / b)^2 (|PI| / |DI|)^c with D the triangle's centre, I the projection of
  // P onto the triangle's plane and b the mean edge length.
  const Vec3 &a = points_.work[t[0]], &b = points_.work[t[1]], &c = points_.work[t[2]];
  Vec3 n = normalized(cross(b - a, c - a));
  Vec3 D = centroid(a, b, c);
  double bl = (dist(a, b) + dist(b, c) + dist(c, a)) / 3.0;
  for (std::size_t k = 0; k < count; ++k) {
    uint32_t p = sphere[k];
    if (p == t[0] || p == t[1] || p == t[2]) continue;
    Vec3 dp = points_.work[p] - D;
    double pi = std::fabs(dot(dp, n));
    double di = norm(dp - n * dot(dp, n));
    // A point straight above or below the triangle is another sheet of a thin part (the
    // paper's thin slabs), not a fold beside it: the crossing test keeps the sheets apart.
    if (di < 0.5 * bl) continue;
    double T = norm2(dp) / (bl * bl) * std::pow(pi / di, flatness_c_);
    if (T >= flatness_a_) return true;
  }
  return false;
}

Verdict TopologyJudge::judge(const Tri &t, const uint32_t *sphere, std::size_t count,
                             bool relaxed) {
  if (degenerate(t)) return Verdict::Degenerate;
  switch (mesh_.check(t)) {
    case TopologyVerdict::Ok:
      break;
    case TopologyVerdict::Orientation:
      return Verdict::Orientation;
    default:
      return Verdict::Manifold;
  }
  if (!relaxed && normal_deviates(t)) return Verdict::Flatness;
  if (edge_folds(t)) return Verdict::EdgeFold;
  if (vertex_folds(t) || faces_backwards(t)) return Verdict::VertexFold;
  if (!relaxed && count > 0 && flatness_fails(t, sphere, count)) return Verdict::Flatness;
  if (crossings_.crosses(t, mesh_)) return Verdict::Intersection;
  return Verdict::Accept;
}

void TopologyJudge::count(Verdict v, moa_stats &stats) {
  ++stats.candidates_tested;
  switch (v) {
    case Verdict::Accept:
      break;
    case Verdict::Degenerate:
      ++stats.rejected_degenerate;
      break;
    case Verdict::Manifold:
      ++stats.rejected_manifold;
      break;
    case Verdict::Orientation:
      ++stats.rejected_orientation;
      break;
    case Verdict::Flatness:
      ++stats.rejected_flatness;
      break;
    case Verdict::EdgeFold:
      ++stats.rejected_edge_fold;
      break;
    case Verdict::VertexFold:
      ++stats.rejected_vertex_fold;
      break;
    case Verdict::Intersection:
      ++stats.rejected_intersection;
      break;
  }
}

}  // namespace moa
