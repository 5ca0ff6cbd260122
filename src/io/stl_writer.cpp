// Binary STL output: float32 corners (STL has no other precision) and a unit normal per
// triangle, zero for degenerate ones.
#include <cmath>
#include <cstring>
#include <limits>

#include "binary_scan.hpp"
#include "formats.hpp"

namespace moa::io::detail {

void write_stl(std::string &out, const std::vector<double> &xyz, const Triangles &triangles) {
  const size_t faces = triangles.size() / 3;
  char header[80] = {};
  // Must not start with "solid", or readers may take the file for ASCII STL.
  std::strncpy(header, "binary STL written by libmoa", sizeof header - 1);
  out.append(header, sizeof header);
  append_little_endian(out, static_cast<uint32_t>(faces));
  out.reserve(out.size() + faces * 50);
  for (size_t f = 0; f < faces; ++f) {
    const double *p[3];
    for (int corner = 0; corner < 3; ++corner) p[corner] = &xyz[3 * triangles[3 * f + corner]];
    const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double &c : n) c = length > 0 && std::isfinite(length) ? c / length : 0.0;
    for (double c : n) append_little_endian(out, static_cast<float>(c));
    for (int corner = 0; corner < 3; ++corner)
      for (int axis = 0; axis < 3; ++axis)
        append_little_endian(out, static_cast<float>(p[corner][axis]));
    append_little_endian(out, uint16_t{0});
  }
}

}  // namespace moa::io::detail
