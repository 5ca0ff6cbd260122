// OBJ output: "v" lines with the shortest exact decimals, "f" lines with 1-based indices.
#include "formats.hpp"
#include "text_scan.hpp"

namespace moa::io::detail {

void write_obj(std::string &out, const std::vector<double> &xyz, const Triangles &triangles) {
  const size_t vertices = xyz.size() / 3, faces = triangles.size() / 3;
  out.reserve(out.size() + 32 + vertices * 42 + faces * 26);
  out += "# written by libmoa\n";
  for (size_t v = 0; v < vertices; ++v) {
    out += 'v';
    for (int axis = 0; axis < 3; ++axis) {
      out += ' ';
      append_number(out, xyz[3 * v + axis]);
    }
    out += '\n';
  }
  for (size_t f = 0; f < faces; ++f) {
    out += 'f';
    for (int corner = 0; corner < 3; ++corner) {
      out += ' ';
      append_unsigned(out, uint64_t{triangles[3 * f + corner]} + 1);
    }
    out += '\n';
  }
}

}  // namespace moa::io::detail
