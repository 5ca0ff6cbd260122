// The crossing index's grid of recent faces (src/core/face_grid.hpp) against a plain map of
// sets: every live face filed under a cell whose box meets the query's is visited once, removed
// faces never, whatever the keys (neighbouring Morton codes, codes far apart, codes that share
// their low bits); boxes rounded to single precision still contain the double ones.
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "core/face_grid.hpp"
#include "core/mesh_state.hpp"

// cmocka last: its macros clash with names in the standard headers.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

namespace {

using Box = moa::FaceGrid::Box;
const Box kEverywhere({-1e30, -1e30, -1e30}, {1e30, 1e30, 1e30});

// A mesh of n separate faces over 3n vertices: only alive() matters to the grid.
moa::MeshState separate_faces(uint32_t n) {
  moa::MeshState mesh(3 * std::size_t(n));
  for (uint32_t f = 0; f < n; ++f) mesh.add({3 * f, 3 * f + 1, 3 * f + 2});
  return mesh;
}

std::set<uint32_t> visited(moa::FaceGrid &grid, uint64_t key, const moa::MeshState &mesh,
                           const Box &query = kEverywhere) {
  std::set<uint32_t> seen;
  auto visit = [&](uint32_t f) {
    assert_true(seen.insert(f).second);  // each face once
    return false;
  };
  assert_false(grid.visit_live(key, mesh, query, visit));
  return seen;
}

void matches_a_map_of_sets(void **) {
  const uint32_t faces = 3000;
  moa::MeshState mesh = separate_faces(faces);
  moa::FaceGrid grid;
  std::map<uint64_t, std::set<uint32_t>> expected;
  std::mt19937_64 random(7);
  // Keys in a dense block (runs of consecutive codes), spread far apart, and sharing their low
  // 20 bits, so that probing, growth and the block hash all get exercised.
  std::vector<uint64_t> keys;
  for (uint64_t k = 0; k < 700; ++k) keys.push_back(k);
  for (int i = 0; i < 500; ++i) keys.push_back(random() >> 1);
  for (uint64_t i = 1; i <= 300; ++i) keys.push_back((i << 20) | 5);
  for (uint32_t f = 0; f < faces; ++f)
    for (int c = 0; c < 3; ++c) {
      const uint64_t key = keys[random() % keys.size()];
      if (expected[key].insert(f).second) grid.insert(key, f, kEverywhere);
    }
  for (uint32_t f = 0; f < faces; f += 3) mesh.remove(f);
  for (auto &[key, set] : expected) {
    std::set<uint32_t> live;
    for (uint32_t f : set)
      if (mesh.alive(f)) live.insert(f);
    assert_true(visited(grid, key, mesh) == live);
    assert_true(visited(grid, key, mesh) == live);  // again, after the removed ones were dropped
  }
  assert_true(visited(grid, uint64_t(1) << 40, mesh).empty());  // a key never filed
}

void stops_when_the_visitor_says_so(void **) {
  moa::MeshState mesh = separate_faces(10);
  moa::FaceGrid grid;
  for (uint32_t f = 0; f < 10; ++f) grid.insert(42, f, kEverywhere);
  int calls = 0;
  auto visit = [&](uint32_t f) {
    ++calls;
    return f == 9;  // the newest face comes first
  };
  assert_true(grid.visit_live(42, mesh, kEverywhere, visit));
  assert_int_equal(calls, 1);
}

void release_forgets_everything(void **) {
  moa::MeshState mesh = separate_faces(4);
  moa::FaceGrid grid;
  for (uint32_t f = 0; f < 4; ++f) grid.insert(f, f, kEverywhere);
  assert_true(grid.memory_bytes() > 0);
  grid.release();
  assert_int_equal(grid.memory_bytes(), 0);
  for (uint64_t key = 0; key < 4; ++key) assert_true(visited(grid, key, mesh).empty());
  grid.insert(2, 3, kEverywhere);  // usable again
  assert_true(visited(grid, 2, mesh) == std::set<uint32_t>{3});
}

// Faces in one cell at x = 0, 1, 2, ...: a query box sees exactly those its box meets, touching
// included; a box made from doubles that single precision cannot hold still contains them.
void the_box_filter_keeps_exactly_the_faces_met(void **) {
  moa::MeshState mesh = separate_faces(8);
  moa::FaceGrid grid;
  for (uint32_t f = 0; f < 8; ++f) grid.insert(7, f, Box({f + 0.0, 0, 0}, {f + 0.5, 1, 1}));
  assert_true(visited(grid, 7, mesh, Box({2.5, 0.2, 0.2}, {4.1, 0.3, 0.3})) ==
              (std::set<uint32_t>{2, 3, 4}));
  assert_true(visited(grid, 7, mesh, Box({5.6, 0, 0}, {5.9, 1, 1})).empty());
  // 0.1 is not a float: rounded outward, the box still meets a query touching it at 0.1.
  const Box thin({0.1, 0.1, 0.1}, {0.1, 0.1, 0.1});
  assert_true(double(thin.lo[0]) <= 0.1 && double(thin.hi[0]) >= 0.1);
  assert_true(thin.meets(Box({0.1, 0.1, 0.1}, {0.2, 0.2, 0.2})));
  assert_true(thin.meets(Box({-0.2, -0.2, -0.2}, {0.1, 0.1, 0.1})));
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(matches_a_map_of_sets),
      cmocka_unit_test(stops_when_the_visitor_says_so),
      cmocka_unit_test(release_forgets_everything),
      cmocka_unit_test(the_box_filter_keeps_exactly_the_faces_met),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
