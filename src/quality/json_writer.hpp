// A minimal streaming JSON writer for reports and statistics files (no dependency for one
// output format). Objects and arrays nest; commas and indentation are handled here.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace moa {

class JsonWriter {
 public:
  // Objects and arrays opened with a key go inside the current object; without, inside the
  // current array (or at the top).
  JsonWriter &begin_object(const char *key = nullptr) { return open(key, '{', false); }
  JsonWriter &end_object() { return close('}'); }
  // inline_items: all items on one line (for short arrays of numbers).
  JsonWriter &begin_array(const char *key = nullptr, bool inline_items = false) {
    return open(key, '[', inline_items);
  }
  JsonWriter &end_array() { return close(']'); }

  JsonWriter &value(const char *key, const std::string &s) { item(key); quote(s); return *this; }
  JsonWriter &value(const char *key, const char *s) { return value(key, std::string(s)); }
  JsonWriter &value(const char *key, bool b) { item(key); out_ += b ? "true" : "false"; return *this; }
  JsonWriter &value(const char *key, double d) {
    item(key);
    if (!std::isfinite(d)) { out_ += "null"; return *this; }
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", d);
    out_ += buf;
    return *this;
  }
  template <typename Int, typename = std::enable_if_t<std::is_integral_v<Int>>>
  JsonWriter &value(const char *key, Int i) {
    item(key);
    out_ += std::to_string(i);
    return *this;
  }
  // Array items.
  template <typename T>
  JsonWriter &item_value(const T &v) { return value(nullptr, v); }

  const std::string &str() const { return out_; }

 private:
  struct Level {
    bool first = true;
    bool inline_items = false;
  };

  void newline() {
    out_ += '\n';
    out_.append(2 * levels_.size(), ' ');
  }
  void item(const char *key) {
    if (!levels_.empty()) {
      Level &l = levels_.back();
      if (!l.first) out_ += l.inline_items ? ", " : ",";
      if (!l.inline_items) newline();
      l.first = false;
    }
    if (key) {
      quote(key);
      out_ += ": ";
    }
  }
  JsonWriter &open(const char *key, char bracket, bool inline_items) {
    item(key);
    out_ += bracket;
    levels_.push_back({true, inline_items});
    return *this;
  }
  JsonWriter &close(char bracket) {
    const Level l = levels_.back();
    levels_.pop_back();
    if (!l.first && !l.inline_items) newline();
    out_ += bracket;
    if (levels_.empty()) out_ += '\n';
    return *this;
  }
  void quote(const std::string &s) {
    out_ += '"';
    for (unsigned char c : s) {
      if (c == '"' || c == '\\') { out_ += '\\'; out_ += char(c); }
      else if (c == '\n') out_ += "\\n";
      else if (c == '\t') out_ += "\\t";
      else if (c < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out_ += buf;
      } else out_ += char(c);
    }
    out_ += '"';
  }

  std::string out_;
  std::vector<Level> levels_;
};

}  // namespace moa
