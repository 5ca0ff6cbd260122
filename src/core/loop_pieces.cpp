// The loop module's work on pieces of the mesh: stray pieces (a second layer beside the surface,
// an island blocking a hole's patch, triangles spanned among outliers) are removed, and a strip
// between two pieces whose loops run side by side is zipped shut.
#include <algorithm>
#include <map>
#include <unordered_map>

#include "core/loop_filler.hpp"

namespace moa {
namespace {

// Largest piece dropped when it lies within kStrayReach spacings of another, and largest piece
// dropped when its median edge is longer than kSparseSpacings median point spacings of the
// cloud (drop_stray_pieces): kMaxSparseFaces, or one kSparseShare-th of the faces when that is
// more (outliers spread through the volume around a scan, 5 % of its points, spanned pieces of
// up to 370 faces with edges ten spacings long).
// A piece of at most kMaxSparseFaces faces counts as sparse from kTinySparseSpacings on: a
// bubble of 8-42 faces that stray points deep in the volume closed among themselves had median
// edges of 2.9-4.2 spacings (10,000-20,000-point samples with 10-20 % stray points). It counts
// as sparse too when its corners list more stray points of the volume (isolated_points.hpp)
// than other points: a clump of stray points close enough together to pass for a surface (in a
// cube holding as many stray points as the torus in it has points, bubbles of 9 and 18 faces
// 17-34 spacings off the torus, their median edges 2.3 spacings).
// A closed piece of more than kMaxSparseFaces faces stays however sparse: a small object
// sampled far more coarsely than the rest of the cloud (a sphere of 100 points beside one of
// 20,000), which was dropped whole. The pieces that stray points spanned among themselves and
// that were dropped as sparse (samples of the shared meshes with 20-100 % stray points, random
// points filling a cube) were all open when larger than that (the nearest to closed had as
// many border edges as 6.5 % of its faces).
constexpr std::size_t kMaxStrayFaces = 12;
constexpr std::size_t kMaxSparseFaces = 64;
constexpr std::size_t kSparseShare = 64;
constexpr double kStrayReach = 2.5;
constexpr double kTinySparseSpacings = 2.5;
// How far apart two loops may run and still be zipped, in hole widths. Two loops of separate
// pieces that stay this close along the whole length of both are the two sides of one strip,
// a far stronger sign of a gap in the sampling than a single loop's width: in a CT stack with
// slices six times farther apart than its voxels such a strip is 6-7 spacings wide (2 of 8
// volumes of our sweep closed with 1, 6 of 8 with 2; no other cloud of it changed but for the
// better).
constexpr double kZipReach = 2.0;

double zip_reach2(const Loop &loop) {
  const double reach = kZipReach * loop.hole_width;
  return reach * reach;
}

std::vector<Vec3> loop_points(const std::vector<Loop> &loops, const std::vector<Vec3> &work) {
  std::vector<Vec3> at;
  for (const Loop &loop : loops)
    for (uint32_t v : loop.vertices) at.push_back(work[v]);
  return at;
}

std::vector<uint32_t> loop_owners(const std::vector<Loop> &loops) {
  std::vector<uint32_t> owner;
  for (uint32_t l = 0; l < loops.size(); ++l)
    owner.insert(owner.end(), loops[l].vertices.size(), l);
  return owner;
}

}  // namespace

LoopVertices::LoopVertices(const std::vector<Loop> &loops, const std::vector<Vec3> &work)
    : at(loop_points(loops, work)), loop(loop_owners(loops)), index(at) {}

// Two pieces that grew apart along a rim (a cylinder's cap and side, sampled on grids that
// meet there) can leave a strip between them one cell wide, bounded by two loops each as
// wide as the rim: borders by their width, though the hole is the strip. Such a pair (each
// vertex of either loop within twice the hole width of the other loop, the loops on two pieces)
// is closed by zipping the two loops together, with the triangles that pass the judgment.
// Returns the strips zipped, whole or in part.
std::size_t LoopFiller::zip_parallel_loops() {
  collect_hole_edges();
  loops_ = trace_loops();
  classify_and_pool();
  if (loops_.size() < 2) return 0;
  // The pieces as the live faces join them now: an orientation component never splits, and
  // the two halves of a stack cut apart along a slice can share one through faces removed
  // since.
  const Pieces pieces(g_.mesh, g_.points.size());
  for (Loop &loop : loops_) loop.piece = pieces.of(face_along(loop.vertices));
  const LoopVertices near(loops_, g_.points.work);
  std::vector<uint32_t> partner(loops_.size(), kNone);
  for (uint32_t l = 0; l < loops_.size(); ++l)
    if (!loops_[l].fillable && !loops_[l].tangled) partner[l] = partner_loop(l, near);
  std::size_t zipped = 0;
  for (uint32_t l = 0; l < loops_.size(); ++l) {
    const uint32_t p = partner[l];
    if (p == kNone || p < l || partner[p] != l) continue;
    bool done = false;
    std::vector<Tri> strip;
    for (bool by_share : {false, true}) {
      strip = zipped_strip(loops_[l].vertices, loops_[p].vertices, by_share);
      for (bool layers_allowed : {false, true})
        if (!done) done = g_.add_all_or_none(strip, layers_allowed);
      if (done) break;
    }
    if (done) {
      g_.stats.triangles_loops += strip.size();
      ++zipped;
      continue;
    }
    // Where a loop zigzags (a vertex of the rim standing out of its slice), the zip folds; the
    // triangles that pass are kept, and the short holes left between them are narrow, for the
    // fill round that follows (fill_loops). Only triangles across the strip: the relaxed
    // judgment would let one pass that reaches across a torus's hole.
    const double reach2 = zip_reach2(loops_[l]);
    const auto &w = g_.points.work;
    std::size_t added = 0;
    for (const Tri &t : strip)
      if (norm2(w[t[0]] - w[t[1]]) <= reach2 && norm2(w[t[1]] - w[t[2]]) <= reach2 &&
          norm2(w[t[2]] - w[t[0]]) <= reach2)
        added += g_.add_all_or_none({t});
    g_.stats.triangles_loops += added;
    zipped += added > 0;
  }
  return zipped;
}

// The loop of another piece that has a vertex within twice the hole width (kZipReach) of every
// vertex of loop l, the nearest to l's first vertex if several do; kNone if there is none. Searched
// by distance among the loops' vertices, not in the neighbour lists: across a gap between two
// slices of a CT stack a point's list may hold its own slice and the next one on its side
// alone, none of the loop across.
uint32_t LoopFiller::partner_loop(uint32_t l, const LoopVertices &near) const {
  const auto &w = g_.points.work;
  const std::vector<uint32_t> &loop = loops_[l].vertices;
  const double reach2 = zip_reach2(loops_[l]);
  uint32_t partner = kNone;
  std::vector<std::pair<uint32_t, double>> found;
  for (uint32_t v : loop) {
    near.index.within(w[v], reach2, found);
    if (partner == kNone) {
      double nearest = reach2;
      for (const auto &[i, d2] : found) {
        const uint32_t other = near.loop[i];
        if (other == l || loops_[other].tangled || loops_[other].piece == loops_[l].piece) continue;
        if (d2 < nearest || (d2 == nearest && other < partner)) {
          nearest = d2;
          partner = other;
        }
      }
      if (partner == kNone) return kNone;
      continue;
    }
    if (std::none_of(found.begin(), found.end(), [&](const std::pair<uint32_t, double> &f) {
          return near.loop[f.first] == partner;
        }))
      return kNone;
  }
  return partner;
}

// The triangles of the strip between loops a and b, oriented as a's piece is: from a's first
// vertex and the vertex of b nearest it, each step adds the triangle whose new side across
// the strip is the shorter, or (by_share) the one whose new vertex comes first by its share of
// its loop's length, walking along b the way that keeps beside a. By the shorter side a vertex
// of one loop standing out of the strip can stall the walk, every later step fanning the other
// loop from the vertex before it; shares pass such a vertex by. The loops of two
// pieces facing the same way run opposite ways round the strip; where they run the same
// way, b's piece faces the other way and turns round when the strip joins it.
std::vector<Tri> LoopFiller::zipped_strip(const std::vector<uint32_t> &a,
                                          const std::vector<uint32_t> &b, bool by_share) const {
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
  // Each loop's vertices at their share of its length from the start, for by_share only.
  std::vector<double> share_a, share_b;
  if (by_share) {
    share_a.assign(n + 1, 0.0);
    share_b.assign(m + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      share_a[i + 1] = share_a[i] + dist(w[a[i]], w[a[(i + 1) % n]]);
    for (std::size_t j = 0; j < m; ++j)
      share_b[j + 1] = share_b[j] + dist(w[b_at(j)], w[b_at(j + 1)]);
    for (double &x : share_a) x /= std::max(share_a[n], 1e-300);
    for (double &x : share_b) x /= std::max(share_b[m], 1e-300);
  }
  std::vector<Tri> strip;
  std::size_t i = 0, j = 0;  // steps taken along a and along b
  while (i < n || j < m) {
    const uint32_t ai = a[i % n], bj = b_at(j);
    const uint32_t a_next = a[(i + 1) % n], b_next = b_at(j + 1);
    const bool along_a =
        j == m || (i < n && (by_share ? share_a[i + 1] <= share_b[j + 1]
                                      : norm2(w[a_next] - w[bj]) <= norm2(w[ai] - w[b_next])));
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

// A few faces lying within kStrayReach spacings of another piece of the surface are taken
// away, so that their points are offered to the take-in like any other left-out point: a
// second layer a noisy patch grew, which no fill can join to the first, or an island left in
// a hole of the other piece, which blocks its patch. A small piece away from other surfaces
// stays, unless its edges are many times the cloud's typical spacing: then its corners are a
// few stray points (outliers) that happened to span triangles, and they stay out of the mesh.
// Before the fill only sparse pieces go (layers = false): outliers that spanned triangles
// among themselves would otherwise take more in from the loops' pools and grow.
std::size_t LoopFiller::drop_stray_pieces(bool layers) {
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
    bool on_other = true, closed = true;
    std::size_t strays_listed = 0, others_listed = 0;  // in the corners' lists
    edges.clear();
    for (uint32_t f : faces) {
      const Tri &t = g_.mesh.stored(f);
      for (int i = 0; i < 3; ++i) {
        edges.push_back(dist(w[t[i]], w[t[(i + 1) % 3]]));
        uint32_t fs[2];
        closed &= g_.mesh.edge_faces(t[i], t[(i + 1) % 3], fs) == 2;
        // Some neighbour of the corner on another piece, within kStrayReach local spacings:
        // the larger of the two points', as a clump of close points has a tiny one.
        const uint32_t v = t[i];
        const uint32_t *nb = g_.nb.of(v);
        bool near = false;
        for (unsigned j = 0; j < g_.nb.k; ++j) {
          if (g_.nb.in_the_volume(nb[j]))
            ++strays_listed;
          else
            ++others_listed;
        }
        for (unsigned j = 0; j < g_.nb.k && !near; ++j) {
          const FacesAround around = g_.mesh.faces_at(nb[j]);
          near = !around.empty() && pieces.of(around.front()) != piece &&
                 dist(w[v], w[nb[j]]) <=
                     kStrayReach * std::max(g_.nb.spacing[v], g_.nb.spacing[nb[j]]);
        }
        on_other &= near;
      }
    }
    std::nth_element(edges.begin(), edges.begin() + std::ptrdiff_t(edges.size() / 2), edges.end());
    const bool layer = layers && faces.size() <= kMaxStrayFaces && on_other;
    const double median_edge = edges[edges.size() / 2];
    const bool sparse =
        (median_edge > sparse_edge && !(closed && faces.size() > kMaxSparseFaces)) ||
        (faces.size() <= kMaxSparseFaces && (median_edge > kTinySparseSpacings * g_.spacing ||
                                             strays_listed > others_listed));
    if (!layer && !sparse) continue;
    for (uint32_t f : faces) g_.mesh.remove(f);
    removed += faces.size();
  }
  return removed;
}

}  // namespace moa
