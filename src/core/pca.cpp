#include "core/pca.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace moa {

namespace {

Eigen::Vector3d vec(const Vec3 &v) { return Eigen::Vector3d(v.x, v.y, v.z); }

// The axes of a scatter matrix, smallest spread first, about the given centre.
PcaFrame frame_of(const Eigen::Matrix3d &cov, const Eigen::Vector3d &centre) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
  es.computeDirect(cov);
  PcaFrame f;
  f.centroid = {centre.x(), centre.y(), centre.z()};
  for (int a = 0; a < 3; ++a) {
    Eigen::Vector3d e = es.eigenvectors().col(a);
    f.axis[a] = normalized(Vec3{e.x(), e.y(), e.z()});
    f.spread[a] = es.eigenvalues()(a);
  }
  return f;
}

// The frame of point `self` and its k neighbours `nb`, each scattered about the centre of its
// sheet (sheet_of(j): 0, with self, or 1); centred on sheet 0.
template <class SheetOf>
PcaFrame sheets_frame(const std::vector<Vec3> &p, uint32_t self, const uint32_t *nb, unsigned k,
                      SheetOf sheet_of) {
  Eigen::Vector3d mean[2] = {vec(p[self]), Eigen::Vector3d::Zero()};
  double count[2] = {1, 0};
  for (unsigned j = 0; j < k; ++j) {
    mean[sheet_of(j)] += vec(p[nb[j]]);
    ++count[sheet_of(j)];
  }
  for (int s = 0; s < 2; ++s)
    if (count[s] > 0) mean[s] /= count[s];
  // Only the six distinct entries of the symmetric scatter are summed (xx, yx, zx, yy, zy, zz),
  // not a full outer product per neighbour.
  double lower[6] = {0, 0, 0, 0, 0, 0};
  auto add = [&](uint32_t i, int s) {
    const Eigen::Vector3d d = vec(p[i]) - mean[s];
    lower[0] += d.x() * d.x();
    lower[1] += d.y() * d.x();
    lower[2] += d.z() * d.x();
    lower[3] += d.y() * d.y();
    lower[4] += d.z() * d.y();
    lower[5] += d.z() * d.z();
  };
  add(self, 0);
  for (unsigned j = 0; j < k; ++j) add(nb[j], sheet_of(j));
  Eigen::Matrix3d cov;
  cov << lower[0], lower[1], lower[2],  //
      lower[1], lower[3], lower[4],     //
      lower[2], lower[4], lower[5];
  return frame_of(cov, mean[0]);
}

}  // namespace

PcaFrame pca_frame(const std::vector<Vec3> &p, uint32_t self, const uint32_t *nb, unsigned k) {
  return sheets_frame(p, self, nb, k, [](unsigned) { return 0; });
}

PcaFrame pca_frame_two_sheets(const std::vector<Vec3> &p, uint32_t self, const uint32_t *nb,
                              unsigned k, const bool *far_sheet) {
  return sheets_frame(p, self, nb, k, [far_sheet](unsigned j) { return far_sheet[j] ? 1 : 0; });
}

double flatness_ratio(const PcaFrame &f) {
  return f.spread[1] > 0 ? std::sqrt(std::max(0.0, f.spread[0]) / f.spread[1]) : 0.0;
}

}  // namespace moa
