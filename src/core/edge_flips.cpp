// Edge flips toward wider angles: step 4's criterion, the maximum opposite angle, applied once
// more to the finished triangles. Algorithm 1 takes each segment's maximum opposite point in
// the order of the list, and the loop module fills holes greedily, so here and there an edge
// is left whose two opposite angles sum past 180 degrees: in the plane an edge that is not
// Delaunay, and a narrow triangle that the other diagonal of its quad would avoid (on a
// 100,000-point sample of bunny 2.2 % of the interior edges; CGAL's advancing front, whose
// faces are restricted Delaunay, none).
//
// Edge uv, with faces uvc and vud, becomes edge cd when
//   - the angles at c and d sum past 180 degrees by kMinGain, and the smaller of the pair's
//     smallest angles grows. Each flip then raises the sorted list of the faces' smallest
//     angles, so the flips come to an end;
//   - the new pair bends no more than the old one did, or no more than kFreeBend: a sharp
//     crease along uv keeps its edge; and no more than kMaxBend (a quad that is not convex in
//     its plane would give a pair facing opposite ways). The old pair may bend past kMaxBend
//     only when the flip widens the smallest angle by kStandingGain: a narrow face standing
//     off the surface on its long edge, as fillings of holes among coarse vertices mostly
//     leave, goes; an in-plane sliver beside a face cut across a sharp edge gains little and
//     stays;
//   - cd is no edge yet, the new faces fold onto none of their neighbours (edge_fold_angle,
//     as the judgment's edge-sharing angle) and, decided exactly, cross no face.
// The pass runs once the loop module is done, so it changes no boundary, genus or vertex,
// only which diagonal each quad has; its order is the faces', whatever the thread count.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "core/growth_state.hpp"
#include "core/predicates.hpp"

namespace moa {
namespace {

// Flip when the two angles sum past 180 degrees by this much (radians).
const double kMinGain = degrees_to_radians(0.5);
// A pair of faces may bend this much after the flip whatever it did before ...
const double kCosFreeBend = std::cos(degrees_to_radians(20.0));
// ... and neither pair more than this. On coarse vertex sets, whose neighbouring faces bend
// by tens of degrees, larger limits flip more edges, and the flips take the mesh closer to
// the reference (elephant's 2,775 vertices: faces with an angle below 30 degrees 7.5 % with no
// flips, 2.3 % with this limit, 1.5 % with 60; the mean distance to the reference 6.0e-5,
// 4.0e-5, 3.2e-5). But across a sharp edge sampled at random, where no point lies on the
// edge, a flip can cut the edge off deeper: on an 8,000-point box the faces' depth below its
// surface, summed, grew by 1.5 % with a limit of 20 degrees, 3 % with 45, 5 % with 60 and
// 11 % with 90, the deepest face unchanged up to 60.
const double kCosMaxBend = std::cos(degrees_to_radians(45.0));
// How much a flip must widen the pair's smallest angle when the old pair bends past kMaxBend.
// Elephant's 2,775 vertices, whose reference has no angle under 30 degrees: with no such flip 29
// faces under 10 degrees, each with an angle of 156-177 degrees, 24 of them standing 46-87 degrees
// off the face across their long edge (the other 5 go too); 0 with this factor, 2 with a factor of
// 2, 0 with any gain; but with any gain one face of an 8,000-point box (test_edge_flips) cut its
// sharp edge deeper (a 2.7-degree sliver flat in a face beside a face across the edge made a
// 2.9-degree one across it), with 1.2 and more none did.
constexpr double kStandingGain = 1.5;

class EdgeFlipper {
 public:
  explicit EdgeFlipper(GrowthState &g)
      : g_(g),
        mesh_(g.mesh),
        p_(g.points.placed()),
        cos_fold_(std::cos(degrees_to_radians(g.params.edge_fold_angle))) {}

  // The edges to flip are first looked for in parallel, reading the mesh only; they are
  // then flipped in the order of their faces, each judged again as it comes, and the four
  // outer edges of a flipped quad are looked at at once. An edge whose two faces stay as they
  // were keeps its angles: the others are not worth a second look.
  std::size_t run(const std::function<void(double)> &tick) {
    const uint32_t count = uint32_t(mesh_.face_count());
    constexpr uint32_t kChunk = 4096;
    std::vector<std::vector<std::pair<uint32_t, uint32_t>>> found((count + kChunk - 1) / kChunk);
    tbb::parallel_for(std::size_t(0), found.size(), [&](std::size_t chunk) {
      const uint32_t end = std::min(count, uint32_t(chunk + 1) * kChunk);
      for (uint32_t f = uint32_t(chunk) * kChunk; f < end; ++f)
        if (mesh_.alive(f)) {
          uint32_t u, v;
          if (offers_edge(f, u, v)) found[chunk].push_back({u, v});
        }
    });
    for (std::size_t chunk = 0; chunk < found.size(); ++chunk) {
      std::vector<std::pair<uint32_t, uint32_t>> &edges = found[chunk];
      tick(double(chunk) / double(found.size()));
      for (const auto &[u, v] : edges)
        if (flip(u, v))
          while (!pending_.empty()) {
            const auto [a, b] = pending_.back();
            pending_.pop_back();
            flip(a, b);
          }
      std::vector<std::pair<uint32_t, uint32_t>>().swap(edges);
    }
    return flips_;
  }

 private:
  // The edge of face f to flip, if any. Two angles facing an edge sum past 180 degrees only
  // if one of them is obtuse: a face offers the edge facing its obtuse angle, if it has one
  // (most faces have none), whichever of the edge's faces that is.
  bool offers_edge(uint32_t f, uint32_t &u, uint32_t &v) const {
    const Tri &t = mesh_.stored(f);
    for (int i = 0; i < 3; ++i) {
      const Vec3 &c = p_[t[(i + 2) % 3]];
      u = t[i];
      v = t[(i + 1) % 3];
      if (!(dot(p_[u] - c, p_[v] - c) < 0)) continue;
      uint32_t fs[2];
      if (mesh_.edge_faces(u, v, fs) != 2) return false;
      const uint32_t d = third_vertex(mesh_.stored(fs[0] == f ? fs[1] : fs[0]), u, v);
      return wider_across(u, v, t[(i + 2) % 3], d);
    }
    return false;
  }
  Vec3 normal(uint32_t a, uint32_t b, uint32_t c) const {
    return normalized(cross(p_[b] - p_[a], p_[c] - p_[a]));
  }
  double smallest_angle(uint32_t a, uint32_t b, uint32_t c) const {
    return moa::smallest_angle(p_[a], p_[b], p_[c]);
  }
  // Whether quad u c v d (faces uvc, vud) has the better pair of faces across cd.
  bool wider_across(uint32_t u, uint32_t v, uint32_t c, uint32_t d) const {
    const Vec3 cu = p_[u] - p_[c], cv = p_[v] - p_[c], du = p_[u] - p_[d], dv = p_[v] - p_[d];
    // The angles at c and d sum past 180 degrees exactly when their cosines sum below 0: a
    // cheap first test, which most edges fail.
    const double cos_c = dot(cu, cv) / std::sqrt(norm2(cu) * norm2(cv));
    const double cos_d = dot(du, dv) / std::sqrt(norm2(du) * norm2(dv));
    if (!(cos_c + cos_d < 0)) return false;
    if (!(angle_between(cu, cv) + angle_between(du, dv) > kPi + kMinGain)) return false;
    const double before = std::min(smallest_angle(u, v, c), smallest_angle(v, u, d));
    const double after = std::min(smallest_angle(d, v, c), smallest_angle(c, u, d));
    if (!(after > before)) return false;
    const Vec3 n1 = normal(u, v, c), n2 = normal(v, u, d);
    const Vec3 m1 = normal(d, v, c), m2 = normal(c, u, d);
    const double bend_before = dot(n1, n2), bend_after = dot(m1, m2);
    if (bend_before < kCosMaxBend && !(after >= kStandingGain * before)) return false;
    return bend_after >= kCosMaxBend && bend_after >= std::min(bend_before, kCosFreeBend);
  }
  // Whether new face t, replacing `old` along its edge ab, would fold onto the face across ab.
  bool folds(const Tri &t, uint32_t a, uint32_t b, uint32_t old) {
    uint32_t fs[2];
    const int n = mesh_.edge_faces(a, b, fs);
    for (int k = 0; k < n; ++k) {
      if (fs[k] == old) continue;
      const Tri o = mesh_.oriented(fs[k]);
      if (dot(normal(t[0], t[1], t[2]), normal(o[0], o[1], o[2])) < -cos_fold_) return true;
    }
    return false;
  }
  // Whether a or b would meet a face other than f1 and f2 (or each other) anywhere but in
  // shared vertices and edges.
  bool cross_any(const Tri &a, const Tri &b, uint32_t f1, uint32_t f2) {
    Vec3 alo, ahi, blo, bhi, glo, ghi;
    g_.crossings.bounds(a, alo, ahi);
    g_.crossings.bounds(b, blo, bhi);
    const Vec3 lo{std::min(alo.x, blo.x), std::min(alo.y, blo.y), std::min(alo.z, blo.z)};
    const Vec3 hi{std::max(ahi.x, bhi.x), std::max(ahi.y, bhi.y), std::max(ahi.z, bhi.z)};
    near_.clear();
    g_.crossings.faces_in_box(lo, hi, mesh_, near_);
    const PointSet &ps = g_.points;
    auto corners = [&](const Tri &t, Vec3 out[3], unsigned id[3]) {
      for (int k = 0; k < 3; ++k) {
        out[k] = ps.exact(t[k]);
        id[k] = t[k];
      }
    };
    Vec3 ap[3], bp[3], gp[3];
    unsigned ai[3], bi[3], gi[3];
    corners(a, ap, ai);
    corners(b, bp, bi);
    if (triangles_cross(ap, ai, bp, bi)) return true;
    // The exact tests only where the boxes meet (faces_in_box pads its boxes as this does).
    for (uint32_t f : near_) {
      if (f == f1 || f == f2) continue;
      const Tri &t = mesh_.stored(f);
      g_.crossings.bounds(t, glo, ghi);
      const bool near_a = boxes_meet(alo, ahi, glo, ghi), near_b = boxes_meet(blo, bhi, glo, ghi);
      if (!near_a && !near_b) continue;
      corners(t, gp, gi);
      if ((near_a && triangles_cross(ap, ai, gp, gi)) ||
          (near_b && triangles_cross(bp, bi, gp, gi)))
        return true;
    }
    return false;
  }
  bool flip(uint32_t u, uint32_t v) {
    uint32_t fs[2];
    if (mesh_.edge_faces(u, v, fs) != 2) return false;
    const Tri t1 = mesh_.oriented(fs[0]), t2 = mesh_.oriented(fs[1]);
    if (!has_directed(t1, u, v)) std::swap(u, v);
    if (!has_directed(t1, u, v) || !has_directed(t2, v, u)) return false;  // not oriented alike
    const uint32_t c = third_vertex(t1, u, v), d = third_vertex(t2, u, v);
    uint32_t on_cd[2];
    if (c == d || !wider_across(u, v, c, d) || mesh_.edge_faces(c, d, on_cd) != 0) return false;
    const Tri a{d, v, c}, b{c, u, d};
    const PointSet &ps = g_.points;
    if (collinear(ps.exact(d), ps.exact(v), ps.exact(c)) ||
        collinear(ps.exact(c), ps.exact(u), ps.exact(d)))
      return false;
    if (folds(a, d, v, fs[1]) || folds(a, v, c, fs[0]) || folds(b, c, u, fs[0]) ||
        folds(b, u, d, fs[1]) || cross_any(a, b, fs[0], fs[1]))
      return false;
    mesh_.remove(fs[0]);
    mesh_.remove(fs[1]);
    // The quad's own edges and fans stay as they were, so these checks pass; kept as a guard.
    if (mesh_.check(a) == TopologyVerdict::Ok) {
      const uint32_t fa = g_.add_face(a);
      if (mesh_.check(b) == TopologyVerdict::Ok) {
        g_.add_face(b);
        ++flips_;
        pending_.push_back({u, d});
        pending_.push_back({d, v});
        pending_.push_back({v, c});
        pending_.push_back({c, u});
        return true;
      }
      mesh_.remove(fa);
    }
    g_.add_face(t1);
    g_.add_face(t2);
    return false;
  }

  GrowthState &g_;
  MeshState &mesh_;
  const std::vector<Vec3> &p_;
  const double cos_fold_;
  std::vector<std::pair<uint32_t, uint32_t>> pending_;
  std::vector<uint32_t> near_;
  std::size_t flips_ = 0;
};

}  // namespace

std::size_t flip_edges(GrowthState &g, const std::function<void(double)> &tick) {
  if (g.params.edge_flips == 0) return 0;
  return EdgeFlipper(g).run(tick);
}

}  // namespace moa
