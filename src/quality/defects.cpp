// find_mesh_defects: the edge map and the fans of analyze_topology, kept as lists instead of
// counts, and the exact self-intersection test without its listing limit.
#include "quality/defects.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdint>

#include "quality/analysis.hpp"
#include "quality/exact_predicates.hpp"

namespace moa {
namespace {

using quality::kFaceFlat;
using quality::kFaceInvalid;
using quality::kFaceOk;
using quality::kFaceRepeated;

constexpr uint32_t kNone = UINT32_MAX;

// The classes of analyze_mesh; the exact collinearity test only when intersections are tested,
// since nothing else needs it.
std::vector<uint8_t> classify(const double *xyz, size_t vertex_count, const uint32_t *tri,
                              size_t triangle_count, bool exact) {
  std::vector<uint8_t> cls(triangle_count);
  auto finite = [](const double *p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  };
  tbb::parallel_for(tbb::blocked_range<size_t>(0, triangle_count), [&](const auto &range) {
    for (size_t f = range.begin(); f != range.end(); ++f) {
      const uint32_t *t = tri + 3 * f;
      if (t[0] >= vertex_count || t[1] >= vertex_count || t[2] >= vertex_count) {
        cls[f] = kFaceInvalid;
      } else if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
        cls[f] = kFaceRepeated;
      } else if (exact) {
        const double *a = xyz + 3 * size_t(t[0]), *b = xyz + 3 * size_t(t[1]),
                     *c = xyz + 3 * size_t(t[2]);
        const bool flat = !finite(a) || !finite(b) || !finite(c) || quality::collinear(a, b, c);
        cls[f] = flat ? kFaceFlat : kFaceOk;
      } else {
        cls[f] = kFaceOk;
      }
    }
  });
  return cls;
}

}  // namespace

MeshDefects find_mesh_defects(const double *xyz, size_t vertex_count, const uint32_t *tri,
                              size_t triangle_count, bool test_intersections) {
  MeshDefects d;
  const std::vector<uint8_t> cls =
      classify(xyz, vertex_count, tri, triangle_count, test_intersections);
  std::vector<uint8_t> bad_face(triangle_count, 0);

  // The edge map: runs of records with one key are the faces of one edge.
  std::vector<quality::EdgeRecord> records = quality::sorted_edge_records(tri, triangle_count, cls);
  std::vector<uint32_t> face_edge(3 * triangle_count, kNone);
  uint32_t edges = 0;
  for (size_t i = 0; i < records.size(); ++edges) {
    size_t j = i;
    for (; j < records.size() && records[j].key == records[i].key; ++j)
      face_edge[3 * size_t(records[j].face) + records[j].slot] = edges;
    const std::pair<uint32_t, uint32_t> edge(uint32_t(records[i].key >> 32),
                                             uint32_t(records[i].key));
    if (j - i == 1) d.boundary_edges.push_back(edge);
    if (j - i > 2) {
      d.non_manifold_edges.push_back(edge);
      for (size_t k = i; k < j; ++k) bad_face[records[k].face] = 1;
    }
    i = j;
  }
  std::vector<quality::EdgeRecord>().swap(records);

  // Faces around each vertex, then its fans: faces joined through an edge at the vertex.
  const quality::VertexFaces vf =
      quality::faces_around_vertices(tri, triangle_count, vertex_count, cls);
  const std::vector<uint32_t> &offset = vf.offset, &vertex_faces = vf.faces;
  struct Scratch {
    std::vector<std::pair<uint32_t, uint32_t>> around;  // (edge, local face)
    std::vector<uint32_t> parent;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  std::vector<uint8_t> pinched(vertex_count, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_count), [&](const auto &range) {
    Scratch &s = scratch.local();
    for (size_t v = range.begin(); v != range.end(); ++v) {
      const uint32_t begin = offset[v], m = offset[v + 1] - begin;
      if (m < 2) continue;
      pinched[v] = quality::group_fans(uint32_t(v), &vertex_faces[begin], m, tri, face_edge,
                                       s.around, s.parent) > 1;
    }
  });
  for (size_t v = 0; v < vertex_count; ++v) {
    if (!pinched[v]) continue;
    d.non_manifold_vertices.push_back(uint32_t(v));
    for (uint32_t i = offset[v]; i < offset[v + 1]; ++i) bad_face[vertex_faces[i]] = 1;
  }

  if (test_intersections) {
    MeshReport unused;
    quality::find_self_intersections(xyz, tri, triangle_count, cls, unused, SIZE_MAX);
    d.intersecting_pairs = std::move(unused.intersecting_pairs);
    d.intersections_tested = true;
    for (const auto &[a, b] : d.intersecting_pairs) bad_face[a] = bad_face[b] = 1;
  }
  for (size_t f = 0; f < triangle_count; ++f)
    if (bad_face[f]) d.defective_faces.push_back(uint32_t(f));
  return d;
}

}  // namespace moa
