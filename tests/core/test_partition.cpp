// The parts of Algorithm 1's parallel first pass (src/core/partition.hpp): every point in the
// box of its own part and of no other, no part over its size, the same parts for the same
// points, and cuts that hold where many points share a coordinate.
#include <cstdint>
#include <random>
#include <vector>

#include "core/partition.hpp"

// cmocka last: its macros clash with names in the standard headers.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

namespace {

using moa::Partition;
using moa::Vec3;

bool in_box(const Partition::Box &b, const Vec3 &p) {
  return p.x >= b.lo.x && p.y >= b.lo.y && p.z >= b.lo.z && p.x < b.hi.x && p.y < b.hi.y &&
         p.z < b.hi.z;
}

// Each point lies in its own part's box and in no other's; no part is empty or over max.
void assert_parts(const std::vector<Vec3> &points, const Partition &parts, std::size_t max) {
  assert_int_equal(parts.part_of.size(), points.size());
  std::vector<std::size_t> size(parts.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const uint16_t own = parts.part_of[i];
    assert_true(own < parts.size());
    ++size[own];
    for (std::size_t b = 0; b < parts.size(); ++b)
      assert_true(in_box(parts.boxes[b], points[i]) == (b == own));
  }
  for (std::size_t s : size) {
    assert_true(s > 0);
    assert_true(s <= max);
  }
}

void random_cloud_cut_into_boxes(void **) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> points(5000);
  for (Vec3 &p : points) p = {u(random), 0.3 * u(random), 0.1 * u(random)};
  const Partition parts = moa::partition_points(points, 700);
  assert_true(parts.size() >= 8);  // 5000 / 700 rounded up to the halvings
  assert_parts(points, parts, 700);
  // The same points give the same parts.
  const Partition again = moa::partition_points(points, 700);
  assert_true(again.part_of == parts.part_of);
}

void grid_with_ties_on_every_cut(void **) {
  // A 40 x 40 x 3 grid: every median falls on a row of equal coordinates.
  std::vector<Vec3> points;
  for (int x = 0; x < 40; ++x)
    for (int y = 0; y < 40; ++y)
      for (int z = 0; z < 3; ++z) points.push_back({double(x), double(y), double(z)});
  const Partition parts = moa::partition_points(points, 300);
  assert_true(parts.size() > 1);
  assert_parts(points, parts, 300);
}

void small_cloud_is_one_part(void **) {
  std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Partition parts = moa::partition_points(points, 4);
  assert_int_equal(parts.size(), 1);
  assert_parts(points, parts, 4);
}

void all_points_equal_on_the_long_axis_but_one(void **) {
  // Every point but one shares x, the longest side: the cut moves to the next axis.
  std::vector<Vec3> points;
  for (int i = 0; i < 200; ++i) points.push_back({0.0, 0.01 * i, 0.001 * (i % 7)});
  points.push_back({100.0, 0.0, 0.0});
  const Partition parts = moa::partition_points(points, 50);
  assert_parts(points, parts, 50);
}

void holds_keeps_the_margin_from_every_cut(void **) {
  std::vector<Vec3> points;
  for (int i = 0; i < 100; ++i) points.push_back({double(i), 0.0, 0.0});
  const Partition parts = moa::partition_points(points, 50);  // cut at x = 50
  assert_int_equal(parts.size(), 2);
  const uint16_t left = parts.part_of[0];
  assert_true(parts.holds(left, {10, 0, 0}, {49, 0, 0}, 0.5));
  assert_false(parts.holds(left, {10, 0, 0}, {49.6, 0, 0}, 0.5));
  assert_false(parts.holds(left, {10, 0, 0}, {50, 0, 0}, 0.0));  // the cut belongs to the right
  const uint16_t right = parts.part_of[99];
  assert_true(parts.holds(right, {50, 0, 0}, {1e9, 5, 5}, 0.0));
  assert_false(parts.holds(right, {49.9, 0, 0}, {60, 0, 0}, 0.0));
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(random_cloud_cut_into_boxes),
      cmocka_unit_test(grid_with_ties_on_every_cut),
      cmocka_unit_test(small_cloud_is_one_part),
      cmocka_unit_test(all_points_equal_on_the_long_axis_but_one),
      cmocka_unit_test(holds_keeps_the_margin_from_every_cut),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
