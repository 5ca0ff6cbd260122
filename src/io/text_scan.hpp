// Line and token scanning over an in-memory text file, and locale-independent number parsing
// and printing (std::from_chars / std::to_chars: fast, and exact round trips for doubles).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace moa::io::detail {

inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Hands out the lines of a buffer without their "\n" or "\r\n", counting line numbers.
class LineReader {
 public:
  explicit LineReader(std::string_view data, size_t offset = 0, size_t lines_before = 0)
      : data_(data), pos_(offset), line_(lines_before) {}

  bool next(std::string_view &line);

  size_t line() const { return line_; }  // 1-based number of the line last returned
  size_t offset() const { return pos_; }  // first byte after the line last returned
  size_t remaining() const { return data_.size() - pos_; }

 private:
  std::string_view data_;
  size_t pos_;
  size_t line_;
};

// Whitespace-separated tokens of one line.
class Tokens {
 public:
  explicit Tokens(std::string_view text) : rest_(text) {}

  bool next(std::string_view &token);
  bool done();  // true when only whitespace is left

 private:
  std::string_view rest_;
};

// The line up to a '#' comment.
std::string_view strip_comment(std::string_view line);
bool is_blank(std::string_view line);

// The next line holding more than whitespace and '#' comments, with the comment cut off.
bool next_data_line(LineReader &lines, std::string_view &line);

// Byte length of a UTF-8 byte-order mark at the start of a text file (0 or 3).
size_t bom_length(std::string_view data);

// Whole-token parses: false unless all of the token is the number. parse_double accepts
// inf and nan (the library rejects them itself, with a better message) and a leading '+'.
bool parse_double(std::string_view token, double &value);
bool parse_unsigned(std::string_view token, uint64_t &value);
bool parse_signed(std::string_view token, int64_t &value);

// Shortest text that reads back as exactly the same double.
void append_number(std::string &out, double value);
void append_unsigned(std::string &out, uint64_t value);

}  // namespace moa::io::detail
