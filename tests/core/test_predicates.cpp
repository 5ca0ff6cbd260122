// The library's exact predicates (src/core/predicates.hpp) against the test suite's own
// (tests/support, GMP rationals throughout) on inputs where the floating-point filter cannot
// decide: points on slanted planes and lines, nudged by one unit in the last place, and
// magnitudes at which an expansion product would underflow or overflow (the GMP fallback).
#include <cmath>
#include <cstdint>
#include <random>

#include "core/predicates.hpp"
#include "support/exact_predicates.hpp"

// cmocka last: its macros clash with names in the standard headers.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

namespace {

using moa::Vec3;

moa::test::Vec3 to_test(const Vec3 &p) { return {p.x, p.y, p.z}; }

// The reference: the support library orients det[a-d; b-d; c-d], the opposite sign of the
// library's det[b-a; c-a; d-a].
int reference_orient3d(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d) {
  return -moa::test::orient3d(to_test(a), to_test(b), to_test(c), to_test(d));
}

int reference_orient2d(const Vec3 &a, const Vec3 &b, const Vec3 &c, int drop) {
  auto u = [drop](const Vec3 &p) { return drop == 0 ? p.y : drop == 1 ? p.z : p.x; };
  auto v = [drop](const Vec3 &p) { return drop == 0 ? p.z : drop == 1 ? p.x : p.y; };
  return moa::test::orient2d(u(a), v(a), u(b), v(b), u(c), v(c));
}

// A point on the plane n.p = 1 (rounded to doubles, so only nearly on it), at (s, t) in the
// plane's own coordinates, scaled by `scale`.
Vec3 on_slanted_plane(double s, double t, double scale) {
  const double x = s, y = t, z = (1.0 - 0.3 * x - 0.7 * y) / 1.1;
  return {x * scale, y * scale, z * scale};
}

// Moves p by one unit in the last place of one coordinate, up or down.
Vec3 nudge(Vec3 p, int axis, bool up) {
  double &c = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
  c = std::nextafter(c, up ? INFINITY : -INFINITY);
  return p;
}

// Returns how many of the cases had a zero sign (exactly coplanar), so that a run that never
// reaches the hard cases is noticed.
int compare_near_plane(double scale, std::uint64_t seed, int cases) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  int zeros = 0;
  for (int i = 0; i < cases; ++i) {
    Vec3 p[4];
    for (Vec3 &q : p) q = on_slanted_plane(coord(rng), coord(rng), scale);
    if (i % 3 == 1) p[3] = nudge(p[3], int(rng() % 3), rng() % 2 == 0);
    if (i % 3 == 2) p[3] = p[int(rng() % 3)];  // a repeated point: exactly zero
    const int got = moa::orient3d(p[0], p[1], p[2], p[3]);
    const int want = reference_orient3d(p[0], p[1], p[2], p[3]);
    if (got != want)
      fail_msg("orient3d case %d at scale %g: library %d, reference %d", i, scale, got, want);
    zeros += want == 0;
    for (int drop = 0; drop < 3; ++drop) {
      // Three points of a slanted line: collinear up to rounding in every projection.
      const double t0 = coord(rng), t1 = coord(rng);
      const Vec3 a = p[0], b = p[1];
      Vec3 c{a.x + t0 * (b.x - a.x), a.y + t0 * (b.y - a.y), a.z + t0 * (b.z - a.z)};
      if (t1 > 0) c = nudge(c, int(rng() % 3), t1 > 0.5);
      const int got2 = moa::orient2d(a, b, c, drop);
      const int want2 = reference_orient2d(a, b, c, drop);
      if (got2 != want2)
        fail_msg("orient2d case %d drop %d at scale %g: library %d, reference %d", i, drop, scale,
                 got2, want2);
    }
  }
  return zeros;
}

void orient_on_slanted_planes(void **) {
  const int zeros = compare_near_plane(1.0, 1, 20000);
  assert_true(zeros >= 20000 / 3);  // the repeated points at least
}

void orient_at_extreme_magnitudes(void **) {
  // Products of parts near 1e-300 underflow and near 1e+200 overflow: the library must fall
  // back to rationals and still agree.
  for (double scale : {1e-300, 1e-160, 1e+100, 1e+200, 3.0e+50})
    compare_near_plane(scale, 7, 2000);
}

void orient_exact_grid_points(void **) {
  // Small integers on the plane z = x + 2y: exactly coplanar, and exactly off it by one.
  for (int i = 0; i < 200; ++i) {
    auto at = [](int x, int y, int off) { return Vec3{double(x), double(y), double(x + 2 * y + off)}; };
    const Vec3 a = at(i % 7, i % 5, 0), b = at(3 + i % 4, -2, 0), c = at(-5, 1 + i % 3, 0);
    const int off = i % 3 - 1;
    const Vec3 d = at(i % 11 - 5, i % 13 - 6, off);
    const int want = reference_orient3d(a, b, c, d);
    assert_int_equal(moa::orient3d(a, b, c, d), want);
    if (off == 0) assert_int_equal(want, 0);
  }
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(orient_on_slanted_planes),
      cmocka_unit_test(orient_at_extreme_magnitudes),
      cmocka_unit_test(orient_exact_grid_points),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
