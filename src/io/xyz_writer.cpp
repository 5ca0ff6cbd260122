// XYZ output: "x y z" per line ("x,y,z" for .csv) with the shortest exact decimals.
#include "formats.hpp"
#include "text_scan.hpp"

namespace moa::io::detail {

void write_xyz(std::string &out, const std::vector<double> &xyz, char separator) {
  out.reserve(out.size() + xyz.size() * 14);
  for (size_t i = 0; i < xyz.size(); ++i) {
    append_number(out, xyz[i]);
    out += i % 3 < 2 ? separator : '\n';
  }
}

}  // namespace moa::io::detail
