// Thin handles. Where a sample is too sparse to tell a narrow gap from a fold (between fingers,
// at the corner of a mouth), Algorithm 1 can bridge the gap with a few triangles, and the loop
// module then closes the holes beside the bridge: the surface gains a handle whose waist is a
// cycle of three or four edges that bounds no face and has no chord. A handle of the sampled
// surface itself is many spacings round, so such a cycle, when it does not separate the
// surface, marks a bridge. The bridge is cut there: the faces at the cycle's corners on one side
// go, the cycle is capped on the other side, and the hole left is patched (both by
// hole_patch.hpp). All of it passes the judgment but its test for a second layer (a bridge is
// a flattened tube, so its cap lies close over the faces beside it), or nothing changes.
#include <algorithm>
#include <array>
#include <tuple>
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

// A waist: its corners in order (three or four).
struct Cycle {
  std::array<uint32_t, 4> corners{kNone, kNone, kNone, kNone};
  int n = 0;
  bool has(uint32_t x) const {
    return std::find(corners.begin(), corners.begin() + n, x) != corners.begin() + n;
  }
  bool operator<(const Cycle &o) const { return std::tie(n, corners) < std::tie(o.n, o.corners); }
  bool operator==(const Cycle &o) const { return n == o.n && corners == o.corners; }
};

// The cycle with these corners, in a form that lists each cycle once: rotated to start at its
// lowest corner, running toward the lower of that corner's two neighbours.
Cycle canonical(std::array<uint32_t, 4> c, int n) {
  std::rotate(c.begin(), std::min_element(c.begin(), c.begin() + n), c.begin() + n);
  if (c[n - 1] < c[1]) std::reverse(c.begin() + 1, c.begin() + n);
  Cycle cycle;
  cycle.corners = c;
  cycle.n = n;
  return cycle;
}

// Whether every edge of the cycle has two faces.
bool edges_full(const MeshState &mesh, const std::array<uint32_t, 4> &c, int n) {
  for (int i = 0; i < n; ++i) {
    uint32_t fs[2];
    if (mesh.edge_faces(c[i], c[(i + 1) % n], fs) != 2) return false;
  }
  return true;
}

// Cycles of three edges that are not one face's, and of four edges without a chord, all edges
// with two faces, through the given vertices. From each vertex u: a three-edge cycle joins two
// of its neighbours; a four-edge cycle runs through two of them to a vertex x two steps away.
std::vector<Cycle> short_cycles(const MeshState &mesh, const std::vector<uint32_t> &at) {
  std::vector<Cycle> cycles;
  IndexMarks near, second;  // the neighbours of u, and the vertices two steps from it
  std::vector<uint32_t> ring, ring_v, far, common;
  auto neighbours = [&](uint32_t v, std::vector<uint32_t> &out) {
    out.clear();
    for (uint32_t f : mesh.faces_at(v))
      for (uint32_t x : mesh.stored(f))
        if (x != v && std::find(out.begin(), out.end(), x) == out.end()) out.push_back(x);
  };
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
          const std::array<uint32_t, 4> c{u, v, x, kNone};
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
      for (std::size_t i = 0; i < common.size(); ++i)
        for (std::size_t j = i + 1; j < common.size(); ++j) {
          uint32_t fs[2];
          if (mesh.edge_faces(common[i], common[j], fs) > 0) continue;  // a chord
          const std::array<uint32_t, 4> c{u, common[i], x, common[j]};
          if (edges_full(mesh, c, 4)) cycles.push_back(canonical(c, 4));
        }
    }
  }
  std::sort(cycles.begin(), cycles.end());
  cycles.erase(std::unique(cycles.begin(), cycles.end()), cycles.end());
  return cycles;
}

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
  const std::vector<Cycle> cycles = short_cycles(g.mesh, at);
  HandleCutter cutter(g);
  std::size_t cut = 0;
  for (const Cycle &c : cycles) cut += cutter.cut(c);
  return cut;
}

}  // namespace moa
