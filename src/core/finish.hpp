// Final stage (DESIGN.md §2.8): orientation made explicit, each closed component turned
// outward, and the vertex-manifold rule enforced on whatever fans did not join.
#pragma once

#include <vector>

#include "core/growth_state.hpp"

namespace moa {

// Oriented faces in internal indices, ready to be mapped to the caller's indices.
std::vector<Tri> finish_mesh(GrowthState &g);

}  // namespace moa
