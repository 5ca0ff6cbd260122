// Algorithm 2 of the paper (§3.5.2), the loop module: the boundary loops Algorithm 1 left are
// traced (loop_tracing.cpp), and each loop small enough to be a hole rather than a border is
// filled by MOA among its own vertices: its shortest segment first, the maximum opposite loop
// vertex that passes the judgment, the loop splitting or shrinking as triangles are added
// (Fig. 10). Points Algorithm 1 left out next to a loop join its candidates, so the filling
// takes them in. fill_loops, at the end, runs the stage's steps in order.
#include "core/loop_filler.hpp"

#include <algorithm>
#include <cmath>

#include "core/cut_cap.hpp"
#include "core/disjoint_sets.hpp"

namespace moa {
namespace {

// Largest number of loop vertices ranked for one segment: the nearest ones to its midpoint.
constexpr std::size_t kMaxLoopCandidates = 24;
// Candidate lists longer than this are searched through the k-NN graph instead of scanned.
constexpr std::size_t kMaxScannedPool = 128;
// Fill passes per round: one with the whole judgment, then two that relax its local-plane and
// fan tests. A second strict pass added 29 triangles in all on building.ply (for 3 s of 22) and
// changed the result of one of 87 other clouds, so there is none.
constexpr int kPasses = 3;
constexpr int kStrictPasses = 1;
// Longest loop capped so (the cost of clipping its ears grows with the square of its length).
constexpr std::size_t kMaxCappedLoop = 8192;
// A piece of the mesh that fills a volume instead of lining a surface (random points in a cube,
// clutter beside a scanned object): Algorithm 1's triangles there meet in several fans at over
// this share of the vertices the piece uses (66 % on random points in a cube, 53-64 % on noisy
// points along a line or in small blobs; at most 18 % on the pieces of 50 vertices or more
// among 346 clouds of surfaces, noisy, anisotropic and scanned ones included). Filling such a
// tangle only builds it again: opening the pinches after the first fill took 61 % of the faces
// away, and the rounds, patches and take-in added and removed about five faces per point, in
// time growing faster than the cloud (526 s at 200,000 random points in a cube).
constexpr double kTangledVertices = 0.5;

// A region of a piece that fills a volume (clutter attached to a scanned surface, which makes
// one piece with it): hot vertices, where over kHotShare of the used points among the vertex
// and its kHotNeighbors nearest carry faces in several fans, joined through those
// neighbour lists, kTangledRegion or more of them. In a volume about two thirds of the
// vertices are pinched (see kTangledVertices): the clutter attached to a unit sphere of 10,000
// to 40,000 points makes one region of 1,972 to 24,966 vertices (3,000 to 34,000 random
// points in a box or a shell touching the sphere). The patches of noisy surfaces hold at most
// 472 (Gaussian noise of 1 % of the diagonal on 20,000 and 100,000 points of bunny, fandisk
// and homer, and of 0.5 % on 300,000); at a share of one half, one on bunny's 300,000 passed
// 2,000. The loop module spent about 1.5 ms per clutter point on fills that the next round
// took apart again.
constexpr unsigned kHotNeighbors = 20;
constexpr double kHotShare = 0.6;
constexpr uint32_t kTangledRegion = 1000;

// A vertex whose faces meet in several fans.
bool pinched(const MeshState &mesh, uint32_t v) { return mesh.fan_count(v) >= 2; }

// Marks, in `tangled`, the vertices of the regions of kTangledRegion or more hot vertices and
// the neighbours of those. Returns whether there is one.
bool mark_tangled_regions(const GrowthState &g, std::vector<uint8_t> &tangled) {
  const uint32_t n = uint32_t(g.points.size());
  const unsigned k = std::min(kHotNeighbors, g.nb.k);
  std::vector<uint8_t> hot(n, 0);
  for (uint32_t v = 0; v < n; ++v) {
    if (!g.mesh.is_used(v) || tangled[v]) continue;
    unsigned among = 1, count = pinched(g.mesh, v);
    const uint32_t *nb = g.nb.of(v);
    for (unsigned j = 0; j < k; ++j) {
      among += g.mesh.is_used(nb[j]);
      count += pinched(g.mesh, nb[j]);
    }
    hot[v] = double(count) > kHotShare * double(among);
  }
  DisjointSets regions(n);
  for (uint32_t v = 0; v < n; ++v) {
    if (!hot[v]) continue;
    const uint32_t *nb = g.nb.of(v);
    for (unsigned j = 0; j < k; ++j)
      if (hot[nb[j]]) regions.join(v, nb[j]);
  }
  std::vector<uint32_t> size(n, 0);
  for (uint32_t v = 0; v < n; ++v)
    if (hot[v]) ++size[regions.root(v)];
  bool any = false;
  for (uint32_t v = 0; v < n; ++v) {
    if (!hot[v] || size[regions.root(v)] < kTangledRegion) continue;
    any = true;
    tangled[v] = 1;
    const uint32_t *nb = g.nb.of(v);
    for (unsigned j = 0; j < k; ++j) tangled[nb[j]] |= g.mesh.is_used(nb[j]);
  }
  return any;
}

// Marks the vertices of the pieces (joined through shared vertices) over kTangledVertices of
// whose vertices carry faces in several fans, and of the tangled regions of the other pieces
// (mark_tangled_regions). A piece, not the whole mesh: clutter beside a surface is a tangle of
// its own (a sphere beside random points in a cube: 67 % of the cube's vertices, none of the
// sphere's); and a region, not a vertex's own neighbourhood alone: a noisy surface has small
// patches where most vertices are pinched. Not in a cloud of a few dozen points, whose first
// faces, grown from lists that reach round the object, meet in several fans at most vertices:
// 20 random points on a sphere were all marked, no hole of theirs was filled, and the widening
// and the dropping of stray pieces left 1 triangle.
void mark_tangles(GrowthState &g) {
  const uint32_t n = uint32_t(g.points.size());
  g.tangled.clear();
  if (lists_hold_half(g.nb, n)) return;
  std::vector<uint8_t> tangled(n, 0);
  bool any = false;
  {  // the pieces' arrays go before the regions' are made
    const Pieces pieces(g.mesh, n);
    std::vector<uint32_t> used(n, 0), pinched_in(n, 0);  // by piece
    for (uint32_t v = 0; v < n; ++v)
      if (g.mesh.is_used(v)) {
        const uint32_t r = pieces.of_vertex(v);
        ++used[r];
        pinched_in[r] += pinched(g.mesh, v);
      }
    for (uint32_t v = 0; v < n; ++v)
      if (g.mesh.is_used(v)) {
        const uint32_t r = pieces.of_vertex(v);
        tangled[v] = double(pinched_in[r]) > kTangledVertices * double(used[r]);
        any |= tangled[v] != 0;
      }
  }
  any |= mark_tangled_regions(g, tangled);
  if (any) g.tangled = std::move(tangled);
}

}  // namespace

// One round: the loops traced and classified, the flat cuts capped, then the fill passes, the
// last ones with the local-plane tests relaxed.
void LoopFiller::run(const std::function<void(double)> &tick) {
  collect_hole_edges();
  loops_ = trace_loops();
  if (g_.stats.boundary_loops_before == 0) {  // the first round sees Algorithm 1's borders
    g_.stats.boundary_loops_before = loops_.size();
    for (const Loop &loop : loops_) g_.stats.boundary_edges_before += loop.vertices.size();
  }
  classify_and_pool();
  cap_flat_cuts();
  for (int pass = 0; pass < kPasses; ++pass) {
    bool relaxed = pass >= kStrictPasses;
    std::size_t added = fill_pass(relaxed);
    tick(double(pass + 1) / kPasses);
    if (added == 0 && relaxed) break;
  }
}

// The last try, after the take-in: a hole still open whose closing needs an edge of a right
// angle or sharper. The fill passes take their apexes only beyond the plane through the
// segment square to the face on it, so the faces of a box, a pyramid or a prism sampled at
// their corners alone never met (CGAL's advancing front closes them). This round takes
// them only from behind that plane, where the judgment's edge-fold test still keeps them
// off the face itself; and it keeps only what closes a hole entirely, so a hole it cannot
// close stays as the passes before left it.
void LoopFiller::close_at_sharp_edges(const std::function<void(double)> &tick) {
  behind_ = true;
  const uint32_t first = uint32_t(g_.mesh.face_count());
  run(tick);
  g_.stats.triangles_loops -= remove_open_groups(first);
}

// Caps the loops that lie in one cut of a contour stack with the triangulation of their
// polygon in its plane (cut_cap.hpp), if every triangle of it passes the relaxed judgment.
void LoopFiller::cap_flat_cuts() {
  for (const Loop &loop : loops_) {
    if (!loop.flat_cut || loop.vertices.size() > kMaxCappedLoop || !still_open(loop.vertices))
      continue;
    g_.poll();
    const std::vector<Tri> tris = flat_cap(g_.points.work, loop.vertices);
    if (!tris.empty() && g_.add_all_or_none(tris, false, true))
      g_.stats.triangles_loops += tris.size();
  }
}

void LoopFiller::push(uint32_t from, uint32_t to) {
  queue_.push({dist(g_.points.work[from], g_.points.work[to]), from, to});
}

std::size_t LoopFiller::fill_pass(bool relaxed) {
  for (auto &kv : hole_loop_) {
    uint32_t from = uint32_t(kv.first >> 32), to = uint32_t(kv.first);
    if (loops_[kv.second].fillable) push(from, to);
  }
  std::size_t added = 0, popped = 0;
  while (!queue_.empty()) {
    if ((++popped & (kPollEvery - 1)) == 0) g_.poll();
    HoleEdge e = queue_.top();
    queue_.pop();
    auto it = hole_loop_.find(hole_edge_key(e.from, e.to));
    if (it == hole_loop_.end()) continue;
    uint32_t fs[2];
    if (g_.mesh.edge_faces(e.from, e.to, fs) != 1) {
      hole_loop_.erase(it);
      continue;
    }
    if (fill_edge(e.from, e.to, it->second, relaxed)) ++added;
  }
  return added;
}

bool LoopFiller::fill_edge(uint32_t u, uint32_t v, uint32_t loop_id, bool relaxed) {
  const auto &w = g_.points.work;
  uint32_t fs[2];
  g_.mesh.edge_faces(u, v, fs);
  const uint32_t z = third_vertex(g_.mesh.stored(fs[0]), u, v);
  Vec3 ab = normalized(w[v] - w[u]);
  Vec3 away = w[u] - w[z];
  Vec3 side = away - ab * dot(away, ab);

  // The loop's own candidates first; the vertices of neighbouring loops only when none of
  // those fits (an island inside a hole: the inner and outer loops combine, Fig. 10 (3)).
  Loop &loop = loops_[loop_id];
  if (!relaxed) g_.search.sphere_points(u, v, sphere_);
  return try_candidates(u, v, z, side, loop.pool, loop_id, relaxed) ||
         try_candidates(u, v, z, side, loop.outer, loop_id, relaxed);
}

// Removes the faces added since face `first` whose group (joined through shared edges)
// still has a boundary edge. Returns how many.
std::size_t LoopFiller::remove_open_groups(uint32_t first) {
  const uint32_t n = uint32_t(g_.mesh.face_count()) - first;
  DisjointSets groups(n);
  std::vector<char> open(n, 0);
  for (uint32_t i = 0; i < n; ++i) {
    if (!g_.mesh.alive(first + i)) continue;
    const Tri &t = g_.mesh.stored(first + i);
    for (int k = 0; k < 3; ++k) {
      uint32_t fs[2];
      const int count = g_.mesh.edge_faces(t[k], t[(k + 1) % 3], fs);
      open[i] |= count == 1;
      for (int j = 0; j < count; ++j)
        if (fs[j] > first + i) groups.join(i, fs[j] - first);
    }
  }
  for (uint32_t i = 0; i < n; ++i)
    if (open[i]) open[groups.root(i)] = 1;
  std::size_t removed = 0;
  for (uint32_t i = 0; i < n; ++i)
    if (g_.mesh.alive(first + i) && open[groups.root(i)]) {
      g_.mesh.remove(first + i);
      ++removed;
    }
  return removed;
}

// Does t close a hole, taking all three of its sides from faces already there?
bool LoopFiller::closes_hole(const Tri &t) const {
  for (int i = 0; i < 3; ++i) {
    uint32_t fs[2];
    if (g_.mesh.edge_faces(t[i], t[(i + 1) % 3], fs) != 1) return false;
  }
  return true;
}

// The last triangle of a hole may be refused because a corner carries a second fan (a
// neighbouring fill touched it): closing would make a disk and a fan meet at one vertex.
// The second fan goes, the hole closes, and the next round refills the space the fan left.
Verdict LoopFiller::clear_pinch_and_retry(const Tri &t) {
  uint32_t v = g_.mesh.fan_closing_blocked(t);
  if (v == kNone) return Verdict::Manifold;
  uint32_t fs[2];
  uint32_t w = t[0] == v ? t[1] : t[0];
  g_.mesh.edge_faces(v, w, fs);
  g_.stats.triangles_removed += g_.mesh.remove_other_fans(v, fs[0]);
  Verdict verdict = g_.judge.judge(t, nullptr, 0, true);
  TopologyJudge::count(verdict, g_.stats);
  return verdict;
}

// Once a triangle joins an island to the loop around it, the two lists become one.
void LoopFiller::merge_loop_of(uint32_t vertex, uint32_t loop_id) {
  auto it = loop_of_vertex_.find(vertex);
  if (it == loop_of_vertex_.end() || it->second == loop_id) return;
  // Once for each island: every later triangle at one of its vertices appended its list
  // again, and in a cloud of many islands the lists grew without bound (a random volume of
  // 50,000 points: 3 GB).
  if (!merged_.insert(uint64_t(loop_id) << 32 | it->second).second) return;
  const std::vector<uint32_t> &other = loops_[it->second].vertices;
  std::vector<uint32_t> &pool = loops_[loop_id].pool;
  // Past kMaxScannedPool entries try_candidates searches the k-NN graph and reads only the
  // pool's size, so one entry past it is all a merge still needs to add: a random volume's
  // loops each merged the same long loops, 64 million entries in all at 50,000 points.
  if (pool.size() > kMaxScannedPool) return;
  const std::size_t take = std::min(other.size(), kMaxScannedPool + 1 - pool.size());
  pool.insert(pool.end(), other.begin(), other.begin() + std::ptrdiff_t(take));
}

// Would t take a boundary edge of another loop as its own? That merges the two loops
// through the surface: a handle when both belong to one component.
bool LoopFiller::joins_another_loop(const Tri &t, uint32_t loop_id) const {
  for (int i = 1; i < 3; ++i) {
    uint32_t a = t[i], b = t[(i + 1) % 3];
    auto it = hole_loop_.find(hole_edge_key(a, b));
    if (it != hole_loop_.end() && it->second != loop_id) return true;
  }
  return false;
}

bool LoopFiller::try_candidates(uint32_t u, uint32_t v, uint32_t z, Vec3 side,
                                const std::vector<uint32_t> &pool, uint32_t loop_id, bool relaxed) {
  const auto &w = g_.points.work;
  Vec3 m = midpoint(w[u], w[v]);
  // A loop of another component may be joined (an island inside a hole); joining another
  // loop of the same component would open a handle through the surface.
  const bool other_loops = &pool == &loops_[loop_id].outer;
  uint32_t own = kNone;
  if (other_loops) {
    uint32_t fs[2];
    g_.mesh.edge_faces(u, v, fs);
    own = g_.mesh.component(fs[0]);
  }
  near_.clear();
  auto consider = [&](uint32_t c) {
    if (c == u || c == v || c == z) return;
    if (other_loops) {
      // A vertex of another loop that has lost its faces belongs to no component: free.
      const FacesAround around = g_.mesh.faces_at(c);
      if (!around.empty() && g_.mesh.component(around.front()) == own) return;
    }
    near_.push_back(c);
  };
  if (pool.size() <= kMaxScannedPool) {
    for (uint32_t c : pool) consider(c);
  } else {
    // A long loop: its members among the neighbours of u and v, instead of a scan of the
    // whole list for every segment.
    for (uint32_t s : {u, v}) {
      const uint32_t *nb = g_.nb.of(s);
      for (unsigned j = 0; j < g_.nb.k; ++j) {
        uint32_t c = nb[j];
        auto it = loop_of_vertex_.find(c);
        bool member = other_loops ? (it != loop_of_vertex_.end() && it->second != loop_id)
                                  : ((it != loop_of_vertex_.end() && it->second == loop_id) ||
                                     (!g_.mesh.is_used(c) && !g_.nb.alone(c)));
        if (member && std::find(near_.begin(), near_.end(), c) == near_.end()) consider(c);
      }
    }
  }
  if (near_.size() > kMaxLoopCandidates) {
    std::nth_element(near_.begin(), near_.begin() + kMaxLoopCandidates, near_.end(),
                     [&](uint32_t a, uint32_t b) {
                       double da = norm2(w[a] - m), db = norm2(w[b] - m);
                       return da != db ? da < db : a < b;
                     });
    near_.resize(kMaxLoopCandidates);
  }
  g_.search.rank(u, v, near_, side, z, ranked_, behind_);
  for (const Candidate &c : ranked_) {
    Tri t{u, v, c.vertex};
    if (joins_another_loop(t, loop_id)) continue;
    Verdict verdict = g_.judge.judge(t, sphere_.data(), relaxed ? 0 : sphere_.size(), relaxed);
    TopologyJudge::count(verdict, g_.stats);
    if (verdict == Verdict::Manifold && relaxed && !behind_ && closes_hole(t))
      verdict = clear_pinch_and_retry(t);
    if (verdict != Verdict::Accept) continue;
    g_.add_face(t);
    ++g_.stats.triangles_loops;
    if (other_loops) merge_loop_of(c.vertex, loop_id);
    // New hole edges belong to the same loop (or to the pieces it splits into).
    for (int i = 0; i < 3; ++i) {
      uint32_t a = t[i], b = t[(i + 1) % 3], gs[2];
      int n = g_.mesh.edge_faces(a, b, gs);
      if (n == 1) {
        hole_loop_[hole_edge_key(b, a)] = loop_id;
        push(b, a);
      } else {
        hole_loop_.erase(hole_edge_key(a, b));
      }
    }
    return true;
  }
  return false;
}

void fill_loops(GrowthState &g, const std::function<void(double)> &tick) {
  // Fill; then open the pinches that filling could not resolve, widen the holes that could
  // not be closed by the faces along them (a bad neighbourhood often blocks the last
  // triangles), and fill again.
  // The fill rounds report the first kRoundsShare of the stage, the steps after them the rest;
  // in between, g.poll reports the fraction reached again.
  constexpr double kRoundsShare = 0.8;
  double reached = 0;
  const auto report = [&](double fraction) {
    reached = std::max(reached, fraction);
    tick(reached);
  };
  g.poll = [&] { tick(reached); };
  struct PollReset {
    GrowthState &g;
    ~PollReset() { g.poll = [] {}; }
  } poll_reset{g};

  const std::size_t first_loop_face = g.mesh.face_count();
  g.stats.triangles_removed += LoopFiller(g).drop_stray_pieces(false);
  // No hole of a tangle is filled, zipped or patched, and no point beside one is taken in.
  mark_tangles(g);
  constexpr int kRounds = 6;
  for (int round = 0; round < kRounds; ++round) {
    LoopFiller filler(g);
    filler.run([&](double f) { report(kRoundsShare * (round + f) / kRounds); });
    if (round + 1 == kRounds) break;
    // In this order, spelled out: the operands of + may be evaluated either way round.
    std::size_t removed = open_pinched_vertices(g);
    removed += filler.widen_open_holes();
    g.stats.triangles_removed += removed;
    if (removed == 0) break;
  }
  // What stays open may be a strip between two pieces whose loops each count as a border. A
  // strip zipped in part leaves short holes between the triangles that passed: a fill round,
  // then the patching below.
  if (LoopFiller(g).zip_parallel_loops() > 0)
    LoopFiller(g).run([&](double) { report(kRoundsShare); });
  // Stray pieces go before the patching (an island in a hole blocks its patch) and after it
  // (widening a hole can cut a piece off); their points join the others left out. Patching one
  // hole can free its neighbour (the faces a widened hole gave up were what blocked the
  // other): patch again while that closes holes.
  g.stats.triangles_removed += LoopFiller(g).drop_stray_pieces();
  constexpr int kPatchRounds = 3;
  for (int round = 0; round < kPatchRounds && LoopFiller(g).patch_open_holes() > 0; ++round) {
  }
  report(0.85);
  // Pieces count as joined through a shared vertex, so the pinches go first: a stray piece
  // hanging from the surface by one vertex would be split off by finish_mesh, and stay.
  g.stats.triangles_removed += open_pinched_vertices(g);
  g.stats.triangles_removed += LoopFiller(g).drop_stray_pieces();
  // Closing holes beside a bridge across a narrow gap makes a handle of it: cut again. Before
  // the take-in, which lengthens a handle's waist when it puts a point on it, and which takes
  // in the points a cut leaves out.
  cut_thin_handles(g, first_loop_face);
  report(0.9);
  if (g.params.take_in_points != 0) take_in_points(g);
  LoopFiller(g).close_at_sharp_edges([&](double f) { report(0.95 + 0.05 * f); });
  // The take-in can shorten a tunnel's waist to the length looked for (homer's mouth corner).
  cut_narrow_tunnels(g, first_loop_face);
  // The take-in and the round above add faces after the last drop: a bubble that stray points
  // closed among themselves goes now.
  g.stats.triangles_removed += LoopFiller(g).drop_stray_pieces(false);
  // The holes that every step above left open: first those of next to no area, whose patch
  // would be a needle; then the others once more, with sharper folds allowed.
  LoopFiller(g).close_slits();
  LoopFiller last(g);
  last.patch_last_holes();
  // The points an excision left inside its patch are taken in again where they fit.
  if (!last.excised_points().empty() && g.params.take_in_points != 0)
    take_in_points(g, &last.excised_points());
  // In a contour stack, what is left between two contours is a band too wide for the above.
  LoopFiller(g).stitch_bands();
  g.stats.boundary_loops_after = LoopFiller(g).count_loops();
  report(1.0);
}

}  // namespace moa
