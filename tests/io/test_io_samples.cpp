// Reading every file in the shared data folder (MOA_SHARED_DATA): counts from its README,
// first coordinates from the files themselves, and the topology the README states.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <utility>

#include "io_test_support.hpp"

namespace {

std::string shared(const std::string &name) {
  const char *root = std::getenv("MOA_SHARED_DATA");
  if (!root || !*root) fail_msg("MOA_SHARED_DATA is not set (ctest sets it)");
  return std::string(root) + "/" + name;
}

void assert_all_finite(const std::vector<double> &xyz) {
  for (double v : xyz) assert_true(std::isfinite(v));
}

void assert_first(const std::vector<double> &xyz, double x, double y, double z) {
  assert_true(xyz.size() >= 3);
  if (xyz[0] != x || xyz[1] != y || xyz[2] != z)
    fail_msg("first point %.17g %.17g %.17g, expected %.17g %.17g %.17g", xyz[0], xyz[1], xyz[2],
             x, y, z);
}

struct MeshSample {
  const char *name;
  size_t vertices, faces;
  long euler;            // V - E + F: 2 - 2 genus per closed component
  size_t boundary_edges;
};

// Counts, closedness and Euler characteristic: a misread face would break them.
void meshes(void **) {
  const MeshSample samples[] = {
      {"bunny00.off", 37706, 75408, 2, 0},  {"elephant.off", 2775, 5558, -4, 0},
      {"fandisk.off", 6475, 12946, 2, 0},   {"knot2.off", 5760, 11520, 0, 0},
      {"eight.off", 315, 634, -2, 0},       {"homer.off", 4930, 9856, 2, 0},
      {"sphere966.off", 926, 1848, 2, 0},   {"mushroom.off", 2337, 4608, 1, 64},
      {"cow.off", 2904, 5804, 2, 0},
  };
  for (const MeshSample &sample : samples) {
    const std::string path = shared(std::string("meshes/") + sample.name);
    const moa::io::MeshData mesh = READ_MESH(path);
    assert_int_equal(mesh.xyz.size(), 3 * sample.vertices);
    assert_int_equal(mesh.triangles.size(), 3 * sample.faces);
    assert_all_finite(mesh.xyz);
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (size_t t = 0; t < mesh.triangles.size(); t += 3)
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = mesh.triangles[t + k], b = mesh.triangles[t + (k + 1) % 3];
        ++uses[std::minmax(a, b)];
      }
    size_t boundary = 0;
    for (const auto &edge : uses) {
      assert_true(edge.second <= 2);
      boundary += edge.second == 1;
    }
    assert_int_equal(boundary, sample.boundary_edges);
    const long euler = static_cast<long>(sample.vertices) - static_cast<long>(uses.size()) +
                       static_cast<long>(sample.faces);
    if (euler != sample.euler) fail_msg("%s: Euler characteristic %ld", sample.name, euler);
    assert_int_equal(READ_POINTS(path).size(), mesh.xyz.size());
  }
  assert_first(READ_POINTS(shared("meshes/bunny00.off")), -0.167662, -0.411917, -0.0732205);
  assert_first(READ_POINTS(shared("meshes/sphere966.off")), 2.78865, 0.400948, -9.59493);
  assert_first(READ_POINTS(shared("meshes/cow.off")), 0.281526, 0.266379, -1.55991e-008);
}

void xyz_files(void **) {
  const std::vector<double> kitten = READ_POINTS(shared("points/kitten.xyz"));
  assert_int_equal(kitten.size(), 3 * 5210);
  assert_first(kitten, -0.0721898, -0.159749, -0.108444);
  // The README says 20,000, but the file holds 21,000 lines of three numbers.
  const std::vector<double> sphere = READ_POINTS(shared("points/sphere_20k.xyz"));
  assert_int_equal(sphere.size(), 3 * 21000);
  assert_first(sphere, -0.708819, 0.473145, 0.631157);
  const std::vector<double> half = READ_POINTS(shared("points/half.xyz"));
  assert_int_equal(half.size(), 3 * 325);
  assert_first(half, -7.515480024991e-007, 0.4928415052762, -1.734723475977e-018);
  for (const auto *xyz : {&kitten, &sphere, &half}) assert_all_finite(*xyz);
}

void ascii_ply_files(void **) {
  const std::vector<double> ball = READ_POINTS(shared("points/ball.ply"));
  assert_int_equal(ball.size(), 3 * 31374);
  assert_first(ball, 37.3579, -12.3512, -3.52648);
  const std::vector<double> building = READ_POINTS(shared("points/building.ply"));
  assert_int_equal(building.size(), 3 * 100000);
  assert_first(building, 8.19821, -21.7553, 7.88123);
  assert_all_finite(ball);
  assert_all_finite(building);
  // A point cloud read as a mesh has no triangles.
  const moa::io::MeshData mesh = READ_MESH(shared("points/ball.ply"));
  assert_int_equal(mesh.xyz.size(), ball.size());
  assert_int_equal(mesh.triangles.size(), 0);
}

// Binary PLY: compare with the doubles at their place in the file (x y z nx ny nz each).
void binary_ply_files(void **) {
  const std::pair<const char *, size_t> samples[] = {{"points/oni.ply", 1435},
                                                     {"points/hippo1.ply", 6104}};
  for (const auto &[name, count] : samples) {
    const std::string path = shared(name);
    const std::vector<double> xyz = READ_POINTS(path);
    assert_int_equal(xyz.size(), 3 * count);
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t body = bytes.find("end_header\n") + std::strlen("end_header\n");
    assert_int_equal(bytes.size() - body, count * 48);
    for (size_t v : {size_t{0}, count / 2, count - 1}) {
      double expected[3];
      std::memcpy(expected, bytes.data() + body + 48 * v, sizeof expected);
      for (int axis = 0; axis < 3; ++axis) assert_true(io_test::same_bits(xyz[3 * v + axis], expected[axis]));
    }
    assert_all_finite(xyz);
  }
}

}  // namespace

int main() {
  const CMUnitTest tests[] = {
      cmocka_unit_test(meshes),
      cmocka_unit_test(xyz_files),
      cmocka_unit_test(ascii_ply_files),
      cmocka_unit_test(binary_ply_files),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
