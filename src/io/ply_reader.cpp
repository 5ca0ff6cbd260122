// PLY: finds the vertex coordinates and the face index lists in the header, then hands the
// body to the ASCII or binary reader.
#include "ply_reader.hpp"

#include <algorithm>
#include <limits>

#include "errors.hpp"

namespace moa::io::detail {
namespace {

PlyPlan make_plan(const std::string &path, const PlyHeader &header, bool want_faces) {
  PlyPlan plan;
  const auto &elements = header.elements;
  plan.roles.resize(elements.size());
  for (size_t e = 0; e < elements.size(); ++e)
    plan.roles[e].assign(elements[e].properties.size(), PlyRole::Skip);

  const auto vertex = std::find_if(elements.begin(), elements.end(),
                                   [](const PlyElement &e) { return e.name == "vertex"; });
  if (vertex == elements.end()) fail(path, "the PLY header declares no vertex element");
  plan.vertex_element = static_cast<size_t>(vertex - elements.begin());
  plan.last_element = plan.vertex_element;
  const char *const axes[] = {"x", "y", "z"}, *const upper_axes[] = {"X", "Y", "Z"};
  for (int axis = 0; axis < 3; ++axis) {
    int p = vertex->find(axes[axis]);
    if (p < 0) p = vertex->find(upper_axes[axis]);  // some scanners' software writes X Y Z
    if (p < 0 || vertex->properties[static_cast<size_t>(p)].is_list)
      fail_at_line(path, vertex->line,
                   std::string("the vertex element has no '") + axes[axis] + "' property");
    plan.roles[plan.vertex_element][static_cast<size_t>(p)] = static_cast<PlyRole>(axis);
  }
  if (!want_faces) return plan;

  if (vertex->count > std::numeric_limits<uint32_t>::max())
    fail_at_line(path, vertex->line, "too many vertices for 32-bit indices");
  const auto face = std::find_if(elements.begin(), elements.end(),
                                 [](const PlyElement &e) { return e.name == "face"; });
  if (face == elements.end()) return plan;  // a point cloud
  int p = face->find("vertex_indices");
  if (p < 0) p = face->find("vertex_index");
  if (p < 0)
    fail_at_line(path, face->line, "the face element has no vertex_indices list");
  const PlyProperty &list = face->properties[static_cast<size_t>(p)];
  if (!list.is_list || !ply_type_is_integer(list.type))
    fail_at_line(path, face->line, "the face element's " + list.name +
                                       " is not a list of integers");
  plan.face_element = face - elements.begin();
  plan.roles[static_cast<size_t>(plan.face_element)][static_cast<size_t>(p)] =
      PlyRole::FaceIndices;
  plan.last_element = std::max(plan.last_element, static_cast<size_t>(plan.face_element));
  return plan;
}

}  // namespace

void read_ply(const Source &source, MeshData &mesh, bool want_faces) {
  const PlyHeader header = parse_ply_header(source.path, source.data);
  const PlyPlan plan = make_plan(source.path, header, want_faces);
  if (header.encoding == PlyEncoding::Ascii)
    read_ply_ascii(source, header, plan, mesh);
  else
    read_ply_binary(source, header, plan, mesh);
}

}  // namespace moa::io::detail
