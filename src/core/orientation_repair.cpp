// Inside-out patches. A triangle that joins two separately seeded pieces of the mesh decides,
// from the one edge it shares with each, how one piece is oriented relative to the other. At a
// sharp crease that edge can mislead, and the whole younger piece is then turned inside out:
// everywhere else along its seam with the rest the two rims run the same way instead of
// opposite ways, so no triangle can ever close the seam and the hole stays (with a wrong genus
// once the loop module works around it).
//
// After Algorithm 1 such seams are found from their open edges: two open edges of one
// orientation class that face each other across a gap and run the same way. The patch behind
// them is cut from the rest at the few edges that hold it (a minimum cut in the graph of faces
// across edges), turned round, and the seam is handed back to Algorithm 1.
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "core/growth_state.hpp"
#include "core/kd_tree.hpp"

namespace moa {
namespace {

// Open edges face each other across a seam when their midpoints are within this many edge
// lengths, their directions within about 45 degrees of parallel, and each lies ahead of the
// other's open side (the cosine of the gap with the outward direction above kFacing).
constexpr double kSeamReach = 1.5;
constexpr double kParallel = 0.7;
constexpr double kFacing = 0.5;
// A patch held to the rest by more edges than this is not cut: the joins there agree with
// each other and the seam is something else.
constexpr int kMaxCut = 6;
// Contradicting pairs across a patch's border needed to turn it (see seam_contradicts).
constexpr int kMinVotes = 2;
constexpr double kRimShare = 0.5;
constexpr int kCutEdgeVotes = 2;
// Or, for a patch along most of whose rim the gap is too wide for pairs to be found across it,
// this many votes against and this many times the votes for: a cone's base held to its side by
// one edge, open along the rest of its 56° rim, had 19 pairs against and 3 votes for where the
// rim share asked for 30. On the cow's vertex set, where a few stray pairs once turned half the
// surface over, no patch has more than 6 pairs against it.
constexpr int kClearVotes = 8;
constexpr int kClearMargin = 4;
// Smaller patches are left to the loop module, which rebuilds small regions anyway.
constexpr std::size_t kMinPatchFaces = 8;
// The cut separates the faces within this many steps of each face of a contradicting pair:
// a disc that wide has a longer rim than kMaxCut edges.
constexpr int kSideDepth = 4;
// Cuts tried per call at most.
constexpr int kMaxAttempts = 24;

struct OpenEdge {
  Vec3 mid, dir, out;
  double length;
  uint32_t face;
};

// The graph of faces across their shared edges, with a unit capacity per edge in each
// direction, for one minimum cut at a time.
class FaceCut {
 public:
  explicit FaceCut(const MeshState &mesh)
      // The face across each edge, looked up once: the searches cross every edge many times.
      : across_(mesh.faces_across()),
        mark_(mesh.face_count(), 0),
        sink_(mesh.face_count(), 0),
        from_(mesh.face_count(), kNone) {}

  // Takes face f out of the graph.
  void remove(uint32_t f) {
    for (int i = 0; i < 3; ++i) {
      const uint32_t h = across_[3 * f + i];
      if (h == kNone) continue;
      for (int j = 0; j < 3; ++j)
        if (across_[3 * h + j] == f) across_[3 * h + j] = kNone;
      across_[3 * f + i] = kNone;
    }
  }

  // The faces on the sources' side of a minimum cut between the sources and the sinks (a face
  // listed as both is a sink) and the number of edges cut, or nothing when more than kMaxCut
  // edges hold them together.
  bool cut(const std::vector<uint32_t> &sources, const std::vector<uint32_t> &sinks,
           std::vector<uint32_t> &side, int &edges) {
    flow_.clear();
    edges = 0;
    ++sink_stamp_;
    for (uint32_t f : sinks) sink_[f] = sink_stamp_;
    for (int paths = 0;; ++paths) {
      const uint32_t end = bfs(sources, true, -1);
      if (end == kNone) break;
      if (paths == kMaxCut) return false;
      edges = paths + 1;
      for (uint32_t f = end; from_[f] != kNone;) {
        const uint32_t p = from_[f];
        ++flow_[key(p, f)];
        --flow_[key(f, p)];
        f = p;
      }
    }
    side = reached_;
    return true;
  }

  // Faces at most `depth` steps from f across shared edges (all of f's piece for depth -1).
  void around(uint32_t f, int depth, std::vector<uint32_t> &out) {
    ++sink_stamp_;  // no sinks
    bfs({f}, false, depth);
    out = reached_;
  }
  // Whether the last search reached f.
  bool reached(uint32_t f) const { return mark_[f] == stamp_; }

  uint32_t across(uint32_t f, int i) const { return across_[3 * f + i]; }

 private:
  static uint64_t key(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }
  int flow(uint32_t a, uint32_t b) const {
    auto it = flow_.find(key(a, b));
    return it == flow_.end() ? 0 : it->second;
  }

  // Breadth-first from the sources, up to `depth` steps (any number for -1), over edges with
  // room left (residual) or all edges; reached_ lists the faces reached, from_ how. Returns
  // the first sink reached, or kNone.
  uint32_t bfs(const std::vector<uint32_t> &sources, bool residual, int depth) {
    ++stamp_;
    reached_.clear();
    for (uint32_t s : sources) {
      if (mark_[s] == stamp_ || sink_[s] == sink_stamp_) continue;
      mark_[s] = stamp_;
      from_[s] = kNone;
      reached_.push_back(s);
    }
    std::size_t level_end = reached_.size();
    for (std::size_t k = 0; k < reached_.size(); ++k) {
      if (k == level_end) {
        if (depth-- == 0) break;
        level_end = reached_.size();
      }
      const uint32_t f = reached_[k];
      for (int i = 0; i < 3; ++i) {
        const uint32_t g = across(f, i);
        if (g == kNone || mark_[g] == stamp_) continue;
        if (residual && flow(f, g) >= 1) continue;
        mark_[g] = stamp_;
        from_[g] = f;
        reached_.push_back(g);
        if (sink_[g] == sink_stamp_) return g;
      }
    }
    return kNone;
  }

  std::vector<uint32_t> across_;  // 3 per face
  std::vector<uint32_t> mark_, sink_;
  uint32_t stamp_ = 0, sink_stamp_ = 0;
  std::vector<uint32_t> reached_;
  std::vector<uint32_t> from_;
  std::unordered_map<uint64_t, int> flow_;
};

std::vector<OpenEdge> open_edges(GrowthState &g) {
  const auto &w = g.points.work;
  std::vector<OpenEdge> edges;
  g.mesh.for_each_open_edge([&](uint32_t f, int i) {
    const Tri &s = g.mesh.stored(f);
    uint32_t p = s[i], q = s[(i + 1) % 3];
    const uint32_t r = s[(i + 2) % 3];
    if (g.mesh.oriented(f) != s) std::swap(p, q);  // the edge as the face now runs
    const Vec3 along = normalized(w[q] - w[p]), away = w[p] - w[r];
    edges.push_back({(w[p] + w[q]) * 0.5, along, normalized(away - along * dot(away, along)),
                     dist(w[p], w[q]), f});
  });
  return edges;
}

using FacePairs = std::vector<std::pair<uint32_t, uint32_t>>;

// Pairs of faces of one orientation class whose open edges face each other across a seam:
// running the same way (contradicting, the seam cannot close) or opposite ways (agreeing).
void seam_pairs(GrowthState &g, const std::vector<OpenEdge> &edges, FacePairs &contradicting,
                FacePairs &agreeing) {
  std::vector<Vec3> mids(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) mids[i] = edges[i].mid;
  if (mids.empty()) return;
  KdIndex index(mids);
  std::vector<std::pair<uint32_t, double>> near;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const OpenEdge &a = edges[i];
    const double reach = kSeamReach * a.length;
    index.within(a.mid, reach * reach, near);
    for (const auto &[j, d2] : near) {
      if (j <= i) continue;
      const OpenEdge &b = edges[j];
      const Vec3 gap = b.mid - a.mid;
      const double d = std::sqrt(d2);
      const double c = dot(a.dir, b.dir);
      if (std::fabs(c) < kParallel) continue;
      if (dot(gap, a.out) < kFacing * d || -dot(gap, b.out) < kFacing * d) continue;
      if (g.mesh.component(a.face) != g.mesh.component(b.face)) continue;
      (c > 0 ? contradicting : agreeing).push_back({a.face, b.face});
    }
  }
  std::sort(contradicting.begin(), contradicting.end());
}

// Does the seam around a patch of `faces` faces (on_side), held by `cut_edges` edges,
// contradict its orientation? Pairs across its border vote against; agreeing pairs and the
// edges that hold it (joins that agree) vote for; and the votes against must come from a fair
// share of its rim, which grows as the square root of its area, or outnumber those for by far.
bool seam_contradicts(const FacePairs &contradicting, const FacePairs &agreeing,
                      const std::vector<uint8_t> &on_side, int cut_edges, std::size_t faces) {
  auto across = [&](const FacePairs &pairs) {
    int n = 0;
    for (const auto &[a, b] : pairs) n += on_side[a] != on_side[b];
    return n;
  };
  const int against = across(contradicting);
  const int for_it = across(agreeing) + kCutEdgeVotes * cut_edges;
  return against >= kMinVotes && against > for_it &&
         (double(against) >= kRimShare * std::sqrt(double(faces)) ||
          (against >= kClearVotes && against >= kClearMargin * for_it));
}

// Cuts free the patches whose seams contradict their orientation, removing the faces that held
// them, and lists the patches' faces in `turn`; returns how many.
std::size_t cut_patches(GrowthState &g, const FacePairs &pairs, const FacePairs &agreeing,
                        std::vector<uint32_t> &turn) {
  FaceCut graph(g.mesh);
  std::vector<uint8_t> settled(g.mesh.face_count(), 0);  // tried, turned or removed
  std::vector<uint32_t> side, piece, rest, sources, sinks;
  std::size_t patches = 0;
  int attempts = 0;
  for (const auto &[a, b] : pairs) {
    if (settled[a] || settled[b] || !g.mesh.alive(a) || !g.mesh.alive(b)) continue;
    // Each attempt costs a few passes over the piece; the pairs of one seam share their
    // answer, so both faces are settled whatever it is.
    settled[a] = settled[b] = 1;
    if (++attempts > kMaxAttempts) break;
    // The cut is sought between the faces around each side of the seam, not between the two
    // faces alone: a face on an open rim hangs by two edges, and those would always be the
    // smallest cut.
    graph.around(a, kSideDepth, sinks);
    if (graph.reached(b)) continue;  // the two lie on one side after all
    graph.around(b, kSideDepth, sources);
    int cut_edges;
    if (!graph.cut(sources, sinks, side, cut_edges)) continue;
    // The two sides: the cut's, and the rest of the faces connected to either face of the
    // pair (a patch cut free in an earlier round is still of the same orientation class, but
    // no longer connected: then the cut is empty and each side is a piece of its own).
    std::vector<uint8_t> on_side(g.mesh.face_count(), 0);
    for (uint32_t f : side) on_side[f] = 1;
    graph.around(b, -1, piece);
    if (!graph.reached(a)) {
      graph.around(a, -1, rest);
      piece.insert(piece.end(), rest.begin(), rest.end());
    }
    // Turn the smaller side: the larger one is the rest of the surface.
    if (2 * side.size() > piece.size()) {
      std::vector<uint32_t> other;
      for (uint32_t f : piece)
        if (!on_side[f]) other.push_back(f);
      for (uint32_t f : piece) on_side[f] ^= 1;
      side.swap(other);
    }
    if (side.size() < kMinPatchFaces ||
        !seam_contradicts(pairs, agreeing, on_side, cut_edges, side.size()))
      continue;
    // The faces holding the patch: those of the patch across a cut edge are removed.
    std::vector<uint32_t> holding;
    for (uint32_t f : side)
      for (int i = 0; i < 3; ++i) {
        const uint32_t h = graph.across(f, i);
        if (h != kNone && !on_side[h]) {
          holding.push_back(f);
          break;
        }
      }
    for (uint32_t f : side) settled[f] = 1;
    for (uint32_t f : holding) {
      g.mesh.remove(f);
      graph.remove(f);
      ++g.stats.triangles_removed;
    }
    for (uint32_t f : side)
      if (g.mesh.alive(f)) turn.push_back(f);
    ++patches;
  }
  return patches;
}

}  // namespace

std::size_t repair_inside_out_patches(GrowthState &g, std::size_t *contradicting) {
  FacePairs pairs, agreeing;
  seam_pairs(g, open_edges(g), pairs, agreeing);
  if (contradicting) *contradicting = pairs.size();
  if (pairs.empty()) return 0;
  // The face graph takes 24 bytes a face, the crossing index's Embree scene about 36, and no
  // crossing is tested meanwhile: the scene is set aside and built again after, with the
  // graph's memory handed back first, so that the two never add up (they set the peak of a
  // million points with noise of 0.05 % of the diagonal: 458 bytes a point, 403 now, in the
  // loop module).
  g.crossings.set_aside();
  std::vector<uint32_t> turn;
  const std::size_t patches = cut_patches(g, pairs, agreeing, turn);
  if (patches > 0) g.mesh.reverse_faces(turn);
  return_free_memory();
  g.crossings.add_all(g.mesh);
  return patches;
}

}  // namespace moa
