// The analyzer on the reference meshes of ../shared/data/meshes, whose closedness, genus,
// boundary and self-intersections are documented in its README.
#include <cstdlib>
#include <string>
#include <vector>

#include "cli/cmocka_cxx.hpp"
#include "io/io.hpp"
#include "quality/quality.hpp"

namespace {

struct Expected {
  const char *file;
  size_t triangles;
  size_t components;
  size_t boundary_edges;
  std::vector<long> genus;  // per component; empty for open meshes
  size_t intersecting_pairs;
};

moa::MeshReport analyze(const std::string &file) {
  const char *root = std::getenv("MOA_SHARED_DATA");
  if (!root) fail_msg("MOA_SHARED_DATA is not set");
  const moa::io::MeshData mesh = moa::io::read_mesh(std::string(root) + "/meshes/" + file);
  return moa::analyze_mesh(mesh.xyz.data(), mesh.xyz.size() / 3, mesh.triangles.data(),
                           mesh.triangles.size() / 3);
}

void test_reference_meshes(void **) {
  const Expected table[] = {
      {"bunny00.off", 75408, 1, 0, {0}, 0},
      {"elephant.off", 5558, 1, 0, {3}, 0},
      {"fandisk.off", 12946, 1, 0, {0}, 0},
      {"knot2.off", 11520, 2, 0, {1, 1}, 0},
      {"eight.off", 634, 1, 0, {2}, 0},
      {"homer.off", 9856, 1, 0, {0}, 0},
      {"sphere966.off", 1848, 1, 0, {0}, 0},
      {"mushroom.off", 4608, 1, 64, {}, 0},
      {"cow.off", 5804, 1, 0, {0}, 101},
  };
  for (const Expected &e : table) {
    const moa::MeshReport r = analyze(e.file);
    print_message("%s: %zu triangles, %.1f ms\n", e.file, r.triangles, r.analysis_ms);
    assert_int_equal(r.triangles, e.triangles);
    assert_int_equal(r.components, e.components);
    assert_int_equal(r.boundary_edges, e.boundary_edges);
    assert_int_equal(r.self_intersecting_pairs, e.intersecting_pairs);
    assert_int_equal(r.degenerate_faces, 0);
    assert_int_equal(r.duplicate_faces, 0);
    assert_int_equal(r.non_manifold_edges, 0);
    assert_int_equal(r.non_manifold_vertices, 0);
    assert_int_equal(r.inconsistent_edges, 0);
    assert_int_equal(r.inward_components, 0);
    if (e.boundary_edges == 0) {
      assert_int_equal(r.closed_components, e.components);
      for (size_t c = 0; c < e.genus.size(); ++c)
        assert_int_equal(r.component_list[c].genus, e.genus[c]);
    } else {
      assert_int_equal(r.boundary_loops, 1);
      assert_int_equal(r.genus, 0);  // a disk
    }
  }
}

}  // namespace

int main() {
  const CMUnitTest tests[] = {cmocka_unit_test(test_reference_meshes)};
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
