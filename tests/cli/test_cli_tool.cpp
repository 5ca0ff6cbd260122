// The `moa` executable, run as a separate process: its commands, its files and its exit codes
// with their one-line messages. Arguments: the tool's path and a scratch folder.
#include <sys/stat.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli/cmocka_cxx.hpp"
#include "moa/moa.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string g_tool, g_dir;

struct Run {
  int code = -1;
  std::string out, err;
};

std::string quote(const std::string &s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string read_file(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const std::string &path, const std::string &text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string path(const std::string &name) { return g_dir + "/" + name; }

// Runs `moa ARGS` with stdout and stderr captured in files (stderr is then no terminal: no
// progress bar).
Run moa(const std::string &args) {
  const std::string out = path("stdout.txt"), err = path("stderr.txt");
  const std::string command = quote(g_tool) + " " + args + " >" + quote(out) + " 2>" + quote(err);
  const int status = std::system(command.c_str());
  Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

bool has(const std::string &text, const std::string &part) {
  return text.find(part) != std::string::npos;
}

#define EXPECT_HAS(text, part) \
  if (!has(text, part)) fail_msg("expected '%s' in: %s", std::string(part).c_str(), (text).c_str())

// An error: the exit code and exactly one line on stderr holding every fragment.
void expect_error(const Run &r, int code, std::initializer_list<std::string> fragments) {
  if (r.code != code) fail_msg("exit code %d, expected %d; stderr: %s", r.code, code, r.err.c_str());
  size_t lines = 0;
  for (char c : r.err) lines += c == '\n';
  if (lines != 1 || r.err.back() != '\n' || r.err.compare(0, 5, "moa: ") != 0)
    fail_msg("expected one line 'moa: ...' on stderr, got: %s", r.err.c_str());
  for (const std::string &f : fragments) EXPECT_HAS(r.err, f);
}

// 800 points spread evenly over the unit sphere (a Fibonacci lattice).
std::string sphere_points() {
  const std::string file = path("sphere.xyz");
  std::string text;
  const int n = 800;
  const double golden = kPi * (3 - std::sqrt(5.0));
  char line[128];
  for (int i = 0; i < n; ++i) {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z), a = golden * i;
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", r * std::cos(a), r * std::sin(a), z);
    text += line;
  }
  write_file(file, text);
  return file;
}

int setup(void **) {
  ::mkdir(g_dir.c_str(), 0755);
  return 0;
}

void test_version_and_help(void **) {
  Run r = moa("--version");
  assert_int_equal(r.code, 0);
  EXPECT_HAS(r.out, std::string("moa ") + MOA_VERSION_STRING);
  EXPECT_HAS(r.out, moa_version());
  r = moa("--help");
  assert_int_equal(r.code, 0);
  for (const char *part : {"moa reconstruct INPUT -o OUTPUT", "moa params", "moa check MESH",
                           "Exit status", "2  usage error", "3  input file error",
                           "4  reconstruction error", "5  output file error"})
    EXPECT_HAS(r.out, part);
  for (const char *command : {"reconstruct", "params", "check"}) {
    r = moa(std::string(command) + " --help");
    assert_int_equal(r.code, 0);
    EXPECT_HAS(r.out, std::string("Usage: moa ") + command);
    r = moa(std::string("help ") + command);
    assert_int_equal(r.code, 0);
    EXPECT_HAS(r.out, std::string("Usage: moa ") + command);
  }
}

void test_params(void **) {
  const Run r = moa("params");
  assert_int_equal(r.code, 0);
  assert_true(moa_param_count() > 0);
  for (size_t i = 0; i < moa_param_count(); ++i) {
    moa_param_info info;
    assert_int_equal(moa_param_info_get(i, &info), MOA_OK);
    EXPECT_HAS(r.out, std::string("  ") + info.name + " = ");
  }
}

void test_reconstruct_and_check(void **) {
  const std::string input = sphere_points(), mesh = path("sphere.ply"), stats = path("stats.json");
  std::remove(mesh.c_str());
  Run r = moa("reconstruct " + quote(input) + " -o " + quote(mesh) + " --stats " + quote(stats) +
              " --param threads=1");
  if (r.code != 0) fail_msg("reconstruct failed (%d): %s", r.code, r.err.c_str());
  EXPECT_HAS(r.out, "800 points");
  EXPECT_HAS(r.out, "triangles");
  EXPECT_HAS(r.out, "boundary edges");
  assert_true(read_file(mesh).compare(0, 4, "ply\n") == 0);
  const std::string json = read_file(stats);
  for (const char *key : {"\"points\": 800", "\"triangles\":", "\"reconstruct_ms\":",
                          "\"stage_ms\":", "\"total_ms\":", "\"used_points\":",
                          "\"boundary_edges\":", "\"rejected_intersection\":", "\"threads\": 1"})
    EXPECT_HAS(json, key);
  for (int s = 0; s < MOA_STAGE_COUNT; ++s)
    EXPECT_HAS(json, std::string("\"") + moa_stage_name(moa_stage(s)) + "\":");

  // --quiet: nothing on stdout; --ascii: ASCII PLY.
  const std::string ascii = path("sphere_ascii.ply");
  r = moa("reconstruct -q --ascii " + quote(input) + " --output=" + quote(ascii));
  assert_int_equal(r.code, 0);
  assert_true(r.out.empty());
  assert_true(r.err.empty());
  EXPECT_HAS(read_file(ascii), "format ascii 1.0");

  r = moa("check " + quote(mesh) + " --points " + quote(input));
  assert_int_equal(r.code, 0);
  for (const char *part : {"triangles", "genus", "non-manifold edges", "self-intersecting pairs",
                           "min angle", "of 800 are mesh vertices", "contract"})
    EXPECT_HAS(r.out, part);
  r = moa("check --json " + quote(mesh));
  assert_int_equal(r.code, 0);
  for (const char *key : {"\"closed\":", "\"genus\":", "\"boundary_loops\":",
                          "\"non_manifold_vertices\":", "\"self_intersecting_pairs\":",
                          "\"below_30\":", "\"inward_components\":"})
    EXPECT_HAS(r.out, key);
}

void test_check_known_meshes(void **) {
  const std::string tetra = path("tetra.off");
  write_file(tetra, "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 1 2 3\n3 0 1 3\n3 0 3 2\n");
  Run r = moa("check --json " + quote(tetra));
  assert_int_equal(r.code, 0);
  for (const char *part : {"\"triangles\": 4", "\"edges\": 6", "\"closed\": true", "\"genus\": 0",
                           "\"euler_characteristic\": 2", "\"ok\": true"})
    EXPECT_HAS(r.out, part);
  // A defective mesh is reported, not an error.
  const std::string bad = path("bowtie.off");
  write_file(bad, "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n");
  r = moa("check " + quote(bad));
  assert_int_equal(r.code, 0);
  EXPECT_HAS(r.out, "1 non-manifold vertices");
  EXPECT_HAS(r.out, "violates");
}

void test_errors(void **) {
  const std::string input = sphere_points(), out = path("out.ply");
  expect_error(moa("reconstruct " + quote(path("missing.xyz")) + " -o " + quote(out)), 3,
               {"missing.xyz"});
  write_file(path("bad.xyz"), "0 0 0\n1 0 0\n1 2\n");
  expect_error(moa("reconstruct " + quote(path("bad.xyz")) + " -o " + quote(out)), 3,
               {"bad.xyz: line 3"});
  expect_error(moa("reconstruct " + quote(input) + " -o " + quote(out) + " --param foo=1"), 2,
               {"unknown parameter 'foo'"});
  expect_error(moa("reconstruct " + quote(input) + " -o " + quote(out) + " --param neighbors=x"),
               2, {"neighbors", "'x'"});
  expect_error(moa("reconstruct " + quote(input) + " -o " + quote(out) + " --param neighbors=1e9"),
               2, {"parameter 'neighbors' must be", "'1e9'"});
  expect_error(moa("reconstruct " + quote(input)), 2, {"missing -o OUTPUT"});
  expect_error(moa("reconstruct -o " + quote(out)), 2, {"missing INPUT"});
  expect_error(moa("reconstruct " + quote(input) + " -o " + quote(out) + " --frobnicate"), 2,
               {"unknown option '--frobnicate'"});
  expect_error(moa("reconstruct " + quote(input) + " -o"), 2, {"-o needs a value"});
  expect_error(moa("frobnicate"), 2, {"unknown command 'frobnicate'"});
  expect_error(moa(""), 2, {"missing command"});
  expect_error(moa("reconstruct " + quote(input) + " -o " + quote(path("no/such/dir/out.ply"))),
               5, {"out.ply"});
  expect_error(moa("reconstruct " + quote(input) + " -o " + quote(path("out.xyz"))), 5,
               {"out.xyz"});
  expect_error(moa("check " + quote(path("missing.ply"))), 3, {"missing.ply"});
  expect_error(moa("check"), 2, {"missing MESH"});
  expect_error(moa("params --json"), 2, {"unknown option '--json'"});
}

}  // namespace

int main(int argc, char **argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s PATH_TO_MOA SCRATCH_DIR\n", argv[0]);
    return 2;
  }
  g_tool = argv[1];
  g_dir = argv[2];
  const CMUnitTest tests[] = {
      cmocka_unit_test(test_version_and_help),
      cmocka_unit_test(test_params),
      cmocka_unit_test(test_reconstruct_and_check),
      cmocka_unit_test(test_check_known_meshes),
      cmocka_unit_test(test_errors),
  };
  return cmocka_run_group_tests(tests, setup, nullptr);
}
