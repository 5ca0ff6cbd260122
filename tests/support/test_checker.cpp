// Self-test of the contract checker on hand-made meshes: clean ones must pass with the right
// counts, and each kind of defect must be found exactly as often as it was planted.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "support/contract_checker.hpp"
#include "support/exact_predicates.hpp"

using moa::test::check_contract;
using moa::test::ContractReport;

namespace {

struct Mesh {
  std::vector<double> xyz;
  std::vector<uint32_t> tris;
  uint32_t add(double x, double y, double z) {
    xyz.push_back(x);
    xyz.push_back(y);
    xyz.push_back(z);
    return uint32_t(xyz.size() / 3 - 1);
  }
  void face(uint32_t a, uint32_t b, uint32_t c) {
    tris.push_back(a);
    tris.push_back(b);
    tris.push_back(c);
  }
  ContractReport check() const { return check_contract(xyz, tris); }
};

Mesh tetrahedron() {
  Mesh m;
  m.add(0, 0, 0), m.add(1, 0, 0), m.add(0, 1, 0), m.add(0, 0, 1);
  m.face(0, 2, 1), m.face(0, 1, 3), m.face(0, 3, 2), m.face(1, 2, 3);
  return m;
}

Mesh octahedron() {
  Mesh m;
  m.add(1, 0, 0), m.add(-1, 0, 0), m.add(0, 1, 0), m.add(0, -1, 0), m.add(0, 0, 1), m.add(0, 0, -1);
  m.face(0, 2, 4), m.face(2, 1, 4), m.face(1, 3, 4), m.face(3, 0, 4);
  m.face(2, 0, 5), m.face(1, 2, 5), m.face(3, 1, 5), m.face(0, 3, 5);
  return m;
}

Mesh cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.add(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto &q : quads) m.face(q[0], q[1], q[2]), m.face(q[0], q[2], q[3]);
  return m;
}

// Closed torus grid mesh, outward facing, genus 1.
Mesh torus(uint32_t nu, uint32_t nv) {
  Mesh m;
  const double pi = 3.14159265358979323846;
  for (uint32_t j = 0; j < nv; ++j)
    for (uint32_t i = 0; i < nu; ++i) {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      m.add((1 + 0.4 * std::cos(v)) * std::cos(u), (1 + 0.4 * std::cos(v)) * std::sin(u), 0.4 * std::sin(v));
    }
  auto id = [&](uint32_t i, uint32_t j) { return (j % nv) * nu + (i % nu); };
  for (uint32_t j = 0; j < nv; ++j)
    for (uint32_t i = 0; i < nu; ++i) {
      m.face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      m.face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return m;
}

// Flat n x n grid of unit squares, each split in two (every quad co-circular).
Mesh flat_grid_mesh(uint32_t n) {
  Mesh m;
  for (uint32_t j = 0; j <= n; ++j)
    for (uint32_t i = 0; i <= n; ++i) m.add(i, j, 0);
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      m.face(a, b, c), m.face(a, c, d);
    }
  return m;
}

void expect_clean(const ContractReport &r) {
  if (!r.ok()) fail_msg("expected a clean mesh:\n%s", r.describe().c_str());
}

void test_exact_predicates(void **) {
  using moa::test::orient3d;
  using moa::test::Vec3;
  // Coplanar points far from the origin: the filter cannot decide, the exact path says 0.
  const double big = 0x1p52;
  const Vec3 a{big, big, big}, b{big + 1, big, big}, c{big, big + 1, big}, d{big + 3, big + 5, big};
  assert_int_equal(orient3d(a, b, c, d), 0);
  // One ulp off the plane, either way, must flip the sign.
  const Vec3 up{d.x, d.y, std::nextafter(big, 2 * big)}, down{d.x, d.y, std::nextafter(big, 0.0)};
  assert_int_equal(orient3d(a, b, c, up), -orient3d(a, b, c, down));
  assert_true(orient3d(a, b, c, up) != 0);
  // Same plane through tiny and huge magnitudes at once (exponents far apart).
  const Vec3 p{1e-300, 0, 0}, q{1e300, 0, 0}, r{0, 1, 0}, s{0, 0, 1e-310};
  assert_int_equal(orient3d(p, q, r, Vec3{5, 7, 0}), 0);
  assert_true(orient3d(p, q, r, s) != 0);
  // Points on x + y + z = 1 with rounded coordinates: the exact sign matches a rational check.
  const Vec3 e{0.1, 0.2, 0.7}, f{0.3, 0.3, 0.4}, g{0.6, 0.1, 0.3};
  const int o = orient3d(e, f, g, Vec3{0.2, 0.2, 0.6});
  assert_int_equal(o, orient3d(f, g, e, Vec3{0.2, 0.2, 0.6}));   // even permutation
  assert_int_equal(o, -orient3d(f, e, g, Vec3{0.2, 0.2, 0.6}));  // odd permutation
  assert_true(moa::test::collinear3d(Vec3{big, 0, 1}, Vec3{big + 2, 2, 3}, Vec3{big + 4, 4, 5}));
  assert_false(moa::test::collinear3d(Vec3{big, 0, 1}, Vec3{big + 2, 2, 3}, Vec3{big + 4, 4, 6}));
}

void test_tetrahedron_clean(void **) {
  const ContractReport r = tetrahedron().check();
  expect_clean(r);
  assert_true(r.closed());
  assert_int_equal(r.vertices_used, 4);
  assert_int_equal(r.edges, 6);
  assert_int_equal(r.euler_characteristic, 2);
  assert_int_equal(r.genus_sum, 0);
}

void test_octahedron_clean(void **) {
  const ContractReport r = octahedron().check();
  expect_clean(r);
  assert_true(r.closed());
  assert_int_equal(r.components, 1);
  assert_int_equal(r.euler_characteristic, 2);
}

void test_cube_clean(void **) {
  const ContractReport r = cube().check();
  expect_clean(r);
  assert_true(r.closed());
  assert_int_equal(r.faces, 12);
  assert_int_equal(r.genus_sum, 0);
}

void test_torus_clean_genus1(void **) {
  const ContractReport r = torus(20, 12).check();
  expect_clean(r);
  assert_true(r.closed());
  assert_int_equal(r.euler_characteristic, 0);
  assert_int_equal(r.genus_sum, 1);
  assert_int_equal(r.closed_genus.size(), 1);
}

void test_two_components(void **) {
  Mesh m = tetrahedron();
  const Mesh o = octahedron();
  const uint32_t base = uint32_t(m.xyz.size() / 3);
  for (size_t i = 0; i < o.xyz.size(); i += 3) m.add(o.xyz[i] + 5, o.xyz[i + 1], o.xyz[i + 2]);
  for (uint32_t v : o.tris) m.tris.push_back(v + base);
  const ContractReport r = m.check();
  expect_clean(r);
  assert_int_equal(r.components, 2);
  assert_int_equal(r.closed_components, 2);
  assert_int_equal(r.euler_characteristic, 4);
}

void test_flat_grid_disk(void **) {
  const ContractReport r = flat_grid_mesh(10).check();
  expect_clean(r);
  assert_true(r.disk());
  assert_int_equal(r.boundary_edges, 40);
  assert_int_equal(r.boundary_loops, 1);
  assert_int_equal(r.closed_components, 0);
}

void test_annulus_two_loops(void **) {
  Mesh m = flat_grid_mesh(6);
  // Drop the faces of the middle 2 x 2 cells: a ring with two boundary loops.
  std::vector<uint32_t> kept;
  for (size_t f = 0; f < m.tris.size() / 3; ++f) {
    const size_t cell = f / 2, i = cell % 6, j = cell / 6;
    if (i >= 2 && i < 4 && j >= 2 && j < 4) continue;
    kept.insert(kept.end(), m.tris.begin() + 3 * f, m.tris.begin() + 3 * f + 3);
  }
  m.tris = kept;
  const ContractReport r = m.check();
  expect_clean(r);
  assert_int_equal(r.boundary_loops, 2);
  assert_int_equal(r.euler_characteristic, 0);
  assert_false(r.disk());
}

void test_flipped_face(void **) {
  Mesh m = tetrahedron();
  std::swap(m.tris[9], m.tris[10]);
  const ContractReport r = m.check();
  assert_int_equal(r.misoriented_edges, 3);
  assert_false(r.c4());
  assert_true(r.c1() && r.c2() && r.c3() && r.c5());
}

void test_inward_component(void **) {
  Mesh m = octahedron();
  for (size_t f = 0; f < m.tris.size(); f += 3) std::swap(m.tris[f + 1], m.tris[f + 2]);
  const ContractReport r = m.check();
  assert_int_equal(r.misoriented_edges, 0);
  assert_int_equal(r.inward_components, 1);
  assert_false(r.ok());
}

void test_hole(void **) {
  Mesh m = octahedron();
  m.tris.resize(m.tris.size() - 3);
  const ContractReport r = m.check();
  expect_clean(r);
  assert_int_equal(r.boundary_edges, 3);
  assert_int_equal(r.boundary_loops, 1);
  assert_int_equal(r.closed_components, 0);
  assert_false(r.closed());
  assert_true(r.disk());
}

void test_non_manifold_edge(void **) {
  Mesh m;
  m.add(0, 0, 0), m.add(1, 0, 0);
  m.add(0.5, 1, 0), m.add(0.5, -0.5, 0.866), m.add(0.5, -0.5, -0.866);
  m.face(0, 1, 2), m.face(1, 0, 3), m.face(0, 1, 4);
  const ContractReport r = m.check();
  assert_int_equal(r.non_manifold_edges, 1);
  assert_int_equal(r.non_manifold_vertices, 0);
  assert_int_equal(r.intersecting_pairs, 0);
  assert_true(r.c1());
}

void test_bowtie_vertex(void **) {
  // Two tetrahedra touching at one vertex: closed, but vertex 0 has two fans.
  Mesh m = tetrahedron();
  m.add(-1, 0, 0), m.add(0, -1, 0), m.add(0, 0, -1);
  m.face(0, 4, 5), m.face(0, 6, 4), m.face(0, 5, 6), m.face(4, 6, 5);
  const ContractReport r = m.check();
  if (r.non_manifold_vertices != 1) fail_msg("%s", r.describe().c_str());
  assert_true(r.c1() && r.c2() && r.c4() && r.c5());
}

void test_crossing_faces(void **) {
  Mesh m = tetrahedron();
  const uint32_t a = m.add(0.2, 0.2, -0.5), b = m.add(0.3, 0.2, 0.3), c = m.add(0.2, 0.3, 0.3);
  m.face(a, b, c);  // pierces the bottom face only
  const ContractReport r = m.check();
  if (r.intersecting_pairs != 1) fail_msg("%s", r.describe().c_str());
}

void test_crossing_at_shared_vertex(void **) {
  Mesh m;
  m.add(0, 0, 0), m.add(1, 0, 0), m.add(0, 1, 0), m.add(0.3, 0.3, -1), m.add(0.3, 0.35, 1);
  m.face(0, 1, 2), m.face(0, 3, 4);
  assert_int_equal(m.check().intersecting_pairs, 1);
  // Same wedge directions but the second triangle stays on one side: no conflict.
  m.xyz[3 * 3 + 2] = 0.5;
  assert_int_equal(m.check().intersecting_pairs, 0);
}

void test_coplanar_overlap(void **) {
  Mesh m;
  m.add(0, 0, 0), m.add(2, 0, 0), m.add(0, 2, 0);
  m.add(0.5, 0.5, 0), m.add(3, 0.5, 0), m.add(0.5, 3, 0);
  m.face(0, 1, 2), m.face(3, 4, 5);
  assert_int_equal(m.check().intersecting_pairs, 1);
  // Shared vertex, the second triangle inside the first's wedge.
  Mesh w;
  w.add(0, 0, 0), w.add(2, 0, 0), w.add(0, 2, 0), w.add(1, 0.2, 0), w.add(0.2, 1, 0);
  w.face(0, 1, 2), w.face(0, 3, 4);
  assert_int_equal(w.check().intersecting_pairs, 1);
}

void test_coplanar_fold_over(void **) {
  Mesh m;
  m.add(0, 0, 0), m.add(1, 0, 0), m.add(0.5, 1, 0), m.add(0.3, 0.5, 0);
  m.face(0, 1, 2), m.face(1, 0, 3);  // consistent directions, but folded onto each other
  ContractReport r = m.check();
  assert_int_equal(r.intersecting_pairs, 1);
  assert_int_equal(r.misoriented_edges, 0);
  m.xyz[3 * 3 + 1] = -0.5;  // unfolded: a flat pair of triangles
  r = m.check();
  expect_clean(r);
}

void test_touching_and_near_miss(void **) {
  Mesh m;
  m.add(0, 0, 0), m.add(1, 0, 0), m.add(0, 1, 0);
  m.add(0.3, 0.3, 0), m.add(0.5, 0.3, 1), m.add(0.3, 0.5, 1);
  m.face(0, 1, 2), m.face(3, 4, 5);
  assert_int_equal(m.check().intersecting_pairs, 1);  // a vertex on the other face
  m.xyz[3 * 3 + 2] = 1e-300;                          // lifted by a hair: exact says apart
  assert_int_equal(m.check().intersecting_pairs, 0);
  m.xyz[3 * 3 + 2] = -1e-300;  // pushed through by a hair: they cross
  assert_int_equal(m.check().intersecting_pairs, 1);
}

void test_duplicate_face(void **) {
  Mesh m = tetrahedron();
  m.face(3, 1, 2);  // face 3 (1 2 3) rotated: the same vertex set
  const ContractReport r = m.check();
  assert_int_equal(r.duplicate_faces, 1);
  assert_false(r.c1());
}

void test_zero_area_faces(void **) {
  Mesh m = tetrahedron();
  const uint32_t mid = m.add(0.5, 0, 0), twin = m.add(0, 0, 1);  // twin sits on vertex 3
  m.face(0, 1, mid), m.face(3, twin, 1);
  const ContractReport r = m.check();
  assert_int_equal(r.zero_area_faces, 2);
  assert_false(r.c1());
}

void test_bad_indices(void **) {
  Mesh m = tetrahedron();
  m.face(0, 1, 99), m.face(2, 2, 3);
  const ContractReport r = m.check();
  assert_int_equal(r.bad_indices, 1);
  assert_int_equal(r.repeated_vertices, 1);
  assert_int_equal(r.faces, 4);
}

// Optimised builds only are timed; debug and sanitizer builds check a smaller mesh, untimed.
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
constexpr bool k_timed = true;
#else
constexpr bool k_timed = false;
#endif

void test_large_mesh_speed(void **) {
  const Mesh m = k_timed ? torus(500, 200) : torus(100, 40);  // 200k faces when timed
  const auto start = std::chrono::steady_clock::now();
  const ContractReport r = m.check();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_message("checked %zu faces in %.2f s\n", r.faces, s);
  expect_clean(r);
  assert_int_equal(r.genus_sum, 1);
  const Mesh flat = flat_grid_mesh(k_timed ? 300 : 60);  // coplanar faces: exact paths everywhere
  const auto start2 = std::chrono::steady_clock::now();
  const ContractReport rf = flat.check();
  const double s2 = std::chrono::duration<double>(std::chrono::steady_clock::now() - start2).count();
  print_message("checked %zu flat grid faces in %.2f s\n", rf.faces, s2);
  expect_clean(rf);
  if (k_timed) {
    assert_true(s < 10);  // about 0.6 s each on one core; a blow-up would show here
    assert_true(s2 < 10);
  }
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_exact_predicates),
      cmocka_unit_test(test_tetrahedron_clean),     cmocka_unit_test(test_octahedron_clean),
      cmocka_unit_test(test_cube_clean),            cmocka_unit_test(test_torus_clean_genus1),
      cmocka_unit_test(test_two_components),        cmocka_unit_test(test_flat_grid_disk),
      cmocka_unit_test(test_annulus_two_loops),     cmocka_unit_test(test_flipped_face),
      cmocka_unit_test(test_inward_component),      cmocka_unit_test(test_hole),
      cmocka_unit_test(test_non_manifold_edge),     cmocka_unit_test(test_bowtie_vertex),
      cmocka_unit_test(test_crossing_faces),        cmocka_unit_test(test_crossing_at_shared_vertex),
      cmocka_unit_test(test_coplanar_overlap),      cmocka_unit_test(test_coplanar_fold_over),
      cmocka_unit_test(test_touching_and_near_miss), cmocka_unit_test(test_duplicate_face),
      cmocka_unit_test(test_zero_area_faces),       cmocka_unit_test(test_bad_indices),
      cmocka_unit_test(test_large_mesh_speed),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
