// Stage 2b: near duplicates, found through the k-NN lists, by two rules (near_duplicates.hpp).
// Copies: a point whose nearest neighbour is far closer than its tenth nearest. Measured against
// the tenth, not against the spacing: in a contour stack the spacing is stretched to the gap
// between slices (neighbors.cpp), and points along a slice may lie far closer than that without
// being copies. A point given up to nine more times still has a tenth neighbour elsewhere.
// Jittered copies: tight clusters, in regions made mostly of them.
#include "core/near_duplicates.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>

#include "core/disjoint_sets.hpp"
#include "core/mesh_state.hpp"

namespace moa {
namespace {

constexpr unsigned kReferenceRank = 9;  // 0-based: the tenth nearest

// Point i's tight cluster: itself and its m nearest (m < kMaxCopies), for the smallest m whose
// m-th nearest lies within kTightRatio of the (m+1)-th; empty when there is none. Distances are
// the caller's (placed): the lists are ordered by the smoothed copy in a noisy cloud, which
// brings points stacked across the surface together; those are not copies.
struct TightCluster {
  unsigned size = 0;
  uint32_t members[kMaxCopies - 1] = {};
  // The nearest member lies off the line to the nearest point outside (more than 30 degrees):
  // points strewn along lines have their chance clusters on their line.
  bool across = false;
};

// `ordered`: the lists are ordered by p already (no smoothed copy), so the first few suffice.
TightCluster tight_cluster(const std::vector<Vec3> &p, const Neighborhood &nb, uint32_t i,
                           bool ordered) {
  constexpr unsigned kProbe = 2 * kMaxCopies;
  std::pair<double, uint32_t> near[kProbe];
  const unsigned probe = std::min(ordered ? kMaxCopies : kProbe, nb.k);
  for (unsigned j = 0; j < probe; ++j) near[j] = {dist(p[i], p[nb.of(i)[j]]), nb.of(i)[j]};
  if (!ordered) std::sort(near, near + probe);
  TightCluster c;
  for (unsigned m = 1; m < kMaxCopies && m < probe; ++m)
    if (near[m - 1].first < kTightRatio * near[m].first) {
      c.size = m;
      for (unsigned j = 0; j < m; ++j) c.members[j] = near[j].second;
      c.across = off_line(p[near[0].second] - p[i], p[near[m].second] - p[i]);
      break;
    }
  return c;
}

}  // namespace

std::vector<uint32_t> near_duplicates(const PointSet &points, const Neighborhood &nb) {
  const std::vector<Vec3> &p = points.placed();
  const std::size_t n = points.size();
  if (nb.k == 0) return {};
  const unsigned reference = std::min(kReferenceRank, nb.k - 1);
  // Whether point i's nearest neighbour lies within `share` of the distance to its tenth.
  auto within = [&](uint32_t i, double share) {
    const uint32_t *list = nb.of(i);
    return dist(p[i], p[list[0]]) < share * dist(p[i], p[list[reference]]);
  };
  const bool ordered = points.raw_work.empty();
  // Counts of points: nearest within kCopyDistance, in a tight cluster, in one across a line.
  struct Counts {
    std::size_t copied = 0, clustered = 0, across = 0;
  };
  std::vector<uint8_t> tight(n);
  const Counts counts = tbb::parallel_reduce(
      tbb::blocked_range<uint32_t>(0, uint32_t(n), 4096), Counts{},
      [&](const tbb::blocked_range<uint32_t> &r, Counts sum) {
        for (uint32_t i = r.begin(); i != r.end(); ++i) {
          sum.copied += within(i, kCopyDistance);
          const TightCluster c = tight_cluster(p, nb, i, ordered);
          tight[i] = c.size > 0;
          sum.clustered += tight[i];
          sum.across += c.across;
        }
        return sum;
      },
      [](Counts a, const Counts &b) {
        a.copied += b.copied, a.clustered += b.clustered, a.across += b.across;
        return a;
      });
  const bool copies = double(counts.copied) >= kCopiedShare * double(n);
  // A region given twice: most of a point's neighbours are in tight clusters too. Where the
  // clusters lie along lines, chance makes that common, unless the whole cloud has copies; with
  // fewer than kRegionNeighbors in the lists (a parameter), the region is too small to judge.
  // Nor is there a region in a cloud of a few dozen points: the lists hold half of it, and a
  // box's 8 corners, 1 x 4 x 4, are "tight clusters" across its thin side (4 points were left).
  const bool clustered_cloud = double(counts.clustered) >= kClusteredShare * double(n);
  const bool judge_regions =
      !lists_hold_half(nb, n) &&
      (clustered_cloud || (double(counts.across) >= kMinAcrossShare * double(counts.clustered) &&
                           nb.k >= kRegionNeighbors));
  const double region_share = clustered_cloud ? kRegionShareInClusteredCloud : kRegionShare;
  const unsigned region = std::min(kRegionNeighbors, nb.k);
  auto in_jittered_region = [&](uint32_t i) {
    unsigned around = 0;
    for (unsigned j = 0; j < region; ++j) around += tight[nb.of(i)[j]];
    return double(around) >= region_share * double(region);
  };

  DisjointSets group;  // allocated at the first join: most clouds have none
  bool joined = false;
  auto join = [&](uint32_t a, uint32_t b) {
    if (!joined) group.reset(n), joined = true;
    group.join(a, b);
  };
  for (uint32_t i = 0; i < n; ++i) {
    if (copies && within(i, kNearDuplicateDistance)) join(i, nb.of(i)[0]);
    if (judge_regions && tight[i] && in_jittered_region(i)) {
      // Found again rather than kept from the count: few points get here, and keeping every
      // cluster's members would cost 12 bytes a point.
      const TightCluster c = tight_cluster(p, nb, i, ordered);
      for (unsigned m = 0; m < c.size; ++m) join(i, c.members[m]);
    }
  }
  if (!joined) return {};
  // Each group keeps the member the caller gave first.
  std::vector<uint32_t> keep(n, kNone);
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t &k = keep[group.root(i)];
    if (k == kNone || points.original[i] < points.original[k]) k = i;
  }
  std::vector<uint32_t> merged;
  for (uint32_t i = 0; i < n; ++i)
    if (keep[group.root(i)] != i) merged.push_back(points.original[i]);
  if (n - merged.size() < 4) return {};
  std::sort(merged.begin(), merged.end());
  return merged;
}

}  // namespace moa
