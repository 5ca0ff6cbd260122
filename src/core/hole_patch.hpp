// The loop module's last resort for a small hole its greedy filling left open: the
// triangulation of the loop polygon that bends the surface least, found by dynamic programming
// over the loop's own vertices (least worst dihedral angle first, then least area; Liepa's
// criterion). Greedy MOA can corner itself in a crumpled spot; the whole-loop optimum cannot.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/geometry.hpp"
#include "core/mesh_state.hpp"

namespace moa {

// loop: the hole's vertices in order, a face filling the hole containing each directed edge
// loop[j] -> loop[j+1]; rim_normals[j]: unit normal of the mesh face on the other side of that
// edge; is_edge(u, v): whether the mesh has the edge u-v already, which a chord of the patch
// must not repeat. Returns the patch's triangles, oriented like the mesh, or nothing when no
// triangulation avoids thin triangles and existing edges, or the loop repeats a vertex.
std::vector<Tri> smoothest_patch(const std::vector<Vec3> &points, const std::vector<uint32_t> &loop,
                                 const std::vector<Vec3> &rim_normals,
                                 const std::function<bool(uint32_t, uint32_t)> &is_edge);

// The same for a hole of `mesh`: every edge loop[j] -> loop[j+1] must have exactly one face,
// whose normal counts as the rim's there; nothing otherwise.
std::vector<Tri> smoothest_patch(MeshState &mesh, const std::vector<Vec3> &points,
                                 const std::vector<uint32_t> &loop);

}  // namespace moa
