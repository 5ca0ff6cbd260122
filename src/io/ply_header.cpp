#include "ply_header.hpp"

#include <cstring>

#include "errors.hpp"
#include "text_scan.hpp"

namespace moa::io::detail {
namespace {

bool parse_type(std::string_view name, PlyType &type) {
  static const struct {
    const char *name;
    PlyType type;
  } names[] = {{"char", PlyType::Int8},     {"int8", PlyType::Int8},
               {"uchar", PlyType::UInt8},   {"uint8", PlyType::UInt8},
               {"short", PlyType::Int16},   {"int16", PlyType::Int16},
               {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},
               {"int", PlyType::Int32},     {"int32", PlyType::Int32},
               {"uint", PlyType::UInt32},   {"uint32", PlyType::UInt32},
               {"float", PlyType::Float32}, {"float32", PlyType::Float32},
               {"double", PlyType::Float64}, {"float64", PlyType::Float64}};
  for (const auto &entry : names)
    if (name == entry.name) {
      type = entry.type;
      return true;
    }
  return false;
}

}  // namespace

size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 0;
}

bool ply_type_is_integer(PlyType type) {
  return type != PlyType::Float32 && type != PlyType::Float64;
}

size_t PlyElement::min_binary_size() const {
  size_t size = 0;
  for (const PlyProperty &p : properties) size += ply_type_size(p.is_list ? p.count_type : p.type);
  return size;
}

bool PlyElement::has_lists() const {
  for (const PlyProperty &p : properties)
    if (p.is_list) return true;
  return false;
}

int PlyElement::find(std::string_view property) const {
  for (size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property) return static_cast<int>(i);
  return -1;
}

PlyHeader parse_ply_header(const std::string &path, std::string_view data) {
  LineReader lines(data);
  std::string_view line, keyword, token;
  if (!lines.next(line) || line != "ply") fail_at_line(path, 1, "not a PLY file: no 'ply' line");
  PlyHeader header;
  bool have_format = false;
  for (;;) {
    if (!lines.next(line)) fail(path, "the PLY header has no end_header line");
    if (std::memchr(line.data(), '\0', line.size()))
      fail_at_line(path, lines.line(), "binary data inside the PLY header (is end_header missing?)");
    Tokens tokens(line);
    if (!tokens.next(keyword)) continue;
    const size_t at = lines.line();
    const auto need = [&](const char *what) {
      if (!tokens.next(token)) fail_at_line(path, at, std::string("missing ") + what);
      return token;
    };
    if (keyword == "end_header") break;
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      const std::string_view encoding = need("encoding after 'format'");
      if (encoding == "ascii")
        header.encoding = PlyEncoding::Ascii;
      else if (encoding == "binary_little_endian")
        header.encoding = PlyEncoding::BinaryLittleEndian;
      else if (encoding == "binary_big_endian")
        header.encoding = PlyEncoding::BinaryBigEndian;
      else
        fail_at_line(path, at, "unknown PLY format " + quoted(encoding));
      have_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = std::string(need("element name"));
      element.line = at;
      const std::string_view count = need("element count");
      if (!parse_unsigned(count, element.count))
        fail_at_line(path, at, quoted(count) + " is not a valid element count");
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) fail_at_line(path, at, "a property before any element");
      PlyProperty property;
      std::string_view type = need("property type");
      if (type == "list") {
        property.is_list = true;
        const std::string_view count_type = need("list count type");
        if (!parse_type(count_type, property.count_type) ||
            !ply_type_is_integer(property.count_type))
          fail_at_line(path, at, quoted(count_type) + " is not an integer type for a list count");
        type = need("list item type");
      }
      if (!parse_type(type, property.type))
        fail_at_line(path, at, "unknown property type " + quoted(type));
      property.name = std::string(need("property name"));
      header.elements.back().properties.push_back(std::move(property));
    } else {
      fail_at_line(path, at, "unknown PLY header keyword " + quoted(keyword));
    }
  }
  if (!have_format) fail_at_line(path, lines.line(), "the PLY header has no format line");
  header.body_offset = lines.offset();
  header.header_lines = lines.line();
  return header;
}

}  // namespace moa::io::detail
