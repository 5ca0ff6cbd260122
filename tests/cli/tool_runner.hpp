// Running the `moa` tool as a separate process from a cmocka test: quoting for the shell, whole
// files read and written, the tool's exit code and output, and the checks on them. Used by the
// tests that take the tool's path and a scratch folder as their arguments (cli_tool, render_cli).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <string>

#include "cli/cmocka_cxx.hpp"

namespace moa::test {

// What one run of the tool did.
struct Run {
  int code = -1;
  std::string out, err;
};

// s as one word for the shell, in single quotes.
inline std::string quote(const std::string &s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::string read_file(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::string &path, const std::string &text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

inline bool exists(const std::string &path) { return ::access(path.c_str(), F_OK) == 0; }

inline bool has(const std::string &text, const std::string &part) {
  return text.find(part) != std::string::npos;
}

#define EXPECT_HAS(text, part) \
  if (!has(text, part)) fail_msg("expected '%s' in: %s", std::string(part).c_str(), (text).c_str())

// Writes 800 points spread evenly over the unit sphere (a Fibonacci lattice) to file, one
// "x y z" line each, and returns file.
inline std::string write_sphere_points(const std::string &file) {
  std::string text;
  const int n = 800;
  const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
  char line[128];
  for (int i = 0; i < n; ++i) {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z), a = golden * i;
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", r * std::cos(a), r * std::sin(a), z);
    text += line;
  }
  write_file(file, text);
  return file;
}

// The tool under test and the scratch folder its files go to.
struct Tool {
  std::string exe, dir;

  std::string path(const std::string &name) const { return dir + "/" + name; }

  // Runs `TOOL ARGS` with stdout and stderr captured in files of the scratch folder (stderr is
  // then no terminal: no progress bar). Stdout goes to `stdout_to` instead when given (a
  // device such as /dev/full); out is then left empty.
  Run run(const std::string &args, const std::string &stdout_to = "") const {
    const std::string out = stdout_to.empty() ? path("stdout.txt") : stdout_to;
    const std::string err = path("stderr.txt");
    const std::string command = quote(exe) + " " + args + " >" + quote(out) + " 2>" + quote(err);
    const int status = std::system(command.c_str());
    Run r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (stdout_to.empty()) r.out = read_file(out);
    r.err = read_file(err);
    return r;
  }
};

// The test's arguments, PATH_TO_MOA SCRATCH_DIR; false (after the usage on stderr) when missing.
inline bool tool_from_args(int argc, char **argv, Tool &tool) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s PATH_TO_MOA SCRATCH_DIR\n", argv[0]);
    return false;
  }
  tool.exe = argv[1];
  tool.dir = argv[2];
  return true;
}

inline void expect_ok(const Run &r) {
  if (r.code != 0) fail_msg("exit code %d; stderr: %s", r.code, r.err.c_str());
}

// An error: the exit code and exactly one line "moa: ..." on stderr holding every fragment.
inline void expect_error(const Run &r, int code, std::initializer_list<std::string> fragments) {
  if (r.code != code)
    fail_msg("exit code %d, expected %d; stderr: %s", r.code, code, r.err.c_str());
  size_t lines = 0;
  for (char c : r.err) lines += c == '\n';
  if (lines != 1 || r.err.back() != '\n' || r.err.compare(0, 5, "moa: ") != 0)
    fail_msg("expected one line 'moa: ...' on stderr, got: %s", r.err.c_str());
  for (const std::string &f : fragments) EXPECT_HAS(r.err, f);
}

}  // namespace moa::test
