// Where a mesh's defects are, element by element, for pictures (`moa render
// --highlight-defects`): the lists behind the counts of MeshReport. Uses the same conventions
// as analyze_mesh, so that the list sizes equal its counts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace moa {

struct MeshDefects {
  // Edges as vertex pairs (smaller index first), sorted.
  std::vector<std::pair<uint32_t, uint32_t>> boundary_edges;      // one face
  std::vector<std::pair<uint32_t, uint32_t>> non_manifold_edges;  // more than two faces
  std::vector<uint32_t> non_manifold_vertices;                    // more than one fan; sorted
  // Face pairs (smaller first), sorted, all of them; empty unless intersections were tested.
  std::vector<std::pair<uint32_t, uint32_t>> intersecting_pairs;
  bool intersections_tested = false;
  // Faces on a non-manifold edge, at a non-manifold vertex or in an intersecting pair; sorted.
  std::vector<uint32_t> defective_faces;
};

// Lists the defects of a triangle mesh (xyz: x y z per vertex, tri: 3 indices per triangle).
// The exact self-intersection test costs about as much as `moa check`; without it only the
// topology is looked at, which is cheap. Uses all cores.
MeshDefects find_mesh_defects(const double *xyz, size_t vertex_count, const uint32_t *tri,
                              size_t triangle_count, bool test_intersections = true);

}  // namespace moa
