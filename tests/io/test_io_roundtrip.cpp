// Write, read back, compare: exactly for the double-precision formats (PLY, OFF, OBJ, XYZ),
// to float precision for STL.
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "io_test_support.hpp"

using moa::io::MeshData;

namespace {

// An octahedron with a quad-free triangle list and awkward coordinates: tiny, huge,
// subnormal, negative zero, values without a short decimal form.
MeshData awkward_octahedron() {
  MeshData mesh;
  mesh.xyz = {1.0,     0.0,    -0.0,  -1.0, 1e-300, 0.1,        0.0,     1.0 / 3.0, 5e-324,
              2.5e300, -1.0,   0.0,   0.2,  0.3,    1.0,        -3.141592653589793,   -0.0,      -1.0,
              123456789.123456789, -7.0, 1e-5};  // one vertex used by no triangle
  mesh.triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  return mesh;
}

// The same shape within float range, for STL.
MeshData plain_octahedron() {
  MeshData mesh = awkward_octahedron();
  mesh.xyz = {1.0, 0.0, -0.0, -1.0, 1e-30, 0.1, 0.0, 1.0 / 3.0, 2.0,
              2.5e30, -1.0, 0.0, 0.2, 0.3, 1.0, -3.141592653589793, -0.0, -1.0,
              123456.789, -7.0, 1e-5};
  return mesh;
}

void assert_same_mesh(const MeshData &expected, const MeshData &actual) {
  assert_int_equal(actual.xyz.size(), expected.xyz.size());
  for (size_t i = 0; i < expected.xyz.size(); ++i)
    if (!io_test::same_bits(actual.xyz[i], expected.xyz[i]))
      fail_msg("coordinate %zu: wrote %.17g, read %.17g", i, expected.xyz[i], actual.xyz[i]);
  assert_true(actual.triangles == expected.triangles);
}

void round_trip_exact(const char *name, bool ascii) {
  const MeshData mesh = awkward_octahedron();
  const std::string path = io_test::temp_path(name);
  moa::io::write_mesh(path, mesh, ascii);
  assert_same_mesh(mesh, READ_MESH(path));
  // read_points gives the vertices alone, unused ones included.
  const std::vector<double> points = READ_POINTS(path);
  assert_same_mesh(MeshData{mesh.xyz, {}}, MeshData{points, {}});
}

void ply_binary(void **) { round_trip_exact("mesh.ply", false); }
void ply_ascii(void **) { round_trip_exact("mesh_ascii.ply", true); }
void off(void **) { round_trip_exact("mesh.off", false); }
void obj(void **) { round_trip_exact("mesh.obj", false); }
void upper_case_extension(void **) { round_trip_exact("MESH.PLY", false); }

void ply_binary_is_little_endian_by_default(void **) {
  const std::string path = io_test::temp_path("header.ply");
  moa::io::write_mesh(path, awkward_octahedron());
  std::ifstream in(path, std::ios::binary);
  std::string head(64, '\0');
  in.read(&head[0], 64);
  assert_non_null(std::strstr(head.c_str(), "format binary_little_endian 1.0"));
}

// STL keeps floats, loses unused vertices and merges equal ones: compare corner by corner.
void stl(void **) {
  const MeshData mesh = plain_octahedron();
  const std::string path = io_test::temp_path("mesh.stl");
  moa::io::write_mesh(path, mesh);
  const MeshData back = READ_MESH(path);
  assert_int_equal(back.triangles.size(), mesh.triangles.size());
  assert_int_equal(back.xyz.size(), 6 * 3);  // the unused vertex is gone
  for (size_t c = 0; c < mesh.triangles.size(); ++c)
    for (int axis = 0; axis < 3; ++axis) {
      const double wrote = mesh.xyz[3 * mesh.triangles[c] + axis];
      const double read = back.xyz[3 * back.triangles[c] + axis];
      const double as_float = static_cast<double>(static_cast<float>(wrote));
      // -0 and +0 are merged into one vertex, so compare values, not bits.
      if (read != as_float) fail_msg("corner %zu axis %d: wrote %.17g, read %.17g", c, axis, wrote, read);
      assert_true(std::fabs(read - wrote) <= std::fabs(wrote) * 6e-8);
    }
  assert_int_equal(READ_POINTS(path).size(), 6 * 3);
}

// Corners with the same position are one vertex after reading STL.
void stl_merges_equal_corners(void **) {
  MeshData mesh;
  mesh.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};  // vertex 4 repeats vertex 0
  mesh.triangles = {0, 1, 2, 4, 2, 3};
  const std::string path = io_test::temp_path("merge.stl");
  moa::io::write_mesh(path, mesh);
  const MeshData back = READ_MESH(path);
  assert_int_equal(back.xyz.size(), 4 * 3);
  assert_int_equal(back.triangles[0], back.triangles[3]);
}

void points(void **) {
  const std::vector<double> xyz = awkward_octahedron().xyz;
  for (const char *name : {"points.xyz", "points.txt", "points.pts", "points.csv", "points.ply",
                           "points.off", "points.obj"}) {
    for (bool ascii : {false, true}) {
      const std::string path = io_test::temp_path(name);
      moa::io::write_points(path, xyz, ascii);
      assert_same_mesh(MeshData{xyz, {}}, MeshData{READ_POINTS(path), {}});
    }
  }
  // A .csv gets commas between its columns, so that spreadsheets split them.
  std::ifstream csv(io_test::temp_path("points.csv"));
  std::string first_line;
  assert_true(bool(std::getline(csv, first_line)));
  assert_int_equal(std::count(first_line.begin(), first_line.end(), ','), 2);
  assert_int_equal(std::count(first_line.begin(), first_line.end(), ' '), 0);
  EXPECT_IO_ERROR(moa::io::write_points(io_test::temp_path("points.stl"), xyz), "points.stl",
                  "STL");
}

// Non-finite coordinates pass through every format: rejecting them is the library's job.
void non_finite(void **) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  MeshData mesh;
  mesh.xyz = {inf, -inf, nan, 0, 1, 2, 3, 4, 5};
  mesh.triangles = {0, 1, 2};
  for (const char *name : {"nonfinite.ply", "nonfinite.off", "nonfinite.obj"})
    for (bool ascii : {false, true}) {
      const std::string path = io_test::temp_path(name);
      moa::io::write_mesh(path, mesh, ascii);
      const MeshData back = READ_MESH(path);
      assert_int_equal(back.xyz.size(), 9);
      assert_true(std::isinf(back.xyz[0]) && back.xyz[0] > 0);
      assert_true(std::isinf(back.xyz[1]) && back.xyz[1] < 0);
      assert_true(std::isnan(back.xyz[2]));
    }
  moa::io::write_points(io_test::temp_path("nonfinite.xyz"), mesh.xyz);
  const std::vector<double> back = READ_POINTS(io_test::temp_path("nonfinite.xyz"));
  assert_true(std::isinf(back[0]) && std::isnan(back[2]));
}

void empty_mesh(void **) {
  for (const char *name : {"empty.ply", "empty.off", "empty.stl"}) {
    const std::string path = io_test::temp_path(name);
    moa::io::write_mesh(path, MeshData{});
    const MeshData back = READ_MESH(path);
    assert_int_equal(back.xyz.size(), 0);
    assert_int_equal(back.triangles.size(), 0);
  }
}

void write_rejects_bad_meshes(void **) {
  const std::string path = io_test::temp_path("bad.off");
  EXPECT_IO_ERROR(moa::io::write_mesh(path, MeshData{{0, 0, 0, 1}, {}}), "bad.off",
                  "4 coordinates");
  EXPECT_IO_ERROR(moa::io::write_mesh(path, MeshData{{0, 0, 0}, {0, 0}}), "bad.off",
                  "2 triangle indices");
  EXPECT_IO_ERROR(moa::io::write_mesh(path, MeshData{{0, 0, 0, 1, 1, 1}, {0, 1, 2}}),
                  "bad.off", "triangle 0 refers to vertex 2", "2 vertices");
  EXPECT_IO_ERROR(moa::io::write_mesh(io_test::temp_path("mesh.xyz"), awkward_octahedron()),
                  "mesh.xyz", "XYZ");
  EXPECT_IO_ERROR(moa::io::write_mesh(io_test::temp_path("mesh.vtk"), awkward_octahedron()),
                  "mesh.vtk", "unknown extension '.vtk'");
}

void write_to_unwritable_path(void **) {
  const std::string missing = io_test::temp_path("no/such/dir/mesh.ply");
  EXPECT_IO_ERROR(moa::io::write_mesh(missing, awkward_octahedron()), missing, "cannot write");
  const std::string dir = io_test::temp_path("a_dir.ply");
  mkdir(dir.c_str(), 0700);
  EXPECT_IO_ERROR(moa::io::write_mesh(dir, awkward_octahedron()), dir, "cannot write");
}

void format_names(void **) {
  assert_true(moa::io::format_from_path("a/b.c/points.XYZ") == moa::io::Format::Xyz);
  assert_true(moa::io::format_from_path("scan.pts") == moa::io::Format::Xyz);
  assert_true(moa::io::format_from_path("scan.txt") == moa::io::Format::Xyz);
  assert_true(moa::io::format_from_path("export.CSV") == moa::io::Format::Xyz);
  assert_true(moa::io::format_from_path("m.Off") == moa::io::Format::Off);
  assert_true(moa::io::format_from_path("m.obj") == moa::io::Format::Obj);
  assert_true(moa::io::format_from_path("m.stl") == moa::io::Format::Stl);
  assert_string_equal(moa::io::format_name(moa::io::Format::Ply), "PLY");
  EXPECT_IO_ERROR(moa::io::format_from_path("dir.d/noextension"), "dir.d/noextension",
                  "no file extension");
}

}  // namespace

int main() {
  const CMUnitTest tests[] = {
      cmocka_unit_test(ply_binary),
      cmocka_unit_test(ply_ascii),
      cmocka_unit_test(off),
      cmocka_unit_test(obj),
      cmocka_unit_test(upper_case_extension),
      cmocka_unit_test(ply_binary_is_little_endian_by_default),
      cmocka_unit_test(stl),
      cmocka_unit_test(stl_merges_equal_corners),
      cmocka_unit_test(points),
      cmocka_unit_test(non_finite),
      cmocka_unit_test(empty_mesh),
      cmocka_unit_test(write_rejects_bad_meshes),
      cmocka_unit_test(write_to_unwritable_path),
      cmocka_unit_test(format_names),
  };
  return cmocka_run_group_tests(tests, io_test::setup_temp_dir, io_test::remove_temp_dir);
}
