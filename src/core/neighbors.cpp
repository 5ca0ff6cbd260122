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

// Anisotropic samples: CT and MRI contour stacks, scanner stripes. Points lie close together
// along lines that are several times farther apart, so a point's nearest neighbours all lie on
// its own line, and their mean distance measures the line, not the gaps between lines, which
// the sphere of a segment must reach across. A neighbour is "across" when the direction to it
// makes more than 30 degrees with the line through the nearest one (cos^2 30 = 0.75). In such
// a cloud the spacing is at least kAcrossShare of the distance to the nearest across.
constexpr double kAlongCos2 = 0.75;
constexpr double kAcrossShare = 0.8;
// The cloud counts as sampled along lines when the floor raises the spacing of at least this
// share of its points. On an even sample it raises about 3 % (points whose nearest two or
// three happen to line up); on contour stacks 70 to 97 %. Below the share nothing changes, so
// that a few chance alignments do not perturb the spheres of an even sample.
constexpr double kLinedShare = 0.25;

bool across(const Vec3 &offset, const Vec3 &first) {
  const double c = dot(offset, first);
  return c * c < kAlongCos2 * norm2(offset) * norm2(first);
}

}  // namespace

Neighborhood compute_neighbors(const KdIndex &index, unsigned k,
                               const std::function<void(double)> &tick) {
  const std::vector<Vec3> &p = index.points();
  const std::size_t n = p.size();
  Neighborhood nb;
  nb.k = unsigned(std::min<std::size_t>(k, n - 1));
  nb.knn.resize(n * nb.k);
  nb.spacing.resize(n);

  std::vector<float> across_gap(n, 0.0f);  // distance to the nearest across; 0: none
  const unsigned want = nb.k + 1;  // the point itself comes back too
  const std::size_t block = 16384;
  for (std::size_t start = 0; start < n; start += block) {
    const std::size_t end = std::min(n, start + block);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(start, end, 256),
                      [&](const tbb::blocked_range<std::size_t> &r) {
                        std::vector<uint32_t> idx(want);
                        std::vector<double> d2(want);
                        std::vector<std::pair<double, uint32_t>> list;
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          std::size_t got = index.nearest(p[i], want, idx.data(), d2.data());
                          list.clear();
                          for (std::size_t j = 0; j < got && list.size() < nb.k; ++j)
                            if (idx[j] != i) list.push_back({norm2(p[idx[j]] - p[i]), idx[j]});
                          // Ties at equal distance come back in tree order; sorted by (distance,
                          // index) the lists are canonical.
                          std::sort(list.begin(), list.end());
                          if (list.empty()) continue;  // a single point
                          uint32_t *out = nb.knn.data() + i * nb.k;
                          const unsigned m = unsigned(list.size());
                          const unsigned ns = std::min(kSpacingNeighbors, m);
                          const Vec3 first = p[list[0].second] - p[i];
                          double sum = 0;
                          for (unsigned j = 0; j < m; ++j) {
                            out[j] = list[j].second;
                            if (j < ns) sum += std::sqrt(list[j].first);
                            if (across_gap[i] == 0 && across(p[out[j]] - p[i], first))
                              across_gap[i] = float(std::sqrt(list[j].first));
                          }
                          nb.spacing[i] = float(sum / ns);
                        }
                      });
    tick(double(end) / double(n));
  }
  std::size_t raised = 0;
  for (std::size_t i = 0; i < n; ++i) raised += kAcrossShare * across_gap[i] > nb.spacing[i];
  if (double(raised) >= kLinedShare * double(n))
    for (std::size_t i = 0; i < n; ++i)
      nb.spacing[i] = std::max(nb.spacing[i], float(kAcrossShare * across_gap[i]));
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
