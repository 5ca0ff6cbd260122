// Principal axes of a small neighbourhood: the local plane used by the neighbour, smoothing and
// noise stages.
#pragma once

#include <cstdint>
#include <vector>

#include "core/geometry.hpp"

namespace moa {

struct PcaFrame {
  Vec3 centroid;
  Vec3 axis[3];      // unit axes, smallest spread first: axis[0] is the plane's normal
  double spread[3];  // eigenvalues of the scatter matrix (sums, not means), ascending
};

// The frame of point `self` and its k neighbours `nb`.
PcaFrame pca_frame(const std::vector<Vec3> &p, uint32_t self, const uint32_t *nb, unsigned k);

// The frame of two parallel sheets: point `self` and its k neighbours `nb`, those with
// far_sheet[j] set scattered about their own centre and the others (with self) about theirs.
// Its normal is the sheets' common normal, which the frame of all the points tilts when the
// far sheet's share lies off to one side.
PcaFrame pca_frame_two_sheets(const std::vector<Vec3> &p, uint32_t self, const uint32_t *nb,
                              unsigned k, const bool *far_sheet);

// Thickness over width of a frame's neighbourhood: the spread off the plane against the larger
// spread in it, both as standard deviations; 0 when the neighbourhood has no width.
double flatness_ratio(const PcaFrame &f);

}  // namespace moa
