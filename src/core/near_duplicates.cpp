// Stage 2b: near duplicates, found through the k-NN lists: a point whose nearest neighbour is
// far closer than its tenth nearest. Measured against the tenth, not against the spacing: in a
// contour stack the spacing is stretched to the gap between slices (neighbors.cpp), and points
// along a slice may lie far closer than that without being copies. A point given up to nine
// more times still has a tenth neighbour elsewhere.
#include "core/near_duplicates.hpp"

#include <algorithm>

#include "core/disjoint_sets.hpp"
#include "core/mesh_state.hpp"

namespace moa {
namespace {

constexpr unsigned kReferenceRank = 9;  // 0-based: the tenth nearest

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
  std::size_t copied = 0;
  for (uint32_t i = 0; i < n; ++i) copied += within(i, kCopyDistance);
  if (double(copied) < kCopiedShare * double(n)) return {};

  DisjointSets group(n);
  for (uint32_t i = 0; i < n; ++i)
    if (within(i, kNearDuplicateDistance)) group.join(i, nb.of(i)[0]);
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
