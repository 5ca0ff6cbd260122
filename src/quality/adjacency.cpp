// The edge map and the fans around vertices, shared by analyze_topology (counts) and
// find_mesh_defects (lists).
#include <tbb/parallel_sort.h>

#include <algorithm>

#include "quality/analysis.hpp"

namespace moa::quality {

std::vector<EdgeRecord> sorted_edge_records(const uint32_t *tri, size_t triangle_count,
                                            const std::vector<uint8_t> &face_class) {
  std::vector<EdgeRecord> records;
  records.reserve(3 * triangle_count);
  for (size_t f = 0; f < triangle_count; ++f) {
    if (face_class[f] > kFaceFlat) continue;
    for (uint32_t k = 0; k < 3; ++k) {
      const uint64_t a = tri[3 * f + k], b = tri[3 * f + (k + 1) % 3];
      records.push_back({a < b ? (a << 32 | b) : (b << 32 | a), static_cast<uint32_t>(f), k});
    }
  }
  tbb::parallel_sort(records.begin(), records.end());
  return records;
}

VertexFaces faces_around_vertices(const uint32_t *tri, size_t triangle_count, size_t vertex_count,
                                  const std::vector<uint8_t> &face_class) {
  VertexFaces vf;
  vf.offset.assign(vertex_count + 1, 0);
  for (size_t f = 0; f < triangle_count; ++f)
    if (face_class[f] <= kFaceFlat)
      for (int k = 0; k < 3; ++k) ++vf.offset[tri[3 * f + k] + 1];
  for (size_t v = 0; v < vertex_count; ++v) vf.offset[v + 1] += vf.offset[v];
  vf.faces.resize(vf.offset[vertex_count]);
  std::vector<uint32_t> fill(vf.offset.begin(), vf.offset.end() - 1);
  for (size_t f = 0; f < triangle_count; ++f)
    if (face_class[f] <= kFaceFlat)
      for (int k = 0; k < 3; ++k) vf.faces[fill[tri[3 * f + k]]++] = static_cast<uint32_t>(f);
  return vf;
}

uint32_t fan_root(std::vector<uint32_t> &parent, uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

uint32_t group_fans(uint32_t v, const uint32_t *faces, uint32_t m, const uint32_t *tri,
                    const std::vector<uint32_t> &face_edge,
                    std::vector<std::pair<uint32_t, uint32_t>> &around,
                    std::vector<uint32_t> &parent) {
  around.clear();
  parent.resize(m);
  for (uint32_t i = 0; i < m; ++i) {
    const size_t f = faces[i];
    const int k = tri[3 * f] == v ? 0 : tri[3 * f + 1] == v ? 1 : 2;
    parent[i] = i;
    // The two edges of f at v: the one leaving v and the one arriving at it.
    around.push_back({face_edge[3 * f + k], i});
    around.push_back({face_edge[3 * f + (k + 2) % 3], i});
  }
  std::sort(around.begin(), around.end());
  for (size_t a = 1; a < around.size(); ++a)
    if (around[a].first == around[a - 1].first) {
      const uint32_t x = fan_root(parent, around[a].second),
                     y = fan_root(parent, around[a - 1].second);
      if (x != y) parent[std::max(x, y)] = std::min(x, y);
    }
  uint32_t fans = 0;
  for (uint32_t i = 0; i < m; ++i) fans += fan_root(parent, i) == i;
  return fans;
}

}  // namespace moa::quality
