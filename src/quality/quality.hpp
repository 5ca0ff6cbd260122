// Mesh analysis for `moa check`, the tests and the benchmarks: measures the output contract
// C1-C5 of DESIGN.md section 1 (faces, edge and vertex manifoldness, orientation,
// self-intersections) plus the topology (components, boundary loops, genus) and the shape of the
// triangles. Independent of the core on purpose, so that it can check the core's output.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace moa {

// One connected component (faces joined through shared vertices).
struct ComponentReport {
  size_t first_triangle = 0;  // smallest triangle index in the component (components are in
                              // this order)
  size_t triangles = 0;
  size_t vertices = 0;
  size_t edges = 0;
  size_t boundary_edges = 0;
  size_t boundary_loops = 0;
  long euler_characteristic = 0;  // V - E + F
  bool closed = false;            // no boundary edges
  bool manifold = false;          // no non-manifold edge or vertex
  bool orientable = false;        // the faces can be oriented consistently (whatever they are)
  long genus = -1;                // (2 - chi - loops) / 2; -1 unless manifold and orientable
  double signed_volume = 0;       // closed components only; > 0 when the faces point outward
};

struct MeshReport {
  // Counts. Faces with an index out of range are "invalid" and skipped by everything else;
  // faces with a repeated index count as degenerate and are left out of the topology.
  size_t vertices = 0;             // vertex_count as given
  size_t vertices_referenced = 0;  // used by a face without a repeated index
  size_t triangles = 0;            // triangle_count as given
  size_t invalid_faces = 0;        // an index >= vertex_count
  size_t edges = 0;
  size_t boundary_edges = 0;       // edges with one face
  size_t boundary_loops = 0;       // boundary edges chained through the fans of their vertices
  size_t components = 0;
  size_t closed_components = 0;
  long euler_characteristic = 0;
  long genus = 0;                  // sum over the components whose genus is defined
  bool genus_defined = true;       // every component is a manifold orientable surface
  std::vector<ComponentReport> component_list;

  // C1: faces.
  size_t degenerate_faces = 0;  // repeated index, exactly collinear or non-finite vertices
  size_t duplicate_faces = 0;   // same vertex set as an earlier face (either orientation)
  // C2, C3: manifoldness.
  size_t non_manifold_edges = 0;     // more than two faces
  size_t non_manifold_vertices = 0;  // faces around the vertex form more than one fan
  // C4: orientation.
  size_t inconsistent_edges = 0;  // two faces using the edge in the same direction
  size_t inward_components = 0;   // closed components with negative signed volume
  // C5: self-intersections, decided exactly. Degenerate faces are not tested; two faces with
  // the same three vertices count as an intersecting pair (they meet in their interiors).
  size_t self_intersecting_pairs = 0;
  size_t candidate_pairs = 0;  // pairs whose bounding boxes overlap (the broad phase)
  std::vector<std::pair<uint32_t, uint32_t>> intersecting_pairs;  // sorted; at most kMaxListed

  // Shape: the smallest angle of each non-degenerate-by-index triangle, in degrees.
  double min_angle = 0;       // over the mesh
  double mean_min_angle = 0;  // mean over triangles of their smallest angle
  double share_below_10 = 0;  // fraction of triangles whose smallest angle is below 10 degrees
  double share_below_20 = 0;
  double share_below_30 = 0;
  std::array<size_t, 12> min_angle_histogram{};  // 5-degree bins from 0 to 60

  // Filled by add_point_coverage (moa check --points).
  bool has_input_points = false;
  size_t input_points = 0;
  size_t input_points_on_mesh = 0;  // input points that are vertices of some face

  double analysis_ms = 0;
  double intersection_ms = 0;

  static constexpr size_t kMaxListed = 1000;

  bool closed() const { return boundary_edges == 0 && components > 0; }
  // C1 to C5 of the output contract (C6, determinism, needs two runs).
  bool faces_ok() const { return invalid_faces == 0 && degenerate_faces == 0 && duplicate_faces == 0; }
  bool edge_manifold() const { return non_manifold_edges == 0; }
  bool vertex_manifold() const { return non_manifold_vertices == 0; }
  bool oriented() const { return inconsistent_edges == 0 && inward_components == 0; }
  bool intersection_free() const { return self_intersecting_pairs == 0; }
  bool contract_ok() const {
    return faces_ok() && edge_manifold() && vertex_manifold() && oriented() && intersection_free();
  }
};

// Analyses a triangle mesh. xyz: x y z per vertex; tri: 3 indices per triangle. Uses all cores.
MeshReport analyze_mesh(const double *xyz, size_t vertex_count, const uint32_t *tri,
                        size_t triangle_count);

// Counts the input points that are vertices of some face of the mesh. A point matches a vertex
// within a tolerance of about 5e-7 of the largest coordinate, so that meshes written in single
// precision still match the double input.
void add_point_coverage(MeshReport &report, const double *points, size_t point_count,
                        const double *xyz, size_t vertex_count, const uint32_t *tri,
                        size_t triangle_count);

// The report as one JSON object (stable key names, documented in the README).
std::string report_to_json(const MeshReport &report);

// The report as a few aligned lines of text for people.
void print_report(std::ostream &out, const MeshReport &report);

}  // namespace moa
