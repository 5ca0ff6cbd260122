// Wavefront OBJ: "v x y z [w | r g b]" vertices and "f" faces whose corners are "i", "i/t",
// "i//n" or "i/t/n", 1-based or negative (relative to the vertices read so far). Every
// other statement (vt, vn, g, o, s, usemtl, ...) is ignored.
#include <limits>

#include "errors.hpp"
#include "formats.hpp"
#include "text_scan.hpp"

namespace moa::io::detail {
namespace {

// The 0-based vertex of a face corner; positive indices are checked once all vertices are
// known, since a face may name a vertex defined further down.
int64_t corner_index(const Source &source, size_t line, std::string_view corner,
                     size_t vertices_so_far) {
  const std::string_view index = corner.substr(0, corner.find('/'));
  int64_t value;
  if (!parse_signed(index, value))
    fail_at_line(source.path, line, quoted(corner) + " is not a face corner (v, v/t, v//n, v/t/n)");
  if (value > 0) return value - 1;
  if (value == 0) fail_at_line(source.path, line, "vertex index 0 (OBJ indices start at 1)");
  const auto relative = static_cast<int64_t>(vertices_so_far) + value;
  if (relative < 0)
    fail_at_line(source.path, line,
                 "relative vertex index " + std::to_string(value) + " reaches before the first "
                 "vertex (" + std::to_string(vertices_so_far) + " read so far)");
  return relative;
}

}  // namespace

void read_obj(const Source &source, MeshData &mesh, bool want_faces) {
  LineReader lines(source.data, bom_length(source.data));
  const size_t first_vertex = mesh.xyz.size() / 3;
  std::string_view line, keyword, token;
  int64_t largest = -1;  // largest positive index and where it was seen
  size_t largest_line = 0;
  std::vector<uint32_t> polygon;

  while (next_data_line(lines, line)) {
    Tokens tokens(line);
    tokens.next(keyword);
    if (keyword == "v") {
      for (int i = 0; i < 3; ++i) {
        double value;
        if (!tokens.next(token))
          fail_at_line(source.path, lines.line(),
                       "a vertex needs 3 numbers (x y z), found " + std::to_string(i));
        if (!parse_double(token, value))
          fail_at_line(source.path, lines.line(), quoted(token) + " is not a number");
        mesh.xyz.push_back(value);
      }
    } else if (keyword == "f" && want_faces) {
      const size_t vertices_so_far = mesh.xyz.size() / 3 - first_vertex;
      polygon.clear();
      while (tokens.next(token)) {
        const int64_t index = corner_index(source, lines.line(), token, vertices_so_far);
        if (index > std::numeric_limits<uint32_t>::max())
          fail_at_line(source.path, lines.line(),
                       "vertex index " + std::to_string(index + 1) + " is out of range");
        if (index > largest) {
          largest = index;
          largest_line = lines.line();
        }
        polygon.push_back(static_cast<uint32_t>(first_vertex + index));
      }
      if (polygon.size() < 3)
        fail_at_line(source.path, lines.line(),
                     "a face needs at least 3 vertices, this one has " +
                         std::to_string(polygon.size()));
      for (size_t i = 2; i < polygon.size(); ++i)
        mesh.triangles.insert(mesh.triangles.end(), {polygon[0], polygon[i - 1], polygon[i]});
    } else {
      const char c = keyword[0];
      // A line of bare numbers is not OBJ; everything else is a statement we need not read.
      if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.')
        fail_at_line(source.path, lines.line(),
                     quoted(keyword) + " is not an OBJ statement (like v or f)");
    }
  }
  const auto vertices = static_cast<int64_t>(mesh.xyz.size() / 3 - first_vertex);
  if (largest >= vertices)
    fail_at_line(source.path, largest_line,
                 "vertex index " + std::to_string(largest + 1) + " is out of range (" +
                     std::to_string(vertices) + " vertices)");
}

}  // namespace moa::io::detail
