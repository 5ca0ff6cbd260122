// Self-test of the point-set generators: determinism, sizes, no duplicates, points on their
// surfaces, and the spacing the property tests rely on.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "support/shapes.hpp"

namespace t = moa::test;

namespace {

size_t count(const t::Points &p) { return p.size() / 3; }

bool has_duplicates(const t::Points &p) {
  std::vector<std::array<double, 3>> v;
  for (size_t i = 0; i < p.size(); i += 3) v.push_back({p[i], p[i + 1], p[i + 2]});
  std::sort(v.begin(), v.end());
  return std::adjacent_find(v.begin(), v.end()) != v.end();
}

// Smallest distance between two points (grid-free brute force: the sets are small).
double min_distance(const t::Points &p) {
  double best = HUGE_VAL;
  for (size_t i = 0; i < p.size(); i += 3)
    for (size_t j = i + 3; j < p.size(); j += 3) {
      const double dx = p[i] - p[j], dy = p[i + 1] - p[j + 1], dz = p[i + 2] - p[j + 2];
      best = std::min(best, dx * dx + dy * dy + dz * dz);
    }
  return std::sqrt(best);
}

void test_engine_is_standard(void **) {
  // The standard fixes mt19937_64's sequence: its 10000th output for the default seed.
  std::mt19937_64 e;
  e.discard(9999);
  assert_true(e() == 9981545732273789042ull);
}

void test_rng_distributions(void **) {
  t::Rng rng(7);
  double sum = 0, sum2 = 0, usum = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double g = rng.normal(), u = rng.uniform();
    sum += g, sum2 += g * g, usum += u;
    assert_true(u >= 0 && u < 1);
  }
  assert_true(std::fabs(sum / n) < 0.01);
  assert_true(std::fabs(sum2 / n - 1) < 0.02);
  assert_true(std::fabs(usum / n - 0.5) < 0.005);
  for (int i = 0; i < 1000; ++i) assert_true(rng.below(7) < 7);
}

void test_generators_deterministic(void **) {
  assert_true(t::sphere_random(500, 1, 3) == t::sphere_random(500, 1, 3));
  assert_true(t::sphere_random(500, 1, 3) != t::sphere_random(500, 1, 4));
  assert_true(t::genus_surface(2, 0.2, 5) == t::genus_surface(2, 0.2, 5));
  assert_true(t::saddle(0.1, 5) == t::saddle(0.1, 5));
  t::Points a = t::fibonacci_sphere(300), b = a;
  t::shuffle(a, 9);
  t::shuffle(b, 9);
  assert_true(a == b);
  assert_true(a != t::fibonacci_sphere(300));
  std::sort(a.begin(), a.end());
  t::Points c = t::fibonacci_sphere(300);
  std::sort(c.begin(), c.end());
  assert_true(a == c);  // a permutation of the same points
}

void test_points_on_surfaces(void **) {
  for (const t::Points &p : {t::fibonacci_sphere(1000, 2.0), t::sphere_random(1000, 2.0, 1)})
    for (size_t i = 0; i < p.size(); i += 3)
      assert_true(std::fabs(std::hypot(p[i], p[i + 1], p[i + 2]) - 2) < 1e-12);
  const t::Points e = t::ellipsoid_random(1000, 3, 2, 1, 2);
  for (size_t i = 0; i < e.size(); i += 3) {
    const double f = e[i] * e[i] / 9 + e[i + 1] * e[i + 1] / 4 + e[i + 2] * e[i + 2];
    assert_true(std::fabs(f - 1) < 1e-12);
  }
  for (const t::Points &p : {t::torus_random(1000, 1, 0.4, 3), t::torus_grid(30, 12, 1, 0.4)})
    for (size_t i = 0; i < p.size(); i += 3) {
      const double rho = std::hypot(p[i], p[i + 1]);
      assert_true(std::fabs(std::hypot(rho - 1, p[i + 2]) - 0.4) < 1e-12);
    }
  const t::Points h = t::hemisphere(500);
  assert_int_equal(count(h), 500);
  for (size_t i = 2; i < h.size(); i += 3) assert_true(h[i] > 0);
  const t::Points s = t::saddle(0.1, 1);
  for (size_t i = 0; i < s.size(); i += 3) {
    assert_true(std::fabs(s[i + 2] - (s[i] * s[i] - s[i + 1] * s[i + 1])) < 1e-12);
    assert_true(std::fabs(s[i]) <= 1 && std::fabs(s[i + 1]) <= 1);
  }
}

void test_grid_shapes(void **) {
  assert_int_equal(count(t::flat_grid(40, 30)), 1200);
  assert_int_equal(count(t::cube_grid(16)), 17 * 17 * 17 - 15 * 15 * 15);
  const t::Points slab = t::box_grid(3, 3, 0.06, 0.1);
  assert_int_equal(count(slab), 2 * 31 * 31);
  assert_false(has_duplicates(slab));
  assert_false(has_duplicates(t::cube_grid(16)));
  assert_false(has_duplicates(t::torus_grid(60, 24, 1, 0.4)));
}

void test_blue_noise_spacing(void **) {
  const t::Points g2 = t::genus_surface(2, 0.13, 1), g3 = t::genus_surface(3, 0.15, 1);
  print_message("genus-2: %zu points, genus-3: %zu points\n", count(g2), count(g3));
  assert_true(min_distance(g2) >= 0.13);
  assert_true(min_distance(g3) >= 0.15);
  assert_true(count(g2) > 700 && count(g2) < 1300);  // about 0.7 area / spacing^2
  const t::Points sheets = t::parallel_sheets(2, 0.1, 0.03, 4);
  size_t upper = 0;
  for (size_t i = 2; i < sheets.size(); i += 3) upper += sheets[i] == 0.03;
  assert_true(upper > 200 && count(sheets) - upper > 200);
  assert_false(has_duplicates(sheets));
  assert_true(min_distance(t::saddle(0.1, 2)) >= 0.1);
}

void test_noise_and_mesh_sampling(void **) {
  t::Points p = t::fibonacci_sphere(1000);
  t::add_noise(p, 0.01, 5);
  double dev = 0;
  for (size_t i = 0; i < p.size(); i += 3) dev += std::fabs(std::hypot(p[i], p[i + 1], p[i + 2]) - 1);
  dev /= 1000;
  const double sigma = 0.01 * std::sqrt(12.0);
  assert_true(dev > 0.3 * sigma && dev < 1.5 * sigma);  // mean |radial noise| ~ 0.8 sigma
  const std::vector<double> v = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  const std::vector<uint32_t> tris = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  const t::Points s = t::sample_mesh(v, tris, 2000, 6);
  assert_int_equal(count(s), 2000);
  size_t upper = 0;
  for (size_t i = 0; i < s.size(); i += 3) {
    assert_true(std::fabs(std::fabs(s[i]) + std::fabs(s[i + 1]) + std::fabs(s[i + 2]) - 1) < 1e-12);
    upper += s[i + 2] > 0;
  }
  assert_true(upper > 850 && upper < 1150);  // equal areas above and below
}

void test_contour_stack(void **) {
  // The octahedron |x| + |y| + |z| = 1 cut by 10 planes z = const: every point on a plane and on
  // the surface, about per_gap points per plane gap along the cuts (squares of side sqrt 2 (1 - |z|)).
  const std::vector<double> v = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  const std::vector<uint32_t> tris = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  const double axis[3] = {0, 0, 2};
  const t::Points s = t::contour_stack(v, tris, axis, 10, 4, 7);
  double length = 0;
  for (int k = 0; k < 10; ++k) length += 4 * std::sqrt(2.0) * (1 - std::fabs(-0.9 + 0.2 * k));
  const double expected = length / (0.2 / 4);
  assert_true(count(s) > 0.9 * expected && count(s) < 1.1 * expected);
  assert_false(has_duplicates(s));
  for (size_t i = 0; i < s.size(); i += 3) {
    const double level = (s[i + 2] + 0.9) / 0.2;
    assert_true(std::fabs(level - std::round(level)) < 1e-9);
    assert_true(std::fabs(std::fabs(s[i]) + std::fabs(s[i + 1]) + std::fabs(s[i + 2]) - 1) < 1e-12);
  }
  assert_true(t::contour_stack(v, tris, axis, 10, 4, 7) == s);  // deterministic
}

void test_triangle_angles(void **) {
  // A right isosceles triangle (0, 1, 2) and a sliver (0, 1, 3) whose corner 3 sees 0-1 nearly
  // flat: angles of 45 and 90 degrees, and one of about 0.6 degrees.
  const t::Points p = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 0.005, 0};
  const double degree = 3.14159265358979323846 / 180;
  assert_true(std::fabs(t::angle_at(p, 0, 1, 2) - 90 * degree) < 1e-12);
  assert_true(std::fabs(t::angle_at(p, 1, 0, 2) - 45 * degree) < 1e-12);
  assert_true(t::angle_at(p, 3, 0, 1) > 178 * degree);
  const std::vector<uint32_t> tris = {0, 1, 2, 0, 1, 3};
  assert_int_equal(t::faces_below(p, tris, 10), 1);
  assert_int_equal(t::faces_below(p, tris, 46), 2);
  assert_int_equal(t::faces_below(p, tris, 0.5), 0);
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_engine_is_standard),    cmocka_unit_test(test_rng_distributions),
      cmocka_unit_test(test_generators_deterministic), cmocka_unit_test(test_points_on_surfaces),
      cmocka_unit_test(test_grid_shapes),           cmocka_unit_test(test_blue_noise_spacing),
      cmocka_unit_test(test_noise_and_mesh_sampling), cmocka_unit_test(test_contour_stack),
      cmocka_unit_test(test_triangle_angles),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
