// The `moa` command-line tool: dispatches to one command per file and turns every error into
// one line on stderr and a documented exit code.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>

#include "cli/cli.hpp"
#include "moa/moa.h"

namespace moa::cli {

namespace {

const char *const kHelp =
    "moa - triangle meshes from unorganized 3-D points by Maximum Opposite Angulation\n"
    "\n"
    "Usage:\n"
    "  moa reconstruct INPUT -o OUTPUT [--param NAME=VALUE]... [--stats FILE.json]\n"
    "                  [--render IMAGE.png] [--ascii] [--quiet]\n"
    "  moa params\n"
    "  moa check MESH [--points INPUT] [--json] [--report REPORT.md]\n"
    "  moa render MESH -o IMAGE.png [--view front|back|left|right|top|bottom|iso]\n"
    "             [--size WxH] [--wireframe] [--highlight-defects]\n"
    "  moa --version\n"
    "  moa --help | moa COMMAND --help | moa help COMMAND\n"
    "\n"
    "Commands:\n"
    "  reconstruct  build a mesh from the points of INPUT and write it to OUTPUT\n"
    "  params       list the reconstruction parameters: default, range, description\n"
    "  check        analyse a mesh: counts, closedness, genus, manifoldness, orientation,\n"
    "               self-intersections, degenerate faces, triangle angles\n"
    "  render       draw a mesh into a PNG picture, optionally with its wireframe, its\n"
    "               boundary edges and its defective faces\n"
    "\n"
    "Files: points are read from .xyz .txt .pts .csv .ply .off .obj; meshes are read and\n"
    "written as .ply .off .obj .stl; pictures are written as .png.\n"
    "\n"
    "Exit status:\n"
    "  0  success (for check: whether or not the mesh is clean)\n"
    "  1  internal error (out of memory, a bug in moa)\n"
    "  2  usage error: unknown command or option, missing argument, unknown parameter or\n"
    "     a value out of range\n"
    "  3  input file error: missing, unreadable or malformed, or points that cannot be\n"
    "     reconstructed (too few, non-finite, all collinear)\n"
    "  4  reconstruction error (including an interrupted run)\n"
    "  5  output file error: the mesh, the statistics, the picture, the report or\n"
    "     standard output cannot be written\n"
    "Errors are reported on one line of stderr: \"moa: FILE: what is wrong\".\n";

// One line, whatever the message holds.
std::string one_line(std::string s) {
  for (char &c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

const char *help_of(const std::string &command) {
  if (command == "reconstruct") return kReconstructHelp;
  if (command == "params") return kParamsHelp;
  if (command == "check") return kCheckHelp;
  if (command == "render") return kRenderHelp;
  return nullptr;
}

int run(int argc, char **argv) {
  if (argc < 2) throw CliError(kExitUsage, "missing command (see moa --help)");
  const std::string command = argv[1];
  if (command == "--help" || command == "-h") {
    std::fputs(kHelp, stdout);
    return kExitOk;
  }
  if (command == "help") {
    if (argc < 3) {
      std::fputs(kHelp, stdout);
      return kExitOk;
    }
    const char *help = help_of(argv[2]);
    if (!help) throw CliError(kExitUsage, "unknown command '" + std::string(argv[2]) + "' (see moa --help)");
    std::fputs(help, stdout);
    return kExitOk;
  }
  if (command == "--version" || command == "-V") {
    std::printf("moa %s (libmoa %s)\n", MOA_VERSION_STRING, moa_version());
    return kExitOk;
  }
  if (command == "reconstruct") return run_reconstruct(argc - 1, argv + 1);
  if (command == "params") return run_params(argc - 1, argv + 1);
  if (command == "check") return run_check(argc - 1, argv + 1);
  if (command == "render") return run_render(argc - 1, argv + 1);
  if (!command.empty() && command[0] == '-')
    throw CliError(kExitUsage, "unknown option '" + command + "' (see moa --help)");
  throw CliError(kExitUsage, "unknown command '" + command + "' (see moa --help)");
}

}  // namespace

bool ArgWalker::next() {
  if (index_ >= args_.size()) return false;
  arg_ = args_[index_++];
  positional_ = options_done_ || arg_.empty() || arg_[0] != '-' || arg_ == "-";
  if (!options_done_ && arg_ == "--") {
    options_done_ = true;
    return next();
  }
  return true;
}

bool ArgWalker::is(const char *short_name, const char *long_name) const {
  if (positional_) return false;
  if (short_name && arg_ == short_name) return true;
  if (!long_name) return false;
  const size_t n = std::strlen(long_name);
  return arg_.compare(0, n, long_name) == 0 && (arg_.size() == n || arg_[n] == '=');
}

std::string ArgWalker::value() {
  const size_t eq = arg_.find('=');
  if (arg_.compare(0, 2, "--") == 0 && eq != std::string::npos) return arg_.substr(eq + 1);
  if (index_ >= args_.size())
    throw CliError(kExitUsage, arg_ + " needs a value (see moa " + command_ + " --help)");
  return args_[index_++];
}

void ArgWalker::unknown() const {
  if (positional_)
    throw CliError(kExitUsage, "unexpected argument '" + arg_ + "' (see moa " + command_ + " --help)");
  throw CliError(kExitUsage, "unknown option '" + arg_ + "' (see moa " + command_ + " --help)");
}

std::string about_file(const std::string &path, const std::string &what) {
  if (what.compare(0, path.size(), path) == 0) return what;
  return path + ": " + what;
}

void check_writable(const std::string &path) {
  auto refuse = [&](int error) {
    throw CliError(kExitOutput, path + ": cannot write: " + std::strerror(error));
  };
  struct stat st;
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) refuse(EISDIR);
    if (::access(path.c_str(), W_OK) != 0) refuse(errno);
    return;
  }
  // Not there yet: its folder must exist and take a new file.
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  if (::access(folder.c_str(), W_OK | X_OK) != 0) refuse(errno);
}

}  // namespace moa::cli

namespace {

// What a command printed must have reached standard output: behind a redirection to a full
// disk, `moa check --json > report.json` lost its report and still exited 0. A command that
// failed already has its own message and code.
int with_stdout_written(int code) {
  using namespace moa::cli;
  errno = 0;
  std::cout.flush();  // through stdout's buffer (synced with stdio), where a failure shows
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (code != kExitOk || (flushed && std::cout.good() && !std::ferror(stdout))) return code;
  std::fprintf(stderr, "moa: standard output: cannot write%s%s\n", error ? ": " : "",
               error ? std::strerror(error) : "");
  return kExitOutput;
}

}  // namespace

int main(int argc, char **argv) {
  using namespace moa::cli;
  try {
    return with_stdout_written(run(argc, argv));
  } catch (const CliError &e) {
    std::fprintf(stderr, "moa: %s\n", one_line(e.what()).c_str());
    return e.code();
  } catch (const std::bad_alloc &) {
    std::fprintf(stderr, "moa: out of memory\n");
    return kExitInternal;
  } catch (const std::exception &e) {
    std::fprintf(stderr, "moa: internal error: %s\n", one_line(e.what()).c_str());
    return kExitInternal;
  }
}
