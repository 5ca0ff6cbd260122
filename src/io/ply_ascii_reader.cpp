// The body of an ASCII PLY file: one element item per line, values separated by whitespace.
// Every value is checked to be a number, also those of properties that are not kept.
#include <algorithm>

#include "errors.hpp"
#include "ply_reader.hpp"
#include "text_scan.hpp"

namespace moa::io::detail {
namespace {

bool next_nonblank_line(LineReader &lines, std::string_view &line) {
  while (lines.next(line))
    if (!is_blank(line)) return true;
  return false;
}

void read_item(const Source &source, size_t line_number, std::string_view line,
               const PlyElement &element, const std::vector<PlyRole> &roles,
               uint64_t vertex_count, MeshData &mesh) {
  const std::string &path = source.path;
  Tokens tokens(line);
  std::string_view token;
  double xyz[3] = {0, 0, 0};
  bool vertex = false;
  const auto next = [&](const PlyProperty &property) {
    if (!tokens.next(token))
      fail_at_line(path, line_number, "the line ends before property '" + property.name +
                                          "' of the " + element.name);
  };
  for (size_t p = 0; p < element.properties.size(); ++p) {
    const PlyProperty &property = element.properties[p];
    next(property);
    if (!property.is_list) {
      double value;
      if (!parse_double(token, value))
        fail_at_line(path, line_number,
                     quoted(token) + " is not a number (property '" + property.name + "')");
      if (roles[p] != PlyRole::Skip) {
        xyz[static_cast<int>(roles[p])] = value;
        vertex = true;
      }
      continue;
    }
    uint64_t length;
    if (!parse_unsigned(token, length))
      fail_at_line(path, line_number,
                   quoted(token) + " is not a list length (property '" + property.name + "')");
    if (roles[p] == PlyRole::FaceIndices && length < 3)
      fail_at_line(path, line_number,
                   "a face needs at least 3 vertices, this one has " + std::to_string(length));
    uint32_t first = 0, previous = 0;
    for (uint64_t k = 0; k < length; ++k) {
      next(property);
      if (roles[p] != PlyRole::FaceIndices) {
        double value;
        if (!parse_double(token, value))
          fail_at_line(path, line_number,
                       quoted(token) + " is not a number (property '" + property.name + "')");
        continue;
      }
      int64_t index;
      if (!parse_signed(token, index))
        fail_at_line(path, line_number, quoted(token) + " is not a vertex index");
      if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
        fail_at_line(path, line_number,
                     "vertex index " + std::to_string(index) + " is out of range (" +
                         std::to_string(vertex_count) + " vertices)");
      const auto current = static_cast<uint32_t>(index);
      if (k == 0) first = current;
      if (k >= 2) mesh.triangles.insert(mesh.triangles.end(), {first, previous, current});
      previous = current;
    }
  }
  if (tokens.next(token))
    fail_at_line(path, line_number,
                 "unexpected " + quoted(token) + " after the " +
                     std::to_string(element.properties.size()) + " properties of a " +
                     element.name);
  if (vertex) mesh.xyz.insert(mesh.xyz.end(), xyz, xyz + 3);
}

}  // namespace

void read_ply_ascii(const Source &source, const PlyHeader &header, const PlyPlan &plan,
                    MeshData &mesh) {
  LineReader lines(source.data, header.body_offset, header.header_lines);
  const uint64_t vertex_count = header.elements[plan.vertex_element].count;
  std::string_view line;
  for (size_t e = 0; e <= plan.last_element; ++e) {
    const PlyElement &element = header.elements[e];
    if (element.properties.empty()) continue;
    // Each value takes at least two bytes, a digit and a separator.
    const uint64_t min_item = 2 * element.properties.size();
    if (element.count > (lines.remaining() + 1) / min_item)
      fail_at_line(source.path, element.line,
                   "the header promises " + std::to_string(element.count) + " " +
                       plural(element.name) + ", more than the " +
                       std::to_string(lines.remaining()) + " bytes left can hold");
    const bool read = e == plan.vertex_element || static_cast<long>(e) == plan.face_element;
    if (e == plan.vertex_element) mesh.xyz.reserve(mesh.xyz.size() + 3 * element.count);
    if (static_cast<long>(e) == plan.face_element)
      mesh.triangles.reserve(mesh.triangles.size() +  // a triangle line takes 8 bytes or more
                             3 * std::min<uint64_t>(element.count, lines.remaining() / 8));
    for (uint64_t i = 0; i < element.count; ++i) {
      if (!next_nonblank_line(lines, line))
        fail_at_line(source.path, lines.line(),
                     "file ends after " + std::to_string(i) + " of " +
                         std::to_string(element.count) + " " + plural(element.name));
      if (read) read_item(source, lines.line(), line, element, plan.roles[e], vertex_count, mesh);
    }
  }
}

}  // namespace moa::io::detail
