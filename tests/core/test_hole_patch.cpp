// The loop module's last-resort patch (src/core/hole_patch.hpp) on loops whose best
// triangulation is known, and its caps of flat cuts (src/core/cut_cap.hpp).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "core/cut_cap.hpp"
#include "core/hole_patch.hpp"

// cmocka last: its macros clash with names in the standard headers.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

namespace {

using moa::Tri;
using moa::Vec3;

const auto kNoEdges = [](uint32_t, uint32_t) { return false; };

// Every loop edge a -> b is in exactly one patch triangle, in that direction; every chord in
// exactly two, once each way; n - 2 triangles.
void assert_patch_of(const std::vector<Tri> &patch, const std::vector<uint32_t> &loop) {
  const std::size_t n = loop.size();
  assert_int_equal(patch.size(), n - 2);
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const Tri &t : patch)
    for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  for (const auto &[edge, count] : directed) assert_int_equal(count, 1);
  for (std::size_t j = 0; j < n; ++j) {
    uint32_t a = loop[j], b = loop[(j + 1) % n];
    assert_true(directed.count({a, b}));
    assert_false(directed.count({b, a}));
  }
  for (const auto &[edge, count] : directed) {
    bool on_loop = false;
    for (std::size_t j = 0; j < n; ++j)
      on_loop |= edge == std::make_pair(loop[j], loop[(j + 1) % n]);
    if (!on_loop) assert_true(directed.count({edge.second, edge.first}));
  }
}

// A flat regular polygon in z = 0 whose rim faces lie in the same plane.
void flat_polygon(std::size_t n, std::vector<Vec3> &points, std::vector<uint32_t> &loop,
                  std::vector<Vec3> &rim) {
  points.clear();
  loop.clear();
  for (std::size_t i = 0; i < n; ++i) {
    double a = 2 * M_PI * double(i) / double(n);
    points.push_back({std::cos(a), std::sin(a), 0});
    loop.push_back(uint32_t(i));
  }
  rim.assign(n, Vec3{0, 0, 1});  // counter-clockwise loop: the patch faces +z
}

void flat_polygons_patch_flat(void **) {
  for (std::size_t n : {3, 4, 7, 20}) {
    std::vector<Vec3> points, rim;
    std::vector<uint32_t> loop;
    flat_polygon(n, points, loop, rim);
    std::vector<Tri> patch = moa::smoothest_patch(points, loop, rim, kNoEdges);
    assert_patch_of(patch, loop);
    for (const Tri &t : patch) {  // every triangle faces the rim's way
      Vec3 c = moa::cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]);
      assert_true(c.z > 0);
    }
  }
}

// A square bent along one diagonal: the patch must use that diagonal, not the other one,
// which would fold across the crease.
void bent_square_follows_the_crease(void **) {
  std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0.5}, {1, 1, 0}, {0, 1, 0.5}};
  std::vector<uint32_t> loop = {0, 1, 2, 3};
  // Rim normals continuing the two halves split by the diagonal 1-3, facing up.
  auto up = [&](int a, int b, int c) {
    return moa::normalized(moa::cross(points[b] - points[a], points[c] - points[a]));
  };
  std::vector<Vec3> rim = {up(0, 1, 3), up(1, 2, 3), up(1, 2, 3), up(0, 1, 3)};
  std::vector<Tri> patch = moa::smoothest_patch(points, loop, rim, kNoEdges);
  assert_patch_of(patch, loop);
  for (const Tri &t : patch) {
    std::set<uint32_t> corners(t.begin(), t.end());
    assert_true(corners.count(1) && corners.count(3));
  }
}

// A chord that is a mesh edge already is never used; with no other way, no patch.
void existing_edges_are_avoided(void **) {
  std::vector<Vec3> points, rim;
  std::vector<uint32_t> loop;
  flat_polygon(4, points, loop, rim);
  auto taken = [](uint32_t a, uint32_t b) { return (a == 0 && b == 2) || (a == 2 && b == 0); };
  std::vector<Tri> patch = moa::smoothest_patch(points, loop, rim, taken);
  assert_patch_of(patch, loop);
  for (const Tri &t : patch) {
    std::set<uint32_t> corners(t.begin(), t.end());
    assert_true(corners.count(1) && corners.count(3));
  }
  auto both = [](uint32_t a, uint32_t b) { return (a + b) % 2 == 0; };  // 0-2 and 1-3
  assert_true(moa::smoothest_patch(points, loop, rim, both).empty());
}

void repeated_vertices_and_degenerate_loops_give_nothing(void **) {
  std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
  std::vector<Vec3> rim(4, Vec3{0, 0, 1});
  assert_true(moa::smoothest_patch(points, {0, 1, 3, 1}, rim, kNoEdges).empty());
  assert_true(moa::smoothest_patch(points, {0, 1, 2}, rim, kNoEdges).empty());  // collinear
  assert_true(moa::smoothest_patch(points, {0, 1}, rim, kNoEdges).empty());
}

// The cap of a loop in one cut of a contour stack (src/core/cut_cap.hpp): a star of 12 tips in
// a tilted plane, both ways round, and a circle of 600 points whose every corner is within 0.6
// degrees of flat. The cap must be a patch of the loop whose triangles all face one way and
// add up to the polygon's area: then they tile it without overlap.
void flat_caps_tile_the_polygon(void **) {
  const Vec3 e1 = moa::normalized(Vec3{1, 0.2, 0.3});
  const Vec3 n = moa::normalized(moa::cross(e1, {0, 1, 0})), e2 = moa::cross(n, e1);
  auto signed_area = [&](const Vec3 &a, const Vec3 &b, const Vec3 &c) {
    return 0.5 * dot(moa::cross(b - a, c - a), n);
  };
  for (int round = 0; round < 3; ++round) {
    const std::size_t count = round < 2 ? 24 : 600;
    std::vector<Vec3> points;
    std::vector<uint32_t> loop;
    double area = 0;  // of the polygon, as a fan from its first corner
    for (std::size_t i = 0; i < count; ++i) {
      const double a = 2 * M_PI * double(i) / double(count);
      const double r = round < 2 && i % 2 == 1 ? 0.4 : 1.0;
      points.push_back(e1 * (r * std::cos(a)) + e2 * (r * std::sin(a)) + Vec3{5, -3, 2});
      loop.push_back(uint32_t(i));
    }
    if (round == 1) std::reverse(loop.begin(), loop.end());
    for (std::size_t i = 0; i < count; ++i)
      area += signed_area(points[loop[0]], points[loop[i]], points[loop[(i + 1) % count]]);
    const std::vector<Tri> cap = moa::flat_cap(points, loop);
    assert_patch_of(cap, loop);
    double covered = 0;
    for (const Tri &t : cap) {
      const double a = signed_area(points[t[0]], points[t[1]], points[t[2]]);
      assert_true(a * area > 0);  // facing the loop's way
      covered += a;
    }
    assert_true(std::fabs(covered - area) < 1e-9 * std::fabs(area));
  }
}

void crossing_and_short_loops_get_no_cap(void **) {
  const std::vector<Vec3> points = {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}};
  assert_true(moa::flat_cap(points, {0, 1, 2, 3}).empty());  // a bow tie: no area
  assert_true(moa::flat_cap(points, {0, 1}).empty());
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(flat_polygons_patch_flat),
      cmocka_unit_test(bent_square_follows_the_crease),
      cmocka_unit_test(existing_edges_are_avoided),
      cmocka_unit_test(repeated_vertices_and_degenerate_loops_give_nothing),
      cmocka_unit_test(flat_caps_tile_the_polygon),
      cmocka_unit_test(crossing_and_short_loops_get_no_cap),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
