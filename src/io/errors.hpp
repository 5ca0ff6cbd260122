// Building IoError messages: "<path>: line 12: <what>" and "<path>: byte 1234: <what>".
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/io.hpp"

namespace moa::io::detail {

[[noreturn]] void fail(const std::string &path, const std::string &what);
[[noreturn]] void fail_at_line(const std::string &path, size_t line, const std::string &what);
[[noreturn]] void fail_at_byte(const std::string &path, size_t offset, const std::string &what);

// A token as shown in a message: quoted, shortened, unprintable bytes escaped (binary garbage
// must not end up raw in a terminal).
std::string quoted(std::string_view token);

// "vertices", "faces" or "'edge' elements": how a message counts the items of a PLY element.
std::string plural(const std::string &element);

// "1 face", "2 faces".
std::string counted(uint64_t count, const char *one, const char *many);

}  // namespace moa::io::detail
