// OFF (Geomview): an optional [ST][C][N][4][n]OFF keyword, the counts "vertices faces [edges]"
// on the same or a later line, then one vertex and one face per line. '#' starts a comment.
// Extra vertex columns (normals, colours, texture coordinates) and face colours are ignored.
#include <algorithm>
#include <limits>

#include "errors.hpp"
#include "formats.hpp"
#include "text_scan.hpp"

namespace moa::io::detail {
namespace {

struct OffHeader {
  uint64_t vertices = 0;
  uint64_t faces = 0;
};

uint64_t parse_count(const Source &source, size_t line, std::string_view token,
                     const char *what) {
  uint64_t value;
  if (!parse_unsigned(token, value))
    fail_at_line(source.path, line,
                 quoted(token) + " is not a valid " + what + " count in the OFF header");
  return value;
}

OffHeader read_header(const Source &source, LineReader &lines) {
  std::string_view line, token;
  if (!next_data_line(lines, line)) fail(source.path, "no OFF header: the file holds no data");
  Tokens tokens(line);
  // The header is free-form: its tokens may spread over lines.
  const auto next_token = [&](const char *what) {
    while (!tokens.next(token)) {
      if (!next_data_line(lines, line))
        fail(source.path, std::string("the file ends in the OFF header, before the ") + what);
      tokens = Tokens(line);
    }
  };
  tokens.next(token);
  if (is_off_keyword(token)) {
    if (token.find('4') != std::string_view::npos)
      fail_at_line(source.path, lines.line(),
                   "4-dimensional OFF (" + std::string(token) + ") is not supported");
    const bool dimension_given = token.size() >= 4 && token[token.size() - 4] == 'n';
    if (dimension_given) {
      next_token("dimension");
      if (token != "3")
        fail_at_line(source.path, lines.line(),
                     "nOFF dimension " + quoted(token) + " is not supported (only 3)");
    }
    next_token("vertex count");
    if (token == "BINARY") fail_at_line(source.path, lines.line(), "binary OFF is not supported");
  } else if (source.content != Content::Numbers) {
    fail_at_line(source.path, lines.line(),
                 "not an OFF file: expected the OFF keyword, found " + quoted(token));
  }
  // Without the keyword (header-less OFF) the first token already is the vertex count.
  OffHeader header;
  header.vertices = parse_count(source, lines.line(), token, "vertex");
  next_token("face count");
  header.faces = parse_count(source, lines.line(), token, "face");
  if (tokens.next(token)) parse_count(source, lines.line(), token, "edge");
  if (tokens.next(token))
    fail_at_line(source.path, lines.line(),
                 "unexpected " + quoted(token) + " after the OFF counts");
  return header;
}

}  // namespace

void read_off(const Source &source, MeshData &mesh, bool want_faces) {
  LineReader lines(source.data, bom_length(source.data));
  const OffHeader header = read_header(source, lines);
  const size_t header_line = lines.line();

  // A vertex line takes at least 6 bytes ("0 0 0\n") and a face 8 ("3 0 1 2\n"): a header
  // that promises more than that is caught before anything is allocated.
  const uint64_t room = lines.remaining() + 2;
  if (header.vertices > room / 6 || header.faces > room / 8 ||
      header.vertices * 6 + header.faces * 8 > room + 8)
    fail_at_line(source.path, header_line,
                 "the header promises " + counted(header.vertices, "vertex", "vertices") +
                     " and " + counted(header.faces, "face", "faces") + ", more than the " +
                     counted(lines.remaining(), "byte", "bytes") + " after it can hold");
  if (want_faces && header.vertices > std::numeric_limits<uint32_t>::max())
    fail_at_line(source.path, header_line, "too many vertices for 32-bit indices");

  std::string_view line, token;
  mesh.xyz.reserve(mesh.xyz.size() + 3 * header.vertices);
  for (uint64_t v = 0; v < header.vertices; ++v) {
    if (!next_data_line(lines, line))
      fail_at_line(source.path, lines.line(),
                   "file ends after " + std::to_string(v) + " of " +
                       std::to_string(header.vertices) + " vertices");
    Tokens tokens(line);
    for (int i = 0; i < 3; ++i) {
      double value;
      if (!tokens.next(token))
        fail_at_line(source.path, lines.line(),
                     "a vertex needs 3 numbers (x y z), found " + std::to_string(i));
      if (!parse_double(token, value))
        fail_at_line(source.path, lines.line(), quoted(token) + " is not a number");
      mesh.xyz.push_back(value);
    }
  }
  if (!want_faces) return;

  // Most OFF files hold triangles; polygons grow the vector as needed.
  mesh.triangles.reserve(mesh.triangles.size() + 3 * header.faces);
  for (uint64_t f = 0; f < header.faces; ++f) {
    if (!next_data_line(lines, line))
      fail_at_line(source.path, lines.line(),
                   "file ends after " + std::to_string(f) + " of " +
                       std::to_string(header.faces) + " faces");
    Tokens tokens(line);
    uint64_t corners;
    tokens.next(token);
    if (!parse_unsigned(token, corners))
      fail_at_line(source.path, lines.line(),
                   quoted(token) + " is not a valid vertex count for a face");
    if (corners < 3)
      fail_at_line(source.path, lines.line(),
                   "a face needs at least 3 vertices, this one has " + std::to_string(corners));
    uint32_t first = 0, previous = 0;
    for (uint64_t i = 0; i < corners; ++i) {
      uint64_t index;
      if (!tokens.next(token))
        fail_at_line(source.path, lines.line(),
                     "the face lists " + std::to_string(i) + " of its " +
                         std::to_string(corners) + " vertices");
      if (!parse_unsigned(token, index))
        fail_at_line(source.path, lines.line(), quoted(token) + " is not a vertex index");
      if (index >= header.vertices)
        fail_at_line(source.path, lines.line(),
                     "vertex index " + std::to_string(index) + " is out of range (" +
                         std::to_string(header.vertices) + " vertices)");
      const auto current = static_cast<uint32_t>(index);
      if (i == 0) first = current;
      if (i >= 2) mesh.triangles.insert(mesh.triangles.end(), {first, previous, current});
      previous = current;
    }
  }
}

}  // namespace moa::io::detail
