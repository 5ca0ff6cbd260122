// Thin handles. Where a sample is too sparse to tell a narrow gap from a fold (between fingers,
// at the corner of a mouth), Algorithm 1 can bridge the gap with a few triangles, and the loop
// module then closes the holes beside the bridge: the surface gains a handle whose waist is a
// cycle of three or four edges that bounds no face and has no chord. A handle of the sampled
// surface itself is many spacings round, so such a cycle, when it does not separate the
// surface, marks a bridge. The bridge is cut there: the faces at the cycle's corners on one side
// go, the cycle is capped on the other side, and the hole left is patched (both by
// hole_patch.hpp). All of it passes the judgment but its test for a second layer (a bridge is
// a flattened tube, so its cap lies close over the faces beside it), or nothing changes.
// Narrow tunnels under such a bridge, whose waist is longer, are cut the same way (below).
#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <memory>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "core/growth_state.hpp"
#include "core/hole_patch.hpp"
#include "core/marks.hpp"

namespace moa {
namespace {

// Faces searched for a way from one side of a cycle to the other: a bridge's way round is
// short, and a cycle without one within this many faces is left alone.
constexpr std::size_t kSearchBudget = 200000;
// Longest loop around the removed faces that is patched (the patch costs its cube).
constexpr std::size_t kMaxLoop = 64;

// Corners of the longest waist looked for (the narrow tunnels below).
constexpr int kMaxCorners = 8;
using Corners = std::array<uint32_t, kMaxCorners>;

// The corners first..last (at most kMaxCorners), the rest of the array kNone.
Corners corners_of(const uint32_t *first, const uint32_t *last) {
  Corners c;
  c.fill(kNone);
  std::copy(first, last, c.begin());
  return c;
}
Corners corners_of(std::initializer_list<uint32_t> list) {
  return corners_of(list.begin(), list.end());
}

// A waist: its corners in order (three to kMaxCorners).
struct Cycle {
  Corners corners = corners_of({});
  int n = 0;
  bool has(uint32_t x) const {
    return std::find(corners.begin(), corners.begin() + n, x) != corners.begin() + n;
  }
  bool operator<(const Cycle &o) const { return std::tie(n, corners) < std::tie(o.n, o.corners); }
  bool operator==(const Cycle &o) const { return n == o.n && corners == o.corners; }
};

// The cycle with these corners, in a form that lists each cycle once: rotated to start at its
// lowest corner, running toward the lower of that corner's two neighbours.
Cycle canonical(Corners c, int n) {
  std::rotate(c.begin(), std::min_element(c.begin(), c.begin() + n), c.begin() + n);
  if (c[n - 1] < c[1]) std::reverse(c.begin() + 1, c.begin() + n);
  Cycle cycle;
  cycle.corners = c;
  cycle.n = n;
  return cycle;
}

// Whether every edge of the cycle has two faces.
bool edges_full(const MeshState &mesh, const Corners &c, int n) {
  for (int i = 0; i < n; ++i) {
    uint32_t fs[2];
    if (mesh.edge_faces(c[i], c[(i + 1) % n], fs) != 2) return false;
  }
  return true;
}

// Appends to `out` the vertices joined to v by an edge, each once, in the order of v's faces.
void append_ring(const MeshState &mesh, uint32_t v, std::vector<uint32_t> &out) {
  const std::size_t start = out.size();
  for (uint32_t f : mesh.faces_at(v))
    for (uint32_t x : mesh.stored(f))
      if (x != v && std::find(out.begin() + std::ptrdiff_t(start), out.end(), x) == out.end())
        out.push_back(x);
}

// Each vertex's ring (append_ring), listed on first use: the searches for waists ask for the
// same rings many times over (each vertex's from each of its neighbours), and listing one walks
// the vertex's faces. The mesh must not change while a Rings is in use. Where each ring
// starts is kept by vertex in a hash map: the searches list the rings of a few tens of
// thousands of vertices spread through a cloud of millions, and two arrays over the cloud
// took 8 MB at a million points, most of their pages touched.
class Rings {
 public:
  explicit Rings(const MeshState &mesh) : mesh_(mesh) {}
  // Valid until the next call.
  const uint32_t *of(uint32_t v, uint32_t &count) {
    auto [at, listed] = where_.try_emplace(v, uint32_t(pool_.size()), 0);
    if (listed) {
      append_ring(mesh_, v, pool_);
      at->second.second = uint32_t(pool_.size()) - at->second.first;
    }
    count = at->second.second;
    return pool_.data() + at->second.first;
  }
  void copy(uint32_t v, std::vector<uint32_t> &out) {
    uint32_t count;
    const uint32_t *ring = of(v, count);
    out.assign(ring, ring + count);
  }

 private:
  const MeshState &mesh_;
  std::unordered_map<uint32_t, std::pair<uint32_t, uint32_t>> where_;  // start in pool_, size
  std::vector<uint32_t> pool_;
};

// Cycles of three edges that are not one face's, and of four edges without a chord, all edges
// with two faces, through the given vertices. From each vertex u: a three-edge cycle joins two
// of its neighbours; a four-edge cycle runs through two of them to a vertex x two steps away.
std::vector<Cycle> short_cycles(const MeshState &mesh, const std::vector<uint32_t> &at) {
  std::vector<Cycle> cycles;
  IndexMarks near, second;  // the neighbours of u, and the vertices two steps from it
  std::vector<uint32_t> ring, ring_v, far, common;
  Rings rings(mesh);
  auto neighbours = [&](uint32_t v, std::vector<uint32_t> &out) { rings.copy(v, out); };
  for (uint32_t u : at) {
    neighbours(u, ring);
    near.clear();
    second.clear();
    for (uint32_t x : ring) near.set(x);
    far.clear();
    for (uint32_t v : ring) {
      neighbours(v, ring_v);
      for (uint32_t x : ring_v) {
        if (x == u) continue;
        if (near.has(x)) {
          const Corners c = corners_of({u, v, x});
          if (v < x && mesh.face_with({u, v, x}) == kNone && edges_full(mesh, c, 3))
            cycles.push_back(canonical(c, 3));
        } else if (!second.has(x)) {
          second.set(x);
          far.push_back(x);
        }
      }
    }
    for (uint32_t x : far) {
      neighbours(x, ring_v);
      common.clear();
      for (uint32_t w : ring_v)
        if (near.has(w)) common.push_back(w);
      for (std::size_t i = 0; i < common.size(); ++i) {
        uint32_t count;
        const uint32_t *ring_i = rings.of(common[i], count);
        for (std::size_t j = i + 1; j < common.size(); ++j) {
          if (std::find(ring_i, ring_i + count, common[j]) != ring_i + count) continue;  // a chord
          const Corners c = corners_of({u, common[i], x, common[j]});
          if (edges_full(mesh, c, 4)) cycles.push_back(canonical(c, 4));
        }
      }
    }
  }
  std::sort(cycles.begin(), cycles.end());
  cycles.erase(std::unique(cycles.begin(), cycles.end()), cycles.end());
  return cycles;
}

// Narrow tunnels. Where two parts of the surface lie closer than the spacing (the lips at a
// mouth's corner), a bridge between them can leave a channel of air under it about a spacing
// wide: the handle's shortest way round then circles air, not a tube of the surface, and is
// five to eight edges long. A thin handle of the sampled surface is circled by a waist as
// long, but around a tube: its corners' normals point away from the waist's axis, where a
// tunnel's point toward it. Only tunnels are cut; a tunnel that narrow is below what the
// sampling can show.
constexpr int kMinTunnelCorners = 5;
// Longest waist round a tunnel, in local spacings (the mean over its corners of the points'
// spacings, neighbors.hpp): homer's mouth-corner tunnel on its 4,930 vertices is 6.2 round,
// and so is the tube of the elephant's thin handle on its 2,775 (6.4).
constexpr double kMaxTunnelWaist = 8.0;
// Every corner's normal must lean toward the axis by at least this cosine (homer's tunnel:
// 0.34 to 0.89; the elephant's tube leans away from it by 0.81 to 0.97).
constexpr double kMinInwardLean = 0.2;
// Sine of the least rise of an edge along a tunnel's waist off its corner's tangent plane
// (an eight-edge waist: 22.5 degrees, 0.38), with a margin for uneven corners.
constexpr double kMinBendRise = 0.25;
// How far the search for a waist goes from its start, in waists (half of one, and a margin).
constexpr double kBranchReach = 0.6;

class TunnelFinder {
 public:
  explicit TunnelFinder(GrowthState &g)
      : g_(g),
        dist_(new double[g.points.size()]),
        pred_(new uint32_t[g.points.size()]),
        hops_(new uint8_t[g.points.size()]),
        rings_(g.mesh) {}

  // The shortest tunnel waist through each vertex of `at` (with a closed fan, on a piece
  // that can have handles), where it has one; whether it separates the surface is left to
  // HandleCutter::cut.
  std::vector<Cycle> find(const std::vector<uint32_t> &at) {
    std::vector<Cycle> found;
    if (at.empty()) return found;
    measure_pieces();
    Cycle c;
    for (uint32_t s : at)
      if (g_.mesh.fan_closed(s) && pieces_[piece_of(s)].may_have_handles() && bends_in(s) &&
          shortest_through(s, c))
        found.push_back(c);
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  }

 private:
  static constexpr double kFar = std::numeric_limits<double>::infinity();

  // A piece of the mesh (an orientation class: faces joined by edges): its signed volume,
  // which tells which way it faces, and what its Euler characteristic needs.
  struct Piece {
    double volume = 0;
    std::size_t faces = 0, open_edges = 0, vertices = 0;
    // Whether V - E + F (2 - 2 genus - loops) leaves room for a handle: a piece with open
    // edges has at least one loop.
    bool may_have_handles() const {
      const double chi = double(vertices) - 0.5 * double(3 * faces + open_edges) + double(faces);
      return chi <= (open_edges == 0 ? 0.0 : -1.0);
    }
  };

  uint32_t piece_of(uint32_t v) { return g_.mesh.component(g_.mesh.faces_at(v).front()); }

  void measure_pieces() {
    const std::vector<Vec3> &w = g_.points.work;
    // Faces and vertices come in runs of one piece (most of them the main piece): one hash
    // per run. An open edge joins two vertices with open fans, and most fans are closed.
    uint32_t last = kNone;
    Piece *p = nullptr;
    for (uint32_t f = 0; f < g_.mesh.face_count(); ++f) {
      if (!g_.mesh.alive(f)) continue;
      const Tri t = g_.mesh.oriented(f);
      const uint32_t piece = g_.mesh.component(f);
      if (piece != last) p = &pieces_[last = piece];
      p->volume += dot(w[t[0]] - w[0], cross(w[t[1]] - w[0], w[t[2]] - w[0]));
      ++p->faces;
      for (int i = 0; i < 3; ++i) {
        const uint32_t a = t[i], b = t[(i + 1) % 3];
        uint32_t fs[2];
        if (!g_.mesh.fan_closed(a) && !g_.mesh.fan_closed(b))
          p->open_edges += g_.mesh.edge_faces(a, b, fs) == 1;
      }
    }
    last = kNone;
    for (uint32_t v = 0; v < g_.points.size(); ++v) {
      if (!g_.mesh.is_used(v)) continue;
      const uint32_t piece = piece_of(v);
      if (piece != last) p = &pieces_[last = piece];
      ++p->vertices;
    }
  }

  // Whether an edge from v rises steeply off v's tangent plane on the outer side: the surface
  // bends in as tightly as round a tunnel a few edges round (six edges turn 60 degrees from
  // corner to corner, so an edge along the waist rises by 30). Most vertices are not near
  // one, and this spares them the search.
  bool bends_in(uint32_t v) {
    const std::vector<Vec3> &w = g_.points.work;
    const Vec3 &normal = outward_normal(v);
    const double length = norm(normal);
    if (!(length > 0)) return false;
    uint32_t count;
    const uint32_t *around = ring(v, count);
    for (uint32_t j = 0; j < count; ++j) {
      const Vec3 edge = w[around[j]] - w[v];
      if (dot(edge, normal) > kMinBendRise * norm(edge) * length) return true;
    }
    return false;
  }

  const uint32_t *ring(uint32_t v, uint32_t &count) { return rings_.of(v, count); }

  // Dijkstra from s over the edges, up to half the corners of the longest waist; then the
  // cycles that close through an edge between two of its branches, shortest first.
  bool shortest_through(uint32_t s, Cycle &out) {
    const std::vector<Vec3> &w = g_.points.work;
    // Each corner is at most half the waist from s, the shorter way round; the corners'
    // spacings may be larger than s's own.
    const double reach = kBranchReach * kMaxTunnelWaist * g_.nb.spacing[s];
    reached_.clear();
    reached_.set(s);
    settled_.clear();
    dist_[s] = 0;
    pred_[s] = kNone;
    hops_[s] = 0;
    heap_.assign(1, {0.0, s});
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
      const auto [d, u] = heap_.back();
      heap_.pop_back();
      if (d > dist_[u]) continue;
      settled_.push_back(u);
      if (hops_[u] >= kMaxCorners / 2) continue;
      uint32_t count;
      const uint32_t *around = ring(u, count);
      for (uint32_t j = 0; j < count; ++j) {
        const uint32_t x = around[j];
        const double nd = d + dist(w[u], w[x]);
        if (nd > reach || nd >= distance(x)) continue;
        if (!reached_.has(x)) reached_.set(x);
        dist_[x] = nd;
        pred_[x] = u;
        hops_[x] = uint8_t(hops_[u] + 1);
        heap_.push_back({nd, x});
        std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
      }
    }
    closing_.clear();
    for (uint32_t u : settled_) {
      uint32_t count;
      const uint32_t *around = ring(u, count);
      for (uint32_t j = 0; j < count; ++j)
        if (const uint32_t x = around[j];
            u < x && reached_.has(x) && pred_[u] != x && pred_[x] != u &&
            hops_[u] + hops_[x] + 1 >= kMinTunnelCorners && hops_[u] + hops_[x] + 1 <= kMaxCorners)
          closing_.push_back({dist_[u] + dist_[x] + dist(w[u], w[x]), u, x});
    }
    std::sort(closing_.begin(), closing_.end());
    for (const Closing &k : closing_) {
      // The branch to u, then back from x: the two must meet at s alone.
      std::vector<uint32_t> &cycle = cycle_;
      cycle.clear();
      for (uint32_t v = k.u; v != kNone; v = pred_[v]) cycle.push_back(v);
      std::reverse(cycle.begin(), cycle.end());
      for (uint32_t v = k.x; v != s; v = pred_[v]) cycle.push_back(v);
      sorted_.assign(cycle.begin(), cycle.end());
      std::sort(sorted_.begin(), sorted_.end());
      if (std::adjacent_find(sorted_.begin(), sorted_.end()) != sorted_.end()) continue;
      const int n = int(cycle.size());
      const Corners c = corners_of(cycle.data(), cycle.data() + n);
      if (!edges_full(g_.mesh, c, n)) continue;
      double spacing = 0;
      for (uint32_t v : cycle) spacing += g_.nb.spacing[v];
      spacing /= n;
      if (k.length > kMaxTunnelWaist * spacing || !circles_air(cycle)) continue;
      out = canonical(c, n);
      return true;
    }
    return false;
  }

  // Whether the corners' normals all lean toward the cycle's axis (its area vector through
  // its centroid): the cycle runs round a channel of air.
  bool circles_air(const std::vector<uint32_t> &cycle) {
    const std::vector<Vec3> &w = g_.points.work;
    Vec3 centre{};
    for (uint32_t v : cycle) centre = centre + w[v];
    centre = centre * (1.0 / double(cycle.size()));
    Vec3 area{};
    for (std::size_t i = 0; i < cycle.size(); ++i)
      area = area + cross(w[cycle[i]] - centre, w[cycle[(i + 1) % cycle.size()]] - centre);
    if (norm(area) == 0) return false;
    const Vec3 axis = normalized(area);
    for (uint32_t v : cycle) {
      const Vec3 radial = (w[v] - centre) - axis * dot(w[v] - centre, axis);
      const Vec3 &normal = outward_normal(v);
      const double lengths = norm(normal) * norm(radial);
      if (!(lengths > 0) || dot(normal, radial) > -kMinInwardLean * lengths) return false;
    }
    return true;
  }

  // The area-weighted normal of the faces round v, facing out of its piece; computed once.
  const Vec3 &outward_normal(uint32_t v) {
    const auto [it, added] = normals_.try_emplace(v);
    if (added) {
      const std::vector<Vec3> &w = g_.points.work;
      for (uint32_t f : g_.mesh.faces_at(v)) {
        const Tri t = g_.mesh.oriented(f);
        const double facing = pieces_[g_.mesh.component(f)].volume < 0 ? -1.0 : 1.0;
        it->second = it->second + cross(w[t[1]] - w[t[0]], w[t[2]] - w[t[0]]) * facing;
      }
    }
    return it->second;
  }

  struct Closing {
    double length;
    uint32_t u, x;
    bool operator<(const Closing &o) const {
      return std::tie(length, u, x) < std::tie(o.length, o.u, o.x);
    }
  };

  GrowthState &g_;
  std::unordered_map<uint32_t, Piece> pieces_;  // by their classes' representative faces
  std::unordered_map<uint32_t, Vec3> normals_;  // outward_normal's, by vertex
  // The search's distances along the edges from its start, the vertex each was reached from,
  // and in how many edges: written where the search reaches (reached_) and read only there,
  // so left unwritten elsewhere (see Rings).
  double distance(uint32_t v) const { return reached_.has(v) ? dist_[v] : kFar; }
  IndexMarks reached_;
  std::unique_ptr<double[]> dist_;
  std::unique_ptr<uint32_t[]> pred_;
  std::unique_ptr<uint8_t[]> hops_;
  std::vector<uint32_t> settled_, cycle_, sorted_;
  Rings rings_;
  std::vector<std::pair<double, uint32_t>> heap_;
  std::vector<Closing> closing_;
};

class HandleCutter {
 public:
  explicit HandleCutter(GrowthState &g) : g_(g) {}

  bool cut(const Cycle &c) {
    // The mesh may have changed since the cycles were listed.
    if (!edges_full(g_.mesh, c.corners, c.n)) return false;
    if (c.n == 3 && g_.mesh.face_with({c.corners[0], c.corners[1], c.corners[2]}) != kNone)
      return false;
    uint32_t fs[2];
    g_.mesh.edge_faces(c.corners[0], c.corners[1], fs);
    if (!goes_round(c, fs[0], fs[1])) return false;  // it separates
    for (uint32_t first : fs)
      if (cut_side(c, first)) return true;
    return false;
  }

 private:
  // Whether face `to` can be reached from face `from` without crossing the cycle's edges.
  // Searched from both at once, a face at a time from each: a cycle that separates the
  // surface stops the search once the smaller side is exhausted (often the few faces around a
  // point the loop module took in), and a bridge's way round is found from both ends.
  bool goes_round(const Cycle &c, uint32_t from, uint32_t to) {
    IndexMarks *reached[2] = {&reached_, &other_reached_};  // from `from`, from `to`
    reached_.clear();
    other_reached_.clear();
    reached_.set(from);
    other_reached_.set(to);
    std::vector<uint32_t> *queues[2] = {&queue_, &other_queue_};
    queue_.assign(1, from);
    other_queue_.assign(1, to);
    std::size_t next[2] = {0, 0};
    for (std::size_t steps = 0; steps < kSearchBudget; ++steps) {
      const int s = int(steps & 1);
      std::vector<uint32_t> &q = *queues[s];
      if (next[s] == q.size()) return false;  // this side is closed off
      const Tri &t = g_.mesh.stored(q[next[s]++]);
      for (int i = 0; i < 3; ++i) {
        const uint32_t a = t[i], b = t[(i + 1) % 3];
        if (c.has(a) && c.has(b)) continue;  // a cycle edge: the cycle has no chord
        uint32_t fs[2];
        const int n = g_.mesh.edge_faces(a, b, fs);
        for (int j = 0; j < n; ++j) {
          if (reached[1 - s]->has(fs[j])) return true;  // the searches met
          if (reached[s]->has(fs[j])) continue;
          reached[s]->set(fs[j]);
          q.push_back(fs[j]);
        }
      }
    }
    return false;
  }

  // The faces around `corner` from the cycle edge to `from` (starting with face `first` on it)
  // round to the cycle edge to `to`; false if the walk does not get there.
  bool arc(uint32_t corner, uint32_t from, uint32_t to, uint32_t first,
           std::vector<uint32_t> &faces, uint32_t &last) {
    uint32_t f = first, prev = from;
    for (std::size_t steps = 0; steps <= g_.mesh.faces_at(corner).size(); ++steps) {
      faces.push_back(f);
      const uint32_t next = third_vertex(g_.mesh.stored(f), corner, prev);
      if (next == to) {
        last = f;
        return true;
      }
      uint32_t fs[2];
      if (g_.mesh.edge_faces(corner, next, fs) != 2) return false;
      f = fs[0] == f ? fs[1] : fs[0];
      prev = next;
    }
    return false;
  }

  // Removes the faces at the corners on the side of face `first` (on the cycle's first edge),
  // caps the cycle on the other side and patches the hole; or leaves everything as it was.
  bool cut_side(const Cycle &c, uint32_t first) {
    // Walk the side round the cycle: at corner 0 from the first edge round to the last, at the
    // last corner from there round to the one before, and so on back to the face it began with.
    std::vector<uint32_t> side;
    uint32_t f = first;
    for (int s = 0; s < c.n; ++s) {
      const int k = (c.n - s) % c.n;
      if (!arc(c.corners[k], c.corners[(k + 1) % c.n], c.corners[(k + c.n - 1) % c.n], f, side, f))
        return false;
    }
    if (f != first) return false;
    std::sort(side.begin(), side.end());
    side.erase(std::unique(side.begin(), side.end()), side.end());

    std::vector<Tri> removed;
    for (uint32_t g : side) removed.push_back(g_.mesh.oriented(g));
    std::vector<uint32_t> loop;
    if (!outer_loop(removed, c, loop)) return false;
    for (uint32_t g : side) g_.mesh.remove(g);

    // The cap's loop runs along each cycle edge against the face that stays there: the way
    // the removed face `first` ran along the first edge.
    const Tri t = removed[std::lower_bound(side.begin(), side.end(), first) - side.begin()];
    bool forward = false;  // `first` runs corner 0 -> corner 1
    for (int i = 0; i < 3; ++i) forward |= t[i] == c.corners[0] && t[(i + 1) % 3] == c.corners[1];
    std::vector<uint32_t> cap_loop(c.corners.begin(), c.corners.begin() + c.n);
    if (!forward) std::reverse(cap_loop.begin(), cap_loop.end());
    std::vector<Tri> added = smoothest_patch(g_.mesh, g_.points.work, cap_loop);
    if (!added.empty()) {
      const std::vector<Tri> hole = smoothest_patch(g_.mesh, g_.points.work, loop);
      if (!hole.empty()) {
        added.insert(added.end(), hole.begin(), hole.end());
        // The crossing test still runs; the second-layer test would refuse the cap (see top).
        if (g_.add_all_or_none(added, true)) {
          g_.stats.triangles_removed += removed.size();
          g_.stats.triangles_loops += added.size();
          return true;
        }
      }
    }
    for (const Tri &r : removed) g_.add_face(r);  // as it was
    return false;
  }

  // The loop of the hole the faces `removed` (oriented, each at a corner of the cycle) leave:
  // their edges that touch no corner and border no other removed face, in the faces' direction
  // (that of the hole's edges). False unless they form one simple loop through every vertex of
  // the faces but the corners.
  bool outer_loop(const std::vector<Tri> &removed, const Cycle &c, std::vector<uint32_t> &loop) {
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    std::vector<uint32_t> others;  // vertices of the faces but the corners
    for (const Tri &t : removed)
      for (int i = 0; i < 3; ++i) {
        const uint32_t a = t[i], b = t[(i + 1) % 3];
        if (!c.has(a) && !c.has(b)) edges.push_back({a, b});
        if (!c.has(a)) others.push_back(a);
      }
    // An edge both of whose faces go lies inside the hole.
    std::vector<std::pair<uint32_t, uint32_t>> rim;
    for (const auto &[a, b] : edges)
      if (std::find(edges.begin(), edges.end(), std::make_pair(b, a)) == edges.end())
        rim.push_back({a, b});
    if (rim.size() < 3 || rim.size() > kMaxLoop) return false;
    std::sort(rim.begin(), rim.end());
    loop.assign(1, rim[0].first);
    for (std::size_t k = 0; k < rim.size(); ++k) {
      const auto it = std::lower_bound(rim.begin(), rim.end(), std::make_pair(loop.back(), 0u));
      if (it == rim.end() || it->first != loop.back()) return false;
      if (it + 1 != rim.end() && (it + 1)->first == loop.back()) return false;  // a pinch
      if (k + 1 < rim.size()) {
        if (it->second == loop.front()) return false;  // closes before using every edge
        loop.push_back(it->second);
      } else if (it->second != loop.front()) {
        return false;
      }
    }
    // Every vertex of the removed faces must stay in the mesh: on the loop, or a corner.
    std::vector<uint32_t> sorted(loop);
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
    for (uint32_t a : others)
      if (!std::binary_search(sorted.begin(), sorted.end(), a)) return false;
    return true;
  }

  GrowthState &g_;
  // The two-sided search's faces in order, and the faces each side reached (a bit per face).
  std::vector<uint32_t> queue_, other_queue_;
  IndexMarks reached_, other_reached_;
};

// The vertices of the live faces numbered from first_face on, and of the faces around them.
std::vector<uint32_t> vertices_near(const MeshState &mesh, std::size_t first_face) {
  std::vector<uint32_t> at;
  for (uint32_t f = uint32_t(first_face); f < mesh.face_count(); ++f)
    if (mesh.alive(f))
      for (uint32_t v : mesh.stored(f))
        for (uint32_t h : mesh.faces_at(v)) {
          const Tri &t = mesh.stored(h);
          at.insert(at.end(), t.begin(), t.end());
        }
  std::sort(at.begin(), at.end());
  at.erase(std::unique(at.begin(), at.end()), at.end());
  return at;
}

// Cuts each waist found that does not separate the surface; returns how many.
std::size_t cut_waists(GrowthState &g, const std::vector<Cycle> &waists) {
  HandleCutter cutter(g);
  std::size_t cut = 0;
  for (const Cycle &c : waists) cut += cutter.cut(c);
  return cut;
}

}  // namespace

std::size_t cut_thin_handles(GrowthState &g, std::size_t first_face) {
  // The cycles are sought only around the faces the loop module added, and one ring beyond:
  // a bridge becomes a handle when the holes beside it are closed.
  return cut_waists(g, short_cycles(g.mesh, vertices_near(g.mesh, first_face)));
}

std::size_t cut_narrow_tunnels(GrowthState &g, std::size_t first_face) {
  // Sought, like the thin handles, around the loop module's faces: those of the take-in too,
  // which can shorten a waist by putting a point on it.
  return cut_waists(g, TunnelFinder(g).find(vertices_near(g.mesh, first_face)));
}

}  // namespace moa
