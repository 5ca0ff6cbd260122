// The mesh analyzer on small meshes whose every count is known: closed solids, a torus, holes,
// and one fixture per defect of the output contract.
#include <cmath>
#include <vector>

#include "cli/cmocka_cxx.hpp"
#include "quality/quality.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Mesh {
  std::vector<double> xyz;
  std::vector<uint32_t> tri;
  void vertex(double x, double y, double z) {
    xyz.push_back(x);
    xyz.push_back(y);
    xyz.push_back(z);
  }
  void face(uint32_t a, uint32_t b, uint32_t c) {
    tri.push_back(a);
    tri.push_back(b);
    tri.push_back(c);
  }
  moa::MeshReport analyze() const {
    return moa::analyze_mesh(xyz.data(), xyz.size() / 3, tri.data(), tri.size() / 3);
  }
};

Mesh tetrahedron() {  // faces point outward
  Mesh m;
  m.vertex(0, 0, 0); m.vertex(1, 0, 0); m.vertex(0, 1, 0); m.vertex(0, 0, 1);
  m.face(0, 2, 1); m.face(1, 2, 3); m.face(0, 1, 3); m.face(0, 3, 2);
  return m;
}

Mesh octahedron() {  // faces point outward
  Mesh m;
  for (int axis = 0; axis < 3; ++axis)
    for (double s : {1.0, -1.0}) {
      double p[3] = {0, 0, 0};
      p[axis] = s;
      m.vertex(p[0], p[1], p[2]);  // vertex 2 * axis + (s < 0)
    }
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        const uint32_t x = sx, y = 2 + sy, z = 4 + sz;
        if ((sx + sy + sz) % 2 == 0) m.face(x, y, z); else m.face(x, z, y);
      }
  return m;
}

// n x m grid on a torus (R = 3, r = 1), faces outward; vertex (i, j) is i * m + j.
Mesh torus(int n, int m) {
  Mesh t;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / m;
      t.vertex((3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v));
    }
  auto id = [&](int i, int j) { return uint32_t((i % n) * m + (j % m)); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      t.face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      t.face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return t;
}

void assert_clean(const moa::MeshReport &r) {
  assert_int_equal(r.invalid_faces, 0);
  assert_int_equal(r.degenerate_faces, 0);
  assert_int_equal(r.duplicate_faces, 0);
  assert_int_equal(r.non_manifold_edges, 0);
  assert_int_equal(r.non_manifold_vertices, 0);
  assert_int_equal(r.inconsistent_edges, 0);
  assert_int_equal(r.inward_components, 0);
  assert_int_equal(r.self_intersecting_pairs, 0);
  assert_true(r.contract_ok());
}

void test_tetrahedron(void **) {
  const moa::MeshReport r = tetrahedron().analyze();
  assert_clean(r);
  assert_int_equal(r.vertices_referenced, 4);
  assert_int_equal(r.triangles, 4);
  assert_int_equal(r.edges, 6);
  assert_int_equal(r.boundary_edges, 0);
  assert_int_equal(r.boundary_loops, 0);
  assert_int_equal(r.components, 1);
  assert_int_equal(r.closed_components, 1);
  assert_int_equal(r.euler_characteristic, 2);
  assert_int_equal(r.genus, 0);
  assert_true(r.genus_defined);
  assert_true(r.closed());
  assert_true(std::fabs(r.component_list[0].signed_volume - 1.0 / 6.0) < 1e-12);
  // Three right isosceles faces (45 degrees) and one equilateral (60).
  assert_true(std::fabs(r.min_angle - 45) < 1e-9);
  assert_true(std::fabs(r.mean_min_angle - 48.75) < 1e-9);
  assert_true(r.share_below_30 == 0);
  assert_int_equal(r.min_angle_histogram[9], 3);
  assert_int_equal(r.min_angle_histogram[11], 1);
}

void test_octahedron(void **) {
  const moa::MeshReport r = octahedron().analyze();
  assert_clean(r);
  assert_int_equal(r.vertices_referenced, 6);
  assert_int_equal(r.edges, 12);
  assert_int_equal(r.euler_characteristic, 2);
  assert_int_equal(r.genus, 0);
  assert_int_equal(r.closed_components, 1);
  assert_true(std::fabs(r.component_list[0].signed_volume - 4.0 / 3.0) < 1e-12);
  assert_true(std::fabs(r.min_angle - 60) < 1e-9);
}

void test_inward(void **) {
  Mesh m = octahedron();
  for (size_t f = 0; f < m.tri.size(); f += 3) std::swap(m.tri[f + 1], m.tri[f + 2]);
  const moa::MeshReport r = m.analyze();
  assert_int_equal(r.inconsistent_edges, 0);
  assert_int_equal(r.inward_components, 1);
  assert_false(r.oriented());
}

void test_torus(void **) {
  const moa::MeshReport r = torus(16, 8).analyze();
  assert_clean(r);
  assert_int_equal(r.vertices_referenced, 128);
  assert_int_equal(r.edges, 384);
  assert_int_equal(r.triangles, 256);
  assert_int_equal(r.euler_characteristic, 0);
  assert_int_equal(r.genus, 1);
  assert_int_equal(r.component_list.size(), 1);
  assert_int_equal(r.component_list[0].genus, 1);
  assert_true(r.closed());
}

void test_two_components(void **) {
  Mesh m = torus(16, 8);
  const Mesh t = tetrahedron();
  const uint32_t base = uint32_t(m.xyz.size() / 3);
  for (double x : t.xyz) m.xyz.push_back(x + 10);
  for (uint32_t v : t.tri) m.tri.push_back(v + base);
  const moa::MeshReport r = m.analyze();
  assert_clean(r);
  assert_int_equal(r.components, 2);
  assert_int_equal(r.closed_components, 2);
  assert_int_equal(r.genus, 1);
  assert_int_equal(r.component_list[0].genus, 1);
  assert_int_equal(r.component_list[1].genus, 0);
  assert_int_equal(r.component_list[1].first_triangle, 256);
}

void test_hole(void **) {
  Mesh m = octahedron();
  m.tri.resize(m.tri.size() - 3);
  moa::MeshReport r = m.analyze();
  assert_clean(r);
  assert_int_equal(r.boundary_edges, 3);
  assert_int_equal(r.boundary_loops, 1);
  assert_int_equal(r.closed_components, 0);
  assert_int_equal(r.euler_characteristic, 1);
  assert_int_equal(r.genus, 0);
  assert_false(r.closed());

  // Two holes far apart on the torus: two loops, still genus 1.
  Mesh t = torus(16, 8);
  t.tri.erase(t.tri.begin() + 3 * 200, t.tri.begin() + 3 * 201);
  t.tri.erase(t.tri.begin(), t.tri.begin() + 3);
  r = t.analyze();
  assert_int_equal(r.boundary_edges, 6);
  assert_int_equal(r.boundary_loops, 2);
  assert_int_equal(r.genus, 1);
  assert_int_equal(r.inconsistent_edges, 0);
}

void test_flipped_face(void **) {
  Mesh m = tetrahedron();
  std::swap(m.tri[1], m.tri[2]);
  const moa::MeshReport r = m.analyze();
  assert_int_equal(r.inconsistent_edges, 3);
  assert_int_equal(r.non_manifold_edges, 0);
  assert_int_equal(r.self_intersecting_pairs, 0);
  assert_true(r.component_list[0].orientable);  // it could be oriented, it just is not
  assert_int_equal(r.genus, 0);
  assert_false(r.contract_ok());
}

void test_moebius(void **) {
  // A strip of 6 quads whose ends are glued with a half twist: not orientable.
  Mesh m;
  const int n = 6;
  for (int i = 0; i < n; ++i) {
    const double u = 2 * kPi * i / n, c = std::cos(u / 2), s = std::sin(u / 2);
    for (double w : {-0.5, 0.5})
      m.vertex((3 + w * c) * std::cos(u), (3 + w * c) * std::sin(u), w * s);
  }
  for (int i = 0; i < n; ++i) {
    uint32_t a = 2 * i, b = 2 * i + 1, c, d;
    if (i + 1 < n) { c = 2 * i + 2; d = 2 * i + 3; } else { c = 1; d = 0; }  // the twist
    m.face(a, c, d);
    m.face(a, d, b);
  }
  const moa::MeshReport r = m.analyze();
  assert_int_equal(r.boundary_loops, 1);
  assert_int_equal(r.boundary_edges, 2 * n);
  assert_false(r.component_list[0].orientable);
  assert_false(r.genus_defined);
  assert_true(r.inconsistent_edges >= 1);
  assert_int_equal(r.self_intersecting_pairs, 0);
}

void test_non_manifold_edge(void **) {
  Mesh m;
  m.vertex(0, 0, 0); m.vertex(1, 0, 0); m.vertex(0.5, 1, 0); m.vertex(0.5, -1, 0);
  m.vertex(0.5, 0, 1);
  m.face(0, 1, 2); m.face(1, 0, 3); m.face(0, 1, 4);
  const moa::MeshReport r = m.analyze();
  assert_int_equal(r.edges, 7);
  assert_int_equal(r.non_manifold_edges, 1);
  assert_int_equal(r.non_manifold_vertices, 0);
  assert_int_equal(r.boundary_edges, 6);
  assert_int_equal(r.boundary_loops, 1);
  assert_int_equal(r.self_intersecting_pairs, 0);
  assert_false(r.component_list[0].manifold);
  assert_false(r.genus_defined);
}

void test_bowtie(void **) {
  Mesh m;
  m.vertex(0, 0, 0); m.vertex(1, 0, 0); m.vertex(1, 1, 0); m.vertex(-1, 0, 0);
  m.vertex(-1, -1, 0);
  m.face(0, 1, 2); m.face(0, 3, 4);
  const moa::MeshReport r = m.analyze();
  assert_int_equal(r.non_manifold_vertices, 1);
  assert_int_equal(r.non_manifold_edges, 0);
  assert_int_equal(r.components, 1);
  assert_int_equal(r.boundary_edges, 6);
  assert_int_equal(r.boundary_loops, 2);
  assert_int_equal(r.self_intersecting_pairs, 0);
  assert_false(r.vertex_manifold());
}

void test_crossing(void **) {
  Mesh m;
  m.vertex(0, 0, 0); m.vertex(2, 0, 0); m.vertex(0, 2, 0);
  m.vertex(0.5, 0.5, -1); m.vertex(1, 0.5, 1); m.vertex(0, 0.5, 1);
  m.face(0, 1, 2); m.face(3, 4, 5);
  moa::MeshReport r = m.analyze();
  assert_int_equal(r.self_intersecting_pairs, 1);
  assert_int_equal(r.intersecting_pairs.size(), 1);
  assert_int_equal(r.intersecting_pairs[0].first, 0);
  assert_int_equal(r.intersecting_pairs[0].second, 1);
  assert_false(r.intersection_free());

  // A corner exactly on the other face counts; one 1e-300 above it does not.
  Mesh touch;
  touch.vertex(0, 0, 0); touch.vertex(2, 0, 0); touch.vertex(0, 2, 0);
  touch.vertex(0.5, 0.5, 0); touch.vertex(3, 3, 1); touch.vertex(3, 4, 1);
  touch.face(0, 1, 2); touch.face(3, 4, 5);
  assert_int_equal(touch.analyze().self_intersecting_pairs, 1);
  touch.xyz[11] = 1e-300;
  assert_int_equal(touch.analyze().self_intersecting_pairs, 0);
}

void test_coplanar_shared_edge(void **) {
  Mesh m;
  m.vertex(0, 0, 0); m.vertex(1, 0, 0); m.vertex(0.5, 1, 0); m.vertex(0.3, 0.5, 0);
  m.vertex(0.5, -1, 0);
  m.face(0, 1, 2); m.face(1, 0, 3);  // folded over onto the same side of edge 01
  assert_int_equal(m.analyze().self_intersecting_pairs, 1);
  m.tri[5] = 4;  // the other side: a flat, proper pair
  const moa::MeshReport r = m.analyze();
  assert_int_equal(r.self_intersecting_pairs, 0);
  assert_int_equal(r.inconsistent_edges, 0);

  // Sharing a vertex only, in one plane: overlapping wedges intersect.
  Mesh w;
  w.vertex(0, 0, 0); w.vertex(2, 0, 1); w.vertex(0, 2, 1); w.vertex(1, 1, 1);
  w.vertex(2, 1, 1.5);  // all on the plane z = (x + y) / 2
  w.face(0, 1, 2); w.face(0, 3, 4);
  assert_int_equal(w.analyze().self_intersecting_pairs, 1);
}

void test_duplicate_face(void **) {
  Mesh m = tetrahedron();
  m.face(0, 1, 2);  // face 0 again, reversed
  const moa::MeshReport r = m.analyze();
  assert_int_equal(r.duplicate_faces, 1);
  assert_int_equal(r.non_manifold_edges, 3);
  assert_int_equal(r.non_manifold_vertices, 0);
  // Identical faces meet in their interiors: C5 counts the pair as well.
  assert_int_equal(r.self_intersecting_pairs, 1);
  assert_false(r.faces_ok());
}

void test_degenerate_faces(void **) {
  Mesh m;
  m.vertex(0, 0, 0); m.vertex(1, 0, 0); m.vertex(2, 0, 0); m.vertex(0, 1, 0);
  m.face(0, 1, 2);  // collinear
  m.face(0, 3, 3);  // repeated index
  m.face(0, 1, 3);  // fine
  m.face(0, 1, 9);  // index out of range
  const moa::MeshReport r = m.analyze();
  assert_int_equal(r.degenerate_faces, 2);
  assert_int_equal(r.invalid_faces, 1);
  assert_int_equal(r.duplicate_faces, 0);
  assert_int_equal(r.self_intersecting_pairs, 0);  // degenerate faces are not tested
  assert_true(r.min_angle == 0);
  assert_false(r.faces_ok());
}

void test_point_coverage_and_json(void **) {
  const Mesh m = tetrahedron();
  moa::MeshReport r = m.analyze();
  // Within float rounding of a vertex matches (meshes may be stored in single precision);
  // 1e-5 away does not.
  const double points[] = {0, 0, 0, 1, 0, 0, 5, 5, 5, 0, 0, 1.00001, 0, 0, 1 + 1e-9};
  moa::add_point_coverage(r, points, 5, m.xyz.data(), 4, m.tri.data(), 4);
  assert_int_equal(r.input_points, 5);
  assert_int_equal(r.input_points_on_mesh, 3);
  const std::string json = moa::report_to_json(r);
  for (const char *key : {"\"triangles\": 4", "\"genus\": 0", "\"closed\": true",
                          "\"self_intersecting_pairs\": 0", "\"input_points_on_mesh\": 3",
                          "\"ok\": true", "\"below_10\": 0"})
    if (json.find(key) == std::string::npos) fail_msg("missing %s in %s", key, json.c_str());
  std::ostringstream text;
  moa::print_report(text, r);
  assert_true(text.str().find("genus 0") != std::string::npos);
}

void test_empty(void **) {
  const moa::MeshReport r = moa::analyze_mesh(nullptr, 0, nullptr, 0);
  assert_int_equal(r.components, 0);
  assert_false(r.closed());
  assert_true(r.contract_ok());
}

}  // namespace

int main() {
  const CMUnitTest tests[] = {
      cmocka_unit_test(test_tetrahedron),
      cmocka_unit_test(test_octahedron),
      cmocka_unit_test(test_inward),
      cmocka_unit_test(test_torus),
      cmocka_unit_test(test_two_components),
      cmocka_unit_test(test_hole),
      cmocka_unit_test(test_flipped_face),
      cmocka_unit_test(test_moebius),
      cmocka_unit_test(test_non_manifold_edge),
      cmocka_unit_test(test_bowtie),
      cmocka_unit_test(test_crossing),
      cmocka_unit_test(test_coplanar_shared_edge),
      cmocka_unit_test(test_duplicate_face),
      cmocka_unit_test(test_degenerate_faces),
      cmocka_unit_test(test_point_coverage_and_json),
      cmocka_unit_test(test_empty),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
