// Bands: in a contour stack, a hole between two contours running side by side, where the
// surface runs nearly along the cuts (a face tilted a few degrees off them) and the contours lie
// tens of spacings apart on it. No segment's sphere reaches across and the loop is a border by
// its width, so nothing else closes it. Its loop is two runs along the contours, joined by an
// edge across at each end; the band is stitched from one end to the other, each step taking the
// next point of whichever run gives the shorter new edge across (the classic way to tile the
// space between two contours), each triangle through the relaxed judgment; where one fails,
// the rest of the band is stitched from its other end, as far as the judgment allows.
#include <cstddef>
#include <vector>

#include "core/loop_filler.hpp"
#include "core/neighbors.hpp"

namespace moa {
namespace {

// Longest loop stitched: a band is as long as its contours.
constexpr std::size_t kMaxBandLoop = 8192;

// Whether edge uv runs along a line of the cloud: within 30 degrees of the direction from one
// of its ends to that end's nearest neighbour, the way the neighbour stage tells a line apart
// from the next (off_line). One end will do: at a contour's corner the nearest neighbour can
// lie on the other side of the corner.
bool along_line(const GrowthState &g, uint32_t u, uint32_t v) {
  const std::vector<Vec3> &w = g.points.work;
  return !off_line(w[v] - w[u], w[g.nb.of(u)[0]] - w[u]) ||
         !off_line(w[u] - w[v], w[g.nb.of(v)[0]] - w[v]);
}

// The triangles that tile the band between run a (a[0] .. a[m], as the loop runs) and run b,
// which the loop reaches from a's last vertex and leaves for a's first, from the end where b
// meets a[0]. The loop's direction is the one the new faces run along its edges. Each choice
// depends only on where the stitch has got to, so any tail of the list is the stitch of the
// band that the triangles before it leave open.
std::vector<Tri> stitched(const std::vector<uint32_t> &a, const std::vector<uint32_t> &b,
                          const std::vector<Vec3> &w) {
  std::vector<Tri> tris;
  std::size_t i = 0, j = b.size() - 1;  // the edge across from b[j] to a[i] is done
  while (i + 1 < a.size() || j > 0) {
    const bool on_a = j == 0 || (i + 1 < a.size() &&
                                 norm2(w[a[i + 1]] - w[b[j]]) <= norm2(w[a[i]] - w[b[j - 1]]));
    if (on_a) {
      tris.push_back(Tri{a[i], a[i + 1], b[j]});
      ++i;
    } else {
      tris.push_back(Tri{b[j - 1], b[j], a[i]});
      --j;
    }
  }
  return tris;
}

}  // namespace

// Stitches the bands of a lined cloud as far as the relaxed judgment allows, from both ends;
// returns how many were closed.
std::size_t LoopFiller::stitch_bands() {
  if (!g_.nb.lined) return 0;
  collect_hole_edges();
  loops_ = trace_loops();
  std::size_t closed = 0;
  std::vector<uint32_t> sorted, a, b, added;
  std::vector<std::size_t> across;
  const std::vector<Vec3> &w = g_.points.work;
  for (const Loop &loop : loops_) {
    const std::vector<uint32_t> &v = loop.vertices;
    const std::size_t n = v.size();
    if (n < 4 || n > kMaxBandLoop) continue;
    if (!simple_and_untangled(v, sorted)) continue;
    across.clear();
    for (std::size_t i = 0; i < n && across.size() <= 2; ++i)
      if (!along_line(g_, v[i], v[(i + 1) % n])) across.push_back(i);
    if (across.size() != 2) continue;
    g_.poll();
    if (!still_open(v)) continue;
    // Run a from the end of the second edge across to the start of the first; run b between.
    a.clear();
    b.clear();
    for (std::size_t i = (across[1] + 1) % n;; i = (i + 1) % n) {
      a.push_back(v[i]);
      if (i == across[0]) break;
    }
    for (std::size_t i = across[0] + 1; i <= across[1]; ++i) b.push_back(v[i]);
    // From the end where b meets a[0], as far as the judgment lets the stitch go; the rest of
    // the list, which stitches what is left open, from its last triangle back toward there.
    const std::vector<Tri> tris = stitched(a, b, w);
    added.clear();
    g_.add_while_accepted(tris.begin(), tris.end(), added);
    const std::size_t left = tris.size() - added.size();
    if (left > 0) g_.add_while_accepted(tris.rbegin(), tris.rbegin() + std::ptrdiff_t(left), added);
    g_.stats.triangles_loops += added.size();
    closed += added.size() == tris.size();
  }
  return closed;
}

}  // namespace moa
