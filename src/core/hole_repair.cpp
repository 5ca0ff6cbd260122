// The loop module's repairs, for holes the fill passes could not close: the faces along them
// go and the next round refills the wider hole; the last ones are patched whole with the
// triangulation of their loop that bends the surface least, widened first if need be; pinched
// vertices are opened.
#include <algorithm>
#include <unordered_map>

#include "core/disjoint_sets.hpp"
#include "core/hole_patch.hpp"
#include "core/loop_filler.hpp"

namespace moa {
namespace {

// Longest loop the last-resort patch triangulates (its cost grows with the cube of the length).
constexpr std::size_t kMaxPatchedLoop = 96;
// Rings of faces a hole may lose so that a wider hole can be patched, and the total number of
// rings removed in a run (each costs a pass over the mesh).
constexpr int kMaxRings = 3;
// Rings of stars a hole is widened by at most (patch_after_clearing_stars): each ring leaves
// its vertices to the take-in, which cannot place those standing more than a spacing off the
// patch (at a sharp crease); a third ring closed a few more holes but left seven times the
// points out.
constexpr int kStarRings = 2;
constexpr std::size_t kMaxWidenings = 256;
// A spike in a hole (clear_spike_and_patch): vertices tried, and their most faces.
constexpr std::size_t kSpikeTries = 2;
constexpr std::size_t kMaxSpikeFaces = 6;

// patch_last_holes: the patch may lie close over faces of the hole's own piece (no
// second-layer test) only when the piece holds at least this many times the square of the
// loop's length in faces. A round hole of L edges spans about L^2 / 6 faces' worth of area, so
// the hole is then a small part of a larger surface. On a piece hardly larger than its hole
// (an open patch of a few dozen points whose whole border counts as a hole) the patch would lie
// over the piece itself, a pillow of two layers.
constexpr double kLayerFreePieceFaces = 1.0;

// excise_crossed_and_patch: rounds of growing the ball, and the most faces inside it.
constexpr int kExcisionRounds = 4;
constexpr std::size_t kMaxExcised = 1024;

// V - E + F of the faces, counting the vertices and edges they use. Faces that ring a hole
// make an annulus (0) when the hole and they together make a disk; a handle among them takes
// 2 off, a closed piece among them adds 2.
long euler_characteristic(const std::vector<Tri> &faces) {
  std::vector<uint32_t> vertices;
  std::vector<uint64_t> edges;
  for (const Tri &t : faces)
    for (int i = 0; i < 3; ++i) {
      const uint32_t a = t[i], b = t[(i + 1) % 3];
      vertices.push_back(a);
      edges.push_back(a < b ? hole_edge_key(a, b) : hole_edge_key(b, a));
    }
  std::sort(vertices.begin(), vertices.end());
  std::sort(edges.begin(), edges.end());
  const auto distinct = [](auto &v) {
    return long(std::unique(v.begin(), v.end()) - v.begin());
  };
  return distinct(vertices) - distinct(edges) + long(faces.size());
}

// The centre of the loop's vertices, and the square of the distance from it to the farthest.
struct Ball {
  Vec3 centre;
  double radius2;
};
Ball ball_around(const std::vector<Vec3> &points, const std::vector<uint32_t> &loop) {
  Vec3 centre{};
  for (uint32_t v : loop) centre = centre + points[v];
  centre = centre * (1.0 / double(loop.size()));
  double radius2 = 0;
  for (uint32_t v : loop) radius2 = std::max(radius2, norm2(points[v] - centre));
  return {centre, radius2};
}

}  // namespace

// The loops of the mesh as it is that are holes (tangles' loops never are) short enough to be
// patched whole; pointers into loops_, which the patching leaves as it is.
std::vector<const Loop *> LoopFiller::trace_patchable_holes() {
  collect_hole_edges();
  loops_ = trace_loops();
  classify_and_pool();
  std::vector<const Loop *> holes;
  for (const Loop &loop : loops_)
    if (loop.fillable && loop.vertices.size() <= kMaxPatchedLoop) holes.push_back(&loop);
  return holes;
}

// After every other step of the loop module, holes still open are patched once more as they
// are, the patch allowed edge folds down to a few degrees (TopologyJudge::allow_sharp_folds)
// and, in a piece much larger than the hole, to lie close over other faces. Such a hole sits
// in a crumpled spot (noise, a misregistered overlap, a gap narrower than the spacing) where
// every patch met a fold sharper than edge_fold_angle or a neighbouring layer: a ridge that
// sharp is a lesser fault than the hole. A hole whose patch crosses faces is patched after
// clearing those (excise_crossed_and_patch). Returns the holes closed.
std::size_t LoopFiller::patch_last_holes() {
  std::unordered_map<uint32_t, std::size_t> piece_faces;
  std::size_t closed = 0;
  for (const Loop *hole : trace_patchable_holes()) {
    g_.poll();
    if (!still_open(hole->vertices)) continue;
    if (piece_faces.empty()) piece_faces = faces_per_component();
    const double n = double(hole->vertices.size());
    const bool layers_allowed = double(piece_faces[hole->piece]) >= kLayerFreePieceFaces * n * n;
    g_.judge.allow_sharp_folds(true);
    closed += patch_pieces(hole->vertices, layers_allowed) ||
              excise_crossed_and_patch(hole->vertices, layers_allowed);
    g_.judge.allow_sharp_folds(false);
  }
  return closed;
}

// The last resort: each hole still open is patched at once with the triangulation of its
// loop that bends the surface least (hole_patch.hpp), if every triangle of it passes the
// relaxed judgment. When the faces around the hole fold over it, they go and the wider hole
// is patched instead; if that fails too, they are put back, and all of it is tried again
// without the second-layer test; then after clearing a spike, and after clearing the whole
// stars of the hole's vertices. Returns the holes closed.
std::size_t LoopFiller::patch_open_holes() {
  std::size_t closed = 0, widenings = 0;
  for (const Loop *loop : trace_patchable_holes()) {
    const std::vector<uint32_t> &hole = loop->vertices;
    g_.poll();
    if (!still_open(hole)) continue;  // widening a neighbouring hole changed it
    // At a sharp corner the faces across the crease can lie over a patch in projection
    // without crossing it: when nothing closes the hole with the second-layer test, it is
    // tried again without it (the crossing test still runs).
    bool done = false;
    for (bool layers_allowed : {false, true})
      if (!done) done = patch_or_widen(hole, layers_allowed, widenings);
    if (!done) done = clear_spike_and_patch(hole);
    for (bool layers_allowed : {false, true})
      if (!done) done = patch_after_clearing_stars(hole, layers_allowed, widenings);
    closed += done;
  }
  return closed;
}

// Removes the faces along every hole that stayed open although it was small enough to
// close. Returns the number of faces removed.
std::size_t LoopFiller::widen_open_holes() {
  std::vector<uint32_t> ring;
  for (const auto &kv : hole_loop_) {
    if (!loops_[kv.second].fillable) continue;
    uint32_t from = uint32_t(kv.first >> 32), to = uint32_t(kv.first), fs[2];
    if (g_.mesh.edge_faces(from, to, fs) == 1) ring.push_back(fs[0]);
  }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  // The main piece of the mesh (half its faces or more) is never widened away whole: when all
  // its faces lie along its holes (three points, a tetrahedron's corners), nothing would be
  // left to fill from. A small piece may go: a stray triangle in a hole blocks its filling.
  std::unordered_map<uint32_t, std::size_t> on_ring;
  for (uint32_t f : ring) ++on_ring[g_.mesh.component(f)];
  const std::unordered_map<uint32_t, std::size_t> in_piece = faces_per_component();
  std::size_t faces = 0;
  for (const auto &piece : in_piece) faces += piece.second;
  std::size_t removed = 0;
  for (uint32_t f : ring) {
    const uint32_t piece = g_.mesh.component(f);
    if (on_ring[piece] == in_piece.at(piece) && 2 * in_piece.at(piece) >= faces) continue;
    g_.mesh.remove(f);
    ++removed;
  }
  return removed;
}

// Patches the hole, or else removes up to kMaxRings rings of faces around it and patches the
// wider hole; puts the faces back if that fails too. Widens first without dropping any vertex
// out of the mesh, then, if that fails, freely: a closed surface missing a point beats one
// with a hole.
bool LoopFiller::patch_or_widen(const std::vector<uint32_t> &hole, bool layers_allowed,
                                std::size_t &widenings) {
  return patch_pieces(hole, layers_allowed) ||
         widen_and_patch(hole, Widening::KeepingVertices, kMaxRings, layers_allowed, widenings) ||
         widen_and_patch(hole, Widening::Rims, kMaxRings, layers_allowed, widenings);
}

// At a sharp crease the faces grown from its two sides can overlap in the wedge between them
// without crossing; a face that shares only a corner with the hole, so that no widening by
// rims removes it, then lies across every patch. The last try: every face at the hole's
// vertices goes (up to kStarRings times, from the wider loop each time) and the loop around
// them is patched; the take-in places the vertices left out again. Or all is put back.
bool LoopFiller::patch_after_clearing_stars(const std::vector<uint32_t> &hole, bool layers_allowed,
                                            std::size_t &widenings) {
  return widen_and_patch(hole, Widening::Stars, kStarRings, layers_allowed, widenings);
}

// Widens the hole ring by ring (at most `rings`, within the run's budget of widenings) and
// patches the wider loop after each ring; on failure puts every removed face back.
bool LoopFiller::widen_and_patch(const std::vector<uint32_t> &hole, Widening widening, int rings,
                                 bool layers_allowed, std::size_t &widenings) {
  std::vector<uint32_t> loop = hole;
  std::vector<Tri> removed;
  for (int ring = 0; ring < rings && widenings < kMaxWidenings; ++ring) {
    ++widenings;
    const bool keep_vertices = widening == Widening::KeepingVertices;
    const std::vector<Tri> ring_faces =
        widening == Widening::Stars ? remove_stars(loop) : remove_rim(loop, keep_vertices);
    removed.insert(removed.end(), ring_faces.begin(), ring_faces.end());
    if (widening == Widening::Stars) {
      // The old loop's vertices have no faces left: the new loop runs through the stars' rims.
      std::vector<uint32_t> corners;
      for (const Tri &t : ring_faces) corners.insert(corners.end(), t.begin(), t.end());
      loop = loop_around(corners, ring_faces);
    } else {
      loop = loop_around(loop, ring_faces);
    }
    if (ring_faces.empty() || loop.empty() || loop.size() > kMaxPatchedLoop) break;
    if (patch_pieces(loop, layers_allowed)) {
      g_.stats.triangles_removed += removed.size();
      return true;
    }
  }
  for (const Tri &t : removed) g_.add_face(t);  // as it was before
  return false;
}

// A vertex inside the hole whose few faces reach out to points beyond it (a spike grown from
// a point that lay in the hole) can pierce every patch of the hole. Its faces go, the hole
// they leave and then the first one are patched, and the take-in places the point again;
// or, if a patch is refused, everything is put back. Tried for the two vertices nearest the
// hole's centre, within the hole's radius of it.
bool LoopFiller::clear_spike_and_patch(const std::vector<uint32_t> &hole) {
  const auto &w = g_.points.work;
  const Ball ball = ball_around(w, hole);
  const Vec3 centre = ball.centre;
  const double radius2 = ball.radius2;
  std::vector<uint32_t> inside;
  for (uint32_t v : hole) {
    const uint32_t *nb = g_.nb.of(v);
    for (unsigned j = 0; j < g_.nb.k; ++j) {
      const uint32_t x = nb[j];
      if (g_.mesh.is_used(x) && norm2(w[x] - centre) < radius2 &&
          std::find(hole.begin(), hole.end(), x) == hole.end())
        inside.push_back(x);
    }
  }
  auto nearer = [&](uint32_t a, uint32_t b) {
    const double da = norm2(w[a] - centre), db = norm2(w[b] - centre);
    return da != db ? da < db : a < b;
  };
  std::sort(inside.begin(), inside.end(), nearer);
  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
  if (inside.size() > kSpikeTries) inside.resize(kSpikeTries);
  for (uint32_t spike : inside) {
    const FacesAround around = g_.mesh.faces_at(spike);
    if (around.size() > kMaxSpikeFaces) continue;
    const std::vector<uint32_t> faces(around.begin(), around.end());
    std::vector<Tri> fan;
    std::vector<uint32_t> link;
    for (uint32_t f : faces) {
      fan.push_back(g_.mesh.oriented(f));
      for (uint32_t x : g_.mesh.stored(f))
        if (x != spike) link.push_back(x);
    }
    for (uint32_t f : faces) g_.mesh.remove(f);
    const std::size_t faces_before = g_.mesh.face_count(), counted = g_.stats.triangles_loops;
    const std::vector<uint32_t> gap = loop_around(link, fan);
    if (!gap.empty() && patch_pieces(gap, true) && patch_pieces(hole, true)) {
      g_.stats.triangles_removed += fan.size();
      return true;
    }
    for (uint32_t f = uint32_t(faces_before); f < g_.mesh.face_count(); ++f)
      if (g_.mesh.alive(f)) g_.mesh.remove(f);
    g_.stats.triangles_loops = counted;
    for (const Tri &t : fan) g_.add_face(t);  // as it was
  }
  return false;
}

// A loop through a vertex twice (a pinch) is two holes meeting there: each is patched on
// its own. All pieces or none.
bool LoopFiller::patch_pieces(const std::vector<uint32_t> &loop, bool layers_allowed) {
  std::vector<std::vector<uint32_t>> pieces;
  std::vector<uint32_t> rest = loop;
  std::unordered_map<uint32_t, std::size_t> first;
  for (std::size_t j = 0; j < rest.size(); ++j) {
    auto [it, fresh] = first.emplace(rest[j], j);
    if (fresh) continue;
    // rest[i .. j) is a closed piece: cut it out and go on from its start.
    const std::size_t i = it->second;
    pieces.emplace_back(rest.begin() + std::ptrdiff_t(i), rest.begin() + std::ptrdiff_t(j));
    rest.erase(rest.begin() + std::ptrdiff_t(i) + 1, rest.begin() + std::ptrdiff_t(j) + 1);
    first.clear();
    for (std::size_t k = 0; k <= i; ++k) first.emplace(rest[k], k);
    j = i;
  }
  pieces.push_back(rest);
  const std::size_t faces_before = g_.mesh.face_count(), counted = g_.stats.triangles_loops;
  std::size_t done = 0;
  for (const auto &piece : pieces) {
    if (piece.size() < 3 || !patch(piece, layers_allowed)) break;
    ++done;
  }
  if (done == pieces.size()) return true;
  for (uint32_t f = uint32_t(faces_before); f < g_.mesh.face_count(); ++f)
    if (g_.mesh.alive(f)) g_.mesh.remove(f);
  g_.stats.triangles_loops = counted;
  return false;
}

// Adds the smoothest patch of the loop if all of it passes the judgment; else adds nothing.
bool LoopFiller::patch(const std::vector<uint32_t> &loop, bool layers_allowed) {
  // A broken trace is no hole: smoothest_patch wants one face on every edge of the loop.
  if (loop.size() > kMaxPatchedLoop) return false;
  const std::vector<Tri> tris = smoothest_patch(g_.mesh, g_.points.work, loop);
  if (tris.empty() || !g_.add_all_or_none(tris, layers_allowed)) return false;
  g_.stats.triangles_loops += tris.size();
  return true;
}

// At a crease sharper than a right angle the faces grown from its two sides can fold over
// the hole between them: the hole's loop then rings faces that every patch of it crosses,
// and no widening along the loop reaches them. The ball centred on the hole that holds its
// loop and the faces its patch crosses is cleared (every face with a corner in it goes) and
// the loop around the cleared disk is patched instead, the ball grown again while that patch
// still crosses faces. Only if the cleared faces and the hole made a disk, whose border is
// one loop: a handle or a separate piece in the ball is never taken away. Otherwise, or if no
// patch passes, everything is put back. The points left inside go to the take-in again (see
// fill_loops): a closed surface short of a few points beats a hole.
bool LoopFiller::excise_crossed_and_patch(const std::vector<uint32_t> &hole, bool layers_allowed) {
  const auto &w = g_.points.work;
  const Ball ball = ball_around(w, hole);
  const Vec3 centre = ball.centre;
  double radius2 = ball.radius2;
  std::vector<uint32_t> loop = hole;
  std::vector<Tri> removed;
  std::vector<uint32_t> faces;
  for (int round = 0; round < kExcisionRounds; ++round) {
    const std::vector<Tri> patch = smoothest_patch(g_.mesh, w, loop);
    bool crossed = false;
    for (const Tri &t : patch) {
      faces.clear();
      g_.crossings.faces_crossed(t, g_.mesh, faces);
      for (uint32_t f : faces) {
        crossed = true;
        for (uint32_t v : g_.mesh.stored(f)) radius2 = std::max(radius2, norm2(w[v] - centre));
      }
    }
    if (!crossed) break;
    const double radius = std::sqrt(radius2);
    const Vec3 reach{radius, radius, radius};
    faces.clear();
    g_.crossings.faces_in_box(centre - reach, centre + reach, g_.mesh, faces);
    faces.erase(std::remove_if(faces.begin(), faces.end(),
                               [&](uint32_t f) {
                                 const Tri &q = g_.mesh.stored(f);
                                 return std::none_of(q.begin(), q.end(), [&](uint32_t v) {
                                   return norm2(w[v] - centre) <= radius2;
                                 });
                               }),
                faces.end());
    if (faces.size() > kMaxExcised) break;
    const std::vector<Tri> gone = remove_faces(faces, false);
    removed.insert(removed.end(), gone.begin(), gone.end());
    std::vector<uint32_t> corners(loop);
    for (const Tri &t : removed) corners.insert(corners.end(), t.begin(), t.end());
    loop = single_loop_around(corners);
    if (loop.empty() || loop.size() > kMaxPatchedLoop || euler_characteristic(removed) != 0) break;
    if (patch_pieces(loop, layers_allowed)) {
      g_.stats.triangles_removed += removed.size();
      const std::size_t before = excised_points_.size();
      for (const Tri &t : removed)
        for (uint32_t v : t)
          if (!g_.mesh.is_used(v)) excised_points_.push_back(v);
      const auto fresh = excised_points_.begin() + std::ptrdiff_t(before);
      std::sort(fresh, excised_points_.end());
      excised_points_.erase(std::unique(fresh, excised_points_.end()), excised_points_.end());
      return true;
    }
  }
  for (const Tri &t : removed) g_.add_face(t);  // as it was before
  return false;
}

// The loop of boundary edges through the given vertices, if the faces around them have
// boundary edges in that one loop and in no other; nothing otherwise.
std::vector<uint32_t> LoopFiller::single_loop_around(std::vector<uint32_t> corners) {
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  const std::size_t edges = open_edges_around(corners);
  std::vector<Loop> loops = trace_loops(&corners);
  if (loops.size() != 1 || loops[0].vertices.size() != edges) return {};
  return std::move(loops[0].vertices);
}

// Puts the boundary edges of the faces around the given vertices in out_, each reversed (as
// collect_hole_edges does), for trace_loops; returns how many.
std::size_t LoopFiller::open_edges_around(const std::vector<uint32_t> &vertices) {
  std::vector<uint32_t> faces;
  for (uint32_t v : vertices) {
    const FacesAround around = g_.mesh.faces_at(v);
    faces.insert(faces.end(), around.begin(), around.end());
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  out_.clear();
  std::size_t edges = 0;
  for (uint32_t f : faces) {
    if (!g_.mesh.alive(f)) continue;
    const Tri t = g_.mesh.oriented(f);
    for (int i = 0; i < 3; ++i) {
      uint32_t a = t[i], b = t[(i + 1) % 3], fs[2];
      if (g_.mesh.edge_faces(a, b, fs) == 1) {
        out_[b].push_back(a);
        ++edges;
      }
    }
  }
  return edges;
}

// Removes every face at the loop's vertices; returns them as they were oriented.
std::vector<Tri> LoopFiller::remove_stars(const std::vector<uint32_t> &loop) {
  std::vector<uint32_t> faces;
  for (uint32_t v : loop)
    for (uint32_t f : g_.mesh.faces_at(v)) faces.push_back(f);
  return remove_faces(faces, false);
}

// Removes the faces on the loop's edges; returns them as they were oriented.
std::vector<Tri> LoopFiller::remove_rim(const std::vector<uint32_t> &loop, bool keep_vertices) {
  std::vector<uint32_t> faces;
  const std::size_t n = loop.size();
  for (std::size_t j = 0; j < n; ++j) {
    uint32_t fs[2];
    if (g_.mesh.edge_faces(loop[j], loop[(j + 1) % n], fs) == 1) faces.push_back(fs[0]);
  }
  return remove_faces(faces, keep_vertices);
}

// Removes the faces listed (a face may be listed twice), in index order; returns them as
// they were oriented. A vertex whose last face one of them is would drop out of the mesh
// (the patch of the wider hole spans only the loop's vertices): with keep_vertices, that
// face stays.
std::vector<Tri> LoopFiller::remove_faces(std::vector<uint32_t> faces, bool keep_vertices) {
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  std::vector<Tri> removed;
  for (uint32_t f : faces) {
    const Tri t = g_.mesh.oriented(f);
    if (keep_vertices) {
      bool last = false;
      for (uint32_t v : t) last |= g_.mesh.faces_at(v).size() == 1;
      if (last) continue;
    }
    removed.push_back(t);
    g_.mesh.remove(f);
  }
  return removed;
}

// The loop that now runs through most of the given loop's vertices, after remove_rim took
// the faces `rim`: traced from the faces around the rim's corners alone, which hold every
// edge of the wider hole, so the cost stays local.
std::vector<uint32_t> LoopFiller::loop_around(const std::vector<uint32_t> &old,
                                              const std::vector<Tri> &rim) {
  std::vector<uint32_t> corners;
  for (const Tri &t : rim) corners.insert(corners.end(), t.begin(), t.end());
  open_edges_around(corners);
  std::vector<Loop> loops = trace_loops(&old);
  std::vector<uint32_t> sorted(old);
  std::sort(sorted.begin(), sorted.end());
  std::size_t best = 0, best_shared = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    std::size_t shared = 0;
    for (uint32_t v : loops[l].vertices)
      shared += std::binary_search(sorted.begin(), sorted.end(), v);
    if (shared > best_shared) {
      best_shared = shared;
      best = l;
    }
  }
  if (best_shared == 0) return {};
  return std::move(loops[best].vertices);
}

// Removes, at every vertex whose faces form several fans, the faces of all fans but the
// largest, opening one hole where a loop could not be closed around a pinch.
std::size_t open_pinched_vertices(GrowthState &g) {
  std::size_t removed = 0;
  std::vector<uint32_t> faces;
  DisjointSets group;
  for (uint32_t v = 0; v < g.points.size(); ++v) {
    if (g.mesh.fan_count(v) < 2) continue;
    const FacesAround around = g.mesh.faces_at(v);
    faces.assign(around.begin(), around.end());
    const std::size_t n = faces.size();
    group.reset(n);
    auto root = [&](uint32_t x) { return group.root(x); };
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        const Tri &a = g.mesh.stored(faces[i]), &b = g.mesh.stored(faces[j]);
        int shared = 0;
        for (uint32_t x : a) shared += (x == b[0] || x == b[1] || x == b[2]);
        if (shared >= 2) group.join(uint32_t(i), uint32_t(j));
      }
    std::vector<uint32_t> size(n, 0);
    for (std::size_t i = 0; i < n; ++i) ++size[root(uint32_t(i))];
    uint32_t best = root(0);
    for (std::size_t i = 0; i < n; ++i)
      if (size[root(uint32_t(i))] > size[best]) best = root(uint32_t(i));
    for (std::size_t i = 0; i < n; ++i)
      if (root(uint32_t(i)) != best) {
        g.mesh.remove(faces[i]);
        ++removed;
      }
  }
  return removed;
}

}  // namespace moa
