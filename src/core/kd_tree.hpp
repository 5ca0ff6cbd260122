// The kd-tree (nanoflann) over work coordinates, shared by the neighbour and smoothing stages.
#pragma once

#include <algorithm>
#include <cstdint>
#include <nanoflann.hpp>
#include <utility>
#include <vector>

#include "core/geometry.hpp"

namespace moa {

struct KdCloud {
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

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, KdCloud>,
                                                   KdCloud, 3, uint32_t>;

// A tree built over `points`, which must outlive it and stay unchanged.
class KdIndex {
 public:
  // Leaf size 12: a good balance of build and query time for 10-300 neighbours.
  explicit KdIndex(const std::vector<Vec3> &points)
      : cloud_{points}, tree_(3, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(12)) {}
  KdIndex(const KdIndex &) = delete;
  KdIndex &operator=(const KdIndex &) = delete;
  const std::vector<Vec3> &points() const { return cloud_.p; }
  // Up to k nearest points to q (itself included when q is a point), nearest first; returns
  // how many were found.
  std::size_t nearest(const Vec3 &q, std::size_t k, uint32_t *idx, double *d2) const {
    double xyz[3] = {q.x, q.y, q.z};
    return tree_.knnSearch(xyz, k, idx, d2);
  }
  // The k nearest points to q by (distance, index), for large k: nanoflann's k-NN search keeps
  // its results in a sorted array (cost k^2), a ball search costs about k. The ball is sized
  // from the nearest few and grown until it holds k points.
  void nearest_many(const Vec3 &q, std::size_t k,
                    std::vector<std::pair<uint32_t, double>> &out) const {
    constexpr std::size_t kProbe = 16;
    uint32_t idx[kProbe];
    double d2[kProbe];
    const std::size_t got = nearest(q, std::min(k, kProbe), idx, d2);
    double radius2 = std::max(d2[got - 1], 1e-300) * double(k) / double(got) * 2.0;
    for (within(q, radius2, out); out.size() < k && out.size() < cloud_.p.size();
         within(q, radius2, out))
      radius2 *= 2.0;
    auto closer = [](const std::pair<uint32_t, double> &a, const std::pair<uint32_t, double> &b) {
      return a.second != b.second ? a.second < b.second : a.first < b.first;
    };
    // The order is total, so selecting and then sorting gives what a partial sort would, at
    // a fraction of the cost of its heap (a twentieth of the noise estimate's time).
    const std::size_t keep = std::min(k, out.size());
    if (keep == 0) return out.clear();
    std::nth_element(out.begin(), out.begin() + std::ptrdiff_t(keep - 1), out.end(), closer);
    out.resize(keep);
    std::sort(out.begin(), out.end(), closer);
  }
  // Every point closer to q than sqrt(radius2), with its squared distance, in the tree's
  // (deterministic) order; cheaper than a k-NN query when many points are wanted.
  void within(const Vec3 &q, double radius2, std::vector<std::pair<uint32_t, double>> &out) const {
    double xyz[3] = {q.x, q.y, q.z};
    out.clear();
    tree_.radiusSearch(xyz, radius2, out, nanoflann::SearchParams(32, 0.0f, false));
  }

 private:
  KdCloud cloud_;
  KdTree tree_;
};

}  // namespace moa
