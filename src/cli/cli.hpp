// The `moa` tool: shared pieces of its commands (exit codes, errors, argument walking).
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace moa::io {
struct MeshData;
}

namespace moa::cli {

// Exit codes, documented in `moa --help`.
enum ExitCode : int {
  kExitOk = 0,
  kExitInternal = 1,     // out of memory, a bug
  kExitUsage = 2,        // the command line: unknown command/option/parameter, missing argument
  kExitInput = 3,        // the input file: missing, unreadable, malformed, unusable points
  kExitReconstruct = 4,  // moa_run failed or was interrupted
  kExitOutput = 5,       // an output file, or standard output, cannot be written
};

// Ends the command: main prints "moa: <what>" on one line of stderr and exits with code().
class CliError : public std::runtime_error {
 public:
  CliError(int code, const std::string &what) : std::runtime_error(what), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

// Walks the arguments of one command. Options come as "-o FILE", "--output FILE" or
// "--output=FILE"; "--" ends the options.
class ArgWalker {
 public:
  ArgWalker(int argc, char **argv, std::string command)
      : args_(argv + 1, argv + argc), command_(std::move(command)) {}

  // Moves to the next argument; false at the end.
  bool next();
  const std::string &arg() const { return arg_; }
  // The current argument is a positional one (not an option, or after "--").
  bool positional() const { return positional_; }
  // The current argument is this option (either spelling; a long option may carry "=VALUE").
  bool is(const char *short_name, const char *long_name) const;
  // The value of the current option, from "=VALUE" or the next argument.
  std::string value();
  // A usage error for the current argument.
  [[noreturn]] void unknown() const;
  const std::string &command() const { return command_; }

 private:
  std::vector<std::string> args_;
  std::string command_;
  size_t index_ = 0;
  std::string arg_;
  bool positional_ = false;
  bool options_done_ = false;
};

// The commands; argv[0] is the command's name. Each returns the exit code or throws CliError.
int run_reconstruct(int argc, char **argv);
int run_params(int argc, char **argv);
int run_check(int argc, char **argv);
int run_render(int argc, char **argv);

// Help texts of the commands, printed by `moa COMMAND --help` and `moa help COMMAND`.
extern const char *const kReconstructHelp;
extern const char *const kParamsHelp;
extern const char *const kCheckHelp;
extern const char *const kRenderHelp;

// Used by `moa reconstruct --render` (defined in render.cpp): the check of the picture's path
// before the run (a .png name, writable: check_writable), and the picture after it; returns
// the milliseconds the picture took.
void check_png_path(const std::string &path);
double render_result(const std::string &image_path, const io::MeshData &mesh);

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// "path: what" unless `what` already names the path (the io library's messages do).
std::string about_file(const std::string &path, const std::string &what);
// Throws CliError(kExitOutput) when a file cannot be written at `path` (its folder is missing
// or read-only, or the path names a folder): called before the long parts, so that a run of
// minutes does not end in "cannot write". Creates nothing; the file is written at the end.
void check_writable(const std::string &path);

}  // namespace moa::cli
