// Shared by moa_bench and the peer runners: clocks, the process's peak memory, other processes'
// load, and the result files (one "key<TAB>value" per line) that run_bench.sh collects and
// `moa_bench report` turns into Markdown. Header-only so that the runners need nothing of
// libmoa but moa_io.
#pragma once

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace moa::bench {

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// High-water mark of the resident set of this process so far, in bytes (Linux reports KiB).
// Nothing is subtracted: this is what the operating system had to give the whole process.
inline uint64_t peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return uint64_t(usage.ru_maxrss) * 1024u;
}

// How busy the machine was with other work while we measured: other processes' CPU time (all
// of /proc/stat's busy time minus this process's own) over the wall time, in cores. A shared
// machine makes timings noisy; this says how much.
class OtherLoad {
 public:
  OtherLoad() : busy_(busy_seconds()), self_(self_seconds()), start_(Clock::now()) {}

  double cores() const {
    const double wall = std::chrono::duration<double>(Clock::now() - start_).count();
    if (wall <= 0) return 0;
    const double other = (busy_seconds() - busy_) - (self_seconds() - self_);
    return other > 0 ? other / wall : 0;
  }

 private:
  static double busy_seconds() {
    std::ifstream stat("/proc/stat");
    std::string cpu;
    unsigned long long user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0,
                       steal = 0;
    stat >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
    if (!stat || cpu != "cpu") return 0;
    return double(user + nice + system + irq + softirq + steal) / double(sysconf(_SC_CLK_TCK));
  }
  static double self_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  }

  double busy_, self_;
  Clock::time_point start_;
};

// FNV-1a over the bytes of an array: a fingerprint to compare outputs across processes.
template <typename T>
uint64_t fnv1a(const T *data, size_t count) {
  const auto *bytes = reinterpret_cast<const unsigned char *>(data);
  uint64_t h = 1469598103934665603ull;
  for (size_t i = 0; i < count * sizeof(T); ++i) {
    h ^= bytes[i];
    h *= 1099511628211ull;
  }
  return h;
}

inline std::string hex64(uint64_t v) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// Collects key/value pairs in order and appends them to a file at the end, so that a process
// that dies half-way leaves no half-written record (run_bench.sh then writes the failure).
class ResultWriter {
 public:
  template <typename T>
  ResultWriter &put(const std::string &key, const T &value) {
    std::ostringstream s;
    s.precision(10);
    s << value;
    lines_.push_back(key + '\t' + s.str());
    return *this;
  }
  ResultWriter &put(const std::string &key, bool value) { return put(key, value ? 1 : 0); }

  // Appends to path (empty path: nothing). Throws when the file cannot be written.
  void append_to(const std::string &path) const {
    if (path.empty()) return;
    std::ofstream out(path, std::ios::app);
    for (const std::string &line : lines_) out << line << '\n';
    if (!out) throw std::runtime_error(path + ": cannot write the result");
  }

 private:
  std::vector<std::string> lines_;
};

// Reads a result file; a key given twice keeps its last value (a failure noted by the script
// after the program's own lines wins).
inline std::map<std::string, std::string> read_result(const std::string &path) {
  std::map<std::string, std::string> out;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const size_t tab = line.find('\t');
    if (tab == std::string::npos) continue;
    out[line.substr(0, tab)] = line.substr(tab + 1);
  }
  return out;
}

}  // namespace moa::bench
