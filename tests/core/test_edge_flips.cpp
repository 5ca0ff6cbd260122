// The edge flips at the end of the reconstruction (edge_flips.cpp): on a flat patch every
// interior edge ends up Delaunay (its opposite angles sum to at most 180 degrees, within the
// pass's half-degree margin), the smallest angles of a curved sample improve, a box's sharp
// edges are not cut across, and the contract holds with and without them.
#include "core_harness.hpp"

#include <cmath>
#include <map>
#include <random>
#include <utility>

// cmocka last: its macros (fail, ...) clash with names in the standard headers.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

using namespace moa::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

moa::Params without_flips() {
  moa::Params p;
  p.edge_flips = 0;
  return p;
}

// A random sample of the unit square in the plane z = 0.
Points flat_patch(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points p;
  for (std::size_t i = 0; i < n; ++i) p.insert(p.end(), {u(rng), u(rng), 0.0});
  return p;
}

// A random sample of the surface of the box [0, 2] x [0, 1] x [0, 1], even by area.
Points box_surface(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double lx = 2, ly = 1, lz = 1;
  const double areas[3] = {ly * lz, lx * lz, lx * ly};  // faces across x, y, z (two of each)
  const double total = areas[0] + areas[1] + areas[2];
  Points p;
  for (std::size_t i = 0; i < n; ++i) {
    const double pick = u(rng) * total, side = u(rng) < 0.5 ? 0.0 : 1.0;
    double x = u(rng) * lx, y = u(rng) * ly, z = u(rng) * lz;
    if (pick < areas[0])
      x = side * lx;
    else if (pick < areas[0] + areas[1])
      y = side * ly;
    else
      z = side * lz;
    p.insert(p.end(), {x, y, z});
  }
  return p;
}

// Interior edges whose two opposite angles sum past 180 degrees by more than `margin` radians.
std::size_t non_delaunay_edges(const Points &p, const std::vector<std::uint32_t> &tris,
                               double margin) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> opposite;
  for (std::size_t f = 0; f < tris.size(); f += 3)
    for (int i = 0; i < 3; ++i) {
      std::uint32_t a = tris[f + i], b = tris[f + (i + 1) % 3];
      if (a > b) std::swap(a, b);
      opposite[{a, b}].push_back(tris[f + (i + 2) % 3]);
    }
  std::size_t count = 0;
  for (const auto &[edge, across] : opposite) {
    if (across.size() != 2) continue;
    const double sum = angle_at(p, across[0], edge.first, edge.second) +
                       angle_at(p, across[1], edge.first, edge.second);
    if (sum > kPi + margin) ++count;
  }
  return count;
}

// Share of the triangles whose smallest angle is below `degrees`.
double share_below(const Points &p, const std::vector<std::uint32_t> &tris, double degrees) {
  return tris.empty() ? 0.0 : double(faces_below(p, tris, degrees)) / double(tris.size() / 3);
}

// How far the faces cut into the box [0, 2] x [0, 1] x [0, 1] from its surface: the depth of
// each face's centroid, summed and the largest. Faces on one side lie in it; those across a
// sharp edge cut the edge off, the deeper the worse the edge is kept.
struct Depth {
  double sum = 0, deepest = 0;
};
Depth depth_below_box_surface(const Points &p, const std::vector<std::uint32_t> &tris) {
  Depth d;
  for (std::size_t f = 0; f < tris.size(); f += 3) {
    double c[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int axis = 0; axis < 3; ++axis) c[axis] += p[3 * tris[f + k] + axis] / 3.0;
    const double depth = std::min({c[0], 2.0 - c[0], c[1], 1.0 - c[1], c[2], 1.0 - c[2]});
    d.sum += depth;
    d.deepest = std::max(d.deepest, depth);
  }
  return d;
}

const Case &flat_patch_case() {
  static const Case c = make_case("flat random patch", flat_patch(4000, 31));
  return c;
}
const Case &sphere_case() {
  static const Case c = make_case("random sphere", sphere_random(6000, 1.0, 32));
  return c;
}
const Case &box_case() {
  static const Case c = make_case("random box surface", box_surface(8000, 33));
  return c;
}

MOA_CONTRACT_TESTS(flat_patch)
MOA_CONTRACT_TESTS(sphere)
MOA_CONTRACT_TESTS(box)

// On a plane every quad is flat: no edge may be left that the flips' own rule would turn.
void test_flat_patch_ends_delaunay(void **) {
  const Case &c = flat_patch_case();
  MOA_EXPECT(disk_failure(c));
  const Run plain = run_reconstruct(c.points, 2, without_flips());
  const std::size_t before = non_delaunay_edges(c.points, plain.triangles, 1e-9);
  const std::size_t after = non_delaunay_edges(c.points, c.run.triangles, kPi / 360.0);
  if (plain.stats.edges_flipped != 0 || before == 0 || after != 0 || c.run.stats.edges_flipped == 0)
    fail_msg("flat patch: %zu edges past 180 degrees without flips (%zu flipped), %zu past "
             "180.5 with them (%zu flipped)",
             before, plain.stats.edges_flipped, after, c.run.stats.edges_flipped);
}

// The flips widen the smallest angles of a curved surface, and keep it closed.
void test_sphere_angles_improve(void **) {
  const Case &c = sphere_case();
  MOA_EXPECT(closed_failure(c, 0));
  const Run plain = run_reconstruct(c.points, 2, without_flips());
  const double before = share_below(c.points, plain.triangles, 10.0);
  const double after = share_below(c.points, c.run.triangles, 10.0);
  if (!(after < 0.95 * before) || c.run.triangles.size() != plain.triangles.size())
    fail_msg("sphere: %.4f of the triangles below 10 degrees without flips, %.4f with them; "
             "%zu and %zu triangles",
             before, after, plain.triangles.size() / 3, c.run.triangles.size() / 3);
}

// A sharp edge is no flat quad: no face may cut the box's edges off deeper than the deepest
// one Algorithm 1 and the loop module made there, and all of them together only a little
// deeper (edge_flips.cpp, kMaxBend: 3 % measured on a box like this one).
void test_box_edges_stay(void **) {
  const Case &c = box_case();
  MOA_EXPECT(closed_failure(c, 0));
  const Run plain = run_reconstruct(c.points, 2, without_flips());
  const Depth before = depth_below_box_surface(c.points, plain.triangles);
  const Depth after = depth_below_box_surface(c.points, c.run.triangles);
  if (after.deepest > before.deepest || after.sum > 1.05 * before.sum ||
      c.run.stats.edges_flipped == 0)
    fail_msg("box: the faces' centroids lie %.6f deep in all, %.6f at most, without flips; "
             "%.6f and %.6f with them (%zu flipped)",
             before.sum, before.deepest, after.sum, after.deepest, c.run.stats.edges_flipped);
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      MOA_CONTRACT_ENTRIES(flat_patch),
      MOA_CONTRACT_ENTRIES(sphere),
      MOA_CONTRACT_ENTRIES(box),
      cmocka_unit_test(test_flat_patch_ends_delaunay),
      cmocka_unit_test(test_sphere_angles_improve),
      cmocka_unit_test(test_box_edges_stay),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
