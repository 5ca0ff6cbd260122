#include "errors.hpp"

#include <cstdio>

namespace moa::io::detail {

void fail(const std::string &path, const std::string &what) { throw IoError(path + ": " + what); }

void fail_at_line(const std::string &path, size_t line, const std::string &what) {
  throw IoError(path + ": line " + std::to_string(line) + ": " + what);
}

void fail_at_byte(const std::string &path, size_t offset, const std::string &what) {
  throw IoError(path + ": byte " + std::to_string(offset) + ": " + what);
}

std::string quoted(std::string_view token) {
  constexpr size_t max_shown = 40;
  std::string out = "'";
  for (size_t i = 0; i < token.size() && i < max_shown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f && c != '\'') {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  if (token.size() > max_shown) out += "...";
  return out + "'";
}

std::string plural(const std::string &element) {
  if (element == "vertex") return "vertices";
  if (element == "face") return "faces";
  return "'" + element + "' elements";
}

std::string counted(uint64_t count, const char *one, const char *many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

}  // namespace moa::io::detail
