// The kd-tree (nanoflann) over work coordinates, shared by the neighbour and smoothing stages.
#pragma once

#include <cstdint>
#include <vector>

#include <nanoflann.hpp>

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

 private:
  KdCloud cloud_;
  KdTree tree_;
};

}  // namespace moa
