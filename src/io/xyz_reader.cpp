// XYZ and the text exports like it (.txt, .pts, .csv): one point per line, x y z in the first
// three columns, or in the columns a header line names x, y and z; further columns (normals,
// colours, intensities) are ignored, as are blank lines and '#' comments. Columns are
// separated by whitespace, or by commas or semicolons (spreadsheet and CloudCompare exports),
// with optional whitespace around each field.
#include <algorithm>
#include <cctype>
#include <cstring>
#include <string>
#include <vector>

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

// What separates the columns, decided by a line: a semicolon if it has one (its commas may be
// decimal commas, which must then fail as numbers rather than split them), else a comma if it
// has one, else whitespace.
char separator_of(std::string_view line) {
  if (line.find(';') != std::string_view::npos) return ';';
  if (line.find(',') != std::string_view::npos) return ',';
  return ' ';
}

// The fields of one line. Whitespace separates in runs; a comma or semicolon separates
// exactly one field from the next, so that an empty field stays in its place instead of
// shifting the columns after it, and the whitespace around a field is not part of it.
class Fields {
 public:
  Fields(std::string_view line, char separator)
      : rest_(line), tokens_(line), separator_(separator) {}

  bool next(std::string_view &field) {
    if (separator_ == ' ') return tokens_.next(field);
    if (done_) return false;
    const size_t end = rest_.find(separator_);
    field = trim(rest_.substr(0, end));
    if (end == std::string_view::npos)
      done_ = true;
    else
      rest_.remove_prefix(end + 1);
    return true;
  }

 private:
  static std::string_view trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
  }

  std::string_view rest_;
  Tokens tokens_;
  char separator_;
  bool done_ = false;
};

// A header's field as a name: without CloudCompare's leading "//" and without quotes; empty
// unless it starts with a letter or '_' (a field such as "1,5" is a number written wrongly).
std::string_view name_of(std::string_view field) {
  while (!field.empty() && field.front() == '/') field.remove_prefix(1);
  if (field.size() >= 2 && (field.front() == '"' || field.front() == '\'') &&
      field.back() == field.front())
    field = field.substr(1, field.size() - 2);
  if (field.empty() || !(std::isalpha(static_cast<unsigned char>(field[0])) || field[0] == '_'))
    return {};
  return field;
}

bool names_axis(std::string_view name, char axis) {
  return name.size() == 1 && std::tolower(static_cast<unsigned char>(name[0])) == axis;
}

// Where x, y and z stand in each line: the first three columns unless a header names them.
struct Columns {
  size_t of[3] = {0, 1, 2};
  size_t needed = 3;  // fields a line must have
  bool named = false;

  // Reads a header line, whose fields are all names (no number among them); false if the
  // line is not one.
  bool read_header(std::string_view line) {
    std::vector<std::string_view> names;
    Fields split(line, separator_of(line));
    std::string_view field;
    double number;
    while (split.next(field)) {
      const std::string_view name = name_of(field);
      if (name.empty() || parse_double(field, number)) return false;  // "nan" and "inf" too
      names.push_back(name);
    }
    size_t found[3];
    for (int axis = 0; axis < 3; ++axis) {
      const auto at = std::find_if(names.begin(), names.end(), [&](std::string_view name) {
        return names_axis(name, char('x' + axis));
      });
      if (at == names.end()) return true;  // names, but not x y z: the first three columns
      found[axis] = static_cast<size_t>(at - names.begin());
    }
    std::copy(found, found + 3, of);
    needed = 1 + std::max({of[0], of[1], of[2]});
    named = true;
    return true;
  }

  std::string too_few(size_t found) const {
    if (!named) return "expected at least 3 numbers (x y z), found " + std::to_string(found);
    return "expected at least " + std::to_string(needed) + " columns (the header puts x y z in " +
           "columns " + std::to_string(of[0] + 1) + ", " + std::to_string(of[1] + 1) + " and " +
           std::to_string(of[2] + 1) + "), found " + std::to_string(found);
  }
};

// The message for a field that should hold a coordinate. Decimal commas are the likely cause
// when a comma or semicolon separates the columns (the first line of numbers decides that) or
// when the field has a comma.
std::string not_a_number(std::string_view field, size_t column, char separator) {
  if (field.empty()) return "column " + std::to_string(column + 1) + " is empty";
  std::string what = quoted(field) + " is not a number";
  if (separator != ' ')
    what += std::string(" (columns are separated by '") + separator +
            "' in this file; decimals must be written with '.')";
  else if (field.find(',') != std::string_view::npos)
    what += " (decimals must be written with '.')";
  return what;
}

}  // namespace

void read_xyz(const Source &source, std::vector<double> &xyz) {
  // One point per line at most: reserving for that avoids regrowing a large vector.
  xyz.reserve(xyz.size() + 3 * count_lines(source.data));
  LineReader lines(source.data, bom_length(source.data));
  std::string_view line;
  Columns columns;
  char separator = 0;  // decided by the first line of numbers
  bool first = true, pts = false;
  std::vector<std::string_view> fields;
  while (next_data_line(lines, line)) {
    // A lone count on the first line is the header of the .pts variant; a file of several
    // scans has one before each.
    if (first || pts) {
      Tokens tokens(line);
      std::string_view token;
      uint64_t count;
      if (tokens.next(token) && parse_unsigned(token, count) && tokens.done()) {
        pts = true;
        first = false;
        continue;
      }
    }
    if (first) {
      first = false;
      if (columns.read_header(line)) continue;
    }
    if (separator == 0) separator = separator_of(line);
    Fields split(line, separator);
    fields.clear();
    std::string_view field;
    while (fields.size() < columns.needed && split.next(field)) fields.push_back(field);
    double value[3];
    for (int axis = 0; axis < 3; ++axis) {
      const size_t column = columns.of[axis];
      if (column < fields.size() && !parse_double(fields[column], value[axis]))
        fail_at_line(source.path, lines.line(), not_a_number(fields[column], column, separator));
    }
    if (fields.size() < columns.needed)
      fail_at_line(source.path, lines.line(), columns.too_few(fields.size()));
    xyz.insert(xyz.end(), value, value + 3);
  }
  if (xyz.empty()) fail(source.path, "the file holds no points");
}

}  // namespace moa::io::detail
