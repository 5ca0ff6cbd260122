// An independent checker of the output contract (DESIGN.md section 1, C1-C5) plus the topology
// counts the tests assert on. It shares no code with the library: it is the library's judge.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace moa::test {

struct ContractReport {
  // C1: faces are proper triangles of input points.
  std::size_t bad_indices = 0;        // faces with an index >= point count
  std::size_t repeated_vertices = 0;  // faces naming the same index twice
  std::size_t duplicate_faces = 0;    // faces whose vertex set repeats an earlier face's
  std::size_t zero_area_faces = 0;    // faces with exactly collinear (or coincident) corners
  // C2: edge-manifold.
  std::size_t non_manifold_edges = 0;  // edges with three or more faces
  // C3: vertex-manifold.
  std::size_t non_manifold_vertices = 0;  // vertices whose faces form more than one fan
  // C4: orientation.
  std::size_t misoriented_edges = 0;  // two-face edges traversed twice in the same direction
  std::size_t inward_components = 0;  // closed components with signed volume <= 0
  // C5: self-intersections.
  std::size_t intersecting_pairs = 0;  // face pairs meeting beyond their shared vertices/edges

  // Counts (faces with bad or repeated indices are left out of everything below).
  std::size_t faces = 0;
  std::size_t vertices_used = 0;
  std::size_t edges = 0;
  std::size_t boundary_edges = 0;
  std::size_t boundary_loops = 0;
  std::size_t components = 0;
  std::size_t closed_components = 0;
  long euler_characteristic = 0;      // V - E + F over the whole mesh
  long genus_sum = 0;                 // sum of (2 - chi) / 2 over closed components
  std::vector<long> closed_genus;     // per closed component, in order of first face

  // The first few offences of each kind, as readable lines.
  std::vector<std::string> samples;

  bool c1() const { return bad_indices + repeated_vertices + duplicate_faces + zero_area_faces == 0; }
  bool c2() const { return non_manifold_edges == 0; }
  bool c3() const { return non_manifold_vertices == 0; }
  bool c4() const { return misoriented_edges + inward_components == 0; }
  bool c5() const { return intersecting_pairs == 0; }
  bool ok() const { return c1() && c2() && c3() && c4() && c5(); }
  bool closed() const { return faces > 0 && boundary_edges == 0 && closed_components == components; }
  bool disk() const {
    return components == 1 && boundary_loops == 1 && euler_characteristic == 1;
  }
  // Every count and every offence sample, one per line.
  std::string describe() const;
};

struct CheckOptions {
  bool check_intersections = true;  // C5 is the expensive part
  std::size_t samples_per_kind = 5;
};

// xyz: point_count * 3 doubles; triangles: 3 indices per face.
ContractReport check_contract(const double *xyz, std::size_t point_count,
                              const std::uint32_t *triangles, std::size_t triangle_count,
                              const CheckOptions &options = {});

inline ContractReport check_contract(const std::vector<double> &xyz,
                                     const std::vector<std::uint32_t> &triangles,
                                     const CheckOptions &options = {}) {
  return check_contract(xyz.data(), xyz.size() / 3, triangles.data(), triangles.size() / 3, options);
}

}  // namespace moa::test
