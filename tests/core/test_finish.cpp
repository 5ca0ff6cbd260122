// The final stage (src/core/finish.cpp) on face lists made by hand: closed components turned
// outward, and at a vertex whose faces form several fans all but the largest removed, whatever
// order the faces come in.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "core/finish.hpp"
#include "core/point_set.hpp"

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

// Runs the final stage on these faces and checks how many faces it kept and removed and how
// many boundary edges it counted.
void finish_and_count(const std::vector<Vec3> &xyz, std::vector<Tri> &faces, std::size_t kept,
                      std::size_t removed, std::size_t boundary_edges) {
  moa::PointSet points;
  points.work = xyz;
  points.input_count = xyz.size();
  moa_stats stats{};
  moa::finish_mesh(points, faces, stats);
  assert_int_equal(faces.size(), kept);
  assert_int_equal(stats.triangles_removed, removed);
  assert_int_equal(stats.boundary_edges, boundary_edges);
}

// An octahedron around `centre` (vertices first + 0..5), its faces oriented outward.
void add_octahedron(std::vector<Vec3> &xyz, std::vector<Tri> &faces, const Vec3 &centre) {
  const uint32_t o = uint32_t(xyz.size());
  for (const Vec3 &d : {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, -1, 0},
                        Vec3{0, 0, 1}, Vec3{0, 0, -1}})
    xyz.push_back(centre + d);
  const uint32_t px = o, nx = o + 1, py = o + 2, ny = o + 3, pz = o + 4, nz = o + 5;
  for (const Tri &t : {Tri{px, py, pz}, Tri{py, nx, pz}, Tri{nx, ny, pz}, Tri{ny, px, pz},
                       Tri{py, px, nz}, Tri{nx, py, nz}, Tri{ny, nx, nz}, Tri{px, ny, nz}})
    faces.push_back(t);
}

double signed_volume(const std::vector<Vec3> &xyz, const std::vector<Tri> &faces) {
  double v = 0;
  for (const Tri &t : faces) v += dot(xyz[t[0]], cross(xyz[t[1]], xyz[t[2]]));
  return v / 6;
}

std::set<std::set<uint32_t>> corner_sets(const std::vector<Tri> &faces) {
  std::set<std::set<uint32_t>> out;
  for (const Tri &t : faces) out.insert({t[0], t[1], t[2]});
  return out;
}

// Inward faces in a scrambled order: all kept, each turned outward.
void closed_inward_turned_out(void **) {
  std::vector<Vec3> xyz;
  std::vector<Tri> faces;
  add_octahedron(xyz, faces, {0, 0, 0});
  const auto expected = corner_sets(faces);
  for (Tri &t : faces) std::swap(t[1], t[2]);
  std::reverse(faces.begin(), faces.end());
  std::swap(faces[0], faces[5]);
  finish_and_count(xyz, faces, 8, 0, 0);
  assert_true(corner_sets(faces) == expected);
  assert_true(signed_volume(xyz, faces) > 0);
}

// A closed fan whose faces are listed so that no two in a row share an edge is one fan.
void scrambled_closed_fan_kept(void **) {
  // A hexagonal bipyramid: apexes 0 and 7, ring 1..6.
  std::vector<Vec3> xyz{{0, 0, 1}};
  for (int i = 0; i < 6; ++i) xyz.push_back({std::cos(i * M_PI / 3), std::sin(i * M_PI / 3), 0});
  xyz.push_back({0, 0, -1});
  std::vector<Tri> faces;
  for (int i : {0, 3, 1, 4, 2, 5}) {
    const uint32_t a = 1 + uint32_t(i), b = 1 + uint32_t((i + 1) % 6);
    faces.push_back({0, a, b});
    faces.push_back({7, b, a});
  }
  finish_and_count(xyz, faces, 12, 0, 0);
}

// Two open fans at vertex 0 (three faces and two): the smaller goes.
void two_open_fans_smaller_removed(void **) {
  std::vector<Vec3> xyz{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0},
                        {0, 0, 1}, {1, 0, 2}, {0, 1, 2}};
  std::vector<Tri> faces{{0, 5, 6}, {0, 1, 2}, {0, 6, 7}, {0, 2, 3}, {0, 3, 4}};
  finish_and_count(xyz, faces, 3, 2, 5);  // the chain's rim: 0-1, 1-2, 2-3, 3-4, 4-0
  assert_true(corner_sets(faces) == corner_sets({{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
}

// A closed surface with a stray triangle hanging from one of its vertices: the triangle goes.
void stray_triangle_at_closed_fan_removed(void **) {
  std::vector<Vec3> xyz;
  std::vector<Tri> faces;
  add_octahedron(xyz, faces, {0, 0, 0});
  xyz.push_back({2, 0, 0});
  xyz.push_back({2, 1, 0});
  faces.insert(faces.begin() + 3, Tri{0, 6, 7});  // vertex 0 is the octahedron's +x
  finish_and_count(xyz, faces, 8, 1, 0);
}

// Two closed surfaces touching at one vertex: one of the two fans there goes, with the faces
// of that fan only.
void closed_surfaces_touching_at_a_vertex(void **) {
  std::vector<Vec3> xyz;
  std::vector<Tri> faces;
  add_octahedron(xyz, faces, {0, 0, 0});
  add_octahedron(xyz, faces, {2, 0, 0});
  // The second octahedron's -x vertex (6 + 1) is the first's +x (0): share it.
  for (std::size_t f = 8; f < faces.size(); ++f)
    for (uint32_t &v : faces[f])
      if (v == 7) v = 0;
  finish_and_count(xyz, faces, 12, 4, 4);  // the rim of the opened octahedron
  std::size_t at_shared = 0;
  for (const Tri &t : faces) at_shared += std::count(t.begin(), t.end(), 0u);
  assert_int_equal(at_shared, 4);
}

// Fans resolved one vertex after another: removing the smaller fan at vertex 0 takes away the
// two faces that joined vertex 5's faces into one fan, so vertex 5 has two fans now, equal in
// size: the one listed first stays. Vertices 6, 8 and 9 are left with one live face listed
// after a removed one, and it stays: a removed face counted as a fan of one outranked it, and
// the removals went on along the strip (3 faces kept, not 5).
void removal_splits_a_later_fan(void **) {
  std::vector<Vec3> xyz;
  for (int i = 0; i < 12; ++i) xyz.push_back({std::cos(i * 0.5), std::sin(i * 0.5), 0.1 * i});
  std::vector<Tri> faces = {
      {0, 1, 2}, {0, 2, 3}, {0, 3, 4},  // vertex 0's larger fan
      {5, 6, 0}, {5, 0, 7},             // its smaller one, the link between 5's two halves
      {5, 8, 6}, {5, 9, 8},             // one half of vertex 5's faces
      {5, 7, 10}, {5, 10, 11},          // the other
  };
  // Kept: vertex 0's larger fan (rim 0-1-2-3-4-0) and faces 5-8-6, 5-9-8 (rim 5-9-8-6-5).
  finish_and_count(xyz, faces, 5, 4, 9);
  assert_true(corner_sets(faces) ==
              corner_sets({{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {5, 8, 6}, {5, 9, 8}}));
}

// A chain of 2,000 octahedra, each touching the next at a vertex (12,000 vertices: the search
// for split fans and for the faces across each edge runs over many ranges in parallel): at
// each touching vertex the earlier octahedron's fan stays, so every octahedron but the first
// loses the four faces at its -x vertex.
void chain_of_touching_surfaces(void **) {
  constexpr uint32_t kCount = 2000;
  std::vector<Vec3> xyz;
  std::vector<Tri> faces;
  for (uint32_t k = 0; k < kCount; ++k) {
    add_octahedron(xyz, faces, {2.0 * k, 0, 0});
    if (k == 0) continue;
    const uint32_t minus_x = 6 * k + 1, previous_plus_x = 6 * (k - 1);
    for (std::size_t f = 8 * k; f < faces.size(); ++f)
      for (uint32_t &v : faces[f])
        if (v == minus_x) v = previous_plus_x;
  }
  finish_and_count(xyz, faces, 4 * kCount + 4, 4 * (kCount - 1), 4 * (kCount - 1));
  // At each touching vertex, four faces, all of the earlier octahedron (vertices 6(k-1)..6k-1).
  std::vector<std::size_t> at_shared(kCount, 0);
  for (const Tri &t : faces)
    for (uint32_t v : t)
      if (v % 6 == 0 && v / 6 + 1 < kCount) {
        ++at_shared[v / 6];
        for (uint32_t w : t)
          if (w < v || w >= v + 6) fail_msg("a face of a later octahedron stays at vertex %u", v);
      }
  for (uint32_t k = 0; k + 1 < kCount; ++k)
    if (at_shared[k] != 4) fail_msg("touching vertex %u has %zu faces", 6 * k, at_shared[k]);
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(closed_inward_turned_out),
      cmocka_unit_test(scrambled_closed_fan_kept),
      cmocka_unit_test(two_open_fans_smaller_removed),
      cmocka_unit_test(stray_triangle_at_closed_fan_removed),
      cmocka_unit_test(closed_surfaces_touching_at_a_vertex),
      cmocka_unit_test(removal_splits_a_later_fan),
      cmocka_unit_test(chain_of_touching_surfaces),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
