// Internal steps of analyze_mesh, one file each.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "quality/quality.hpp"

namespace moa::quality {

// Face classes decided before the topology.
enum FaceClass : uint8_t {
  kFaceOk = 0,         // usable everywhere
  kFaceFlat = 1,       // exactly collinear or non-finite vertices: topology only
  kFaceRepeated = 2,   // repeated index: left out of the topology
  kFaceInvalid = 3,    // index out of range: left out of everything
};

// Edges, fans, boundary loops, components, orientation and genus of the faces whose class is
// kFaceOk or kFaceFlat.
void analyze_topology(const double *xyz, size_t vertex_count, const uint32_t *tri,
                      size_t triangle_count, const std::vector<uint8_t> &face_class,
                      MeshReport &report);

// Exact self-intersection test of the kFaceOk faces with an Embree broad phase. Lists at most
// max_listed pairs in report.intersecting_pairs (find_mesh_defects wants them all).
void find_self_intersections(const double *xyz, const uint32_t *tri, size_t triangle_count,
                             const std::vector<uint8_t> &face_class, MeshReport &report,
                             size_t max_listed = MeshReport::kMaxListed);

// Union-find over 32-bit ids with path halving; `parity` variant tracks whether two elements
// need opposite orientations.
class UnionFind {
 public:
  explicit UnionFind(size_t n) : parent_(n) {
    for (size_t i = 0; i < n; ++i) parent_[i] = static_cast<uint32_t>(i);
  }
  uint32_t find(uint32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  // Keeps the smaller id as the root, so roots do not depend on the order of unions.
  void unite(uint32_t a, uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b) parent_[b] = a; else parent_[a] = b;
  }

 private:
  std::vector<uint32_t> parent_;
};

}  // namespace moa::quality
