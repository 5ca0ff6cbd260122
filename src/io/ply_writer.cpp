// PLY output: double coordinates (exact round trips), faces as uchar-counted int lists, the
// layout most tools read.
#include <limits>

#include "binary_scan.hpp"
#include "formats.hpp"
#include "text_scan.hpp"

namespace moa::io::detail {

void write_ply(std::string &out, const std::vector<double> &xyz, const Triangles *triangles,
               bool ascii) {
  const size_t vertices = xyz.size() / 3;
  const size_t faces = triangles ? triangles->size() / 3 : 0;
  // int indices are what most readers expect; beyond their range only uint will do.
  const bool wide = vertices > static_cast<size_t>(std::numeric_limits<int32_t>::max());
  out += "ply\nformat ";
  out += ascii ? "ascii" : "binary_little_endian";
  out += " 1.0\ncomment written by libmoa\nelement vertex ";
  append_unsigned(out, vertices);
  out += "\nproperty double x\nproperty double y\nproperty double z\n";
  if (triangles) {
    out += "element face ";
    append_unsigned(out, faces);
    out += wide ? "\nproperty list uchar uint vertex_indices\n"
                : "\nproperty list uchar int vertex_indices\n";
  }
  out += "end_header\n";

  if (ascii) {
    out.reserve(out.size() + vertices * 40 + faces * 24);
    for (size_t v = 0; v < vertices; ++v) {
      for (int axis = 0; axis < 3; ++axis) {
        append_number(out, xyz[3 * v + axis]);
        out += axis < 2 ? ' ' : '\n';
      }
    }
    for (size_t f = 0; f < faces; ++f) {
      out += '3';
      for (int corner = 0; corner < 3; ++corner) {
        out += ' ';
        append_unsigned(out, (*triangles)[3 * f + corner]);
      }
      out += '\n';
    }
    return;
  }
  out.reserve(out.size() + vertices * 24 + faces * 13);
  for (double value : xyz) append_little_endian(out, value);
  for (size_t f = 0; f < faces; ++f) {
    append_little_endian(out, uint8_t{3});
    for (int corner = 0; corner < 3; ++corner) append_little_endian(out, (*triangles)[3 * f + corner]);
  }
}

}  // namespace moa::io::detail
