// ASCII STL: "solid name", then per facet "facet normal ..", "outer loop", "vertex x y z"
// lines, "endloop", "endfacet"; "endsolid". Loops of more than 3 vertices are fan-triangulated.
#include "errors.hpp"
#include "formats.hpp"
#include "text_scan.hpp"
#include "vertex_merger.hpp"

namespace moa::io::detail {

void read_stl_ascii(const Source &source, MeshData &mesh) {
  VertexMerger merger(mesh, source.data.size() / 40);  // a vertex line is ~40 bytes
  LineReader lines(source.data, bom_length(source.data));
  std::string_view line, keyword, token;
  std::vector<uint32_t> loop;
  bool in_solid = false, in_loop = false;
  size_t loop_line = 0;

  while (lines.next(line)) {
    Tokens tokens(line);
    if (!tokens.next(keyword)) continue;
    if (keyword == "vertex") {
      if (!in_loop)
        fail_at_line(source.path, lines.line(), "'vertex' outside an 'outer loop'");
      double value[3];
      for (double &v : value) {
        if (!tokens.next(token))
          fail_at_line(source.path, lines.line(), "a vertex needs 3 numbers (x y z)");
        if (!parse_double(token, v))
          fail_at_line(source.path, lines.line(), quoted(token) + " is not a number");
      }
      loop.push_back(merger.add(value[0], value[1], value[2]));
    } else if (keyword == "solid") {
      in_solid = true;  // the rest of the line is the name
    } else if (keyword == "facet" || keyword == "endfacet") {
      if (!in_solid) fail_at_line(source.path, lines.line(), quoted(keyword) + " before 'solid'");
    } else if (keyword == "outer") {
      if (!in_solid || in_loop)
        fail_at_line(source.path, lines.line(), "unexpected 'outer loop'");
      in_loop = true;
      loop_line = lines.line();
      loop.clear();
    } else if (keyword == "endloop") {
      if (!in_loop) fail_at_line(source.path, lines.line(), "'endloop' without 'outer loop'");
      if (loop.size() < 3)
        fail_at_line(source.path, lines.line(),
                     "a facet needs at least 3 vertices, this one has " +
                         std::to_string(loop.size()));
      for (size_t i = 2; i < loop.size(); ++i)
        mesh.triangles.insert(mesh.triangles.end(), {loop[0], loop[i - 1], loop[i]});
      in_loop = false;
    } else if (keyword == "endsolid") {
      in_solid = false;
    } else {
      fail_at_line(source.path, lines.line(),
                   "unexpected " + quoted(keyword) + " in an ASCII STL file");
    }
  }
  if (in_loop)
    fail_at_line(source.path, lines.line(),
                 "file ends inside the facet begun at line " + std::to_string(loop_line));
}

}  // namespace moa::io::detail
