// Binary STL: an 80-byte header, a little-endian triangle count, then 50 bytes per triangle
// (normal, three corners as float32, a 16-bit attribute). ASCII STL is in stl_ascii_reader.cpp.
#include "binary_scan.hpp"
#include "errors.hpp"
#include "formats.hpp"
#include "vertex_merger.hpp"

namespace moa::io::detail {

void read_stl(const Source &source, MeshData &mesh) {
  if (source.content == Content::StlAscii)
    read_stl_ascii(source, mesh);
  else
    read_stl_binary(source, mesh);
}

void read_stl_binary(const Source &source, MeshData &mesh) {
  constexpr size_t header_size = 84, triangle_size = 50;
  const auto *bytes = reinterpret_cast<const unsigned char *>(source.data.data());
  const size_t size = source.data.size();
  if (size < header_size)
    fail_at_byte(source.path, size,
                 "the file ends inside the 84-byte header of a binary STL file (and does not "
                 "start with 'solid' as ASCII STL does)");
  const uint64_t count = load<uint32_t>(bytes + 80, false);
  const uint64_t fit = (size - header_size) / triangle_size;
  if (count > fit)
    fail_at_byte(source.path, header_size + fit * triangle_size,
                 "file ends after " + std::to_string(fit) + " of " + std::to_string(count) +
                     " triangles");

  VertexMerger merger(mesh, 3 * count);
  mesh.triangles.reserve(mesh.triangles.size() + 3 * count);
  const unsigned char *p = bytes + header_size;
  for (uint64_t t = 0; t < count; ++t, p += triangle_size) {
    for (int corner = 0; corner < 3; ++corner) {
      const unsigned char *c = p + 12 + 12 * corner;  // after the normal
      mesh.triangles.push_back(merger.add(load<float>(c, false), load<float>(c + 4, false),
                                          load<float>(c + 8, false)));
    }
  }
}

}  // namespace moa::io::detail
