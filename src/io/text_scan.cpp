#include "text_scan.hpp"

#include <charconv>
#include <cstdlib>
#include <cstring>

namespace moa::io::detail {

bool LineReader::next(std::string_view &line) {
  if (pos_ >= data_.size()) return false;
  const char *begin = data_.data() + pos_;
  const size_t left = data_.size() - pos_;
  const auto *newline = static_cast<const char *>(std::memchr(begin, '\n', left));
  size_t length = newline ? static_cast<size_t>(newline - begin) : left;
  pos_ += newline ? length + 1 : length;
  if (length > 0 && begin[length - 1] == '\r') --length;
  line = std::string_view(begin, length);
  ++line_;
  return true;
}

bool Tokens::next(std::string_view &token) {
  size_t i = 0;
  while (i < rest_.size() && is_space(rest_[i])) ++i;
  if (i == rest_.size()) {
    rest_ = {};
    return false;
  }
  size_t j = i;
  while (j < rest_.size() && !is_space(rest_[j])) ++j;
  token = rest_.substr(i, j - i);
  rest_.remove_prefix(j);
  return true;
}

bool Tokens::done() {
  std::string_view ignored;
  Tokens copy = *this;
  return !copy.next(ignored);
}

std::string_view strip_comment(std::string_view line) {
  const size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

bool is_blank(std::string_view line) {
  for (char c : line)
    if (!is_space(c)) return false;
  return true;
}

bool next_data_line(LineReader &lines, std::string_view &line) {
  while (lines.next(line)) {
    line = strip_comment(line);
    if (!is_blank(line)) return true;
  }
  return false;
}

size_t bom_length(std::string_view data) {
  return data.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
}

bool parse_double(std::string_view token, double &value) {
  const char *first = token.data();
  const char *last = first + token.size();
  // from_chars rejects the '+' that strtod (and many writers) accept.
  if (first != last && *first == '+' && last - first > 1 && first[1] != '-' && first[1] != '+')
    ++first;
  const auto [end, ec] = std::from_chars(first, last, value);
  if (end != last || first == last) return false;
  if (ec == std::errc::result_out_of_range) {
    // Overflow becomes +-inf and underflow 0, as strtod does; rare, so a copy is fine.
    const std::string copy(first, last);
    value = std::strtod(copy.c_str(), nullptr);
    return true;
  }
  return ec == std::errc();
}

bool parse_unsigned(std::string_view token, uint64_t &value) {
  const char *first = token.data();
  const char *last = first + token.size();
  if (first != last && *first == '+') ++first;
  const auto [end, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && end == last && first != last;
}

bool parse_signed(std::string_view token, int64_t &value) {
  const char *first = token.data();
  const char *last = first + token.size();
  if (first != last && *first == '+' && last - first > 1 && first[1] != '-') ++first;
  const auto [end, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && end == last && first != last;
}

void append_number(std::string &out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

void append_unsigned(std::string &out, uint64_t value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace moa::io::detail
