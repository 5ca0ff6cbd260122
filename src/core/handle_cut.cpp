// Thin handles. Where a sample is too sparse to tell a narrow gap from a fold (between fingers,
// at the corner of a mouth), Algorithm 1 can bridge the gap with a few triangles, and the loop
// module then closes the holes beside the bridge: the surface gains a handle whose waist is a
// cycle of three edges that bounds no face. A handle of the sampled surface itself is many
// spacings round, so such a cycle, when it does not separate the surface, marks a bridge. The
// bridge is cut there: the faces at the cycle's corners on one side go, the cycle is capped by
// one triangle on the other side, and the hole left is patched (hole_patch.hpp). All of it
// passes the judgment, or nothing changes.
#include <algorithm>
#include <tuple>
#include <vector>

#include "core/growth_state.hpp"
#include "core/hole_patch.hpp"

namespace moa {
namespace {

// Faces searched for a way from one side of a cycle to the other: a bridge's way round is
// short, and a cycle without one within this many faces is left alone.
constexpr std::size_t kSearchBudget = 200000;
// Longest loop around the removed faces that is patched (the patch costs its cube).
constexpr std::size_t kMaxLoop = 64;

struct Cycle {
  uint32_t u, v, w;
};

// Cycles of three edges with two faces each that are not the edges of one face, through the
// given vertices: their neighbours are marked, and the neighbours of each neighbour looked up.
// Each cycle is listed once, its corners in increasing order.
std::vector<Cycle> three_edge_cycles(const MeshState &mesh, const std::vector<uint32_t> &at,
                                     std::size_t vertex_count) {
  std::vector<Cycle> cycles;
  std::vector<uint32_t> mark(vertex_count, kNone), ring;  // u on the neighbours of u
  for (uint32_t u : at) {
    ring.clear();
    for (uint32_t f : mesh.faces_at(u))
      for (uint32_t x : mesh.stored(f))
        if (x != u && mark[x] != u) {
          mark[x] = u;
          ring.push_back(x);
        }
    for (uint32_t v : ring)
      for (uint32_t h : mesh.faces_at(v)) {
        // Each edge v-w once: from the face that runs v -> w in stored order.
        const Tri &t = mesh.stored(h);
        const int i = int(std::find(t.begin(), t.end(), v) - t.begin());
        const uint32_t w = t[(i + 1) % 3];
        if (mark[w] != u || std::count(t.begin(), t.end(), u) != 0) continue;
        uint32_t fs[2];
        if (mesh.edge_faces(u, v, fs) != 2 || mesh.edge_faces(v, w, fs) != 2 ||
            mesh.edge_faces(w, u, fs) != 2)
          continue;
        bool face = false;  // u-v-w itself
        for (uint32_t g : mesh.faces_at(u)) {
          const Tri &s = mesh.stored(g);
          face |= std::count(s.begin(), s.end(), v) + std::count(s.begin(), s.end(), w) == 2;
        }
        if (face) continue;
        uint32_t c[3] = {u, v, w};
        std::sort(c, c + 3);
        cycles.push_back({c[0], c[1], c[2]});
      }
  }
  std::sort(cycles.begin(), cycles.end(), [](const Cycle &a, const Cycle &b) {
    return std::tie(a.u, a.v, a.w) < std::tie(b.u, b.v, b.w);
  });
  cycles.erase(std::unique(cycles.begin(), cycles.end(),
                           [](const Cycle &a, const Cycle &b) {
                             return a.u == b.u && a.v == b.v && a.w == b.w;
                           }),
               cycles.end());
  return cycles;
}

class HandleCutter {
 public:
  explicit HandleCutter(GrowthState &g) : g_(g) {}

  bool cut(const Cycle &c) {
    const uint32_t corners[3] = {c.u, c.v, c.w};
    uint32_t on_edge[3][2];  // the two faces on each edge of the cycle
    for (int i = 0; i < 3; ++i)
      if (g_.mesh.edge_faces(corners[i], corners[(i + 1) % 3], on_edge[i]) != 2) return false;
    // A face u-v-w may have been added since the cycles were listed.
    for (uint32_t f : g_.mesh.faces_at(c.u)) {
      const Tri &t = g_.mesh.stored(f);
      if (std::count(t.begin(), t.end(), c.v) + std::count(t.begin(), t.end(), c.w) == 2)
        return false;
    }
    if (!goes_round(c, on_edge[0][0], on_edge[0][1])) return false;  // it separates
    for (int side = 0; side < 2; ++side)
      if (cut_side(corners, on_edge[0][side])) return true;
    return false;
  }

 private:
  // Whether face `to` can be reached from face `from` without crossing the cycle's edges.
  // Searched from both at once, a face at a time from each: a cycle that separates the
  // surface stops the search once the smaller side is exhausted (often the few faces around a
  // point the loop module took in), and a bridge's way round is found from both ends.
  bool goes_round(const Cycle &c, uint32_t from, uint32_t to) {
    auto corner = [&](uint32_t x) { return x == c.u || x == c.v || x == c.w; };
    if (mark_.size() < g_.mesh.face_count()) mark_.resize(g_.mesh.face_count(), 0);
    stamp_ += 2;  // stamp_ - 1 marks the faces reached from `from`, stamp_ those from `to`
    const uint32_t stamps[2] = {stamp_ - 1, stamp_};
    mark_[from] = stamps[0];
    mark_[to] = stamps[1];
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
        if (corner(a) && corner(b)) continue;
        uint32_t fs[2];
        const int n = g_.mesh.edge_faces(a, b, fs);
        for (int j = 0; j < n; ++j) {
          if (mark_[fs[j]] == stamps[1 - s]) return true;  // the searches met
          if (mark_[fs[j]] == stamps[s]) continue;
          mark_[fs[j]] = stamps[s];
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

  // Removes the faces at the corners on the side of face `first` (on edge u-v), caps the cycle
  // on the other side and patches the hole; or leaves everything as it was.
  bool cut_side(const uint32_t (&corners)[3], uint32_t first) {
    // Walk the side round the cycle: from u-v at u to w, from there at w to v, and at v back
    // to the face the walk began with.
    std::vector<uint32_t> side;
    uint32_t at_uw, at_wv, at_vu;
    if (!arc(corners[0], corners[1], corners[2], first, side, at_uw)) return false;
    if (!arc(corners[2], corners[0], corners[1], at_uw, side, at_wv)) return false;
    if (!arc(corners[1], corners[2], corners[0], at_wv, side, at_vu) || at_vu != first)
      return false;
    std::sort(side.begin(), side.end());
    side.erase(std::unique(side.begin(), side.end()), side.end());

    std::vector<Tri> removed;
    for (uint32_t f : side) removed.push_back(g_.mesh.oriented(f));
    std::vector<uint32_t> loop;
    if (!outer_loop(removed, corners, loop)) return false;

    // The cap runs along u-v against the face that stays there.
    uint32_t fs[2];
    g_.mesh.edge_faces(corners[0], corners[1], fs);
    const Tri kept = g_.mesh.oriented(fs[0] == first ? fs[1] : fs[0]);
    bool forward = false;  // kept runs u -> v
    for (int i = 0; i < 3; ++i) forward |= kept[i] == corners[0] && kept[(i + 1) % 3] == corners[1];
    const Tri cap = forward ? Tri{corners[1], corners[0], corners[2]}
                            : Tri{corners[0], corners[1], corners[2]};

    const auto &w = g_.points.work;
    std::vector<Vec3> rim(loop.size());
    for (std::size_t j = 0; j < loop.size(); ++j) {
      const uint32_t a = loop[j], b = loop[(j + 1) % loop.size()];
      g_.mesh.edge_faces(a, b, fs);
      const bool first_removed = std::binary_search(side.begin(), side.end(), fs[0]);
      const Tri t = g_.mesh.oriented(first_removed ? fs[1] : fs[0]);
      rim[j] = normalized(cross(w[t[1]] - w[t[0]], w[t[2]] - w[t[0]]));
    }
    for (uint32_t f : side) g_.mesh.remove(f);
    std::vector<Tri> added = smoothest_patch(w, loop, rim, [this](uint32_t a, uint32_t b) {
      uint32_t gs[2];
      return g_.mesh.edge_faces(a, b, gs) > 0;
    });
    if (!added.empty()) {
      added.insert(added.begin(), cap);
      if (g_.add_all_or_none(added)) {
        g_.stats.triangles_removed += removed.size();
        g_.stats.triangles_loops += added.size();
        return true;
      }
    }
    for (const Tri &t : removed) g_.add_face(t);  // as it was
    return false;
  }

  // The loop of the hole the faces `removed` (oriented, each at a corner of the cycle) leave:
  // their edges that touch no corner and border no other removed face, in the faces' direction
  // (that of the hole's edges). False unless they form one simple loop through every vertex of
  // the faces but the corners.
  bool outer_loop(const std::vector<Tri> &removed, const uint32_t (&corners)[3],
                  std::vector<uint32_t> &loop) {
    auto corner = [&](uint32_t x) { return x == corners[0] || x == corners[1] || x == corners[2]; };
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    std::vector<uint32_t> others;  // vertices of the faces but the corners
    for (const Tri &t : removed)
      for (int i = 0; i < 3; ++i) {
        const uint32_t a = t[i], b = t[(i + 1) % 3];
        if (!corner(a) && !corner(b)) edges.push_back({a, b});
        if (!corner(a)) others.push_back(a);
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
  std::vector<uint32_t> queue_, other_queue_, mark_;  // the search's faces, its stamps
  uint32_t stamp_ = 0;
};

}  // namespace

std::size_t cut_thin_handles(GrowthState &g, std::size_t first_face) {
  // The cycles are sought only around the faces the loop module added, and one ring beyond:
  // a bridge becomes a handle when the holes beside it are closed.
  std::vector<uint32_t> at;
  for (uint32_t f = uint32_t(first_face); f < g.mesh.face_count(); ++f)
    if (g.mesh.alive(f))
      for (uint32_t v : g.mesh.stored(f))
        for (uint32_t h : g.mesh.faces_at(v)) {
          const Tri &t = g.mesh.stored(h);
          at.insert(at.end(), t.begin(), t.end());
        }
  std::sort(at.begin(), at.end());
  at.erase(std::unique(at.begin(), at.end()), at.end());
  const std::vector<Cycle> cycles = three_edge_cycles(g.mesh, at, g.points.size());
  HandleCutter cutter(g);
  std::size_t cut = 0;
  for (const Cycle &c : cycles) cut += cutter.cut(c);
  return cut;
}

}  // namespace moa
