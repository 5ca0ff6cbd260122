// Stage 2b: near duplicates. A cloud made of pairs of nearly coincident points (two copies of
// one sample, one of them rounded to single precision or moved slightly by a registration) has
// a second sample at every site, a small fraction of the spacing away. MOA then meets a fan of
// needle-short segments at every point, and the surface falls apart: a 10,000-point sphere
// given twice, the copy moved by 10^-7 to 10^-3 of the nearest-neighbour distance, kept 74 to
// 5,233 boundary edges. Such pairs are merged into one point, the caller's first, as exact
// duplicates are. A few close pairs by chance (a random sample has some) mesh well and stay.
#pragma once

#include <cstdint>
#include <vector>

#include "core/neighbors.hpp"
#include "core/point_set.hpp"

namespace moa {

// Distances are measured against the distance from a point to its tenth nearest neighbour. A
// cloud counts as given more than once when at least kCopiedShare of its points have their
// nearest neighbour within kCopyDistance of that: a cloud given twice has all of them there, a
// random sample of a surface about 0.01 %, and points strewn at random along contour lines,
// whose close pairs are far more common (one dimension, not two), 0.7-1.5 %. In such a cloud
// every point within kNearDuplicateDistance of its nearest is a near duplicate: copies
// jittered by up to about a fiftieth of the spacing.
inline constexpr double kCopyDistance = 0.003;
inline constexpr double kCopiedShare = 0.2;
inline constexpr double kNearDuplicateDistance = 0.03;

// The caller's indices of the points to leave out: of each group of near duplicates, all but
// the one with the lowest caller index. Empty unless the cloud counts as given more than once,
// or when fewer than 4 points would be left. Independent of the thread count.
std::vector<uint32_t> near_duplicates(const PointSet &points, const Neighborhood &nb);

}  // namespace moa
