// The library's exact predicates (src/core/predicates.hpp) against the test suite's own
// (tests/support, GMP rationals throughout) on inputs where the floating-point filter cannot
// decide: points on slanted planes and lines, nudged by one unit in the last place, and
// magnitudes at which an expansion product would underflow or overflow (the GMP fallback). And
// the triangle crossing test against the support library's on pairs of triangles lying (nearly
// or exactly) in one plane, where the library first tries to keep them apart in floating point.
#include <cmath>
#include <cstdint>
#include <random>

#include "core/predicates.hpp"
#include "support/exact_predicates.hpp"
#include "support/triangle_intersection.hpp"

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

// Whether the library's crossing test agrees with the support library's on triangle t and
// triangle f, which share t's corner 0 when `share` is set; fails the test on a disagreement.
// Returns the verdict.
bool compare_crossing(const Vec3 (&t)[3], const Vec3 (&f)[3], bool share, const char *what, int i) {
  const unsigned it[3] = {0, 1, 2}, jf[3] = {share ? 0u : 3u, 4, 5};
  const bool got = moa::triangles_cross(t, it, f, jf);
  const moa::test::Vec3 tt[3] = {to_test(t[0]), to_test(t[1]), to_test(t[2])};
  const moa::test::Vec3 ft[3] = {to_test(f[0]), to_test(f[1]), to_test(f[2])};
  const bool want = share ? moa::test::shared_vertex_conflict(tt[0], tt[1], tt[2], ft[1], ft[2])
                          : moa::test::triangles_meet(tt, ft);
  if (got != want) fail_msg("%s case %d: library %d, reference %d", what, i, got, want);
  return want;
}

void crossing_of_coplanar_triangles(void **) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coord(-1.0, 1.0), unit(0.0, 1.0);
  int met[2] = {0, 0}, apart[2] = {0, 0};
  for (int i = 0; i < 20000; ++i) {
    const bool share = i % 2 == 1;
    // A triangle on a slanted plane, and a copy turned about its corner 0 or moved in the
    // plane, by amounts from nothing to well clear of it: the two straddle each other's planes
    // by rounding, overlap, touch or lie apart by a hair.
    Vec3 t[3], f[3];
    double st[3][2];
    for (int k = 0; k < 3; ++k) {
      st[k][0] = coord(rng);
      st[k][1] = coord(rng);
      t[k] = on_slanted_plane(st[k][0], st[k][1], 1.0);
    }
    const double amount = std::pow(10.0, -12.0 * unit(rng)) * (rng() % 2 ? 2.5 : 0.5);
    const double turn = share ? amount * 6.0 : 0.0, c = std::cos(turn), s = std::sin(turn);
    const double ds = share ? 0.0 : amount * coord(rng), dt = share ? 0.0 : amount * coord(rng);
    for (int k = 0; k < 3; ++k) {
      const double u = st[k][0] - st[0][0], v = st[k][1] - st[0][1];
      f[k] = on_slanted_plane(st[0][0] + c * u - s * v + ds, st[0][1] + s * u + c * v + dt, 1.0);
    }
    if (share) f[0] = t[0];
    (compare_crossing(t, f, share, "slanted plane", i) ? met : apart)[share]++;
  }
  // Faces of a fan around a corner v: t = v a b, and f = v b' c, whose edge v b' is t's edge
  // v b turned a hair into t or out of it, and c is a mirrored about v b (in the plane's own
  // coordinates). The two meet only in v, or overlap in a sliver too thin to see in floating
  // point.
  for (int i = 0; i < 4000; ++i) {
    const double s0 = coord(rng), t0 = coord(rng), r = 0.01 + unit(rng), wide = 0.2 + unit(rng);
    const double ab = 3.0 * coord(rng), hair = std::pow(10.0, -14.0 * unit(rng));
    const double bent = ab + (i % 2 ? hair : -hair);
    auto around = [&](double angle, double radius) {
      return on_slanted_plane(s0 + radius * std::cos(angle), t0 + radius * std::sin(angle), 1.0);
    };
    const Vec3 t[3] = {on_slanted_plane(s0, t0, 1.0), around(ab - wide, r), around(ab, 0.7 * r)};
    const Vec3 f[3] = {t[0], around(bent, 1.3 * r), around(ab + wide, r)};
    (compare_crossing(t, f, true, "fan", i) ? met : apart)[1]++;
  }
  // The same fans exactly coplanar, on integers up to 2^41 in a plane z = constant (a slice of
  // a CT stack): b' is b moved by one, into t's corner or out of it, a turn of about 2^-41
  // radians.
  auto at_large = [](double x, double y) { return Vec3{x, y, 0.25}; };
  for (int i = 0; i < 2000; ++i) {
    const double big = 0x1p40, bx = big * (1 + unit(rng)), by = std::round(big * coord(rng));
    const double ax = std::round(big * unit(rng)), ay = std::round(-big * (0.2 + unit(rng)));
    // c: a mirrored about the line v b, rounded to integers.
    const double len2 = bx * bx + by * by, along = 2 * (ax * bx + ay * by) / len2;
    const double cx = std::round(along * bx - ax), cy = std::round(along * by - ay);
    // Moving b by (0, 1) takes it to the left of line v b (bx > 0): toward a when a lies on
    // the left, into t's corner.
    const double a_side = bx * ay - by * ax > 0 ? 1 : -1, step = i % 2 ? a_side : -a_side;
    const Vec3 t[3] = {at_large(0, 0), at_large(ax, ay), at_large(bx, by)};
    const Vec3 f[3] = {t[0], at_large(bx, by + step), at_large(cx, cy)};
    (compare_crossing(t, f, true, "integer fan", i) ? met : apart)[1]++;
  }
  // Exactly coplanar: small integers on the plane z = x + 2y, one triangle moved by whole
  // steps, so corners land exactly on the other's edges and corners.
  auto at = [](int x, int y) { return Vec3{double(x), double(y), double(x + 2 * y)}; };
  for (int i = 0; i < 2000; ++i) {
    const bool share = i % 2 == 1;
    const int dx = int(rng() % 9) - 4, dy = int(rng() % 9) - 4;
    const Vec3 t[3] = {at(0, 0), at(4, 0), at(0, 4)};
    Vec3 f[3] = {at(dx, dy), at(4 + dy, -dx), at(dx - 2, 4 + dy)};
    if (share) f[0] = t[0];
    (compare_crossing(t, f, share, "integer plane", i) ? met : apart)[share]++;
  }
  // Both verdicts reached, with and without a shared corner.
  assert_true(met[0] > 1000 && apart[0] > 1000 && met[1] > 1000 && apart[1] > 1000);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(orient_on_slanted_planes),
      cmocka_unit_test(orient_at_extreme_magnitudes),
      cmocka_unit_test(orient_exact_grid_points),
      cmocka_unit_test(crossing_of_coplanar_triangles),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
