// The loop module's slit closing (LoopFiller::close_slits, src/core/slit_closing.cpp) on a cube
// meshed by hand. On its top face, two points stand in a row along one grid edge (or a little
// off it): the faces below the row take them in, the face above the edge does not, and the
// hole between the row and the edge has next to no area. Its only patch, the triangle over the
// row, is a needle; the slit is closed by splitting the face above the edge instead.
#include <cstdint>
#include <map>
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

// The unit cube [0, 1]^3, each side a grid of n x n squares, each square two triangles facing
// outward. On the top side (z = 1) the squares on either side of the grid edge from
// A = (2/n, 3/n) to C = (3/n, 3/n) are meshed differently: the one above the edge as two
// triangles, one of them on the edge; the one below as a fan that runs through the row
// B1, B2 at a third and two thirds of the edge, each `off` edge lengths below it (toward -y).
struct SlitCube {
  static constexpr int n = 6;
  std::vector<double> xyz;
  std::vector<Tri> faces;
  uint32_t a = 0, c = 0, x = 0;  // the edge's ends and the third corner of the face above it
  std::map<std::vector<long>, uint32_t> index;  // a grid point's vertex, by its coordinates

  explicit SlitCube(double off) {
    // The six sides: the fixed axis and its value, the two axes the grid runs along.
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side <= 1; ++side)
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) {
            if (axis == 2 && side == 1 && i == 2 && (j == 2 || j == 3)) continue;
            const uint32_t p = grid(axis, side, i, j), q = grid(axis, side, i + 1, j);
            const uint32_t r = grid(axis, side, i + 1, j + 1), s = grid(axis, side, i, j + 1);
            face(p, q, r);
            face(p, r, s);
          }
    a = grid(2, 1, 2, 3);
    c = grid(2, 1, 3, 3);
    const uint32_t c_up = grid(2, 1, 3, 4), a_up = grid(2, 1, 2, 4);
    const uint32_t a_down = grid(2, 1, 2, 2), c_down = grid(2, 1, 3, 2);
    // Above the edge: the face A C c_up on it, so its third corner x is c_up.
    face(a, c, c_up);
    face(a, c_up, a_up);
    x = c_up;
    // Below: the row and the square's lower corners.
    const double h = 1.0 / n;
    const uint32_t b1 = add(2.0 * h + h / 3, 3.0 * h - off * h, 1.0);
    const uint32_t b2 = add(2.0 * h + 2 * h / 3, 3.0 * h - off * h, 1.0);
    face(a_down, c_down, b2);
    face(c_down, c, b2);
    face(a_down, b2, b1);
    face(a_down, b1, a);
  }

  uint32_t add(double px, double py, double pz) {
    xyz.insert(xyz.end(), {px, py, pz});
    return uint32_t(xyz.size() / 3 - 1);
  }

  // Grid point (i, j) of a side; shared by the sides that meet at it.
  uint32_t grid(int axis, int side, int i, int j) {
    long coord[3];
    coord[axis] = side * n;
    coord[(axis + 1) % 3] = i;
    coord[(axis + 2) % 3] = j;
    const std::vector<long> key(coord, coord + 3);
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    const uint32_t v = add(double(coord[0]) / n, double(coord[1]) / n, double(coord[2]) / n);
    index.emplace(key, v);
    return v;
  }

  // Adds triangle p q r facing away from the centre: the cube is convex.
  void face(uint32_t p, uint32_t q, uint32_t r) {
    faces.push_back(moa::test::facing_away(xyz, p, q, r, {0.5, 0.5, 0.5}));
  }

  // A thin triangle standing upright in the hole, at y halfway between the edge and the row,
  // from below the top side to above it: it crosses no face of the cube, but every patch of the
  // hole.
  void add_pin(double off) {
    const double h = 1.0 / n, y = 3.0 * h - 0.5 * off * h, xm = 2.5 * h;
    const uint32_t p = add(xm, y, 1.1), q = add(xm, y, 0.9), r = add(xm + 0.05 * h, y, 1.0);
    faces.push_back({p, q, r});
  }
};

struct Outcome {
  std::size_t closed = 0;
  moa::test::MeshCounts before, after;
  bool face_above_kept = false;  // the face on the edge A C is still there
  bool fan_from_x = false;       // three faces added, each with x as a corner
};

Outcome close_slits_of(const SlitCube &cube) {
  moa::test::HandMesh mesh(cube.xyz, cube.faces);
  assert_true(mesh.loaded());
  moa::GrowthState &g = mesh.g;
  Outcome out;
  out.before = moa::test::count_mesh(g.mesh);
  const uint32_t first_new = g.mesh.face_count();
  out.closed = moa::LoopFiller(g).close_slits();
  out.after = moa::test::count_mesh(g.mesh);
  const Tri above = mesh.internal({cube.a, cube.c, cube.x});
  out.face_above_kept = g.mesh.face_with(above) != moa::kNone;
  // The faces added, each with x as a corner.
  std::size_t fan = 0;
  for (uint32_t f = first_new; f < g.mesh.face_count(); ++f)
    if (g.mesh.alive(f)) {
      const Tri &t = g.mesh.stored(f);
      fan += t[0] == above[2] || t[1] == above[2] || t[2] == above[2];
    }
  out.fan_from_x = fan == 3;
  return out;
}

// The row exactly on the edge: a slit of no area at all, closed by the fan from x.
void slit_on_the_edge_closed(void **) {
  const Outcome o = close_slits_of(SlitCube(0.0));
  assert_int_equal(o.before.open_edges, 4);
  assert_int_equal(o.closed, 1);
  assert_int_equal(o.after.open_edges, 0);
  assert_int_equal(o.after.over_full_edges, 0);
  assert_int_equal(o.after.faces, o.before.faces + 2);
  assert_int_equal(o.after.euler_characteristic(), 2);  // a closed sphere
  assert_false(o.face_above_kept);
  assert_true(o.fan_from_x);
}

// The row a twentieth of the edge off it: still a slit.
void slit_beside_the_edge_closed(void **) {
  const Outcome o = close_slits_of(SlitCube(0.05));
  assert_int_equal(o.closed, 1);
  assert_int_equal(o.after.open_edges, 0);
  assert_int_equal(o.after.over_full_edges, 0);
  assert_int_equal(o.after.euler_characteristic(), 2);
  assert_true(o.fan_from_x);
}

// A third of the edge off it: a hole with an area of its own, which the patches are for; left
// as it is.
void wider_hole_left_alone(void **) {
  const Outcome o = close_slits_of(SlitCube(0.3));
  assert_int_equal(o.closed, 0);
  assert_int_equal(o.after.open_edges, 4);
  assert_int_equal(o.after.faces, o.before.faces);
  assert_true(o.face_above_kept);
}

// A pin through the slit: the fan would cross it, so the judgment refuses it and the face
// above the edge is put back.
void slit_with_a_pin_kept_open(void **) {
  SlitCube cube(0.08);
  cube.add_pin(0.08);
  const Outcome o = close_slits_of(cube);
  assert_int_equal(o.before.open_edges, 4 + 3);
  assert_int_equal(o.closed, 0);
  assert_int_equal(o.after.open_edges, 4 + 3);
  assert_int_equal(o.after.faces, o.before.faces);
  assert_true(o.face_above_kept);
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(slit_on_the_edge_closed),
      cmocka_unit_test(slit_beside_the_edge_closed),
      cmocka_unit_test(wider_hole_left_alone),
      cmocka_unit_test(slit_with_a_pin_kept_open),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
