// The crossing index (src/core/intersection.hpp) on a cloud that one far point squeezes into a
// corner of its unit box: a flat grid, 1 apart, and a point ten million away. Its boxes must stay
// local (before, each box's padding covered the whole grid, and every crossing test tested
// every face), and Embree, in single precision, must still find the faces a triangle crosses,
// and count those a ray passes.
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/intersection.hpp"
#include "core/mesh_state.hpp"
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

constexpr int kSide = 40;  // grid points per side

struct SqueezedGrid {
  std::vector<double> xyz;
  std::vector<uint32_t> at;  // caller's index -> internal index
  moa::PointSet points;

  SqueezedGrid() {
    for (int i = 0; i < kSide; ++i)
      for (int j = 0; j < kSide; ++j) add({double(i), double(j), 0});
    add({20.3, 20.2, 1});    // above the grid
    add({20.3, 20.2, -1});   // below it
    add({20.6, 20.7, 0.5});  // above, beside
    add({20.4, 20.6, 0.8});  // above, beside
    add({1e7, 0, 0});        // the far point
    points = moa::prepare_points(xyz.data(), xyz.size() / 3);
    at.resize(xyz.size() / 3);
    for (uint32_t k = 0; k < points.size(); ++k) at[points.original[k]] = k;
  }
  void add(const Vec3 &p) { xyz.insert(xyz.end(), {p.x, p.y, p.z}); }
  uint32_t grid(int i, int j) const { return at[uint32_t(i * kSide + j)]; }
  uint32_t extra(int e) const { return at[uint32_t(kSide * kSide + e)]; }
  double spacing() const { return moa::dist(points.work[grid(0, 0)], points.work[grid(0, 1)]); }
};

// Two triangles per grid square, all in the mesh; the index holds them in its Embree scene.
void triangulate(const SqueezedGrid &g, moa::MeshState &mesh, moa::CrossingIndex &index) {
  for (int i = 0; i + 1 < kSide; ++i)
    for (int j = 0; j + 1 < kSide; ++j) {
      mesh.add({g.grid(i, j), g.grid(i + 1, j), g.grid(i + 1, j + 1)});
      mesh.add({g.grid(i, j), g.grid(i + 1, j + 1), g.grid(i, j + 1)});
    }
  index.add_all(mesh);
}

void boxes_stay_local(void **) {
  SqueezedGrid g;
  moa::MeshState mesh(g.points.size());
  moa::CrossingIndex index(g.points, 2 * g.spacing());
  triangulate(g, mesh, index);
  // A box a quarter of the spacing wide around grid point (20, 20): the six faces around it,
  // and no more than the faces of the squares beside them.
  const Vec3 c = g.points.work[g.grid(20, 20)], h{0.125 * g.spacing(), 0.125 * g.spacing(), 0};
  std::vector<uint32_t> found;
  index.faces_in_box(c - h, c + h, mesh, found);
  assert_true(found.size() >= 6);
  assert_true(found.size() <= 24);  // of 3,042
}

void crossings_found_through_embree(void **) {
  SqueezedGrid g;
  moa::MeshState mesh(g.points.size());
  moa::CrossingIndex index(g.points, 2 * g.spacing());
  triangulate(g, mesh, index);
  std::vector<uint32_t> near;
  const double pad = 0.5 * g.spacing();
  // Through the grid, inside square (20, 20): a crossing.
  assert_true(index.crosses({g.extra(0), g.extra(1), g.extra(2)}, pad, mesh, near));
  // Above it: no crossing, and a neighbourhood of a few squares.
  near.clear();
  assert_false(index.crosses({g.extra(0), g.extra(2), g.extra(3)}, pad, mesh, near));
  assert_true(near.size() >= 2);
  assert_true(near.size() <= 40);
}

// A second index over the same points and cell size (a part of Algorithm 1's parallel pass)
// reads the first one's single-precision points rather than a copy of its own, and finds the
// same crossings; one over another cell size, whose frame differs, makes its own.
void second_index_shares_the_points(void **) {
  SqueezedGrid g;
  moa::MeshState mesh_a(g.points.size()), mesh_b(g.points.size());
  moa::CrossingIndex a(g.points, 2 * g.spacing());
  moa::CrossingIndex b(g.points, 2 * g.spacing(), a.embree_points());
  moa::CrossingIndex c(g.points, 3 * g.spacing(), a.embree_points());
  assert_ptr_equal(b.embree_points().get(), a.embree_points().get());
  assert_ptr_not_equal(c.embree_points().get(), a.embree_points().get());
  assert_int_equal(c.embree_points()->xyz.size(), a.embree_points()->xyz.size());
  triangulate(g, mesh_a, a);
  triangulate(g, mesh_b, b);
  a.release();  // b keeps the points alive
  std::vector<uint32_t> near;
  const double pad = 0.5 * g.spacing();
  assert_true(b.crosses({g.extra(0), g.extra(1), g.extra(2)}, pad, mesh_b, near));
  near.clear();
  assert_false(b.crosses({g.extra(0), g.extra(2), g.extra(3)}, pad, mesh_b, near));
}

// Rays for the inside-out regions (parity_orientation.cpp): every live face they pass through
// counts once, the face they leave from and removed faces not at all.
void rays_count_the_faces_they_pass(void **) {
  SqueezedGrid g;
  moa::MeshState mesh(g.points.size());
  moa::CrossingIndex index(g.points, 2 * g.spacing());
  const uint32_t above = mesh.add({g.extra(0), g.extra(2), g.extra(3)});
  triangulate(g, mesh, index);
  const auto &w = g.points.work;
  const Vec3 centre = (w[g.extra(0)] + w[g.extra(2)] + w[g.extra(3)]) * (1.0 / 3.0);
  const Vec3 up{0, 0, 1}, down{0, 0, -1}, below = centre - up * (2 * g.spacing());
  std::vector<uint32_t> hits;
  assert_int_equal(index.faces_along_ray(below, up, moa::kNone, mesh, hits), 2);
  assert_int_equal(index.faces_along_ray(below, down, moa::kNone, mesh, hits), 0);
  assert_int_equal(index.faces_along_ray(centre, up, above, mesh, hits), 0);
  assert_int_equal(index.faces_along_ray(centre, down, above, mesh, hits), 1);
  mesh.remove(above);
  assert_int_equal(index.faces_along_ray(below, up, moa::kNone, mesh, hits), 1);
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(boxes_stay_local),
      cmocka_unit_test(crossings_found_through_embree),
      cmocka_unit_test(second_index_shares_the_points),
      cmocka_unit_test(rays_count_the_faces_they_pass),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
