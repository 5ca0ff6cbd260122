// Topology judgment (paper §3.4). Cheap tests run first; the exact crossing test runs last.
#include "core/topology_judgment.hpp"

#include <algorithm>
#include <cmath>

#include "core/predicates.hpp"

namespace moa {
namespace {

// A triangle whose largest angle exceeds this is a needle or a cap: its area is nearly zero
// and its normal meaningless.
const double kMaxCornerCos = std::cos(degrees_to_radians(175.0));
// The loop module's last passes accept flatter triangles: a sliver closes a crack that no
// better triangle can.
const double kMaxCornerCosRelaxed = std::cos(degrees_to_radians(179.0));
// Steepest bend across which a triangle may join two pieces of the mesh (see
// merges_across_a_bend): a right angle, with room for rounding. The faces of a box sampled on
// a grid meet at exactly 90 degrees, and the cosine computed for that bend comes out 0 or a
// hair either side of it, while cos(90°) is 6e-17: compared with that, such a box's faces were
// joined along some edges and not along others.
constexpr double kMinMergeBendCos = -1e-9;

// The sharpest edge fold the loop module's last patches may make (allow_sharp_folds): a ridge
// this sharp beats a hole left open, while a face folded flat onto its neighbour does not.
constexpr double kSharpFoldDegrees = 5.0;

// A triangle whose normal is more than about 100 degrees from the mean normal of a fan it
// joins faces backwards.
constexpr double kBackwardsCosine = -0.17;

// A point that projects into a triangle from closer than this fraction of its mean edge lies
// on the same sheet: the triangle would cover it, and the surface there would be two-layered.
constexpr double kCoverHeight = 0.2;

bool covers(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &n, const Vec3 &p,
            double height, double mean_edge) {
  if (height >= kCoverHeight * mean_edge) return false;
  // Inside test by the signs of the sub-triangle normals along n.
  return dot(cross(b - a, p - a), n) > 0 && dot(cross(c - b, p - b), n) > 0 &&
         dot(cross(a - c, p - c), n) > 0;
}

// Layers: faces overlapping t in projection are a second layer when closer to t's plane than
// this many mean edge lengths (facing the same way within one component) or than the other.
constexpr double kSameFacingLayer = 1.0;
constexpr double kAnyLayer = 0.3;
// A triangle whose smallest height is below this fraction of its longest edge is a sliver.
constexpr double kSliverHeight = 0.15;
// Faces are searched within this many mean edge lengths of t's bounding box.
constexpr double kGatherPad = 0.5;
// Triangles are shrunk this much toward their centres before the overlap test, so that
// touching along shared vertices does not count.
constexpr double kShrink = 0.98;

// Do two 2-D triangles overlap? Separating axis test over the six edge normals.
bool triangles_overlap_2d(const double (&p)[3][2], const double (&q)[3][2]) {
  const double(*tri[2])[2] = {p, q};
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 3; ++i) {
      const double *u = tri[k][i], *v = tri[k][(i + 1) % 3];
      double ax = v[1] - u[1], ay = u[0] - v[0];
      double pmin = 1e300, pmax = -1e300, qmin = 1e300, qmax = -1e300;
      for (int j = 0; j < 3; ++j) {
        double dp = p[j][0] * ax + p[j][1] * ay, dq = q[j][0] * ax + q[j][1] * ay;
        pmin = std::min(pmin, dp);
        pmax = std::max(pmax, dp);
        qmin = std::min(qmin, dq);
        qmax = std::max(qmax, dq);
      }
      if (pmax <= qmin || qmax <= pmin) return false;
    }
  return true;
}

double cosine(const Vec3 &u, const Vec3 &v) {
  double d = std::sqrt(norm2(u) * norm2(v));
  return d > 0 ? dot(u, v) / d : 1.0;
}

// Whether the corners APB and CPD, seen from P in the plane of APB, share no direction: two
// triangles side by side in one fan, not one folded over the other. Each corner is an arc of
// directions narrower than half a turn; two such arcs meet when one starts inside the other.
bool corners_apart(const Vec3 &P, const Vec3 &A, const Vec3 &B, const Vec3 &C, const Vec3 &D) {
  const Vec3 n = normalized(cross(A - P, B - P));
  const Vec3 e1 = normalized(A - P), e2 = cross(n, e1);
  auto direction = [&](const Vec3 &X) { return std::atan2(dot(X - P, e2), dot(X - P, e1)); };
  struct Arc {
    double start, width;
  };
  auto arc = [](double from, double to) {
    const double w = std::remainder(to - from, 2 * kPi);  // in [-pi, pi]
    return w >= 0 ? Arc{from, w} : Arc{to, -w};
  };
  auto ahead = [](double from, double to) {  // turn from `from` to `to`, in [0, 2 pi)
    const double d = std::fmod(to - from, 2 * kPi);
    return d < 0 ? d + 2 * kPi : d;
  };
  const Arc t = arc(0.0, direction(B)), g = arc(direction(C), direction(D));
  return ahead(t.start, g.start) >= t.width && ahead(g.start, t.start) >= g.width;
}

// Local planes kept at once (TopologyJudge::plane_at).
constexpr std::size_t kPlaneCacheSlots = std::size_t(1) << 16;

// Within a thin wall a triangle must follow the planes more closely than max_normal_deviation
// asks. There a front's edge has its points' own sheet filled on both sides once the fronts
// meet, and the next best third vertices are on the far sheet: concentric spheres 1.8 spacings
// apart (20k points) took in triangles bridging the sheets at 46-66 degrees off the true
// normals, and the sheets did not close round them (271-697 boundary edges, joined). With
// this limit three samples of four close as two spheres and the fourth keeps 13 boundary
// edges (20 with 45 degrees); faces on the sheets stand under 5 degrees off (99 %). Only where
// every corner is in a thin wall: a face across a crease of a thin-walled box stands 45
// degrees off the planes of its corners on the faces beside the crease, which see the far
// sheet too (with the limit at every such corner, boxes opened along their creases).
constexpr double kThinWallNormalDeviation = 40;

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
      cos_vertex_fold_(std::cos(degrees_to_radians(params.vertex_fold_angle))),
      cos_vertex_open_(std::cos(degrees_to_radians(params.vertex_open_angle))),
      cos_normal_(std::cos(degrees_to_radians(params.max_normal_deviation))),
      cos_thin_wall_normal_(std::cos(degrees_to_radians(
          std::min(params.max_normal_deviation, kThinWallNormalDeviation)))),
      // Never stricter than the parameter: with edge_fold_angle under 5 degrees, that is kept.
      cos_sharp_fold_(std::max(cos_edge_fold_, std::cos(degrees_to_radians(kSharpFoldDegrees)))) {
  std::size_t slots = 1;  // a power of two, up to 2^16 (2.5 MB)
  while (slots < points.size() && slots < kPlaneCacheSlots) slots *= 2;
  planes_.resize(slots);
}

bool TopologyJudge::is_sliver(const Tri &t) const {
  const Vec3 &a = points_.work[t[0]], &b = points_.work[t[1]], &c = points_.work[t[2]];
  double longest2 = std::max({norm2(b - a), norm2(c - b), norm2(a - c)});
  // Twice the area over the longest edge is the smallest height; compare it with that edge.
  return norm(cross(b - a, c - a)) < kSliverHeight * longest2;
}

bool TopologyJudge::degenerate(const Tri &t, bool relaxed, bool flat_corners) const {
  const double limit = flat_corners ? -1.0 : relaxed ? kMaxCornerCosRelaxed : kMaxCornerCos;
  const Vec3 &a = points_.work[t[0]], &b = points_.work[t[1]], &c = points_.work[t[2]];
  // A corner above the limit has a cosine below cos(limit).
  auto corner_cos = [](const Vec3 &p, const Vec3 &q, const Vec3 &r) {
    Vec3 u = q - p, v = r - p;
    return dot(u, v) / std::sqrt(norm2(u) * norm2(v));
  };
  if (corner_cos(a, b, c) < limit || corner_cos(b, c, a) < limit || corner_cos(c, a, b) < limit)
    return true;
  return collinear(points_.exact(t[0]), points_.exact(t[1]), points_.exact(t[2]));
}

const LocalPlane &TopologyJudge::plane_at(uint32_t v) const {
  CachedPlane &c = planes_[v & (planes_.size() - 1)];
  if (c.point != v) c = {v, local_plane(points_, nb_, v)};
  return c.plane;
}

bool TopologyJudge::normal_deviates(const Tri &t) const {
  const Vec3 &a = points_.work[t[0]], &b = points_.work[t[1]], &c = points_.work[t[2]];
  Vec3 n = normalized(cross(b - a, c - a));
  bool in_thin_wall = true;
  double least_cos = 1;
  for (uint32_t v : t) {
    const LocalPlane &plane = plane_at(v);
    if (plane.undirected) continue;  // no plane to deviate from
    const double cos_v = std::fabs(dot(n, plane.normal));
    if (cos_v < cos_normal_) return true;
    in_thin_wall = in_thin_wall && plane.in_thin_wall;
    least_cos = std::min(least_cos, cos_v);
  }
  return in_thin_wall && least_cos < cos_thin_wall_normal_;
}

TopologyJudge::EdgeFaces TopologyJudge::faces_on_edges(const Tri &t) const {
  EdgeFaces edges;
  for (int i = 0; i < 3; ++i) {
    uint32_t fs[2];
    mesh_.edge_faces(t[i], t[(i + 1) % 3], fs);
    edges.face[i] = fs[0];
  }
  return edges;
}

bool TopologyJudge::edge_folds(const Tri &t, const EdgeFaces &edges, double cos_fold) const {
  // Fig. 8 (2): alpha is the angle between AB x BC and AB x BD; near 0 the two triangles lie
  // on the same side of AB, folded onto each other.
  for (int i = 0; i < 3; ++i) {
    uint32_t ia = t[i], ib = t[(i + 1) % 3];
    if (edges.face[i] != kNone) {
      uint32_t id = third_vertex(mesh_.stored(edges.face[i]), ia, ib);
      const Vec3 &A = points_.work[ia], &B = points_.work[ib];
      const Vec3 &C = points_.work[t[(i + 2) % 3]], &D = points_.work[id];
      Vec3 ab = B - A;
      Vec3 u = normalized(cross(ab, C - B)), w = normalized(cross(ab, D - B));
      if (dot(u, w) > cos_fold) return true;
    }
  }
  return false;
}

bool TopologyJudge::merges_across_a_bend(const Tri &t, const EdgeFaces &edges) {
  // A triangle that joins two pieces of the mesh decides how one piece is oriented relative to
  // the other, for good. Across a steep bend that decision is a guess: two fronts of a noisy
  // sample meeting at a step would turn a whole region inside out, and the seam where it meets
  // the rest again could never close. So a joining triangle must continue both pieces smoothly:
  // with D the far corner of a neighbour across edge AB, the neighbour oriented to match t is
  // BAD, and its normal must not turn away from t's by more than a right angle.
  const auto &w = points_.work;
  const Vec3 nt = normalized(cross(w[t[1]] - w[t[0]], w[t[2]] - w[t[0]]));
  uint32_t first = kNone;
  bool joins = false;
  for (int i = 0; i < 3 && !joins; ++i) {
    if (edges.face[i] == kNone) continue;
    const uint32_t c = mesh_.component(edges.face[i]);
    if (first == kNone) first = c;
    joins = c != first;
  }
  if (!joins) return false;
  for (int i = 0; i < 3; ++i) {
    const uint32_t a = t[i], b = t[(i + 1) % 3];
    if (edges.face[i] == kNone) continue;
    const uint32_t d = third_vertex(mesh_.stored(edges.face[i]), a, b);
    const Vec3 nd = normalized(cross(w[a] - w[b], w[d] - w[b]));
    if (dot(nt, nd) < kMinMergeBendCos) return true;
  }
  return false;
}

bool TopologyJudge::vertex_folds(const Tri &t) const {
  // Fig. 8 (1): triangles PAB and PCD sharing only P. A small alpha between the directions to
  // their centres M and N, with both beta = AOB and gamma = COD large (O the centre of A, B,
  // C, D), marks a duplicated fan, unless the two corners at P lie side by side. Needles (a
  // contour stack with 20 or more points per slice gap: corners of 3 degrees at one end, 88 at
  // the other) have the centres of neighbours in a fan within the 15 degrees of alpha: taken
  // for duplicated fans, such stacks fell apart into dozens or hundreds of pieces.
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
      // Angles compared through their cosines: alpha < limit <=> cos(alpha) > cos(limit).
      if (cosine(M - P, N - P) <= cos_vertex_fold_) continue;
      Vec3 O = (A + B + C + D) * 0.25;
      if (cosine(A - O, B - O) < cos_vertex_open_ && cosine(C - O, D - O) < cos_vertex_open_ &&
          !corners_apart(P, A, B, C, D))
        return true;
    }
  }
  return false;
}

TopologyJudge::Frame TopologyJudge::frame_of(const Tri &t, const EdgeFaces &edges) const {
  Frame fr;
  for (int i = 0; i < 3; ++i) {
    uint32_t u = t[i], v = t[(i + 1) % 3];
    if (edges.face[i] == kNone) continue;
    const uint32_t f = edges.face[i];
    Tri g = mesh_.oriented(f);
    bool same_direction = false;  // t and g both run u->v: g's class is flipped relative to t
    for (int k = 0; k < 3; ++k) same_direction |= (g[k] == u && g[(k + 1) % 3] == v);
    fr.roots[fr.linked] = mesh_.component(f);
    fr.sign[fr.linked++] = same_direction ? -1.0 : 1.0;
  }
  return fr;
}

bool TopologyJudge::faces_backwards(const Tri &t, const Frame &frame) const {
  // Where t joins faces whose orientation is tied to its own (a component it shares an edge
  // with), its normal must agree with theirs at each corner: a triangle whose normal turns
  // against the fan it joins wraps around to the far side of a thin part.
  if (frame.linked == 0) return false;
  const auto &w = points_.work;
  Vec3 nt = normalized(cross(w[t[1]] - w[t[0]], w[t[2]] - w[t[0]]));
  for (uint32_t v : t) {
    Vec3 sum{};
    for (uint32_t f : mesh_.faces_at(v)) {
      double s = frame.sign_of(mesh_.component(f));
      if (s == 0) continue;
      Tri g = mesh_.oriented(f);
      sum = sum + normalized(cross(w[g[1]] - w[g[0]], w[g[2]] - w[g[0]])) * s;
    }
    if (norm2(sum) > 0 && dot(nt, normalized(sum)) < kBackwardsCosine) return true;
  }
  return false;
}

bool TopologyJudge::overlaps_layer(const Tri &t, const Frame &frame,
                                   const std::vector<uint32_t> &near) const {
  // Two triangles that overlap when projected onto t's plane, lying close to it and facing
  // the same way, make a two-layered surface even when they do not intersect (a large
  // triangle under small ones): the duplicated structure of paper Fig. 6 (2).
  const auto &w = points_.work;
  const Vec3 &a = w[t[0]], &b = w[t[1]], &c = w[t[2]];
  Vec3 n = normalized(cross(b - a, c - a));
  double bl = (dist(a, b) + dist(b, c) + dist(c, a)) / 3.0;
  Vec3 e1 = normalized(b - a), e2 = cross(n, e1);
  auto project = [&](const Vec3 &p, const Vec3 &centre, double(&out)[2]) {
    Vec3 q = centre + (p - centre) * kShrink - a;
    out[0] = dot(q, e1);
    out[1] = dot(q, e2);
  };
  double tp[3][2];
  Vec3 ct = centroid(a, b, c);
  for (int i = 0; i < 3; ++i) project(w[t[i]], ct, tp[i]);
  const double reach = std::max({dist(ct, a), dist(ct, b), dist(ct, c)});
  for (uint32_t f : near) {
    const Tri &g = mesh_.stored(f);
    int shared = 0;
    for (uint32_t x : g) shared += (x == t[0] || x == t[1] || x == t[2]);
    if (shared >= 2) continue;  // sharing an edge: the edge-fold angle decides
    // Cheapest tests first: height above t's plane, then the overlap in projection.
    const Vec3 &ga = w[g[0]], &gb = w[g[1]], &gc = w[g[2]];
    Vec3 cg0 = centroid(ga, gb, gc);
    double greach = std::max({dist(cg0, ga), dist(cg0, gb), dist(cg0, gc)});
    if (dist(cg0, ct) > reach + greach) continue;  // too far apart to overlap at all
    double h =
        std::max({std::fabs(dot(ga - a, n)), std::fabs(dot(gb - a, n)), std::fabs(dot(gc - a, n))});
    if (h > kSameFacingLayer * bl) continue;
    double gp[3][2];
    Vec3 cg = centroid(ga, gb, gc);
    project(ga, cg, gp[0]);
    project(gb, cg, gp[1]);
    project(gc, cg, gp[2]);
    if (!triangles_overlap_2d(tp, gp)) continue;
    Vec3 ng = normalized(cross(gb - ga, gc - ga));
    double facing = dot(ng, n);
    if (std::fabs(facing) < 0.5) continue;  // not a parallel layer
    if (h <= kAnyLayer * bl) return true;
    // Between the two limits only a layer facing the same way within one orientation class
    // counts: the far sheet of a thin part faces the other way.
    double s = frame.sign_of(mesh_.component(f));
    if (s == 0) continue;
    Tri go = mesh_.oriented(f);
    if ((go == g ? facing : -facing) * s > 0) return true;
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
    if (covers(a, b, c, n, dp + D, pi, bl)) return true;
    // A point straight above or below the triangle is another sheet of a thin part (the
    // paper's thin slabs), not a fold beside it: the crossing test keeps the sheets apart.
    if (di < 0.5 * bl) continue;
    double ratio = pi / di;
    double T = norm2(dp) / (bl * bl) * (flatness_c_ == 1.0 ? ratio : std::pow(ratio, flatness_c_));
    if (T >= flatness_a_) return true;
  }
  return false;
}

double TopologyJudge::reach(const Tri &t) const {
  const auto &w = points_.work;
  const double mean_edge =
      (dist(w[t[0]], w[t[1]]) + dist(w[t[1]], w[t[2]]) + dist(w[t[2]], w[t[0]])) / 3.0;
  return kGatherPad * mean_edge;
}

Verdict TopologyJudge::judge(const Tri &t, const uint32_t *sphere, std::size_t count, bool relaxed,
                             bool layers_allowed, bool flat_corners) {
  if (degenerate(t, relaxed, relaxed && flat_corners)) return Verdict::Degenerate;
  switch (mesh_.check(t)) {
    case TopologyVerdict::Ok:
      break;
    case TopologyVerdict::Orientation:
      return Verdict::Orientation;
    default:
      return Verdict::Manifold;
  }
  if (!relaxed && normal_deviates(t)) return Verdict::Flatness;
  const EdgeFaces edges = faces_on_edges(t);
  if (edge_folds(t, edges, sharp_folds_ ? cos_sharp_fold_ : cos_edge_fold_) ||
      merges_across_a_bend(t, edges))
    return Verdict::EdgeFold;
  Frame frame = frame_of(t, edges);
  if (!relaxed && (vertex_folds(t) || faces_backwards(t, frame))) return Verdict::VertexFold;
  if (!relaxed && count > 0 && flatness_fails(t, sphere, count)) return Verdict::Flatness;
  if (crossings_.crosses(t, reach(t), mesh_, near_)) return Verdict::Intersection;
  // A sliver's plane is too ill-defined to project onto: on the relaxed passes it is left to
  // the exact crossing test alone.
  if (!layers_allowed && !(relaxed && is_sliver(t)) && overlaps_layer(t, frame, near_))
    return Verdict::VertexFold;
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
