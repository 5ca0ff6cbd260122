// Reading result records and formatting their numbers for the report (report.cpp).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

namespace moa::bench {

// One run's result file, or one line of inputs.tsv: key -> value.
using Record = std::map<std::string, std::string>;

inline bool has(const Record &r, const std::string &key) { return r.count(key) != 0; }

inline std::string text(const Record &r, const std::string &key, const std::string &fallback = "") {
  const auto it = r.find(key);
  return it == r.end() ? fallback : it->second;
}

// NaN when missing or not a number ("-" in inputs.tsv).
inline double num(const Record &r, const std::string &key) {
  const auto it = r.find(key);
  if (it == r.end() || it->second.empty()) return NAN;
  char *end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  return end == it->second.c_str() ? NAN : v;
}

// The reconstruction ran to the end.
inline bool ok(const Record &r) { return text(r, "status") == "ok"; }
// ... and its mesh went through the checker.
inline bool analysed(const Record &r) { return ok(r) && text(r, "analysis") == "ok"; }

inline std::string fmt(const char *format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// 1234567 -> "1,234,567"; missing -> "—".
inline std::string grouped(double v) {
  if (!std::isfinite(v)) return "—";
  std::string digits = std::to_string((long long)std::llround(v));
  const bool negative = digits[0] == '-';
  if (negative) digits.erase(0, 1);
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return negative ? "-" + out : out;
}

// Three significant digits, whatever the magnitude of the time.
inline std::string seconds(double ms) {
  if (!std::isfinite(ms)) return "—";
  const double s = ms / 1000;
  return fmt(s < 0.01 ? "%.4f" : s < 1 ? "%.3f" : s < 10 ? "%.2f" : s < 100 ? "%.1f" : "%.0f", s);
}

inline std::string percent(double share) {
  return std::isfinite(share) ? fmt(share > 0 && share < 0.001 ? "%.2f" : "%.1f", 100 * share) : "—";
}

inline std::string megabytes(double bytes) {
  if (!std::isfinite(bytes)) return "—";
  return bytes < 10e6 ? fmt("%.1f", bytes / 1e6) : grouped(bytes / 1e6);
}

// A distance relative to the bounding-box diagonal, in per cent with two significant digits.
inline std::string relative(double v) {
  if (!std::isfinite(v)) return "—";
  if (v == 0) return "0";
  return fmt(100 * v >= 0.1 ? "%.2f" : "%.2g", 100 * v);
}

// Why a run has no result: the script's status without the log path.
inline std::string failure(const Record &r) {
  std::string why = text(r, "status", "no result");
  why = why.substr(0, why.find(" (log "));
  if (why.compare(0, 8, "failed: ") == 0) why.erase(0, 8);
  return why;
}

}  // namespace moa::bench
