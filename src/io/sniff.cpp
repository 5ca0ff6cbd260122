#include "sniff.hpp"

#include <cstdint>
#include <cstring>

#include "binary_scan.hpp"
#include "errors.hpp"
#include "text_scan.hpp"

namespace moa::io::detail {
namespace {

constexpr size_t sniff_window = 4096;

bool has_nul(std::string_view data, size_t limit) {
  return std::memchr(data.data(), '\0', std::min(limit, data.size())) != nullptr;
}

// The first whitespace-separated token outside '#' comment lines, within the window.
std::string_view first_keyword(std::string_view data) {
  const size_t skip = bom_length(data);
  LineReader lines(data.substr(0, std::min(data.size(), sniff_window)), skip);
  std::string_view line, token;
  while (lines.next(line)) {
    Tokens tokens(line);
    if (!tokens.next(token)) continue;
    if (token[0] == '#') continue;
    return token;
  }
  return {};
}

bool is_obj_keyword(std::string_view token) {
  static const char *const keywords[] = {"v", "vt", "vn", "vp", "f", "l", "p", "o",
                                         "g", "s", "mtllib", "usemtl"};
  for (const char *keyword : keywords)
    if (token == keyword) return true;
  return false;
}

const char *describe(Content content) {
  switch (content) {
    case Content::Ply: return "a PLY file";
    case Content::Off: return "an OFF file";
    case Content::StlBinary: return "a binary STL file";
    case Content::StlAscii: return "an ASCII STL file";
    case Content::Obj: return "an OBJ file";
    case Content::Numbers: return "columns of numbers (XYZ)";
    case Content::Binary: return "binary data";
    default: return "unrecognised";
  }
}

bool compatible(Format format, Content content) {
  switch (format) {
    case Format::Xyz: return content == Content::Numbers || content == Content::Unknown;
    case Format::Ply: return content == Content::Ply;
    case Format::Off:
      return content == Content::Off || content == Content::Numbers || content == Content::Unknown;
    case Format::Obj: return content == Content::Obj || content == Content::Unknown;
    case Format::Stl:
      // Unrecognised content goes to the binary STL reader, which says what is missing.
      return content == Content::StlBinary || content == Content::StlAscii ||
             content == Content::Binary || content == Content::Unknown;
  }
  return false;
}

}  // namespace

bool is_off_keyword(std::string_view token) {
  if (token.size() < 3 || token.substr(token.size() - 3) != "OFF") return false;
  std::string_view prefix = token.substr(0, token.size() - 3);
  if (prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
  for (char optional : {'C', 'N', '4', 'n'})
    if (!prefix.empty() && prefix[0] == optional) prefix.remove_prefix(1);
  return prefix.empty();
}

Content sniff_content(std::string_view data) {
  if (data.empty()) return Content::Empty;
  if (data.substr(0, 4) == "ply\n" || data.substr(0, 5) == "ply\r\n") return Content::Ply;
  if (data.size() >= 84) {
    const auto count = load<uint32_t>(reinterpret_cast<const unsigned char *>(data.data()) + 80,
                                      false);
    if (84 + 50 * uint64_t{count} == data.size()) return Content::StlBinary;
  }
  const std::string_view keyword = first_keyword(data);
  const bool binary = has_nul(data, sniff_window);
  // Some binary STL writers start the 80-byte header with "solid" too.
  if (keyword == "solid") return binary ? Content::StlBinary : Content::StlAscii;
  if (binary) return Content::Binary;
  if (keyword.empty()) return Content::Unknown;
  if (is_off_keyword(keyword)) return Content::Off;
  if (is_obj_keyword(keyword)) return Content::Obj;
  const char c = keyword[0];
  if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.') return Content::Numbers;
  return Content::Unknown;
}

Content check_content(const std::string &path, std::string_view data, Format format) {
  const Content content = sniff_content(data);
  if (content == Content::Empty) fail(path, "the file is empty");
  if (compatible(format, content)) return content;
  const std::string expected = format_name(format);
  if (content == Content::Unknown)  // only PLY demands a signature
    fail(path, "not a PLY file: it does not start with a 'ply' line");
  fail(path, "the extension says " + expected + " but the content is " + describe(content));
}

}  // namespace moa::io::detail
