// Whole-file reads and writes: parsing a buffer is much faster than stream extraction, and
// knowing the size up front lets the readers reject headers that promise more than it holds.
#pragma once

#include <string>

namespace moa::io::detail {

// The bytes of a regular file. Throws IoError naming the path for a missing, unreadable or
// non-regular file (a directory, a FIFO).
std::string read_whole_file(const std::string &path);

// Creates or replaces a file. Throws IoError naming the path when it cannot be written.
void write_whole_file(const std::string &path, const std::string &bytes);

}  // namespace moa::io::detail
