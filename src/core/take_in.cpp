// Taking in left-out points (paper §3.5.2, step 1): a point that no triangle reached but that
// lies over a triangle of the finished surface becomes a vertex by splitting that triangle in
// three, when the three new triangles pass the same judgment as every other. When no such split
// passes (on a noisy cloud a point can stand well off its neighbours' triangles), splitting an
// edge of a nearby triangle, and the two triangles on it in two each, is tried instead; then
// a star: a few faces around the point replaced by the fan from the point to their rim.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "core/growth_state.hpp"
#include "core/marks.hpp"

namespace moa {
namespace {

// Only the faces around this many of a point's nearest neighbours are considered.
constexpr unsigned kNearbyVertices = 8;
// A point farther from a face's plane than this many local spacings is not on that face; a
// point's spacing counts as at most kIsolation times its neighbours' (surface_spacing).
constexpr double kMaxHeight = 1.0;
constexpr double kIsolation = 2.0;
// A face whose nearest barycentric coordinate for the point is below minus this is not near
// enough for an edge split either.
constexpr double kMaxOutside = 0.5;
// A patch a star replaces has fewer than kMaxStarFaces faces (three to seven: one and two are
// the splits) and grows only over faces whose centres lie within kStarReach local spacings of
// the point.
constexpr std::size_t kMaxStarFaces = 8;
constexpr double kStarReach = 2.5;

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

  // Each point left out is tried with the whole judgment; those still out, again without its
  // second-layer test: beside a crease the faces across it can overlap a split in projection
  // without crossing it. A point whose nearest neighbours were all out (a hole's rim the loop
  // module took away) finds faces to split only once one of them is in: after each pass, the
  // points still out next to one just taken in are tried again (not every point still out:
  // on a scan with hundreds of outliers each pass re-added the faces of every failed try).
  // `only`: the points to try, if not every point left out.
  std::size_t run(const std::vector<uint32_t> *only) {
    std::size_t taken = 0;
    std::vector<uint32_t> out, again;
    IndexMarks just_in;
    for (bool layers_allowed : {false, true}) {
      layers_allowed_ = layers_allowed;
      out.clear();
      const auto offer = [&](uint32_t p) {
        if (!g_.mesh.is_used(p) && !beside_tangle(p)) out.push_back(p);
      };
      if (only)
        std::for_each(only->begin(), only->end(), offer);
      else
        for (uint32_t p = 0; p < g_.points.size(); ++p) offer(p);
      while (!out.empty()) {
        just_in.clear();
        for (std::size_t i = 0; i < out.size(); ++i) {
          if ((i & (kPollEvery - 1)) == kPollEvery - 1) g_.poll();
          if (take(out[i])) just_in.set(out[i]);
        }
        again.clear();
        for (uint32_t p : out) {
          if (g_.mesh.is_used(p)) {
            ++taken;
            continue;
          }
          const uint32_t *nb = g_.nb.of(p);
          for (unsigned j = 0; j < std::min(kNearbyVertices, g_.nb.k); ++j)
            if (just_in.has(nb[j])) {
              again.push_back(p);
              break;
            }
        }
        out.swap(again);
      }
    }
    return taken;
  }

 private:
  // A point of a tangle (GrowthState::tangled; pinch opening can leave one out), or one whose
  // nearest neighbours include a vertex of one, is part of it: no surface there to take it in.
  bool beside_tangle(uint32_t p) const {
    if (g_.tangled.empty()) return false;
    if (g_.in_tangle(p)) return true;
    const uint32_t *nb = g_.nb.of(p);
    for (unsigned j = 0; j < std::min(kNearbyVertices, g_.nb.k); ++j)
      if (g_.in_tangle(nb[j])) return true;
    return false;
  }

  // The spacing of the surface p would join: its own, but at most kIsolation times that of its
  // nearest neighbours. A stray point off the surface is as far from the surface as its own
  // spacing, so measuring its height in that unit would take it in as a spike.
  double surface_spacing(uint32_t p) const {
    const uint32_t *nb = g_.nb.of(p);
    const unsigned n = std::min(kNearbyVertices, g_.nb.k);
    std::vector<float> around(n);
    for (unsigned j = 0; j < n; ++j) around[j] = g_.nb.spacing[nb[j]];
    std::nth_element(around.begin(), around.begin() + n / 2, around.end());
    return std::min<double>(g_.nb.spacing[p], kIsolation * around[n / 2]);
  }

  // Faces near p, by their corners as stored (a failed attempt re-adds faces under new
  // indices): those p lies over first, nearest plane first, then those its projection misses
  // by a little, which an edge split can still reach. The faces around p's nearest neighbours,
  // and the faces near p in space: at a sharp corner a long face across the crease can cover p
  // with no corner among them, and every split of another face would then cross it.
  void host_faces(uint32_t p, double spacing) {
    const auto &w = g_.points.work;
    const double limit = kMaxHeight * spacing;
    const bool in_the_volume = g_.nb.in_the_volume(p);
    const Vec3 reach{limit, limit, limit};
    nearby_.clear();
    g_.crossings.faces_in_box(w[p] - reach, w[p] + reach, g_.mesh, nearby_);
    const uint32_t *nb = g_.nb.of(p);
    for (unsigned j = 0; j < std::min(kNearbyVertices, g_.nb.k); ++j)
      for (uint32_t f : g_.mesh.faces_at(nb[j])) nearby_.push_back(f);
    std::sort(nearby_.begin(), nearby_.end());
    nearby_.erase(std::unique(nearby_.begin(), nearby_.end()), nearby_.end());
    hosts_.clear();
    for (uint32_t f : nearby_) {
      const Tri &t = g_.mesh.stored(f);
      double l[3];
      if (!barycentric(w[t[0]], w[t[1]], w[t[2]], w[p], l)) continue;
      const double outside = -std::min({l[0], l[1], l[2], 0.0});
      if (outside > kMaxOutside) continue;
      Vec3 n = normalized(cross(w[t[1]] - w[t[0]], w[t[2]] - w[t[0]]));
      double h = std::fabs(dot(w[p] - w[t[0]], n));
      double face_limit = limit;
      if (in_the_volume) {
        const auto &sp = g_.nb.spacing;
        face_limit = std::min(limit, kMaxHeight * (double(sp[t[0]]) + sp[t[1]] + sp[t[2]]) / 3);
      }
      if (h <= face_limit) hosts_.push_back({outside > 0, h, t});
    }
    std::sort(hosts_.begin(), hosts_.end());
  }

  bool take(uint32_t p) {
    // Measured once: the splits and every star below use it.
    const double spacing = surface_spacing(p);
    host_faces(p, spacing);
    for (const Host &host : hosts_) {
      const uint32_t f = g_.mesh.face_with(host.corners);
      if (host.outside || f == kNone) continue;
      const Tri o = g_.mesh.oriented(f);
      if (replace({f}, {Tri{o[0], o[1], p}, Tri{o[1], o[2], p}, Tri{o[2], o[0], p}})) return true;
    }
    for (const Host &host : hosts_)
      for (int i = 0; i < 3; ++i) {
        // Looked up again each time: a failed split puts the face back under a new index.
        const uint32_t f = g_.mesh.face_with(host.corners);
        if (f == kNone) break;
        const Tri o = g_.mesh.oriented(f);
        // The edge between corners i and i + 1, in the direction f runs along it.
        const auto at = std::find(o.begin(), o.end(), host.corners[i]) - o.begin();
        const bool forward = o[(at + 1) % 3] == host.corners[(i + 1) % 3];
        const uint32_t u = forward ? o[at] : o[(at + 2) % 3];
        const uint32_t v = forward ? o[(at + 1) % 3] : o[at];
        const uint32_t w = forward ? o[(at + 2) % 3] : o[(at + 1) % 3];
        uint32_t fs[2];
        if (g_.mesh.edge_faces(u, v, fs) != 2) continue;
        const uint32_t across = fs[0] == f ? fs[1] : fs[0];
        const uint32_t x = third_vertex(g_.mesh.stored(across), u, v);
        // f runs u -> v, so the consistently oriented face across runs v -> u.
        if (replace({f, across}, {Tri{u, p, w}, Tri{p, v, w}, Tri{v, p, x}, Tri{p, u, x}}))
          return true;
      }
    for (const Host &host : hosts_)
      if (take_by_star(p, host.corners, spacing)) return true;
    return false;
  }

  // Grows a patch from the face with corners `seed`, one face at a time across its rim (the
  // face nearest p whose third corner is not yet in the patch, so that every corner stays on
  // the rim and the patch stays a disk), and after each step tries the fan from p to the rim
  // in its place. Split faces are narrow or tilted where noise lifts p off its neighbours'
  // triangles; a wider fan spreads the step over more, larger triangles.
  bool take_by_star(uint32_t p, const Tri &seed, double spacing) {
    const auto &w = g_.points.work;
    const double reach2 = std::pow(kStarReach * spacing, 2);
    std::vector<Tri> patch{seed};  // by corners: a failed attempt re-adds faces anew
    std::vector<uint32_t> faces, corners;
    std::vector<Tri> fan;
    while (patch.size() < kMaxStarFaces) {
      faces.clear();
      corners.clear();
      for (const Tri &t : patch) {
        const uint32_t f = g_.mesh.face_with(t);
        if (f == kNone) return false;
        faces.push_back(f);
        corners.insert(corners.end(), t.begin(), t.end());
      }
      // Rim edges as the patch's faces run along them, and the best face across one.
      fan.clear();
      uint32_t next = kNone;
      double next_d2 = reach2;
      for (uint32_t f : faces) {
        const Tri o = g_.mesh.oriented(f);
        for (int i = 0; i < 3; ++i) {
          const uint32_t a = o[i], b = o[(i + 1) % 3];
          uint32_t fs[2];
          const int n = g_.mesh.edge_faces(a, b, fs);
          const uint32_t across = n == 2 ? (fs[0] == f ? fs[1] : fs[0]) : kNone;
          if (across != kNone && std::find(faces.begin(), faces.end(), across) != faces.end())
            continue;  // inside the patch
          fan.push_back(Tri{a, b, p});
          if (across == kNone) continue;
          const Tri &c = g_.mesh.stored(across);
          // Its third corner is new: the patch grows as a disk.
          const bool opens =
              std::find(corners.begin(), corners.end(), third_vertex(c, a, b)) == corners.end();
          const double d2 = norm2(centroid(w[c[0]], w[c[1]], w[c[2]]) - w[p]);
          if (opens && (d2 < next_d2 || (d2 == next_d2 && across < next))) {
            next = across;
            next_d2 = d2;
          }
        }
      }
      // One and two faces are the splits tried before.
      if (patch.size() > 2 && replace(faces, fan)) return true;
      if (next == kNone) return false;
      patch.push_back(g_.mesh.stored(next));
    }
    return false;
  }

  // Removes `old` and adds `parts` when every part passes the judgment; otherwise puts the old
  // faces back (under new indices).
  bool replace(const std::vector<uint32_t> &old, const std::vector<Tri> &parts) {
    std::vector<Tri> kept;
    for (uint32_t f : old) {
      kept.push_back(g_.mesh.oriented(f));
      g_.mesh.remove(f);
    }
    if (g_.add_all_or_none(parts, layers_allowed_)) {
      g_.stats.triangles_loops += parts.size() - old.size();
      return true;
    }
    for (const Tri &t : kept) g_.add_face(t);
    return false;
  }

  struct Host {
    bool outside;  // p's projection misses the face: only an edge split can reach p
    double height;
    Tri corners;
    bool operator<(const Host &o) const {
      return std::tie(outside, height, corners) < std::tie(o.outside, o.height, o.corners);
    }
  };

  GrowthState &g_;
  bool layers_allowed_ = false;
  std::vector<Host> hosts_;
  std::vector<uint32_t> nearby_;
};

}  // namespace

std::size_t take_in_points(GrowthState &g, const std::vector<uint32_t> *only) {
  return PointTaker(g).run(only);
}

}  // namespace moa
