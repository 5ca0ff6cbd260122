// XYZ: one point per line, at least three numeric columns; further columns (normals, colours,
// intensities) are ignored, as are blank lines and '#' comments.
#include <cstring>

#include "errors.hpp"
#include "formats.hpp"
#include "text_scan.hpp"

namespace moa::io::detail {
namespace {

size_t count_lines(std::string_view data) {
  size_t lines = 1;
  const char *p = data.data();
  const char *end = p + data.size();
  while ((p = static_cast<const char *>(std::memchr(p, '\n', static_cast<size_t>(end - p))))) {
    ++lines;
    ++p;
  }
  return lines;
}

}  // namespace

void read_xyz(const Source &source, std::vector<double> &xyz) {
  // One point per line at most: reserving for that avoids regrowing a large vector.
  xyz.reserve(xyz.size() + 3 * count_lines(source.data));
  LineReader lines(source.data, bom_length(source.data));
  std::string_view line;
  bool first = true;
  while (next_data_line(lines, line)) {
    Tokens tokens(line);
    std::string_view token[3];
    int found = 0;
    while (found < 3 && tokens.next(token[found])) ++found;
    // A lone count on the first line is the header of the .pts variant.
    uint64_t count;
    if (first && found == 1 && parse_unsigned(token[0], count)) {
      first = false;
      continue;
    }
    first = false;
    double value[3];
    for (int i = 0; i < found; ++i)
      if (!parse_double(token[i], value[i]))
        fail_at_line(source.path, lines.line(), quoted(token[i]) + " is not a number");
    if (found < 3)
      fail_at_line(source.path, lines.line(),
                   "expected at least 3 numbers (x y z), found " + std::to_string(found));
    xyz.insert(xyz.end(), value, value + 3);
  }
  if (xyz.empty()) fail(source.path, "the file holds no points");
}

}  // namespace moa::io::detail
