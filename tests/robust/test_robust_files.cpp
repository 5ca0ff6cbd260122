// Files that tests/io does not reach: paths that are not files (a FIFO, a device, symlinks,
// names too long), paths the user may not read (also when the tests run as root), and files that read cleanly but hold points that moa_run must refuse.
// Malformed, truncated and lying files and the wrong format behind an extension are tests/io's.
#include <climits>
#include <limits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/io.hpp"
#include "robust/robust.hpp"

namespace {

std::string g_dir;  // the group's scratch directory

int make_dir(void **) {
  char templ[] = "/tmp/moa_robust_files_XXXXXX";
  if (mkdtemp(templ) == nullptr) return -1;
  g_dir = templ;
  return 0;
}

int remove_dir(void **) {
  const std::string command = "rm -rf '" + g_dir + "'";
  return std::system(command.c_str()) == 0 ? 0 : -1;
}

std::string path_of(const std::string &name) { return g_dir + "/" + name; }

std::string write_file(const std::string &name, const std::string &bytes) {
  const std::string path = path_of(name);
  FILE *f = std::fopen(path.c_str(), "wb");
  assert_non_null(f);
  assert_int_equal(std::fwrite(bytes.data(), 1, bytes.size(), f), bytes.size());
  assert_int_equal(std::fclose(f), 0);
  return path;
}

// Fails unless reading `path` throws IoError whose message holds the path and `what`.
void expect_io_error(const std::string &path, const char *what, const char *file, int line) {
  try {
    (void)moa::io::read_points(path);
  } catch (const moa::io::IoError &e) {
    const std::string message = e.what();
    if (message.find(path) == std::string::npos || message.find(what) == std::string::npos)
      robust::fail_at(file, line, "message '%s' lacks the path or '%s'", e.what(), what);
    return;
  } catch (const std::exception &e) {
    robust::fail_at(file, line, "%s: not an IoError but '%s'", path.c_str(), e.what());
  }
  robust::fail_at(file, line, "%s: read without an error", path.c_str());
}
#define EXPECT_IO_ERROR(path, what) expect_io_error((path), (what), __FILE__, __LINE__)

void on_alarm(int) {
  static const char message[] = "a read blocked for 20 s\n";
  (void)!write(2, message, sizeof message - 1);
  _exit(1);
}

// None of these may block, crash or be read as points.
void paths_that_are_not_files(void **) {
  std::signal(SIGALRM, on_alarm);
  alarm(20);  // opening a FIFO without a writer would block for ever
  const std::string fifo = path_of("pipe.xyz");
  assert_int_equal(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_IO_ERROR(fifo, "not a regular file");
  const std::string zero = path_of("zero.ply");  // endless bytes
  assert_int_equal(symlink("/dev/zero", zero.c_str()), 0);
  EXPECT_IO_ERROR(zero, "not a regular file");
  const std::string dir = path_of("dir.xyz");
  assert_int_equal(symlink(g_dir.c_str(), dir.c_str()), 0);
  EXPECT_IO_ERROR(dir, "is a directory");
  const std::string dangling = path_of("dangling.off");
  assert_int_equal(symlink(path_of("nowhere.off").c_str(), dangling.c_str()), 0);
  EXPECT_IO_ERROR(dangling, "No such file");
  const std::string loop = path_of("loop.obj");
  assert_int_equal(symlink(loop.c_str(), loop.c_str()), 0);
  EXPECT_IO_ERROR(loop, "symbolic links");
  EXPECT_IO_ERROR(path_of(std::string(NAME_MAX + 1, 'n') + ".xyz"), "too long");
  EXPECT_IO_ERROR(write_file("file.xyz", "1 2 3\n") + "/", "not a directory");
  try {
    (void)moa::io::read_points("");
    fail_msg("an empty path was read");
  } catch (const moa::io::IoError &) {
  }
  alarm(0);
}

// Paths the user may not read: a file without read permission, and a file in a folder without
// search permission. Root reads anything, and CI runs as root, so the reads run in a child
// that first gives root up (to nobody); the child reports through its exit status.
void unreadable_paths(void **) {
  const std::string locked = write_file("locked.xyz", "1 2 3\n");
  const std::string closed = path_of("closed");
  assert_int_equal(mkdir(closed.c_str(), 0755), 0);
  const std::string inside = write_file("closed/inside.xyz", "1 2 3\n");
  assert_int_equal(chmod(locked.c_str(), 0), 0);
  assert_int_equal(chmod(closed.c_str(), 0), 0);
  assert_int_equal(chmod(g_dir.c_str(), 0755), 0);  // nobody may look inside the scratch folder
  std::fflush(nullptr);
  const pid_t pid = fork();
  assert_true(pid >= 0);
  if (pid == 0) {
    if (geteuid() == 0 && (setgid(65534) != 0 || setuid(65534) != 0)) _exit(3);
    for (const std::string &path : {locked, inside}) {
      try {
        (void)moa::io::read_points(path);
        std::fprintf(stderr, "%s: read without permission\n", path.c_str());
        _exit(1);
      } catch (const moa::io::IoError &e) {
        const std::string message = e.what();
        if (message.find(path) == std::string::npos ||
            message.find("Permission denied") == std::string::npos) {
          std::fprintf(stderr, "message '%s' lacks the path or 'Permission denied'\n", e.what());
          _exit(1);
        }
      } catch (...) {
        _exit(2);
      }
    }
    _exit(0);
  }
  int status = 0;
  assert_int_equal(waitpid(pid, &status, 0), pid);
  chmod(closed.c_str(), 0700);  // so that the scratch folder can be removed
  assert_int_equal(chmod(g_dir.c_str(), 0700), 0);
  assert_true(WIFEXITED(status));
  if (WEXITSTATUS(status) == 3) fail_msg("could not give up root to test permissions");
  assert_int_equal(WEXITSTATUS(status), 0);
}

// A file that reads cleanly but whose points moa_run refuses: the whole path from file to
// status, with the message naming the problem and the context usable afterwards.
void expect_points_refused(moa_ctx *ctx, const std::string &path, const char *what,
                           const char *file, int line) {
  std::vector<double> xyz;
  try {
    xyz = moa::io::read_points(path);
  } catch (const std::exception &e) {
    robust::fail_at(file, line, "%s: %s", path.c_str(), e.what());
  }
  if (moa_set_points(ctx, xyz.data(), xyz.size() / 3) != MOA_OK)
    robust::fail_at(file, line, "moa_set_points: %s", moa_last_error(ctx));
  robust::expect_failure(ctx, moa_run(ctx), MOA_ERROR_INVALID_INPUT, {what}, file, line);
}
#define EXPECT_POINTS_REFUSED(ctx, path, what) \
  expect_points_refused((ctx), (path), (what), __FILE__, __LINE__)

std::string binary_ply(const std::vector<float> &xyz) {
  std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " +
                    std::to_string(xyz.size() / 3) +
                    "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  out.append(reinterpret_cast<const char *>(xyz.data()), xyz.size() * sizeof(float));
  return out;
}

void readable_files_with_bad_points(void **) {
  moa_ctx *ctx = robust::new_ctx();
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  EXPECT_POINTS_REFUSED(ctx, write_file("nan.xyz", body + "nan 1 1\n"), "point 4 ");
  EXPECT_POINTS_REFUSED(ctx, write_file("inf.xyz", body + "1 -inf 1\n"), "non-finite");
  EXPECT_POINTS_REFUSED(ctx, write_file("overflow.xyz", body + "1 1 1e400\n"), "non-finite");
  EXPECT_POINTS_REFUSED(ctx, write_file("huge.obj", "v 0 0 0\nv 1 0 0\nv 0 1e300 0\n"), "1e150");
  EXPECT_POINTS_REFUSED(ctx, write_file("two.off", "OFF\n2 0 0\n0 0 0\n1 1 1\n"), "got 2");
  EXPECT_POINTS_REFUSED(ctx, write_file("line.xyz", "0 0 0\n1 1 1\n2 2 2\n3 3 3\n"), "collinear");
  EXPECT_POINTS_REFUSED(ctx, write_file("same.ply", binary_ply({1, 2, 3, 1, 2, 3, 1, 2, 3})),
                        "only 1 distinct");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_POINTS_REFUSED(ctx, write_file("nan.ply", binary_ply({0, 0, 0, 1, 0, 0, 0, nan, 0})),
                        "point 2 ");
  // The same context then takes a good file: a georeferenced sphere written with millimetres.
  std::string text;
  const robust::Points unit = robust::sphere(300);
  for (std::size_t i = 0; i < unit.size(); i += 3) {
    char line[128];
    std::snprintf(line, sizeof line, "%.3f %.3f %.3f\n", 431000 + 10 * unit[i],
                  5120000 + 10 * unit[i + 1], 250 + 10 * unit[i + 2]);
    text += line;
  }
  const std::vector<double> geo = moa::io::read_points(write_file("geo.xyz", text));
  assert_true(EXPECT_RUN_OK(ctx, geo) > 0);
  moa_ctx_destroy(ctx);
}

}  // namespace

int main() {
  const CMUnitTest tests[] = {
      cmocka_unit_test(paths_that_are_not_files),
      cmocka_unit_test(unreadable_paths),
      cmocka_unit_test(readable_files_with_bad_points),
  };
  return cmocka_run_group_tests(tests, make_dir, remove_dir);
}
