// The `moa` executable, run as a separate process: its commands, its files and its exit codes
// with their one-line messages. Arguments: the tool's path and a scratch folder.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli/tool_runner.hpp"
#include "moa/moa.h"

namespace {

using namespace moa::test;

Tool g_moa;

std::string path(const std::string &name) { return g_moa.path(name); }
Run moa(const std::string &args) { return g_moa.run(args); }

int setup(void **) {
  ::mkdir(g_moa.dir.c_str(), 0755);
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
  const std::string input = write_sphere_points(path("sphere.xyz")), mesh = path("sphere.ply"),
                    stats = path("stats.json");
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

// The same points exported as CloudCompare does it (a header line, commas, x y z after other
// columns and out of order) give the same mesh, byte for byte.
void test_reconstruct_from_csv(void **) {
  const std::string xyz = write_sphere_points(path("plain.xyz"));
  std::istringstream lines(read_file(xyz));
  std::string csv = "//Intensity,Z,Y,X\n", x, y, z;
  while (lines >> x >> y >> z) csv += "7," + z + "," + y + "," + x + "\n";
  write_file(path("export.csv"), csv);
  const std::string from_xyz = path("plain.ply"), from_csv = path("export.ply");
  std::remove(from_csv.c_str());
  Run r = moa("reconstruct -q " + quote(xyz) + " -o " + quote(from_xyz));
  assert_int_equal(r.code, 0);
  r = moa("reconstruct " + quote(path("export.csv")) + " -o " + quote(from_csv));
  if (r.code != 0) fail_msg("reconstruct from .csv failed (%d): %s", r.code, r.err.c_str());
  EXPECT_HAS(r.out, "800 points");
  assert_true(read_file(from_csv) == read_file(from_xyz));
}

// The summary counts in words that agree with the numbers.
void test_summary_of_one_triangle(void **) {
  write_file(path("triangle.xyz"), "0 0 0\n1 0 0\n0 1 0\n");
  const Run r = moa("reconstruct " + quote(path("triangle.xyz")) + " -o " +
                    quote(path("triangle.ply")));
  assert_int_equal(r.code, 0);
  EXPECT_HAS(r.out, "3 points -> 1 triangle, 3 boundary edges (1 open loop), 3 of 3 points used");
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
  const std::string input = write_sphere_points(path("sphere.xyz")), out = path("out.ply");
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

// Every file a command will write is checked before the input is read and the work done: a
// missing folder or a folder in the file's place ends the command at once. Each case pairs the
// bad output with a malformed input, which fails with exit code 3 only once it is read.
void test_outputs_checked_first(void **) {
  const std::string bad = path("bad_input.xyz"), missing = path("no/such/dir/");
  write_file(bad, "0 0 0\n1 0 0\n1 2\n");
  const std::string folder = path("a_folder.ply");
  ::mkdir(folder.c_str(), 0755);
  expect_error(moa("reconstruct " + quote(bad) + " -o " + quote(missing + "out.ply")), 5,
               {"no/such/dir/out.ply: cannot write"});
  expect_error(moa("reconstruct " + quote(bad) + " -o " + quote(folder)), 5,
               {"a_folder.ply: cannot write"});
  const std::string out = path("never_written.ply");
  expect_error(moa("reconstruct " + quote(bad) + " -o " + quote(out) + " --stats " +
                   quote(missing + "s.json")),
               5, {"s.json: cannot write"});
  expect_error(moa("reconstruct " + quote(bad) + " -o " + quote(out) + " --render " +
                   quote(missing + "p.png")),
               5, {"p.png: cannot write"});
  assert_false(exists(out));  // checked, not created
  expect_error(moa("render " + quote(path("missing.ply")) + " -o " + quote(missing + "p.png")), 5,
               {"p.png: cannot write"});
  expect_error(moa("check " + quote(path("missing.ply")) + " --report " + quote(missing + "r.md")),
               5, {"r.md: cannot write"});
  // A file in a folder that exists is fine: the malformed input is what fails.
  expect_error(moa("reconstruct " + quote(bad) + " -o " + quote(out)), 3, {"bad_input.xyz"});
}

// Output to standard output that cannot be written (a full disk: /dev/full) is an output error,
// not a success with the report lost; a command that writes nothing there is not affected.
void test_stdout_cannot_be_written(void **) {
  const std::string input = write_sphere_points(path("stdout.xyz")), mesh = path("stdout.ply");
  for (const std::string &args :
       {std::string("params"), std::string("--help"), std::string("--version"),
        "reconstruct " + quote(input) + " -o " + quote(mesh), "check --json " + quote(mesh)})
    expect_error(g_moa.run(args, "/dev/full"), 5, {"standard output: cannot write"});
  // With the reason when the final flush is the write that fails (a report written out
  // earlier fails there, and by the end its reason is gone). One short line: held to the end.
  expect_error(g_moa.run("--version", "/dev/full"), 5,
               {"standard output: cannot write: No space left on device"});
  const Run quiet = g_moa.run("reconstruct -q " + quote(input) + " -o " + quote(mesh), "/dev/full");
  assert_int_equal(quiet.code, 0);
  assert_true(quiet.err.empty());
  // The command's own error comes first, and alone.
  expect_error(g_moa.run("check " + quote(path("missing.ply")), "/dev/full"), 3, {"missing.ply"});
}

// More threads than the machine has: the run uses the cores there are, says so in the
// statistics and makes the same mesh, with nothing on stderr (TBB warned there when asked for
// more workers than it may run). A process of its own, as TBB warns once per process.
void test_more_threads_than_cores(void **) {
  const std::string input = write_sphere_points(path("threads.xyz"));
  const std::string one = path("threads_1.ply"), many = path("threads_many.ply"),
                    stats = path("threads_many.json");
  Run r = moa("reconstruct -q " + quote(input) + " -o " + quote(one) + " --param threads=1");
  assert_int_equal(r.code, 0);
  r = moa("reconstruct -q " + quote(input) + " -o " + quote(many) + " --stats " + quote(stats) +
          " --param threads=1024");
  assert_int_equal(r.code, 0);
  if (!r.err.empty()) fail_msg("expected nothing on stderr, got: %s", r.err.c_str());
  assert_true(read_file(one) == read_file(many));
  const std::string json = read_file(stats);
  const std::size_t at = json.find("\"threads\": ");  // the first: the run's, then params'
  assert_true(at != std::string::npos);
  const long used = std::strtol(json.c_str() + at + 11, nullptr, 10);
  const long cores = ::sysconf(_SC_NPROCESSORS_ONLN);
  if (used < 1 || used > cores) fail_msg("threads used: %ld on %ld cores", used, cores);
  EXPECT_HAS(json, "\"threads\": 1024");  // the parameter as set
}

}  // namespace

int main(int argc, char **argv) {
  if (!tool_from_args(argc, argv, g_moa)) return 2;
  const CMUnitTest tests[] = {
      cmocka_unit_test(test_version_and_help),
      cmocka_unit_test(test_params),
      cmocka_unit_test(test_reconstruct_and_check),
      cmocka_unit_test(test_reconstruct_from_csv),
      cmocka_unit_test(test_summary_of_one_triangle),
      cmocka_unit_test(test_check_known_meshes),
      cmocka_unit_test(test_errors),
      cmocka_unit_test(test_outputs_checked_first),
      cmocka_unit_test(test_stdout_cannot_be_written),
      cmocka_unit_test(test_more_threads_than_cores),
  };
  return cmocka_run_group_tests(tests, setup, nullptr);
}
