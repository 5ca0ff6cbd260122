// The loop module's last patch (LoopFiller::patch_last_holes, src/core/hole_repair.cpp) on a
// blade meshed by hand: a triangular prism whose cross-section has a sharp corner, the blade's
// edge. One face along that edge is taken out, leaving a hole of three edges whose only patch
// opens against the face across the edge at the blade's own angle. Sharper than
// edge_fold_angle (30 degrees), the patch is refused by the judgment of the earlier steps; the
// last patch takes it down to 5 degrees, and no sharper. (On this clean blade the earlier
// steps would close the hole another way, widening it and patching a tent inside the blade; in
// crumpled spots of real clouds they find none.)
// Then on a flat sheet whose hole holds a small closed piece: every patch crosses the piece, and
// taking away the faces around the hole with those it crosses (as at a fold along a sharp
// crease) would delete the piece with its points, so the hole is left as it was.
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/loop_filler.hpp"
#include "hand_mesh.hpp"

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

// The prism: cross-section A (the edge, at the origin), B = (1, 0, h), C = (1, 0, -h) in the
// xz-plane, h = tan(angle / 2), swept along y from 0 to 1. Each long side is a grid of n x n
// squares, the back (x = 1) one of 2 x n, the two ends a strip of triangles. Every vertex is
// computed once, so faces sharing it share its index.
struct Blade {
  static constexpr int n = 10;
  std::vector<double> xyz;
  std::vector<Tri> faces;  // caller's indices, facing outward
  Tri removed{};           // the face taken out: on the top side, along the edge

  explicit Blade(double angle_degrees) {
    const double h = std::tan(angle_degrees * M_PI / 360.0);
    auto add = [&](double x, double y, double z) {
      xyz.insert(xyz.end(), {x, y, z});
      return uint32_t(xyz.size() / 3 - 1);
    };
    // edge[j]; top[i][j] and bottom[i][j] for i = 1..n (i = 0 is the edge); back[j] at z = 0.
    std::vector<uint32_t> edge(n + 1), back(n + 1);
    std::vector<std::vector<uint32_t>> top(n + 1, std::vector<uint32_t>(n + 1)), bottom = top;
    for (int j = 0; j <= n; ++j) {
      const double y = double(j) / n;
      edge[j] = top[0][j] = bottom[0][j] = add(0, y, 0);
      for (int i = 1; i <= n; ++i) {
        const double x = double(i) / n;
        top[i][j] = add(x, y, h * x);
        bottom[i][j] = add(x, y, -h * x);
      }
      back[j] = add(1, y, 0);
    }
    auto quad = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
      face(a, b, c);
      face(a, c, d);
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        quad(top[i][j], top[i + 1][j], top[i + 1][j + 1], top[i][j + 1]);
        quad(bottom[i][j], bottom[i + 1][j], bottom[i + 1][j + 1], bottom[i][j + 1]);
      }
    for (int j = 0; j < n; ++j) {
      quad(top[n][j], back[j], back[j + 1], top[n][j + 1]);
      quad(back[j], bottom[n][j], bottom[n][j + 1], back[j + 1]);
    }
    for (int j : {0, n}) {
      face(edge[j], top[1][j], bottom[1][j]);
      for (int i = 1; i + 1 < n; ++i)
        quad(top[i][j], top[i + 1][j], bottom[i + 1][j], bottom[i][j]);
      face(top[n - 1][j], top[n][j], back[j]);
      face(top[n - 1][j], back[j], bottom[n - 1][j]);
      face(bottom[n - 1][j], back[j], bottom[n][j]);
    }
    // The top side's face on the edge between edge[4] and edge[5].
    for (std::size_t f = 0; f < faces.size(); ++f) {
      int on_edge = 0;
      for (uint32_t v : faces[f]) on_edge += v == edge[4] || v == edge[5];
      bool on_top = false;
      for (uint32_t v : faces[f]) on_top |= xyz[3 * v + 2] > 0;
      if (on_edge == 2 && on_top) {
        removed = faces[f];
        faces.erase(faces.begin() + std::ptrdiff_t(f));
        break;
      }
    }
  }

  // Adds triangle a b c facing away from the prism's centroid (2/3, 1/2, 0): it is convex.
  void face(uint32_t a, uint32_t b, uint32_t c) {
    faces.push_back(moa::test::facing_away(xyz, a, b, c, {2.0 / 3.0, 0.5, 0.0}));
  }
};

struct Outcome {
  bool refused_earlier = false;
  std::size_t closed_by_last_patch = 0;
  std::size_t open_edges = 0, over_full_edges = 0;
};

// Builds the blade's mesh with its hole, as the loop module would meet it; tries the patch with
// the judgment of the earlier steps, then runs the last patch.
Outcome patch_blade(const Blade &blade) {
  moa::test::HandMesh mesh(blade.xyz, blade.faces);
  assert_true(mesh.loaded());
  moa::GrowthState &g = mesh.g;
  assert_int_equal(moa::test::count_mesh(g.mesh).open_edges, 3);

  Outcome out;
  // The face taken out, put back as a patch by the relaxed judgment of the earlier steps.
  out.refused_earlier = !g.add_all_or_none({mesh.internal(blade.removed)}, true);
  out.closed_by_last_patch = moa::LoopFiller(g).patch_last_holes();
  const moa::test::MeshCounts counts = moa::test::count_mesh(g.mesh);
  out.open_edges = counts.open_edges;
  out.over_full_edges = counts.over_full_edges;
  return out;
}

// A 12-degree blade: the patch opens 12 degrees against the bottom face across the edge.
void blade_hole_closed_by_last_patch(void **) {
  const Outcome o = patch_blade(Blade(12.0));
  assert_true(o.refused_earlier);
  assert_int_equal(o.closed_by_last_patch, 1);
  assert_int_equal(o.open_edges, 0);
  assert_int_equal(o.over_full_edges, 0);
}

// A 3-degree blade: sharper than the last patch may fold, the hole stays.
void blade_sharper_than_5_degrees_kept_open(void **) {
  const Outcome o = patch_blade(Blade(3.0));
  assert_true(o.refused_earlier);
  assert_int_equal(o.closed_by_last_patch, 0);
  assert_int_equal(o.open_edges, 3);
  assert_int_equal(o.over_full_edges, 0);
}

// A flat sheet of 12 x 12 unit squares at z = 0 without the 2 x 2 squares at its centre, and in
// that hole an octahedron of radius 0.4 centred 0.05 above the sheet's plane, which the plane
// cuts: every patch of the hole crosses it.
struct SheetWithPiece {
  static constexpr int n = 12;
  std::vector<double> xyz;
  std::vector<Tri> faces;

  SheetWithPiece() {
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) xyz.insert(xyz.end(), {double(i), double(j), 0.0});
    auto at = [](int i, int j) { return uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if ((i == 5 || i == 6) && (j == 5 || j == 6)) continue;  // the hole
        faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    const double c[3] = {6.0, 6.0, 0.05}, r = 0.4;
    const uint32_t first = uint32_t(xyz.size() / 3);
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {1.0, -1.0}) {
        double p[3] = {c[0], c[1], c[2]};
        p[axis] += sign * r;
        xyz.insert(xyz.end(), {p[0], p[1], p[2]});
      }
    // Corners first + 0..5: +x, -x, +y, -y, +z, -z; a face for each octant.
    for (uint32_t x : {0u, 1u})
      for (uint32_t y : {2u, 3u})
        for (uint32_t z : {4u, 5u})
          faces.push_back(moa::test::facing_away(xyz, first + x, first + y, first + z, c));
  }
};

// The octahedron's faces and the sheet's are all still there, and the hole is open.
void hole_around_a_closed_piece_left_open(void **) {
  const SheetWithPiece sheet;
  moa::test::HandMesh mesh(sheet.xyz, sheet.faces);
  assert_true(mesh.loaded());
  moa::GrowthState &g = mesh.g;
  const moa::test::MeshCounts before = moa::test::count_mesh(g.mesh);
  assert_int_equal(before.open_edges, 4 * SheetWithPiece::n + 8);  // the border and the hole

  assert_int_equal(moa::LoopFiller(g).patch_last_holes(), 0);
  const moa::test::MeshCounts after = moa::test::count_mesh(g.mesh);
  assert_int_equal(after.faces, before.faces);
  assert_int_equal(after.vertices_used, before.vertices_used);
  assert_int_equal(after.open_edges, before.open_edges);
  assert_int_equal(after.euler_characteristic(), before.euler_characteristic());
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(blade_hole_closed_by_last_patch),
      cmocka_unit_test(blade_sharper_than_5_degrees_kept_open),
      cmocka_unit_test(hole_around_a_closed_piece_left_open),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
