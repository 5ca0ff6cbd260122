// The loop module's band stitching (LoopFiller::stitch_bands, src/core/band_stitching.cpp) on
// a terrace meshed by hand: a plane tilted 11 degrees off the cuts of a contour stack, on which
// the cuts leave straight lines 40 spacings apart. The bands between the lines are meshed but
// for the middle third of one, which is left open: a hole whose loop runs along two lines and
// across at its ends, far too wide for a hole by its width.
#include <cstdint>
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

// Lines j = 0..4 at y = apart j, z = apart j / 5 (the cuts z = const), each with points at
// x = 0..60 (unit spacing). Band j joins line j to line j + 1 by two triangles per unit of x,
// all facing the same way; band 1 has none for x in [20, 40).
struct Terrace {
  static constexpr int kLines = 5, kPoints = 61;
  static constexpr int kHoleFrom = 20, kHoleTo = 40;
  std::vector<double> xyz;
  std::vector<Tri> faces;

  explicit Terrace(double apart) {
    for (int j = 0; j < kLines; ++j)
      for (int i = 0; i < kPoints; ++i)
        xyz.insert(xyz.end(), {double(i), apart * j, apart * j / 5});
    for (int j = 0; j + 1 < kLines; ++j)
      for (int i = 0; i + 1 < kPoints; ++i) {
        if (j == 1 && i >= kHoleFrom && i < kHoleTo) continue;
        const uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
      }
  }
  static uint32_t at(int i, int j) { return uint32_t(j * kPoints + i); }

  // A thin triangle standing in the hole, across the plane: it crosses no face of the terrace,
  // but every stitch of the band.
  void add_pin() {
    const double x = 30.2, y = 60.0, z = 12.0;  // on the plane, halfway across band 1
    const uint32_t p = uint32_t(xyz.size() / 3);
    xyz.insert(xyz.end(), {x, y - 1, z + 5, x, y + 1, z - 5, x + 0.3, y, z});
    faces.push_back({p, p + 1, p + 2});
  }
};

struct Outcome {
  bool lined = false;
  std::size_t stitched = 0;
  moa::test::MeshCounts before, after;
};

Outcome stitch(const Terrace &terrace) {
  moa::test::HandMesh mesh(terrace.xyz, terrace.faces);
  assert_true(mesh.loaded());
  moa::GrowthState &g = mesh.g;
  Outcome out;
  out.lined = g.nb.lined;
  out.before = moa::test::count_mesh(g.mesh);
  out.stitched = moa::LoopFiller(g).stitch_bands();
  out.after = moa::test::count_mesh(g.mesh);
  return out;
}

// The terrace's own border: along lines 0 and 4, across every line at x = 0 and x = 60.
constexpr std::size_t kBorderEdges = 2 * (Terrace::kPoints - 1) + 2 * (Terrace::kLines - 1);
// The hole: along lines 1 and 2, and the two edges across at its ends.
constexpr std::size_t kHoleEdges = 2 * (Terrace::kHoleTo - Terrace::kHoleFrom) + 2;

// The band is stitched, two triangles per unit of x; the terrace's border, which runs along two
// lines but across them eight times, stays open.
void band_stitched_border_kept(void **) {
  const Outcome o = stitch(Terrace(40));
  assert_true(o.lined);
  assert_int_equal(o.before.open_edges, kBorderEdges + kHoleEdges);
  assert_int_equal(o.stitched, 1);
  assert_int_equal(o.after.open_edges, kBorderEdges);
  assert_int_equal(o.after.over_full_edges, 0);
  assert_int_equal(o.after.faces, o.before.faces + 2 * (Terrace::kHoleTo - Terrace::kHoleFrom));
  assert_int_equal(o.after.euler_characteristic(), 1);  // a disk
}

// A pin through the band: the stitch is refused where it would cross the pin, and goes on from
// the band's other end, back to there: a hole of one or two triangles is left round the pin.
void band_stitched_from_both_ends_up_to_a_pin(void **) {
  Terrace terrace(40);
  terrace.add_pin();
  const Outcome o = stitch(terrace);
  const std::size_t band = 2 * (Terrace::kHoleTo - Terrace::kHoleFrom);
  assert_int_equal(o.before.open_edges, kBorderEdges + kHoleEdges + 3);
  assert_int_equal(o.stitched, 0);
  assert_true(o.after.faces >= o.before.faces + band - 2);
  assert_true(o.after.faces < o.before.faces + band);
  assert_true(o.after.open_edges > kBorderEdges + 3);
  assert_true(o.after.open_edges <= kBorderEdges + 3 + 4);
  assert_int_equal(o.after.over_full_edges, 0);
}

// Lines two spacings apart are no contour stack (the cloud is not lined): the band is a hole
// for the loop module's other steps, and stitch_bands leaves it alone.
void band_of_a_cloud_not_lined_left_alone(void **) {
  const Outcome o = stitch(Terrace(2));
  assert_false(o.lined);
  assert_int_equal(o.stitched, 0);
  assert_int_equal(o.after.open_edges, kBorderEdges + kHoleEdges);
  assert_int_equal(o.after.faces, o.before.faces);
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(band_stitched_border_kept),
      cmocka_unit_test(band_stitched_from_both_ends_up_to_a_pin),
      cmocka_unit_test(band_of_a_cloud_not_lined_left_alone),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
