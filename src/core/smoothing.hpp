// Stage 2a: noisy clouds. When the points scatter about their surface by a sizeable fraction of
// their spacing, angles measured between raw points say little about the surface: triangles
// stand on edge, the reference planes wobble and the judgment refuses nearly everything. For
// such clouds the judgment measures its angles on a smoothed copy of the points (each moved
// onto a quadric fitted to its neighbourhood), while the mesh's vertices, and every crossing
// test, stay on the caller's points. Where the noise is small next to the surface's curvature,
// a triangulation chosen on the smoothed points and lifted back onto the raw ones is a graph
// over the same local plane, and a graph does not cross itself.
#pragma once

#include <functional>
#include <vector>

#include "core/geometry.hpp"
#include "core/kd_tree.hpp"
#include "core/point_set.hpp"

namespace moa {

struct NoiseEstimate {
  bool noisy = false;        // the roughness shrinks as the neighbourhood grows, in the cloud
                             // or in enough of its parts; or the lines of a cloud sampled
                             // along lines are not plane curves; or the sheets of a cloud of
                             // thin walls are rough (thin_walls)
  unsigned smoothing_k = 0;  // neighbourhood size at which the cloud looks flattest
  double small_scale = 0;    // median thickness / width at 10 or 20 points, the rougher (at
                             // 10 alone when that is flat: see estimate_noise); over the
                             // noisy-looking points when the cloud is noisy in part
  double large_scale = 0;    // the same at smoothing_k points
  bool thin_walls = false;   // noisy sheets with a far sheet just beyond smoothing_k points
};

// Looks at a fixed sample of points at several neighbourhood sizes. Thickness over width grows
// with the neighbourhood on a clean surface (curvature) and shrinks on a noisy one (the scatter
// is the same at every size while the width grows). In a cloud sampled along lines it also
// looks at each line's thickness. Deterministic. `smoothed`: the points are a smoothed copy
// already (a later pass), not the caller's.
NoiseEstimate estimate_noise(const KdIndex &index, bool smoothed = false);

// Each point moved onto the quadric fitted (least squares, in its PCA frame) to the ball
// around it that holds about k points of a surface; except where whole regions moved several
// times farther than the cloud's median point and they are thin parts (two sheets that one
// quadric pulled together, not creases it rounded off): those points keep their place.
// Where the ball wraps round a part narrower than itself (a neck), the quadric is fitted to a
// smaller, flatter ball of the point's nearest. `near_sheet_only` (NoiseEstimate::thin_walls)
// fits each quadric to the points near the plane of the point's nearest few only, so that a
// far sheet within the ball is left out.
// Parallel over points; independent of the thread count.
std::vector<Vec3> smoothed_points(const KdIndex &index, unsigned k, bool near_sheet_only,
                                  const std::function<void(double)> &tick);

}  // namespace moa
