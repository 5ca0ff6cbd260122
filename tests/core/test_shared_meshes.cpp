// Uniform random samples of the shared reference meshes (../shared/data/meshes): the contract
// holds and the surfaces come out closed with their true genus. Each of these once kept holes:
// torn at sharp edges (fandisk), crumpled rims the greedy filling could not close, fronts
// meeting across a steep bend.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "core_harness.hpp"
#include "io/io.hpp"
#include "support/shapes.hpp"

// cmocka last: its macros clash with names in the standard headers.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

using namespace moa::test;

namespace {

// A file of the shared data (../shared/data), whose path CTest passes in MOA_SHARED_DATA.
std::string shared_data(const std::string &relative) {
  const char *root = std::getenv("MOA_SHARED_DATA");
  if (root == nullptr) fail_msg("MOA_SHARED_DATA is not set");
  return std::string(root) + "/" + relative;
}

Points sample_of(const char *mesh, std::size_t count, double noise, std::uint64_t seed) {
  const moa::io::MeshData m = moa::io::read_mesh(shared_data(std::string("meshes/") + mesh));
  Points p = sample_mesh(m.xyz, m.triangles, count, seed);
  if (noise > 0) add_noise(p, noise, seed);
  return p;
}

// Contract, one closed component of the given genus, and at most `unused` points left out.
void expect_closed(const char *mesh, double noise, long genus, std::size_t unused) {
  const Case c = make_case(std::string(mesh) + (noise > 0 ? " 50k noisy" : " 50k"),
                           sample_of(mesh, 50000, noise, 1234));
  MOA_EXPECT(contract_failure(c));
  const ContractReport &r = c.report;
  if (r.boundary_edges != 0 || r.genus_sum != genus || r.vertices_used + unused < 50000)
    fail_msg("%s: %zu boundary edges, genus %ld (expected %ld), %zu of 50000 points used",
             c.name.c_str(), r.boundary_edges, r.genus_sum, genus, r.vertices_used);
}

// The contract, one closed component of the given genus, every point used.
void expect_watertight(const Case &c, long genus) {
  MOA_EXPECT(contract_failure(c));
  MOA_EXPECT(closed_failure(c, genus, 1.0));
}

void elephant_closed(void **) { expect_closed("elephant.off", 0, 3, 5); }
void knot2_closed(void **) { expect_closed("knot2.off", 0, 2, 5); }
void fandisk_closed(void **) { expect_closed("fandisk.off", 0, 0, 30); }

// Fandisk at 50k points, sample 1: a hole of three edges at a sharp corner, its neighbours bent
// 63 to 92 degrees away. The faces across the crease overlap its only patch in projection,
// without crossing it, so the second-layer test refused the patch (3 boundary edges before).
void fandisk_corner_hole_patched(void **) {
  expect_watertight(make_case("fandisk.off 50k, sample 1", sample_of("fandisk.off", 50000, 0, 1)),
                    0);
}

// Elephant at 50k points, sample 3: one point beside a crease was left out, as each split and
// star that took it in overlapped the faces across the crease in projection (second-layer
// test). Points still out are tried again without that test.
void elephant_point_beside_crease_taken_in(void **) {
  expect_watertight(make_case("elephant.off 50k, sample 3", sample_of("elephant.off", 50000, 0, 3)),
                    3);
}

// Elephant's own 2,775 vertices: a point in a hole of three edges had grown three faces out to
// points beyond the hole, which pierced its only patch (3 boundary edges). The spike's faces
// go, both holes are patched, and the point is taken in again.
void elephant_vertices_spike_cleared(void **) {
  const moa::io::MeshData m = moa::io::read_mesh(shared_data("meshes/elephant.off"));
  expect_watertight(make_case("elephant.off vertices", m.xyz), 3);
}

// The vertices of two meshes whose faces are all well shaped (elephant: no angle under 30 degrees,
// fandisk: none under 16). The loop module's fillings of the holes Algorithm 1 leaves among them
// (and Algorithm 1 here and there) make some narrow faces, with an angle of 156-177 degrees, most
// of them standing off the surface on their long edge, up to 87 degrees off the face across it. The
// flips turn those over too (edge_flips.cpp, kStandingGain), which they did not while the pair bent
// past 45 degrees: 29 faces under 10 degrees on elephant, 3 on fandisk.
void vertex_sets_keep_no_narrow_faces(void **) {
  for (const char *mesh : {"elephant.off", "fandisk.off"}) {
    const moa::io::MeshData m = moa::io::read_mesh(shared_data(std::string("meshes/") + mesh));
    const Case c = make_case(std::string(mesh) + " vertices", m.xyz);
    MOA_EXPECT(contract_failure(c));
    const std::size_t narrow = faces_below(c.points, c.run.triangles, 10.0);
    if (narrow != 0)
      fail_msg("%s: %zu of %zu faces have an angle under 10 degrees", c.name.c_str(), narrow,
               c.run.triangles.size() / 3);
  }
}

// Homer at 50k points, test sample `seed`.
Case homer_sample(unsigned seed) {
  return make_case("homer.off 50k, sample " + std::to_string(seed),
                   sample_of("homer.off", 50000, 0, seed));
}

// Homer at 50k points, sample 3: at the sharp concave crease of the mouth a join once turned a
// patch of 1,500 faces inside out, and its seam with the rest (126 boundary edges) could never
// close. The inside-out patch is now found from its seam, cut free and turned back. Three close
// points there then made a stray triangle beside the surface, and once it was dropped, taking
// them in lengthened the waist of a thin handle past what the handle cut looks for (genus 1):
// the cut now comes before the take-in, and the surface closes with every point.
void homer_inside_out_patch_turned(void **) { expect_watertight(homer_sample(3), 0); }

// Homer at 50k points, sample 6: the same crease turned a patch of about 700 faces on the lower
// lip, held to the rest by several short runs of edges. A face on an open rim hangs by two
// edges, so the cut is sought between the faces around each side of the seam, not between two
// faces (158 boundary edges and genus 1 before). The holes left along the crease close once the
// widened holes may be patched without the second-layer test too (12 boundary edges before).
void homer_patch_held_by_several_edges_turned(void **) { expect_watertight(homer_sample(6), 0); }

// Homer at 50k points, sample 7: between the fingers the gap is under two spacings, and a few
// triangles bridge it; once the loop module closed the holes beside them, the surface had two
// handles (genus 2), each with a waist of three edges bounding no face. Those are cut and the
// surface comes out closed with its true genus.
void homer_finger_bridges_cut(void **) { expect_watertight(homer_sample(7), 0); }

// Homer at 50k points, sample 5: a bridge between the fingers whose waist is four edges without
// a chord (genus 1 before). Cut, the surface has genus 0; the small hole left at a corner of
// the crease (3 boundary edges) takes the patch the second-layer test refused.
void homer_four_edge_waist_cut(void **) { expect_watertight(homer_sample(5), 0); }

// Homer at 50k points, sample 14: eight faces grown from a few points inside a hole, 1.3 to 2
// spacings from its rim, were an island that blocked the hole's patch (6 boundary edges, 2
// pieces). An island within a few spacings of another piece is dropped before the patching,
// and its points taken in.
void homer_island_in_hole_dropped(void **) { expect_watertight(homer_sample(14), 0); }

// Homer's own 4,930 vertices: at the right corner of the mouth the lips lie 0.9 of a spacing
// apart, and the faces joining them over part of their length left a channel of air under
// them, a handle whose waist of six edges (6.2 local spacings) circles air (genus 1 before).
// The elephant's thin handle on its own vertices has a waist as long, around a tube of its
// surface, and stays (elephant_vertices_spike_cleared: genus 3).
void homer_vertices_mouth_tunnel_cut(void **) {
  const moa::io::MeshData m = moa::io::read_mesh(shared_data("meshes/homer.off"));
  expect_watertight(make_case("homer.off vertices", m.xyz), 0);
}

// A scan of an icosahedron (points/ball.ply) whose faces carry a light, uneven roughness, with a
// second layer half a spacing off in places. The noise estimate catches it and the smoothed
// cloud closes with every point; without smoothing the loop module must still close it and
// take in every point (it once kept two holes and a stray piece of four faces, with 21 points
// left out; then 11 points beside the second layer, until the take-in tried the points still
// out without the second-layer test).
Points ball_scan() { return moa::io::read_points(shared_data("points/ball.ply")); }

void ball_scan_closed(void **) {
  const Case c = make_case("ball.ply", ball_scan());
  expect_watertight(c, 0);
  assert_true(c.run.stats.smoothing_passes >= 1);
}

void ball_scan_closed_unsmoothed(void **) {
  moa::Params params;
  params.smoothing = 0;
  const Case c = make_case("ball.ply, smoothing=0", ball_scan(), 0, params);
  expect_watertight(c, 0);
  assert_int_equal(c.run.stats.smoothing_passes, 0);
}

// Coordinates rounded to a grid (a CT scan's voxel centres, a scanner's integer units): a 20k
// sample of bunny00 rounded to multiples of 1/300 of its diagonal, about its nearest-neighbour
// distance, duplicates dropped (17,944 points). The rounding reads as noise and the cloud is
// smoothed; at the ears the quadrics fitted through both sheets merged them (208 boundary
// edges in 11 loops when every smoothed point was kept).
void grid_rounded_bunny_closed(void **) {
  const Points p = sample_of("bunny00.off", 20000, 0, 9);
  const double step = bbox_diagonal(p) / 300.0;
  std::set<std::array<long, 3>> cells;
  Points rounded;
  for (std::size_t i = 0; i < p.size(); i += 3) {
    const std::array<long, 3> c{std::lround(p[i] / step), std::lround(p[i + 1] / step),
                                std::lround(p[i + 2] / step)};
    if (!cells.insert(c).second) continue;
    for (long x : c) rounded.push_back(double(x) * step);
  }
  const Case c = make_case("bunny00.off 20k rounded to a grid", rounded);
  assert_int_equal(rounded.size() / 3, 17944);
  assert_true(c.run.stats.smoothing_passes >= 1);
  expect_watertight(c, 0);
}

// Elephant at 50k points with noise of 0.05 % of the diagonal (about a quarter of the
// nearest-neighbour distance), sample 33: the smoothing pulled the two sheets of thin parts
// together, and far fewer of their points than of a thin ear's sat exactly where twice their
// move led: 38 boundary edges and genus 5, both with every smoothed point kept and with only
// that probe looking for the other sheet.
void elephant_noisy_thin_parts_closed(void **) {
  const Case c = make_case("elephant.off 50k, noise 0.05 %, sample 33",
                           sample_of("elephant.off", 50000, 0.0005, 33));
  expect_watertight(c, 3);
}

// Fandisk at 20k points with Gaussian noise of 0.7 nearest-neighbour distances on the half of
// it beyond its median x (a second scanner, farther off). It closes after two smoothing passes.
// One pass leaves scatter that is no flatter at 20 points than at 10, so the test of noise in
// part that looks for that step on the caller's points must not look for it on the smoothed
// copy: there it stopped the smoothing after one pass, and samples 5 and 2 kept 17 and 178
// boundary edges. (Samples 1 and 3 keep 72 and 9 either way: noise that heavy on half a cloud
// is near what the smoothing can take.)
Points half_noisy_fandisk(std::uint64_t seed) {
  Points p = sample_of("fandisk.off", 20000, 0, seed);
  std::vector<double> xs;
  for (std::size_t i = 0; i < p.size(); i += 3) xs.push_back(p[i]);
  std::nth_element(xs.begin(), xs.begin() + std::ptrdiff_t(xs.size() / 2), xs.end());
  add_noise_beyond(p, xs[xs.size() / 2], 0.7 * median_nearest_distance(p), seed);
  return p;
}

void fandisk_half_noisy_closed(void **) {
  const Case c = make_case("fandisk.off 20k, noise 0.7 spacings on half", half_noisy_fandisk(5));
  MOA_EXPECT(contract_failure(c));
  MOA_EXPECT(closed_failure(c, 0, 0.999));
}

}  // namespace

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(elephant_closed),
      cmocka_unit_test(elephant_point_beside_crease_taken_in),
      cmocka_unit_test(elephant_vertices_spike_cleared),
      cmocka_unit_test(vertex_sets_keep_no_narrow_faces),
      cmocka_unit_test(ball_scan_closed),
      cmocka_unit_test(ball_scan_closed_unsmoothed),
      cmocka_unit_test(knot2_closed),
      cmocka_unit_test(fandisk_closed),
      cmocka_unit_test(fandisk_corner_hole_patched),
      cmocka_unit_test(homer_inside_out_patch_turned),
      cmocka_unit_test(homer_patch_held_by_several_edges_turned),
      cmocka_unit_test(homer_finger_bridges_cut),
      cmocka_unit_test(homer_four_edge_waist_cut),
      cmocka_unit_test(homer_island_in_hole_dropped),
      cmocka_unit_test(homer_vertices_mouth_tunnel_cut),
      cmocka_unit_test(grid_rounded_bunny_closed),
      cmocka_unit_test(elephant_noisy_thin_parts_closed),
      cmocka_unit_test(fandisk_half_noisy_closed),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
