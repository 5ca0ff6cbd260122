// Recognising a file's format from its content, to catch a file whose extension lies.
#pragma once

#include <string>
#include <string_view>

#include "io/io.hpp"

namespace moa::io::detail {

enum class Content {
  Empty,
  Ply,        // starts with the "ply" magic line
  Off,        // first keyword is OFF or a variant (COFF, NOFF, ...)
  StlBinary,  // size fits the triangle count at byte 80, or binary data after "solid"
  StlAscii,   // text starting with "solid"
  Obj,        // first keyword is an OBJ statement (v, f, o, g, mtllib, ...)
  Numbers,    // text whose first data line starts with a number: XYZ or header-less OFF
  Binary,     // NUL bytes near the start
  Unknown,    // text that matches none of the above
};

Content sniff_content(std::string_view data);

// Whether a token is an OFF keyword: [ST][C][N][4][n]OFF.
bool is_off_keyword(std::string_view token);

// Throws IoError for an empty file, and for content that contradicts the extension's format
// (naming both); returns the content found otherwise.
Content check_content(const std::string &path, std::string_view data, Format format);

}  // namespace moa::io::detail
