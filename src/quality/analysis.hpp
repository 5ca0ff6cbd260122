// Internal steps of analyze_mesh, one file each.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
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

// The edge map and the fans shared by analyze_topology and find_mesh_defects. A face takes part
// in the topology when its class is kFaceOk or kFaceFlat.
struct EdgeRecord {
  uint64_t key;  // (smaller index << 32) | larger index
  uint32_t face;
  uint32_t slot;  // the edge runs from corner slot to corner slot + 1
  bool operator<(const EdgeRecord &o) const {
    return key != o.key ? key < o.key : face != o.face ? face < o.face : slot < o.slot;
  }
};

// One record per edge of each topology face, sorted: runs with one key are the faces of one
// edge.
std::vector<EdgeRecord> sorted_edge_records(const uint32_t *tri, size_t triangle_count,
                                            const std::vector<uint8_t> &face_class);

// The topology faces around each vertex: those of v are faces[offset[v] .. offset[v + 1]).
struct VertexFaces {
  std::vector<uint32_t> offset, faces;
};
VertexFaces faces_around_vertices(const uint32_t *tri, size_t triangle_count, size_t vertex_count,
                                  const std::vector<uint8_t> &face_class);

// Groups the m faces around vertex v into fans (faces joined through an edge at v), given
// face_edge (the edge id of each face corner's edge). Leaves `around` holding the (edge, local
// face) pairs of the edges at v, sorted, and `parent` a union-find over the local faces whose
// roots (fan_root) are the fans. Returns the number of fans.
uint32_t group_fans(uint32_t v, const uint32_t *faces, uint32_t m, const uint32_t *tri,
                    const std::vector<uint32_t> &face_edge,
                    std::vector<std::pair<uint32_t, uint32_t>> &around,
                    std::vector<uint32_t> &parent);
uint32_t fan_root(std::vector<uint32_t> &parent, uint32_t local_face);

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
