// Algorithm 2 of the paper (§3.5.2), the loop module: the boundary loops Algorithm 1 left are
// traced (inner and outer loops of one hole alike, a vertex met twice counted twice), and each
// loop small enough to be a hole rather than a border is filled by MOA among its own vertices:
// its shortest segment first, the maximum opposite loop vertex that passes the judgment, the
// loop splitting or shrinking as triangles are added (Fig. 10). Points Algorithm 1 left out
// next to a loop join its candidates, so the filling takes them in.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <queue>
#include <unordered_map>
#include <vector>

#include "core/cut_cap.hpp"
#include "core/disjoint_sets.hpp"
#include "core/growth_state.hpp"
#include "core/hole_patch.hpp"
#include "core/neighbors.hpp"
#include "core/pca.hpp"

namespace moa {
namespace {

uint64_t key(uint32_t u, uint32_t v) { return (uint64_t(u) << 32) | v; }

struct Loop {
  std::vector<uint32_t> vertices;  // in order; a hole edge runs from each to the next
  std::vector<uint32_t> pool;      // candidate apexes: the loop's vertices and nearby free points
  std::vector<uint32_t> outer;     // vertices of other loops next to this one, tried last
  double hole_width = 0;           // hole_size times the mean spacing of its vertices
  uint32_t piece = kNone;          // the component of the faces along it
  bool fillable = false;
  bool flat_cut = false;           // too wide, but lying in one cut of a contour stack (capped)
};

struct HoleEdge {
  double length;
  uint32_t from, to;
  bool operator>(const HoleEdge &o) const {
    if (length != o.length) return length > o.length;
    if (from != o.from) return from > o.from;
    return to > o.to;
  }
};

// Largest number of loop vertices ranked for one segment: the nearest ones to its midpoint.
constexpr std::size_t kMaxLoopCandidates = 24;
// Candidate lists longer than this are searched through the k-NN graph instead of scanned.
constexpr std::size_t kMaxScannedPool = 128;
// Fill passes per round: one with the whole judgment, then two that relax its local-plane and
// fan tests. A second strict pass added 29 triangles in all on building.ply (for 3 s of 22) and
// changed the result of one of 87 other clouds, so there is none.
constexpr int kPasses = 3;
constexpr int kStrictPasses = 1;
// Loops longer than this are borders unless the solid setting closes everything: measuring
// their width costs a quadratic number of distances.
constexpr std::size_t kMaxMeasuredLoop = 4096;
// A loop's waist joins two of its vertices whose path along the loop is at least this many
// times their distance (widest_waist): pi/2 across a circle, 1 between neighbours. On 192 test
// clouds (before the smoothing below) 1.5 closed one fewer than 1.3, and 1.2 none more.
constexpr double kShortcutRatio = 1.3;
// Vertices each way over which the loop is smoothed before its waists are measured; at most
// one kWaistSmoothingShare-th of the loop, as the mean of 7 of a short loop's vertices lies
// well inside it (at 0.46 of the radius of a round loop of 11: a hole 12 spacings across,
// its rim a few long edges, measured about half as wide and filled as narrow).
constexpr std::size_t kWaistSmoothing = 3;
constexpr std::size_t kWaistSmoothingShare = 8;
// A loop at most this share of the square root of its surface's vertex count long, and at most
// kSmallLoopWidths times the hole width wide, is a hole torn along a crease (see
// classify_and_pool) when it bends across one: the planes at two of its vertices at most two
// steps apart stand at least kCreaseAngle apart. A round hole through a smooth part of the
// surface is a border however short, and its planes turn gradually: 0 degrees on a flat ring,
// at most 20 within two steps on a sphere and a cylinder with holes 8-20 spacings across
// (47 across the whole loop). The loops of the quality sweep that this rule closed turn by
// 25-90 degrees within two steps, but for 57 of building.ply's 654, which now stay open.
// The two vertices must lie within kCreaseReach spacings: a crease turns the planes at once, a
// curved surface gradually. A random 20,000-point bunny with round holes 8-12 spacings across
// cut out has planes 25 degrees apart at vertices 2.3-3.8 spacings apart on three of its hole
// loops (their edges are long), which closed with faces 12 spacings long; the 42 loops along
// creases that this rule closed on 47 clouds (samples and vertex sets of the shared meshes,
// cones, prisms, cubes) have such a pair within 0.2-1.3 spacings.
constexpr double kSmallLoopShare = 0.5;
constexpr double kSmallLoopWidths = 3.0;
constexpr double kCreaseAngle = 25.0;
constexpr double kCreaseReach = 2.0;
// A loop lies in one cut of a lined cloud (in_one_cut) when its vertices stand off their plane
// by at most this many spacings (root mean square; a strip between two cuts: half a gap, about
// 0.6 spacings, as the spacing of a point on a line is about 0.8 gaps), and at least half of
// them have a neighbour at least kCutBeside spacings off it (on the next cut).
constexpr double kCutFlatness = 0.1;
constexpr double kCutBeside = 0.5;
// Longest loop capped so (the cost of clipping its ears grows with the square of its length).
constexpr std::size_t kMaxCappedLoop = 8192;
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
// Largest piece dropped when it lies within kStrayReach spacings of another, and largest piece
// dropped when its median edge is longer than kSparseSpacings median point spacings of the
// cloud (drop_stray_pieces): kMaxSparseFaces, or one kSparseShare-th of the faces when that is
// more (outliers spread through the volume around a scan, 5 % of its points, spanned pieces of
// up to 370 faces with edges ten spacings long).
// A piece of at most kMaxSparseFaces faces counts as sparse from kTinySparseSpacings on: a
// bubble of 8-42 faces that stray points deep in the volume closed among themselves had median
// edges of 2.9-4.2 spacings (10,000-20,000-point samples with 10-20 % stray points).
constexpr std::size_t kMaxStrayFaces = 12;
constexpr std::size_t kMaxSparseFaces = 64;
constexpr std::size_t kSparseShare = 64;
constexpr double kStrayReach = 2.5;
constexpr double kSparseSpacings = 4.0;
constexpr double kTinySparseSpacings = 2.5;

// The live faces under each key (a piece, a component). Faces of one key mostly come in a run
// (the main piece holds most of them), so the map is looked up once per run, not per face.
template <class KeyOf>
std::unordered_map<uint32_t, std::size_t> count_live_faces(const MeshState &mesh, KeyOf key_of) {
  std::unordered_map<uint32_t, std::size_t> count;
  uint32_t last = kNone;
  std::size_t *n = nullptr;
  for (uint32_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.alive(f)) {
      const uint32_t key = key_of(f);
      if (key != last) n = &count[last = key];
      ++*n;
    }
  return count;
}

class LoopFiller {
 public:
  explicit LoopFiller(GrowthState &g) : g_(g) {}

  // The last try, after the take-in: a hole still open whose closing needs an edge of a right
  // angle or sharper. The fill passes take their apexes only beyond the plane through the
  // segment square to the face on it, so the faces of a box, a pyramid or a prism sampled at
  // their corners alone never met (CGAL's advancing front closes them). This round takes
  // them only from behind that plane, where the judgment's edge-fold test still keeps them
  // off the face itself; and it keeps only what closes a hole entirely, so a hole it cannot
  // close stays as the passes before left it.
  void close_at_sharp_edges(const std::function<void(double)> &tick) {
    behind_ = true;
    const uint32_t first = uint32_t(g_.mesh.face_count());
    run(tick);
    g_.stats.triangles_loops -= remove_open_groups(first);
  }

  std::size_t count_loops() {
    collect_hole_edges();
    return trace_loops().size();
  }

  // Two pieces that grew apart along a rim (a cylinder's cap and side, sampled on grids that
  // meet there) can leave a strip between them one cell wide, bounded by two loops each as
  // wide as the rim: borders by their width, though the hole is the strip. Such a pair (each
  // vertex of either loop within the hole width of the other loop, the loops on two pieces)
  // is closed by zipping the two loops together, if every triangle passes the judgment.
  // Returns the strips closed.
  std::size_t zip_parallel_loops() {
    collect_hole_edges();
    loops_ = trace_loops();
    classify_and_pool();
    std::vector<uint32_t> partner(loops_.size(), kNone);
    for (uint32_t l = 0; l < loops_.size(); ++l)
      if (!loops_[l].fillable) partner[l] = partner_loop(l);
    std::size_t zipped = 0;
    for (uint32_t l = 0; l < loops_.size(); ++l) {
      const uint32_t p = partner[l];
      if (p == kNone || p < l || partner[p] != l) continue;
      const std::vector<Tri> strip = zipped_strip(loops_[l].vertices, loops_[p].vertices);
      bool done = false;
      for (bool layers_allowed : {false, true})
        if (!done) done = g_.add_all_or_none(strip, layers_allowed);
      if (done) {
        g_.stats.triangles_loops += strip.size();
        ++zipped;
      }
    }
    return zipped;
  }

  // The loop of another piece that every vertex of loop l has among its neighbours within the
  // hole width; kNone if there is none.
  uint32_t partner_loop(uint32_t l) const {
    const auto &w = g_.points.work;
    const std::vector<uint32_t> &loop = loops_[l].vertices;
    const double reach2 = loops_[l].hole_width * loops_[l].hole_width;
    uint32_t partner = kNone;
    for (uint32_t v : loop) {
      bool beside = false;
      const uint32_t *nb = g_.nb.of(v);
      for (unsigned j = 0; j < g_.nb.k && !beside; ++j) {
        const uint32_t x = nb[j];
        if (norm2(w[x] - w[v]) > reach2) break;  // the list runs nearest first
        const auto it = loop_of_vertex_.find(x);
        if (it == loop_of_vertex_.end() || it->second == l) continue;
        if (partner == kNone) {
          const FacesAround around = g_.mesh.faces_at(x);
          if (around.empty() || g_.mesh.component(around.front()) == loops_[l].piece) continue;
          partner = it->second;
        }
        beside = it->second == partner;
      }
      if (!beside) return kNone;
    }
    return partner;
  }

  // The triangles of the strip between loops a and b, oriented as a's piece is: from a's first
  // vertex and the vertex of b nearest it, each step adds the triangle whose new side across
  // the strip is the shorter, walking along b the way that keeps beside a. The loops of two
  // pieces facing the same way run opposite ways round the strip; where they run the same
  // way, b's piece faces the other way and turns round when the strip joins it.
  std::vector<Tri> zipped_strip(const std::vector<uint32_t> &a,
                                const std::vector<uint32_t> &b) const {
    const auto &w = g_.points.work;
    const std::size_t n = a.size(), m = b.size();
    std::size_t start = 0;
    for (std::size_t j = 1; j < m; ++j)
      if (norm2(w[b[j]] - w[a[0]]) < norm2(w[b[start]] - w[a[0]])) start = j;
    const Vec3 &a1 = w[a[1 % n]];
    const bool forward = norm2(w[b[(start + 1) % m]] - a1) < norm2(w[b[(start + m - 1) % m]] - a1);
    auto b_at = [&](std::size_t steps) {
      steps %= m;
      return b[forward ? (start + steps) % m : (start + m - steps) % m];
    };
    std::vector<Tri> strip;
    std::size_t i = 0, j = 0;  // steps taken along a and along b
    while (i < n || j < m) {
      const uint32_t ai = a[i % n], bj = b_at(j);
      const uint32_t a_next = a[(i + 1) % n], b_next = b_at(j + 1);
      const bool along_a =
          j == m || (i < n && norm2(w[a_next] - w[bj]) <= norm2(w[ai] - w[b_next]));
      if (along_a) {
        strip.push_back({ai, a_next, bj});
        ++i;
      } else {
        strip.push_back({b_next, bj, ai});
        ++j;
      }
    }
    return strip;
  }

  // Caps the loops that lie in one cut of a contour stack with the triangulation of their
  // polygon in its plane (cut_cap.hpp), if every triangle of it passes the relaxed judgment.
  void cap_flat_cuts() {
    for (const Loop &loop : loops_) {
      if (!loop.flat_cut || loop.vertices.size() > kMaxCappedLoop || !still_open(loop.vertices))
        continue;
      g_.poll();
      const std::vector<Tri> tris = flat_cap(g_.points.work, loop.vertices);
      if (!tris.empty() && g_.add_all_or_none(tris, false, true))
        g_.stats.triangles_loops += tris.size();
    }
  }

  // The last resort: each hole still open is patched at once with the triangulation of its
  // loop that bends the surface least (hole_patch.hpp), if every triangle of it passes the
  // relaxed judgment. When the faces around the hole fold over it, they go and the wider hole
  // is patched instead; if that fails too, they are put back, and all of it is tried again
  // without the second-layer test; then after clearing a spike, and after clearing the whole
  // stars of the hole's vertices. Returns the holes closed.
  std::size_t patch_open_holes() {
    collect_hole_edges();
    loops_ = trace_loops();
    classify_and_pool();
    std::vector<std::vector<uint32_t>> holes;
    for (const Loop &loop : loops_)
      if (loop.fillable && loop.vertices.size() <= kMaxPatchedLoop) holes.push_back(loop.vertices);
    std::size_t closed = 0, widenings = 0;
    for (const std::vector<uint32_t> &hole : holes) {
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
  std::size_t widen_open_holes() {
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

  // A few faces lying within kStrayReach spacings of another piece of the surface are taken
  // away, so that their points are offered to the take-in like any other left-out point: a
  // second layer a noisy patch grew, which no fill can join to the first, or an island left in
  // a hole of the other piece, which blocks its patch. A small piece away from other surfaces
  // stays, unless its edges are many times the cloud's typical spacing: then its corners are a
  // few stray points (outliers) that happened to span triangles, and they stay out of the mesh.
  // Before the fill only sparse pieces go (layers = false): outliers that spanned triangles
  // among themselves would otherwise take more in from the loops' pools and grow.
  std::size_t drop_stray_pieces(bool layers = true) {
    const Pieces pieces(g_.mesh, g_.points.size());
    const std::size_t live = g_.mesh.face_count() - g_.mesh.removed_count();
    const std::size_t max_sparse = std::max(kMaxSparseFaces, live / kSparseShare);
    std::map<uint32_t, std::vector<uint32_t>> small;
    uint32_t last = kNone;
    bool last_small = false;
    for (uint32_t f = 0; f < g_.mesh.face_count(); ++f) {
      if (!g_.mesh.alive(f)) continue;
      const uint32_t piece = pieces.of(f);
      if (piece != last) last_small = pieces.faces(last = piece) <= max_sparse;
      if (last_small) small[piece].push_back(f);
    }
    const auto &w = g_.points.work;
    const double sparse_edge = kSparseSpacings * g_.spacing;
    std::size_t removed = 0;
    std::vector<double> edges;
    for (const auto &[piece, faces] : small) {
      bool on_other = true;
      edges.clear();
      for (uint32_t f : faces) {
        const Tri &t = g_.mesh.stored(f);
        for (int i = 0; i < 3; ++i) {
          edges.push_back(dist(w[t[i]], w[t[(i + 1) % 3]]));
          // Some neighbour of the corner on another piece, within kStrayReach local spacings:
          // the larger of the two points', as a clump of close points has a tiny one.
          const uint32_t v = t[i];
          const uint32_t *nb = g_.nb.of(v);
          bool near = false;
          for (unsigned j = 0; j < g_.nb.k && !near; ++j) {
            const FacesAround around = g_.mesh.faces_at(nb[j]);
            near = !around.empty() && pieces.of(around.front()) != piece &&
                   dist(w[v], w[nb[j]]) <=
                       kStrayReach * std::max(g_.nb.spacing[v], g_.nb.spacing[nb[j]]);
          }
          on_other &= near;
        }
      }
      std::nth_element(edges.begin(), edges.begin() + std::ptrdiff_t(edges.size() / 2),
                       edges.end());
      const bool layer = layers && faces.size() <= kMaxStrayFaces && on_other;
      const double median_edge = edges[edges.size() / 2];
      const bool sparse =
          median_edge > sparse_edge ||
          (faces.size() <= kMaxSparseFaces && median_edge > kTinySparseSpacings * g_.spacing);
      if (!layer && !sparse) continue;
      for (uint32_t f : faces) g_.mesh.remove(f);
      removed += faces.size();
    }
    return removed;
  }

  void run(const std::function<void(double)> &tick) {
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

 private:
  // The pieces of the live faces, joined through shared vertices. Not the orientation
  // components: their union-find never splits, so a piece cut off by removed faces would still
  // count as part of the other. Four bytes per point.
  class Pieces {
   public:
    explicit Pieces(const MeshState &mesh, std::size_t points) : mesh_(mesh), parent_(points) {
      for (uint32_t v = 0; v < parent_.size(); ++v) parent_[v] = v;
      for (uint32_t f = 0; f < mesh.face_count(); ++f)
        if (mesh.alive(f)) {
          const Tri &t = mesh.stored(f);
          parent_[root(t[1])] = root(t[0]);
          parent_[root(t[2])] = root(t[0]);
        }
      for (uint32_t v = 0; v < parent_.size(); ++v) parent_[v] = root(v);  // flat from here on
      faces_ = count_live_faces(mesh, [this](uint32_t f) { return of(f); });
    }
    uint32_t of(uint32_t face) const { return parent_[mesh_.stored(face)[0]]; }
    std::size_t faces(uint32_t piece) const { return faces_.at(piece); }

   private:
    uint32_t root(uint32_t x) {
      while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
      return x;
    }
    const MeshState &mesh_;
    std::vector<uint32_t> parent_;
    std::unordered_map<uint32_t, std::size_t> faces_;  // by piece: few pieces, one large
  };

  // Live faces of each piece of the mesh (orientation component), by its representative.
  std::unordered_map<uint32_t, std::size_t> faces_per_component() {
    return count_live_faces(g_.mesh, [this](uint32_t f) { return g_.mesh.component(f); });
  }

  bool still_open(const std::vector<uint32_t> &loop) const {
    const std::size_t n = loop.size();
    for (std::size_t j = 0; j < n; ++j) {
      uint32_t fs[2];
      if (g_.mesh.edge_faces(loop[j], loop[(j + 1) % n], fs) != 1) return false;
    }
    return true;
  }

  // Patches the hole, or else removes up to kMaxRings rings of faces around it and patches the
  // wider hole; puts the faces back if that fails too. Widens first without dropping any vertex
  // out of the mesh, then, if that fails, freely: a closed surface missing a point beats one
  // with a hole.
  bool patch_or_widen(const std::vector<uint32_t> &hole, bool layers_allowed,
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
  bool patch_after_clearing_stars(const std::vector<uint32_t> &hole, bool layers_allowed,
                                  std::size_t &widenings) {
    return widen_and_patch(hole, Widening::Stars, kStarRings, layers_allowed, widenings);
  }

  // How a hole is widened: the faces on its edges, those a vertex needs to stay in the mesh
  // excepted or not; or every face at its vertices.
  enum class Widening { KeepingVertices, Rims, Stars };

  // Widens the hole ring by ring (at most `rings`, within the run's budget of widenings) and
  // patches the wider loop after each ring; on failure puts every removed face back.
  bool widen_and_patch(const std::vector<uint32_t> &hole, Widening widening, int rings,
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
  bool clear_spike_and_patch(const std::vector<uint32_t> &hole) {
    const auto &w = g_.points.work;
    Vec3 centre{};
    for (uint32_t v : hole) centre = centre + w[v];
    centre = centre * (1.0 / double(hole.size()));
    double radius2 = 0;
    for (uint32_t v : hole) radius2 = std::max(radius2, norm2(w[v] - centre));
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
  bool patch_pieces(const std::vector<uint32_t> &loop, bool layers_allowed) {
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
  bool patch(const std::vector<uint32_t> &loop, bool layers_allowed) {
    // A broken trace is no hole: smoothest_patch wants one face on every edge of the loop.
    if (loop.size() > kMaxPatchedLoop) return false;
    const std::vector<Tri> tris = smoothest_patch(g_.mesh, g_.points.work, loop);
    if (tris.empty() || !g_.add_all_or_none(tris, layers_allowed)) return false;
    g_.stats.triangles_loops += tris.size();
    return true;
  }

  // Removes every face at the loop's vertices; returns them as they were oriented.
  std::vector<Tri> remove_stars(const std::vector<uint32_t> &loop) {
    std::vector<uint32_t> faces;
    for (uint32_t v : loop)
      for (uint32_t f : g_.mesh.faces_at(v)) faces.push_back(f);
    return remove_faces(faces, false);
  }

  // Removes the faces on the loop's edges; returns them as they were oriented.
  std::vector<Tri> remove_rim(const std::vector<uint32_t> &loop, bool keep_vertices) {
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
  std::vector<Tri> remove_faces(std::vector<uint32_t> faces, bool keep_vertices) {
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
  std::vector<uint32_t> loop_around(const std::vector<uint32_t> &old, const std::vector<Tri> &rim) {
    std::vector<uint32_t> faces;
    for (const Tri &t : rim)
      for (uint32_t v : t) {
        const FacesAround around = g_.mesh.faces_at(v);
        faces.insert(faces.end(), around.begin(), around.end());
      }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    out_.clear();
    for (uint32_t f : faces) {
      if (!g_.mesh.alive(f)) continue;
      Tri t = g_.mesh.oriented(f);
      for (int i = 0; i < 3; ++i) {
        uint32_t a = t[i], b = t[(i + 1) % 3], fs[2];
        if (g_.mesh.edge_faces(a, b, fs) == 1) out_[b].push_back(a);
      }
    }
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

  // Hole edges: the reverse of each boundary edge of a face, so that a face filling the hole
  // along it keeps the orientation.
  void collect_hole_edges() {
    out_.clear();
    // Only a vertex whose fan is open has a hole edge: the faces around those, each edge
    // a -> b (as its face runs) found from a, recorded in face order as a scan of every face
    // would (the order decides how loops are traced through a vertex on two of them).
    std::vector<std::pair<uint32_t, int>> edges;  // (face, index of a in it)
    for (uint32_t a = 0; a < g_.points.size(); ++a) {
      if (!g_.mesh.is_used(a) || g_.mesh.fan_closed(a)) continue;
      for (uint32_t f : g_.mesh.faces_at(a)) {
        const Tri t = g_.mesh.oriented(f);
        const int i = int(std::find(t.begin(), t.end(), a) - t.begin());
        uint32_t fs[2];
        if (g_.mesh.edge_faces(a, t[(i + 1) % 3], fs) == 1) edges.push_back({f, i});
      }
    }
    std::sort(edges.begin(), edges.end());
    for (const auto &[f, i] : edges) {
      const Tri t = g_.mesh.oriented(f);
      out_[t[(i + 1) % 3]].push_back(t[i]);
    }
  }

  // Next hole edge at v after arriving from u: the first one met turning clockwise from vu
  // (the face on uv lies counter-clockwise of it, the hole clockwise).
  uint32_t pick_next(uint32_t u, uint32_t v, std::vector<uint32_t> &outs) {
    if (outs.size() == 1) return 0;
    uint32_t fs[2];
    g_.mesh.edge_faces(u, v, fs);
    Tri f = g_.mesh.oriented(fs[0]);
    const auto &w = g_.points.work;
    Vec3 n = normalized(cross(w[f[1]] - w[f[0]], w[f[2]] - w[f[0]]));
    Vec3 d0 = w[u] - w[v];
    d0 = d0 - n * dot(d0, n);
    uint32_t best = 0;
    double best_angle = 1e9;
    for (uint32_t k = 0; k < outs.size(); ++k) {
      Vec3 d = w[outs[k]] - w[v];
      d = d - n * dot(d, n);
      double ccw = std::atan2(dot(n, cross(d0, d)), dot(d0, d));
      double cw = ccw > 0 ? 2 * kPi - ccw : -ccw;
      if (cw < best_angle) {
        best_angle = cw;
        best = k;
      }
    }
    return best;
  }

  // Traces the loops through the hole edges in out_, starting from `from` when given (the
  // vertices of one hole, whose loop is then traced first and whole), else from every vertex.
  std::vector<Loop> trace_loops(const std::vector<uint32_t> *from = nullptr) {
    std::vector<Loop> loops;
    std::vector<uint32_t> starts;
    if (from != nullptr) {
      for (uint32_t v : *from)
        if (out_.count(v)) starts.push_back(v);
    } else {
      for (auto &kv : out_) starts.push_back(kv.first);
      std::sort(starts.begin(), starts.end());  // deterministic order
    }
    for (uint32_t s : starts) {
      while (!out_[s].empty()) {
        Loop loop;
        uint32_t prev = s, cur = out_[s].back();
        out_[s].pop_back();
        loop.vertices.push_back(s);
        while (cur != s || !out_[s].empty()) {
          auto &outs = out_[cur];
          if (outs.empty()) break;
          if (cur == s) break;
          loop.vertices.push_back(cur);
          uint32_t k = pick_next(prev, cur, outs);
          uint32_t next = outs[k];
          outs.erase(outs.begin() + k);
          prev = cur;
          cur = next;
        }
        loops.push_back(std::move(loop));
      }
    }
    return loops;
  }

  // How wide a loop is: for each vertex, the distance to the nearest vertex at least a quarter
  // of the loop away; the largest of these. A gap left between growing fronts is narrow
  // however long it is; a true border (the rim of an open scan) is as wide as the surface.
  double loop_width(const std::vector<uint32_t> &loop) const {
    const auto &w = g_.points.work;
    const std::size_t n = loop.size();
    if (n <= 3) return 0;
    if (n > kMaxMeasuredLoop) return std::numeric_limits<double>::infinity();
    const std::size_t quarter = std::max<std::size_t>(1, n / 4);
    double width = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t k = quarter; k <= n - quarter; ++k)
        nearest = std::min(nearest, norm2(w[loop[i]] - w[loop[(i + k) % n]]));
      width = std::max(width, nearest);
    }
    return std::sqrt(width);
  }

  // The widest waist of a loop. The waist at vertex i is its distance to the nearest vertex j
  // the loop reaches from i only the long way round: by a path at least kShortcutRatio times
  // the straight distance ij (pi/2 across a circle, far more across a narrow strip). A strip
  // torn open along a sharp edge has waists as narrow as the strip, however long it is, where
  // loop_width sees its length from the vertices near its ends. Vertices with no such j (the
  // tip of a wedge) have no waist.
  double widest_waist(const std::vector<uint32_t> &loop) const {
    const auto &w = g_.points.work;
    const std::size_t n = loop.size();
    if (n <= 3) return 0;
    if (n > kMaxMeasuredLoop) return std::numeric_limits<double>::infinity();
    // A loop that meets itself is a chain of holes joined at pinches (two pieces touching at
    // points along a rim), which open_pinched_vertices parts into loops of their own.
    std::vector<uint32_t> sorted(loop);
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      return std::numeric_limits<double>::infinity();
    // The loop smoothed over a few vertices each way: a staircase (the rim of a grid) has a
    // shortcut at every step, the smoothed one none.
    std::vector<Vec3> at(n);
    const std::size_t reach = std::min<std::size_t>(kWaistSmoothing, n / kWaistSmoothingShare);
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 sum{0, 0, 0};
      for (std::size_t k = n - reach; k <= n + reach; ++k) sum = sum + w[loop[(i + k) % n]];
      at[i] = sum * (1.0 / double(2 * reach + 1));
    }
    std::vector<double> along(n + 1, 0.0);  // path length from at[0] to at[i]
    for (std::size_t i = 0; i < n; ++i) along[i + 1] = along[i] + dist(at[i], at[(i + 1) % n]);
    const double round = along[n];
    const double ratio2 = kShortcutRatio * kShortcutRatio;
    double width = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < n; ++j) {
        const double forward = std::abs(along[j] - along[i]);
        const double path = std::min(forward, round - forward);
        const double d2 = norm2(at[i] - at[j]);
        if (path * path >= ratio2 * d2 && d2 < nearest && j != i) nearest = d2;
      }
      if (nearest != std::numeric_limits<double>::infinity()) width = std::max(width, nearest);
    }
    return std::sqrt(width);
  }

  // Whether a loop bends across a crease (kCreaseAngle, within kCreaseReach). In a cloud
  // sampled along lines any such turn counts: there a short loop is the unsampled surface
  // between two lines, a hole however gradually it turns (where the surface runs nearly
  // parallel to the lines; a noisy torus contour stack kept four such, 100 boundary edges).
  bool bends(const std::vector<uint32_t> &loop) const {
    const auto &w = g_.points.work;
    const std::size_t n = loop.size();
    std::vector<Vec3> normals;
    for (uint32_t v : loop) normals.push_back(plane_normal(g_.points, g_.nb, v));
    const double cos_crease = std::cos(kCreaseAngle * M_PI / 180);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t step : {1, 2}) {
        const uint32_t a = loop[i], b = loop[(i + step) % n];
        const double reach = kCreaseReach * 0.5 * (g_.nb.spacing[a] + g_.nb.spacing[b]);
        if (std::fabs(dot(normals[i], normals[(i + step) % n])) <= cos_crease &&
            (g_.nb.lined || norm2(w[a] - w[b]) <= reach * reach))
          return true;
      }
    return false;
  }

  // Whether a loop of a cloud sampled along lines lies in the plane of one cut, with other cuts
  // beside it: a face parallel to the slices, which gets no points but its rim (an object's
  // flat top or bottom, or one cut off by the scan's field), is such a loop. A strip between
  // two cuts spans the gap between them, and a flat open surface's border has no point off
  // its plane.
  bool in_one_cut(const std::vector<uint32_t> &loop, double spacing) const {
    const auto &w = g_.points.work;
    const std::size_t n = loop.size();
    if (n < 3) return false;
    const PcaFrame f = pca_frame(w, loop[0], loop.data() + 1, unsigned(n - 1));
    const double thickness = std::sqrt(std::max(0.0, f.spread[0]) / double(n));
    if (!(thickness <= kCutFlatness * spacing)) return false;
    std::size_t beside = 0;
    for (uint32_t v : loop) {
      const uint32_t *nb = g_.nb.of(v);
      for (unsigned j = 0; j < g_.nb.k; ++j)
        if (std::fabs(dot(w[nb[j]] - w[v], f.axis[0])) > kCutBeside * spacing) {
          ++beside;
          break;
        }
    }
    return 2 * beside >= n;
  }

  // A loop is a hole, to be filled, when it is narrow (at most hole_size spacings wide, or its
  // widest waist is: a gap left between growing fronts, a strip torn along a sharp edge), or
  // when it is short next to the surface it bounds and not too wide (a hole torn at a sharp
  // edge or a crease of a large surface). A border of an open scan runs around the whole
  // surface: its length is of the order of the square root of the surface's vertex count or
  // more, however the scan is shaped.
  void classify_and_pool() {
    std::unordered_map<uint32_t, uint32_t> &loop_of_vertex = loop_of_vertex_;
    // Counted only if a loop gets as far as the test that needs it: a pass over every face.
    std::unordered_map<uint32_t, std::size_t> faces_of_component;
    bool counted = false;
    auto surface_vertices = [&](uint32_t piece) {
      if (!counted) faces_of_component = faces_per_component();
      counted = true;
      return 0.5 * double(faces_of_component[piece]);
    };
    const double sparse_spacing = kSparseSpacings * g_.spacing;
    for (uint32_t l = 0; l < loops_.size(); ++l) {
      Loop &loop = loops_[l];
      double spacing = 0;
      const std::size_t n = loop.vertices.size();
      for (std::size_t i = 0; i < n; ++i) {
        uint32_t a = loop.vertices[i], b = loop.vertices[(i + 1) % n];
        spacing += g_.nb.spacing[a];
        hole_loop_[key(a, b)] = l;
        loop_of_vertex.emplace(a, l);
      }
      spacing /= double(n);
      const double width = loop_width(loop.vertices);
      const double hole_width = loop.hole_width = g_.params.hole_size * spacing;
      uint32_t fs[2];
      g_.mesh.edge_faces(loop.vertices[1 % n], loop.vertices[0], fs);
      loop.piece = g_.mesh.component(fs[0]);
      // Narrow, or else small; a strip is narrow by its waists too, the spacing capped where
      // the loop runs among stray points: their own spacing would make a gap of any width among
      // them look narrow. The dearer tests come last: the waists take a quadratic number of
      // distances, the bend a fitted plane per vertex.
      loop.fillable =
          g_.params.solid != 0 || width <= hole_width ||
          widest_waist(loop.vertices) <= g_.params.hole_size * std::min(spacing, sparse_spacing) ||
          (double(n) <= kSmallLoopShare * std::sqrt(surface_vertices(loop.piece)) &&
           width <= kSmallLoopWidths * hole_width && bends(loop.vertices));
      loop.flat_cut = !loop.fillable && g_.nb.lined && in_one_cut(loop.vertices, spacing);
    }
    // Candidates of a loop: its own vertices, and the neighbours of its vertices that lie on
    // another loop (the outer loop around an island, Fig. 9 (2), whose lists the paper
    // combines) or that Algorithm 1 left out (step 1 of §3.5.2).
    const bool take_in = g_.params.take_in_points != 0;
    std::vector<uint32_t> mark(g_.points.size(), kNone);
    for (uint32_t l = 0; l < loops_.size(); ++l) {
      Loop &loop = loops_[l];
      loop.pool = loop.vertices;
      for (uint32_t v : loop.vertices) mark[v] = l;
      for (uint32_t v : loop.vertices) {
        const uint32_t *nb = g_.nb.of(v);
        for (unsigned j = 0; j < g_.nb.k; ++j) {
          uint32_t p = nb[j];
          if (mark[p] == l) continue;
          if (!g_.mesh.is_used(p)) {
            if (!take_in || g_.nb.alone(p)) continue;
            mark[p] = l;
            loop.pool.push_back(p);
          } else if (loop_of_vertex.count(p)) {
            mark[p] = l;
            loop.outer.push_back(p);
          }
        }
      }
    }
  }

  void push(uint32_t from, uint32_t to) {
    queue_.push({dist(g_.points.work[from], g_.points.work[to]), from, to});
  }

  std::size_t fill_pass(bool relaxed) {
    for (auto &kv : hole_loop_) {
      uint32_t from = uint32_t(kv.first >> 32), to = uint32_t(kv.first);
      if (loops_[kv.second].fillable) push(from, to);
    }
    std::size_t added = 0, popped = 0;
    while (!queue_.empty()) {
      if ((++popped & (kPollEvery - 1)) == 0) g_.poll();
      HoleEdge e = queue_.top();
      queue_.pop();
      auto it = hole_loop_.find(key(e.from, e.to));
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

  bool fill_edge(uint32_t u, uint32_t v, uint32_t loop_id, bool relaxed) {
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
  std::size_t remove_open_groups(uint32_t first) {
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
  bool closes_hole(const Tri &t) const {
    for (int i = 0; i < 3; ++i) {
      uint32_t fs[2];
      if (g_.mesh.edge_faces(t[i], t[(i + 1) % 3], fs) != 1) return false;
    }
    return true;
  }

  // The last triangle of a hole may be refused because a corner carries a second fan (a
  // neighbouring fill touched it): closing would make a disk and a fan meet at one vertex.
  // The second fan goes, the hole closes, and the next round refills the space the fan left.
  Verdict clear_pinch_and_retry(const Tri &t) {
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
  void merge_loop_of(uint32_t vertex, uint32_t loop_id) {
    auto it = loop_of_vertex_.find(vertex);
    if (it == loop_of_vertex_.end() || it->second == loop_id) return;
    const std::vector<uint32_t> &other = loops_[it->second].vertices;
    std::vector<uint32_t> &pool = loops_[loop_id].pool;
    pool.insert(pool.end(), other.begin(), other.end());
  }

  // Would t take a boundary edge of another loop as its own? That merges the two loops
  // through the surface: a handle when both belong to one component.
  bool joins_another_loop(const Tri &t, uint32_t loop_id) const {
    for (int i = 1; i < 3; ++i) {
      uint32_t a = t[i], b = t[(i + 1) % 3];
      auto it = hole_loop_.find(key(a, b));
      if (it != hole_loop_.end() && it->second != loop_id) return true;
    }
    return false;
  }

  bool try_candidates(uint32_t u, uint32_t v, uint32_t z, Vec3 side,
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
          hole_loop_[key(b, a)] = loop_id;
          push(b, a);
        } else {
          hole_loop_.erase(key(a, b));
        }
      }
      return true;
    }
    return false;
  }

  GrowthState &g_;
  std::unordered_map<uint32_t, std::vector<uint32_t>> out_;
  std::vector<Loop> loops_;
  std::unordered_map<uint64_t, uint32_t> hole_loop_;
  std::unordered_map<uint32_t, uint32_t> loop_of_vertex_;
  std::priority_queue<HoleEdge, std::vector<HoleEdge>, std::greater<HoleEdge>> queue_;
  std::vector<uint32_t> near_, sphere_;
  std::vector<Candidate> ranked_;
  bool behind_ = false;  // apexes from behind the rim face only (close_at_sharp_edges)
};

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

}  // namespace

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
  // Stray pieces go before the patching (an island in a hole blocks its patch) and after it
  // (widening a hole can cut a piece off); their points join the others left out. Patching one
  // hole can free its neighbour (the faces a widened hole gave up were what blocked the
  // other): patch again while that closes holes.
  g.stats.triangles_removed += LoopFiller(g).drop_stray_pieces();
  constexpr int kPatchRounds = 3;
  for (int round = 0; round < kPatchRounds && LoopFiller(g).patch_open_holes() > 0; ++round) {
  }
  report(0.85);
  // What stays open may be a strip between two pieces whose loops each count as a border.
  // Pieces count as joined through a shared vertex, so the pinches go first: a stray piece
  // hanging from the surface by one vertex would be split off by finish_mesh, and stay.
  LoopFiller(g).zip_parallel_loops();
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
  g.stats.boundary_loops_after = LoopFiller(g).count_loops();
  report(1.0);
}

}  // namespace moa
