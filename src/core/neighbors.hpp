// Stage 2 (DESIGN.md §2.2; paper §3.5.1 steps 1-2): k nearest neighbours of every point, the
// local point spacing and, on demand, the local reference plane (PCA normal).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/geometry.hpp"
#include "core/kd_tree.hpp"
#include "core/point_set.hpp"

namespace moa {

// A point's spacing is its mean distance to this many of its nearest neighbours.
inline constexpr unsigned kSpacingNeighbors = 6;

// Marks of stray points (Neighborhood::isolated): beside a surface, or deep in the volume
// among other stray points.
inline constexpr uint8_t kNearSurface = 1;
inline constexpr uint8_t kInTheVolume = 2;

struct Neighborhood {
  unsigned k = 0;                 // the parameter's, or more in a cloud sampled along lines
                                  // or of thin walls
  std::vector<uint32_t> knn;      // k per point, nearest first, the point itself excluded
  std::vector<float> spacing;     // mean distance to the nearest few neighbours (work units); in
                                  // a cloud sampled along lines, or a region of one that is (a
                                  // face a range scan met at a grazing angle), at least most of
                                  // the gap to the nearest neighbour off the point's line
  bool thin_walls = false;        // the cloud's walls are two or three spacings thick: local
                                  // planes look past the far sheet (local_plane)
  bool lined = false;             // the cloud is sampled along lines (kLinedShare)
  std::vector<uint8_t> isolated;  // per point, kNearSurface or kInTheVolume for a stray point
                                  // (isolated_points.hpp), else 0; empty when the cloud has none

  const uint32_t *of(uint32_t i) const { return knn.data() + std::size_t(i) * k; }
  bool alone(uint32_t i) const { return !isolated.empty() && isolated[i] != 0; }
  bool in_the_volume(uint32_t i) const { return !isolated.empty() && isolated[i] == kInTheVolume; }
};

// Parallel over points (TBB); the result does not depend on the number of threads.
// `tick(fraction)` is called now and then from the calling thread; it may throw Cancelled.

Neighborhood compute_neighbors(const KdIndex &index, unsigned k,
                               const std::function<void(double)> &tick);

// Points sampled along lines (contour stacks, scanner stripes): whether the neighbour at
// `offset` from a point lies off the line through the point's nearest neighbour, at
// `to_nearest` (more than 30 degrees from it).
bool off_line(const Vec3 &offset, const Vec3 &to_nearest);
// A cloud is sampled along lines when at least this share of its points lie on one. On an
// even sample about 3 % do (points whose nearest two or three happen to line up), on contour
// stacks 70 to 97 %; below the share nothing changes, so that a few chance alignments do not
// perturb an even sample.
inline constexpr double kLinedShare = 0.25;
// How point i sits among its first m neighbours (nearest first): the mean distance to the
// nearest six, and the distance to and (0-based) rank of the nearest neighbour off the line
// (0 and m when none is).
struct LineMeasure {
  double spacing = 0;
  double across_gap = 0;
  unsigned across_rank = 0;
};
LineMeasure measure_line(const std::vector<Vec3> &p, uint32_t i, const uint32_t *nb, unsigned m);
// Whether a point so measured lies on a line of such a cloud: no neighbour is off the line, or
// the nearest off it is farther than 1.25 spacings (the spacing's floor, 0.8 of that distance,
// would raise the spacing).
bool on_a_line(double spacing, double across_gap);

// The median of the points' spacings (work units), never zero; stray points, once marked
// (isolated_points.hpp), left out: in a cloud with as many stray points as surface points
// theirs would raise it towards their own.
double median_spacing(const Neighborhood &nb);

// Whether the cloud is so small (a few dozen points at the default k) that every point's list
// holds at least half of it: such a list reaches round the object, and what it measures is the
// whole object's, not a neighbourhood's.
inline bool lists_hold_half(const Neighborhood &nb, std::size_t points) {
  return 2 * std::size_t(nb.k) + 1 >= points;
}

// The plane fitted at a point: the unit normal, unoriented, and whether the point lies on one
// sheet of a thin wall whose far sheet, parallel to it, is in the point's list. Undirected when
// the fit has no direction to speak of: in a cloud of a few dozen points, where the list
// holds at least half of the cloud, reaches round the object and scatters about as far in
// every direction (its normal then says nothing of the surface at the point).
struct LocalPlane {
  Vec3 normal;
  bool in_thin_wall = false;
  bool undirected = false;
};

// The least-squares plane through point i and its k neighbours. In a cloud of thin walls, where
// the list holds a far sheet parallel to the point's own: the plane of its nearest few when the
// rest lie on that sheet, else that of the two sheets (each scattered about its own centre).
// Computed when asked (the judgment caches it) rather than stored: 24 bytes per point.
LocalPlane local_plane(const PointSet &points, const Neighborhood &nb, uint32_t i);
// Its normal alone.
Vec3 plane_normal(const PointSet &points, const Neighborhood &nb, uint32_t i);

}  // namespace moa
