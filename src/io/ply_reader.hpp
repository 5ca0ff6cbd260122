// What the PLY body readers take from which element (shared by the ASCII and binary readers).
#pragma once

#include <vector>

#include "formats.hpp"
#include "ply_header.hpp"

namespace moa::io::detail {

// What a property is read for.
enum class PlyRole : int8_t { Skip = -1, X = 0, Y = 1, Z = 2, FaceIndices = 3 };

struct PlyPlan {
  size_t vertex_element = 0;
  long face_element = -1;     // -1: no faces wanted or none in the file
  size_t last_element = 0;    // later elements are not read
  std::vector<std::vector<PlyRole>> roles;  // per element, per property
};

void read_ply_ascii(const Source &source, const PlyHeader &header, const PlyPlan &plan,
                    MeshData &mesh);
void read_ply_binary(const Source &source, const PlyHeader &header, const PlyPlan &plan,
                     MeshData &mesh);

}  // namespace moa::io::detail
