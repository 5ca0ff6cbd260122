// OFF output with the shortest exact decimal for each coordinate.
#include "formats.hpp"
#include "text_scan.hpp"

namespace moa::io::detail {

void write_off(std::string &out, const std::vector<double> &xyz, const Triangles &triangles) {
  const size_t vertices = xyz.size() / 3, faces = triangles.size() / 3;
  out.reserve(out.size() + 32 + vertices * 40 + faces * 24);
  out += "OFF\n";
  append_unsigned(out, vertices);
  out += ' ';
  append_unsigned(out, faces);
  out += " 0\n";
  for (size_t v = 0; v < vertices; ++v)
    for (int axis = 0; axis < 3; ++axis) {
      append_number(out, xyz[3 * v + axis]);
      out += axis < 2 ? ' ' : '\n';
    }
  for (size_t f = 0; f < faces; ++f) {
    out += '3';
    for (int corner = 0; corner < 3; ++corner) {
      out += ' ';
      append_unsigned(out, triangles[3 * f + corner]);
    }
    out += '\n';
  }
}

}  // namespace moa::io::detail
