// The PLY header: encoding, elements and their properties.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace moa::io::detail {

enum class PlyType : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

size_t ply_type_size(PlyType type);
bool ply_type_is_integer(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // of the value, or of a list's items
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;  // of a list's length
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
  size_t line = 0;  // of its "element" line, for messages

  // Bytes per item in binary: exact without lists, a lower bound with them.
  size_t min_binary_size() const;
  bool has_lists() const;
  int find(std::string_view property) const;  // index, or -1
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  size_t body_offset = 0;  // first byte after end_header's line
  size_t header_lines = 0;
};

// Throws IoError naming the header line that is wrong.
PlyHeader parse_ply_header(const std::string &path, std::string_view data);

}  // namespace moa::io::detail
