// Final stage (DESIGN.md §2.8): orientation made explicit, each closed component turned
// outward, and the vertex-manifold rule enforced on whatever fans did not join.
#pragma once

#include <vector>

#include "core/mesh_state.hpp"
#include "core/point_set.hpp"
#include "moa/moa.h"

namespace moa {

// The alive faces of the grown mesh, each as currently oriented.
std::vector<Tri> oriented_faces(MeshState &mesh);

// Turns closed components outward and removes, at any vertex whose faces still form several
// fans, all but the largest fan. `faces` are internal indices, ready to be mapped to the
// caller's indices afterwards.
void finish_mesh(const PointSet &points, std::vector<Tri> &faces, moa_stats &stats);

}  // namespace moa
