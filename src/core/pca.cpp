#include "core/pca.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace moa {

PcaFrame pca_frame(const std::vector<Vec3> &p, uint32_t self, const uint32_t *nb, unsigned k) {
  auto vec = [&](uint32_t i) { return Eigen::Vector3d(p[i].x, p[i].y, p[i].z); };
  Eigen::Vector3d mean = vec(self);
  for (unsigned j = 0; j < k; ++j) mean += vec(nb[j]);
  mean /= double(k + 1);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  auto add = [&](uint32_t i) {
    Eigen::Vector3d d = vec(i) - mean;
    cov += d * d.transpose();
  };
  add(self);
  for (unsigned j = 0; j < k; ++j) add(nb[j]);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
  es.computeDirect(cov);
  PcaFrame f;
  f.centroid = {mean.x(), mean.y(), mean.z()};
  for (int a = 0; a < 3; ++a) {
    Eigen::Vector3d e = es.eigenvectors().col(a);
    f.axis[a] = normalized(Vec3{e.x(), e.y(), e.z()});
    f.spread[a] = es.eigenvalues()(a);
  }
  return f;
}

double flatness_ratio(const PcaFrame &f) {
  return f.spread[1] > 0 ? std::sqrt(std::max(0.0, f.spread[0]) / f.spread[1]) : 0.0;
}

}  // namespace moa
