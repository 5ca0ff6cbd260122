// Stage 2: neighbours. A nanoflann kd-tree over the Morton-ordered points answers the k-NN
// queries in parallel blocks; each point also gets its spacing. The PCA plane of a point and its
// neighbours is the topology judgment's local reference plane.
#include "core/neighbors.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <nanoflann.hpp>

namespace moa {
namespace {

struct Cloud {
  const std::vector<Vec3> &p;
  std::size_t kdtree_get_point_count() const { return p.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t d) const {
    return d == 0 ? p[i].x : d == 1 ? p[i].y : p[i].z;
  }
  template <class Box>
  bool kdtree_get_bbox(Box &) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud,
                                                 3, uint32_t>;

constexpr unsigned kSpacingNeighbors = 6;

Vec3 least_squares_normal(const std::vector<Vec3> &p, uint32_t self, const uint32_t *nb,
                          unsigned k) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  auto vec = [&](uint32_t i) { return Eigen::Vector3d(p[i].x, p[i].y, p[i].z); };
  mean += vec(self);
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
  Eigen::Vector3d n = es.eigenvectors().col(0);
  return normalized(Vec3{n.x(), n.y(), n.z()});
}

}  // namespace

Neighborhood compute_neighbors(const PointSet &points, unsigned k,
                               const std::function<void(double)> &tick) {
  const std::vector<Vec3> &p = points.work;
  const std::size_t n = p.size();
  Neighborhood nb;
  nb.k = unsigned(std::min<std::size_t>(k, n - 1));
  nb.knn.resize(n * nb.k);
  nb.spacing.resize(n);

  Cloud cloud{p};
  Tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(12));
  const unsigned want = nb.k + 1;  // the point itself comes back too
  const std::size_t block = 16384;
  for (std::size_t start = 0; start < n; start += block) {
    const std::size_t end = std::min(n, start + block);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(start, end, 256),
                      [&](const tbb::blocked_range<std::size_t> &r) {
                        std::vector<uint32_t> idx(want);
                        std::vector<double> d2(want);
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          double q[3] = {p[i].x, p[i].y, p[i].z};
                          std::size_t got = tree.knnSearch(q, want, idx.data(), d2.data());
                          uint32_t *out = nb.knn.data() + i * nb.k;
                          unsigned m = 0;
                          for (std::size_t j = 0; j < got && m < nb.k; ++j)
                            if (idx[j] != i) out[m++] = idx[j];
                          // Ties at equal distance come back in tree order; sort them by (distance,
                          // index) so the neighbour lists are canonical.
                          std::vector<std::pair<double, uint32_t>> tmp(m);
                          for (unsigned j = 0; j < m; ++j)
                            tmp[j] = {norm2(p[out[j]] - p[i]), out[j]};
                          std::sort(tmp.begin(), tmp.end());
                          double sum = 0;
                          unsigned ns = std::min(kSpacingNeighbors, m);
                          for (unsigned j = 0; j < m; ++j) {
                            out[j] = tmp[j].second;
                            if (j < ns) sum += std::sqrt(tmp[j].first);
                          }
                          nb.spacing[i] = float(sum / std::max(1u, ns));
                        }
                      });
    tick(double(end) / double(n));
  }
  return nb;
}

Vec3 plane_normal(const PointSet &points, const Neighborhood &nb, uint32_t i) {
  return least_squares_normal(points.work, i, nb.of(i), nb.k);
}

}  // namespace moa
