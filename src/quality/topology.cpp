// Topology of a triangle soup: the edge map (C2, C4 edge directions), the fans around each
// vertex (C3), boundary loops, components, orientability, Euler characteristic and genus.
#include <cmath>
#include <utility>

#include "quality/analysis.hpp"

namespace moa::quality {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

// Union-find whose elements carry a flip bit relative to their root: uniting two faces that use
// a shared edge in the same direction asks for opposite flips. A contradiction marks the set
// non-orientable.
class ParityUnionFind {
 public:
  explicit ParityUnionFind(size_t n) : parent_(n), parity_(n, 0), conflict_(n, 0) {
    for (size_t i = 0; i < n; ++i) parent_[i] = static_cast<uint32_t>(i);
  }
  uint32_t find(uint32_t x, uint8_t &parity) {
    uint32_t r = x;
    uint8_t acc = 0;
    while (parent_[r] != r) { acc ^= parity_[r]; r = parent_[r]; }
    uint8_t rest = acc;
    while (x != r) {  // point the path at the root
      uint32_t next = parent_[x];
      uint8_t own = parity_[x];
      parent_[x] = r;
      parity_[x] = rest;
      rest ^= own;
      x = next;
    }
    parity = acc;
    return r;
  }
  void unite(uint32_t a, uint32_t b, uint8_t relation) {
    uint8_t pa, pb;
    uint32_t ra = find(a, pa), rb = find(b, pb);
    if (ra == rb) {
      if ((pa ^ pb) != relation) conflict_[ra] = 1;
      return;
    }
    if (ra > rb) std::swap(ra, rb);
    parent_[rb] = ra;
    parity_[rb] = pa ^ pb ^ relation;
    conflict_[ra] |= conflict_[rb];
  }
  bool conflicted(uint32_t x) {
    uint8_t p;
    return conflict_[find(x, p)] != 0;
  }

 private:
  std::vector<uint32_t> parent_;
  std::vector<uint8_t> parity_;
  std::vector<uint8_t> conflict_;
};

}  // namespace

void analyze_topology(const double *xyz, size_t vertex_count, const uint32_t *tri,
                      size_t triangle_count, const std::vector<uint8_t> &face_class,
                      MeshReport &r) {
  auto in_topology = [&](size_t f) { return face_class[f] <= kFaceFlat; };

  // The edge map.
  std::vector<EdgeRecord> records = sorted_edge_records(tri, triangle_count, face_class);

  std::vector<uint32_t> face_edge(3 * triangle_count, kNone);
  std::vector<uint32_t> edge_faces;  // faces per edge
  std::vector<uint32_t> edge_first;  // first face of each edge
  ParityUnionFind orientation(triangle_count);
  auto forward = [&](const EdgeRecord &e) {
    return tri[3 * e.face + e.slot] < tri[3 * e.face + (e.slot + 1) % 3];
  };
  for (size_t i = 0; i < records.size();) {
    size_t j = i;
    const uint32_t e = static_cast<uint32_t>(edge_faces.size());
    while (j < records.size() && records[j].key == records[i].key) {
      face_edge[3 * records[j].face + records[j].slot] = e;
      ++j;
    }
    const size_t n = j - i;
    edge_faces.push_back(static_cast<uint32_t>(n));
    edge_first.push_back(records[i].face);
    if (n == 1) {
      ++r.boundary_edges;
    } else if (n > 2) {
      ++r.non_manifold_edges;
    } else {
      const bool same = forward(records[i]) == forward(records[i + 1]);
      if (same) ++r.inconsistent_edges;
      orientation.unite(records[i].face, records[i + 1].face, same ? 1 : 0);
    }
    i = j;
  }
  r.edges = edge_faces.size();
  std::vector<EdgeRecord>().swap(records);

  // Faces around each vertex.
  const VertexFaces vf = faces_around_vertices(tri, triangle_count, vertex_count, face_class);
  const std::vector<uint32_t> &offset = vf.offset, &vertex_faces = vf.faces;

  // Fans: faces around v are joined when they share an edge at v. Boundary edges at v are
  // chained into one loop when their faces lie in the same fan.
  UnionFind components(triangle_count);
  UnionFind loops(edge_faces.size());
  std::vector<uint8_t> vertex_non_manifold(vertex_count, 0);
  std::vector<std::pair<uint32_t, uint32_t>> around;  // (edge, local face)
  std::vector<uint32_t> parent, loop_edge;
  for (size_t v = 0; v < vertex_count; ++v) {
    const uint32_t begin = offset[v], m = offset[v + 1] - begin;
    if (m == 0) continue;
    ++r.vertices_referenced;
    for (uint32_t i = 1; i < m; ++i) components.unite(vertex_faces[begin], vertex_faces[begin + i]);
    const uint32_t fans =
        group_fans(uint32_t(v), &vertex_faces[begin], m, tri, face_edge, around, parent);
    if (fans > 1) {
      ++r.non_manifold_vertices;
      vertex_non_manifold[v] = 1;
    }
    loop_edge.assign(m, kNone);
    for (const auto &[e, i] : around) {
      if (edge_faces[e] != 1) continue;
      const uint32_t fan = fan_root(parent, i);
      if (loop_edge[fan] == kNone) loop_edge[fan] = e; else loops.unite(loop_edge[fan], e);
    }
  }

  // Components, numbered by their first face.
  std::vector<uint32_t> component_of(triangle_count, kNone);
  std::vector<ComponentReport> &list = r.component_list;
  list.clear();
  for (size_t f = 0; f < triangle_count; ++f) {
    if (!in_topology(f)) continue;
    const uint32_t root = components.find(static_cast<uint32_t>(f));
    if (component_of[root] == kNone) {
      component_of[root] = static_cast<uint32_t>(list.size());
      list.emplace_back();
      list.back().first_triangle = f;
      list.back().manifold = true;
      list.back().orientable = true;
    }
    component_of[f] = component_of[root];
    ComponentReport &c = list[component_of[f]];
    ++c.triangles;
    if (orientation.conflicted(static_cast<uint32_t>(f))) c.orientable = false;
  }
  for (size_t v = 0; v < vertex_count; ++v) {
    if (offset[v] == offset[v + 1]) continue;
    ComponentReport &c = list[component_of[vertex_faces[offset[v]]]];
    ++c.vertices;
    if (vertex_non_manifold[v]) c.manifold = false;
  }
  for (uint32_t e = 0; e < edge_faces.size(); ++e) {
    ComponentReport &c = list[component_of[edge_first[e]]];
    ++c.edges;
    if (edge_faces[e] > 2) c.manifold = false;
    if (edge_faces[e] == 1) {
      ++c.boundary_edges;
      if (loops.find(e) == e) {
        ++c.boundary_loops;
        ++r.boundary_loops;
      }
    }
  }

  // Signed volumes of the closed components, about a point of each to limit cancellation.
  std::vector<double> volume(list.size(), 0.0);
  for (size_t f = 0; f < triangle_count; ++f) {
    if (face_class[f] != kFaceOk) continue;
    const ComponentReport &c = list[component_of[f]];
    if (c.boundary_edges != 0) continue;
    const double *o = xyz + 3 * size_t(tri[3 * c.first_triangle]);
    const double *a = xyz + 3 * size_t(tri[3 * f]), *b = xyz + 3 * size_t(tri[3 * f + 1]),
                 *d = xyz + 3 * size_t(tri[3 * f + 2]);
    const double ax = a[0] - o[0], ay = a[1] - o[1], az = a[2] - o[2];
    const double bx = b[0] - o[0], by = b[1] - o[1], bz = b[2] - o[2];
    const double dx = d[0] - o[0], dy = d[1] - o[1], dz = d[2] - o[2];
    volume[component_of[f]] += ax * (by * dz - bz * dy) + ay * (bz * dx - bx * dz) + az * (bx * dy - by * dx);
  }

  r.components = list.size();
  r.euler_characteristic = 0;
  r.genus = 0;
  r.genus_defined = true;
  for (size_t i = 0; i < list.size(); ++i) {
    ComponentReport &c = list[i];
    c.euler_characteristic = long(c.vertices) - long(c.edges) + long(c.triangles);
    c.closed = c.boundary_edges == 0;
    const long twice = 2 - c.euler_characteristic - long(c.boundary_loops);
    c.genus = (c.manifold && c.orientable && twice >= 0 && twice % 2 == 0) ? twice / 2 : -1;
    r.euler_characteristic += c.euler_characteristic;
    if (c.genus >= 0) r.genus += c.genus; else r.genus_defined = false;
    if (c.closed) {
      ++r.closed_components;
      c.signed_volume = volume[i] / 6.0;
      if (c.signed_volume < 0) ++r.inward_components;
    }
  }
}

}  // namespace moa::quality
