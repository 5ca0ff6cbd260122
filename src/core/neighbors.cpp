// Stage 2: neighbours. A nanoflann kd-tree over the Morton-ordered points answers the k-NN
// queries in parallel blocks; each point also gets its spacing. The PCA plane of a point and its
// neighbours is the topology judgment's local reference plane.
#include "core/neighbors.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/kd_tree.hpp"
#include "core/pca.hpp"

namespace moa {
namespace {

constexpr unsigned kSpacingNeighbors = 6;

}  // namespace

Neighborhood compute_neighbors(const KdIndex &index, unsigned k,
                               const std::function<void(double)> &tick) {
  const std::vector<Vec3> &p = index.points();
  const std::size_t n = p.size();
  Neighborhood nb;
  nb.k = unsigned(std::min<std::size_t>(k, n - 1));
  nb.knn.resize(n * nb.k);
  nb.spacing.resize(n);

  const unsigned want = nb.k + 1;  // the point itself comes back too
  const std::size_t block = 16384;
  for (std::size_t start = 0; start < n; start += block) {
    const std::size_t end = std::min(n, start + block);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(start, end, 256),
                      [&](const tbb::blocked_range<std::size_t> &r) {
                        std::vector<uint32_t> idx(want);
                        std::vector<double> d2(want);
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          std::size_t got = index.nearest(p[i], want, idx.data(), d2.data());
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

double median_spacing(const Neighborhood &nb) {
  std::vector<float> s(nb.spacing);
  std::nth_element(s.begin(), s.begin() + std::ptrdiff_t(s.size() / 2), s.end());
  return std::max(1e-9, double(s[s.size() / 2]));
}

Vec3 plane_normal(const PointSet &points, const Neighborhood &nb, uint32_t i) {
  return pca_frame(points.work, i, nb.of(i), nb.k).axis[0];
}

}  // namespace moa
