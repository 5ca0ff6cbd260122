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
// Copies moved farther (jittered up to about a third of the nearest-neighbour distance, or
// shifted by a registration error that small) are told by tight clusters: a point whose m
// nearest (m < kMaxCopies) lie within kTightRatio of the distance to the next one.
// - Points in such clusters: random surface samples 13-14 %, contour stacks 29-38 %, points at
//   random along lines 45 %; a cloud given twice with a jitter of a fifth of the
//   nearest-neighbour distance 85 %, of a third 62 %.
// - A cluster is merged when at least kRegionShare of the point's kRegionNeighbors nearest are
//   in clusters too: a region given twice, as where two scans overlap. No point of about three
//   million in random samples of 20 clouds passes, nor of two sheets closer than their spacing.
// - Of points along lines 0.5 % pass, but their clusters lie along their lines (the nearest
//   member within 30 degrees of the line to the next point: nearly all of them, against a
//   third in random samples and 13 % for copies jittered in 3-D). A cloud with fewer than
//   kMinAcrossShare of its clusters across that line is left alone.
// - When kClusteredShare of the whole cloud is in clusters, the cloud has copies, and a region
//   needs only kRegionShareInClusteredCloud. A random region has 13-14 %; 0.4 % of a random
//   sample's points have a cluster in a region of 40 %. A 20,000-point bunny sample with half
//   of it given twice (jitter 5 %) has 10,130 points merged for its 10,000 copies: the others
//   are points closer to one another than a few jitters. At 50 %, a 20,000-point elephant
//   sample given twice with a jitter of a third of the spacing kept 14 boundary edges.
inline constexpr double kTightRatio = 0.35;
inline constexpr unsigned kMaxCopies = 4;
inline constexpr unsigned kRegionNeighbors = 20;
inline constexpr double kRegionShare = 0.8;
inline constexpr double kClusteredShare = 0.55;
inline constexpr double kRegionShareInClusteredCloud = 0.4;
inline constexpr double kMinAcrossShare = 0.3;

// The caller's indices of the points to leave out: of each group of near duplicates, all but
// the one with the lowest caller index. Empty when neither rule finds copies, or when fewer
// than 4 points would be left. Independent of the thread count.
std::vector<uint32_t> near_duplicates(const PointSet &points, const Neighborhood &nb);

}  // namespace moa
