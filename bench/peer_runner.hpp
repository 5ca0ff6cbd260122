// Shared by the peer runners (cgal_afront, open3d_recon, pcl_gp3): their command line, the
// normals a run may be given, the end of a run (the triangles' fingerprint, the mesh file and
// the result record) and main's report of an exception.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bench_common.hpp"
#include "io/io.hpp"

namespace moa::bench {

// A runner's command line: INPUT, --mesh OUT, --result FILE, -h/--help, and the runner's own
// options, each followed by one value (an option given last, without its value, is a bad
// argument).
class RunnerArgs {
 public:
  std::string input, mesh, result;

  RunnerArgs(const char *name, const char *usage) : name_(name), usage_(usage) {
    option("--mesh", mesh).option("--result", result);
  }
  RunnerArgs(const RunnerArgs &) = delete;  // the options hold references to the members
  RunnerArgs &operator=(const RunnerArgs &) = delete;

  RunnerArgs &option(const std::string &flag, std::function<void(const char *)> set) {
    options_[flag] = std::move(set);
    return *this;
  }
  RunnerArgs &option(const std::string &flag, std::string &value) {
    return option(flag, [&value](const char *v) { value = v; });
  }
  RunnerArgs &option(const std::string &flag, double &value) {
    return option(flag, [&value](const char *v) { value = std::atof(v); });
  }
  RunnerArgs &option(const std::string &flag, int &value) {
    return option(flag, [&value](const char *v) { value = std::atoi(v); });
  }

  // Reads the arguments. Returns -1 to go on, or the exit code to end with: 0 after --help (the
  // usage on stdout), 2 after a bad argument or without INPUT (the usage on stderr).
  int parse(int argc, char **argv) {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      const auto found = i + 1 < argc ? options_.find(a) : options_.end();
      if (found != options_.end()) {
        found->second(argv[++i]);
      } else if (a == "-h" || a == "--help") {
        std::fputs(usage_, stdout);
        return 0;
      } else if (a[0] != '-' && input.empty()) {
        input = a;
      } else {
        std::fprintf(stderr, "%s: bad argument %s\n%s", name_, a.c_str(), usage_);
        return 2;
      }
    }
    if (input.empty()) return usage_error();
    return -1;
  }

  // The usage on stderr; returns the exit code 2.
  int usage_error() const {
    std::fputs(usage_, stderr);
    return 2;
  }

 private:
  const char *name_, *usage_;
  std::map<std::string, std::function<void(const char *)>> options_;
};

// The normals in path, nx ny nz for each of the points xyz holds.
inline std::vector<double> read_normals(const std::string &path, const std::vector<double> &xyz) {
  std::vector<double> normals = moa::io::read_points(path);
  if (normals.size() != xyz.size()) throw std::runtime_error(path + ": not one normal per point");
  return normals;
}

// The end of a successful run: the triangles' fingerprint, the mesh written to args.mesh (when
// asked for), status ok, and the record appended to args.result (when asked for).
inline void finish_run(ResultWriter &r, const moa::io::MeshData &mesh, const RunnerArgs &args) {
  r.put("hash", hex64(fnv1a(mesh.triangles.data(), mesh.triangles.size())));
  if (!args.mesh.empty()) moa::io::write_mesh(args.mesh, mesh);
  r.put("status", "ok");
  r.append_to(args.result);
}

// A runner's main: run(argc, argv), an exception said as "NAME: what" with the exit code 1.
inline int runner_main(const char *name, int (*run)(int, char **), int argc, char **argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception &e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 1;
  }
}

}  // namespace moa::bench
