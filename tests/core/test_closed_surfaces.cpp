// Property tests on well-sampled closed surfaces: the contract (C1-C6), consistent stats, and a
// closed result of the true genus that uses every point.
#include "core/kd_tree.hpp"
#include "core/neighbors.hpp"
#include "core/point_set.hpp"
#include "core_harness.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

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

Points shuffled(Points p, std::uint64_t seed) {
  shuffle(p, seed);
  return p;
}

const Case &fibonacci_sphere_case() {
  static const Case c = make_case("Fibonacci sphere", shuffled(fibonacci_sphere(2000), 11));
  return c;
}

const Case &random_sphere_case() {
  static const Case c = make_case("uniform random sphere", sphere_random(1500, 1.0, 12));
  return c;
}

const Case &torus_grid_case() {
  // Every grid cell is an isosceles trapezoid: four co-circular points.
  static const Case c = make_case("regular torus grid", shuffled(torus_grid(60, 24, 1.0, 0.4), 13));
  return c;
}

const Case &genus2_case() {
  static const Case c = make_case("genus-2 surface", shuffled(genus_surface(2, 0.1, 14), 14));
  return c;
}

const Case &genus3_case() {
  static const Case c = make_case("genus-3 surface", shuffled(genus_surface(3, 0.11, 15), 15));
  return c;
}

const Case &cube_case() {
  // Sharp edges and corners, and square grids full of ties on every face.
  static const Case c = make_case("cube grid", shuffled(cube_grid(14), 16));
  return c;
}

const Case &box_case() {
  // A flat box with a corner at the origin, on a grid: its faces meet at exactly 90 degrees,
  // and a triangle joining two of them across an edge was refused as turning further than
  // that whenever rounding made the cosine of the bend a hair below cos(90°): 5,160 triangles
  // came out where the closed box has 5,600.
  static const Case c = make_case("box grid", shuffled(box_grid(2.0, 1.0, 0.5, 0.05), 20));
  return c;
}

// A closed cylinder of radius 1 and height 2 on grids: `around` points round each of `rows`
// + 1 rings along the side, and on each cap `rings` - 1 rings inside the rim (the rim's own
// points are the side's end rings) and the centre.
Points cylinder_grid(std::size_t around, std::size_t rows, std::size_t rings) {
  Points p;
  const double pi = 3.14159265358979323846;
  for (std::size_t i = 0; i < around; ++i) {
    const double a = 2 * pi * double(i) / double(around), c = std::cos(a), s = std::sin(a);
    for (std::size_t k = 0; k <= rows; ++k)
      p.insert(p.end(), {c, s, 2.0 * double(k) / double(rows)});
    for (std::size_t r = 1; r < rings; ++r)
      for (double z : {0.0, 2.0}) {
        const double f = double(r) / double(rings);
        p.insert(p.end(), {f * c, f * s, z});
      }
  }
  p.insert(p.end(), {0, 0, 0, 0, 0, 2});
  return p;
}

const Case &cylinder_case() {
  // The cap and the side grow as two pieces up to the rim, and the strip of one cell between
  // them is bounded by two loops as wide as the rim: borders by their width. They are zipped
  // together (loop_pieces.cpp); before that, 192 boundary edges along both rims.
  static const Case c = make_case("cylinder grid", shuffled(cylinder_grid(48, 20, 8), 21));
  return c;
}

// Thin walls, sampled at random: the far sheet lies about two spacings away, inside a point's
// list of neighbours. The noise estimate took it for scatter and smoothed the two sheets into
// one; and on the raw points a quarter of a list on the far sheet made it about as thick as
// wide, so that its fitted plane sometimes stood across the wall and the normal test refused
// the wall's own triangles (neighbors.cpp).
const Case &thin_plate_case() {
  // 1 x 1 x 0.022, 20,000 points 0.01 apart: 593 boundary edges when smoothed; on the raw
  // points without the far-sheet rule, 13.
  static const Case c = make_case("thin plate", plate_samples(1.0, 0.022, 20000, 22));
  return c;
}

const Case &pipe_case() {
  // Wall 0.07, 12,000 points 0.033 apart: 470 boundary edges in 2 loops when smoothed; on the
  // raw points without the far-sheet rule, 3.
  static const Case c = make_case("thin-walled pipe", pipe_samples(0.07, 1.0, 12000, 23));
  return c;
}

const Case &drilled_plate_case() {
  // Bores 0.1 across and 0.1 deep, 12,000 points about 0.014 apart: each bore's mouth is a
  // right-angled edge, each its own tunnel; none may be capped or cut. (Bores 0.04 across,
  // under three spacings, are closed as the README's known limits say: genus 1 here.)
  static const Case c = make_case("drilled plate", drilled_plate_samples(0.05, 12000, 24));
  return c;
}

// A regular tetrahedron sampled at random: six edges of 70.5 degrees, sharper than the cube's.
Points tetrahedron_samples(std::size_t n, std::uint64_t seed) {
  const std::vector<double> v = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1};
  const std::vector<std::uint32_t> t = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
  return sample_mesh(v, t, n, seed);
}

// A cone of height 1.5 on a unit disc, sampled at random: the rim is an edge of 56 degrees.
Points cone_samples(std::size_t n, std::uint64_t seed) {
  const std::uint32_t m = 256;
  std::vector<double> v = {0, 0, 1.5, 0, 0, 0};  // apex, centre of the base
  std::vector<std::uint32_t> t;
  for (std::uint32_t i = 0; i < m; ++i) {
    const double a = 2 * M_PI * double(i) / double(m);
    v.insert(v.end(), {std::cos(a), std::sin(a), 0.0});
    const std::uint32_t p = 2 + i, q = 2 + (i + 1) % m;
    t.insert(t.end(), {0, p, q, 1, q, p});
  }
  return sample_mesh(v, t, n, seed);
}

const Case &cone_case() {
  // Sample 6: the side and the base grew apart along a quarter of the rim, leaving a strip 45
  // boundary edges round, a border by the width loop_width saw from the strip's ends.
  static const Case c = make_case("random cone samples", cone_samples(5000, 6));
  return c;
}

const Case &cone_take_in_case() {
  // Sample 3: the loop module patched a hole at the rim with faces that covered 3 points none
  // of whose nearest neighbours was a corner: the take-in never saw those faces, and every
  // split it tried crossed them.
  static const Case c = make_case("random cone samples, seed 3", cone_samples(5000, 3));
  return c;
}

const Case &tetrahedron_case() {
  // Sample 6: holes along the edges that no widening by rims closed (6 boundary edges before
  // the last resort cleared the stars of a hole's vertices).
  static const Case c = make_case("random tetrahedron samples", tetrahedron_samples(20000, 6));
  return c;
}

// A prism 2 long on an equilateral triangle of circumradius 1, sampled at random: three long
// edges of 60 degrees, and the six of the ends at right angles.
Points triangular_prism_samples(std::size_t n, std::uint64_t seed) {
  std::vector<double> v;
  for (double z : {-1.0, 1.0})
    for (int k = 0; k < 3; ++k) {
      const double a = 2 * M_PI * k / 3;
      v.insert(v.end(), {std::cos(a), std::sin(a), z});
    }
  std::vector<std::uint32_t> t = {0, 2, 1, 3, 4, 5};
  for (std::uint32_t k = 0; k < 3; ++k) {
    const std::uint32_t a = k, b = (k + 1) % 3;
    t.insert(t.end(), {a, b, b + 3, a, b + 3, a + 3});
  }
  return sample_mesh(v, t, n, seed);
}

// A prism 3 long whose cross-section is a blade: an edge of 40 degrees at x = 0 and two of 70
// at x = 1, sampled at random.
Points blade_samples(std::size_t n, std::uint64_t seed) {
  const double half = std::tan(20 * M_PI / 180);
  std::vector<double> v;
  for (double z : {-1.5, 1.5}) v.insert(v.end(), {0, 0, z, 1, half, z, 1, -half, z});
  std::vector<std::uint32_t> t = {0, 2, 1, 3, 4, 5};
  for (std::uint32_t k = 0; k < 3; ++k) {
    const std::uint32_t a = k, b = (k + 1) % 3;
    t.insert(t.end(), {a, b, b + 3, a, b + 3, a + 3});
  }
  return sample_mesh(v, t, n, seed);
}

const Case &tetrahedron_take_in_case() {
  // Sample 4: one point whose neighbours were all out stayed out before the take-in retried
  // the points next to one it had just taken in.
  static const Case c = make_case("random tetrahedron samples, seed 4", tetrahedron_samples(20000, 4));
  return c;
}

const Case &sphere_duplicates_case() {
  // A Fibonacci sphere with every tenth point given twice: the copies must be merged.
  Points p = fibonacci_sphere(1000);
  for (std::size_t i = 0; i < 1000; i += 10) p.insert(p.end(), p.begin() + 3 * i, p.begin() + 3 * i + 3);
  static const Case c = make_case("Fibonacci sphere with duplicates", shuffled(p, 17), 100);
  return c;
}

const Case &noisy_torus_case() {
  // Uniform random samples with Gaussian noise of 0.02 % of the diagonal, as scanners deliver:
  // fronts meeting at noisy steps must still join the right way round and close.
  Points p = torus_random(6000, 1.0, 0.35, 18);
  add_noise(p, 0.0002, 18);
  static const Case c = make_case("noisy uniform torus", p);
  return c;
}

const Case &noisy_genus2_case() {
  Points p = shuffled(genus_surface(2, 0.05, 19), 19);
  add_noise(p, 0.0002, 19);
  static const Case c = make_case("noisy genus-2 surface", p);
  return c;
}

const Case &density_gradient_case() {
  // Uniform random samples of a torus thinned to a density ten times higher at one end than at
  // the other (about 12,000 of 30,000 points kept): the spacing, the sphere and the hole width
  // all follow the local spacing, so nothing is tuned to one density.
  static const Case c = make_case("torus with a tenfold density gradient",
                                  density_gradient(torus_random(30000, 1.0, 0.35, 24), 10.0, 24));
  return c;
}

// Anisotropic sampling: uniform samples of a torus stretched threefold along an oblique axis,
// so the points lie three times farther apart along that axis than across it (as where a
// scanner's lines lie farther apart than its samples along a line, or in the vertices of a mesh
// of long, thin triangles).
// Every spacing-relative default must still see one closed surface of genus 1.
const Case &stretched_torus_case() {
  // Built once: the cloud is made inside the initializer, not again on every call.
  static const Case c = [] {
    Points p = torus_random(8000, 1.0, 0.35, 27);
    const double d[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3};  // the axis, of unit length
    constexpr double kStretch = 3.0;
    for (std::size_t i = 0; i < p.size(); i += 3) {
      const double along = p[i] * d[0] + p[i + 1] * d[1] + p[i + 2] * d[2];
      for (int a = 0; a < 3; ++a) p[i + a] += (kStretch - 1) * along * d[a];
    }
    return make_case("torus stretched threefold along an oblique axis", p);
  }();
  return c;
}

// Survey data as LAS files hold it: metres far from the origin (a UTM-like offset), rounded to a
// fixed step. The coordinates differ from each other only in their last seven or eight digits,
// the rounding lines points up and makes exact duplicates, and every one must merge.
const Case &survey_coordinates_case() {
  // Built once: the cloud is made inside the initializer, not again on every call.
  static const Case c = [] {
    const Points torus = torus_random(6000, 1.0, 0.35, 25);
    const double offset[3] = {512345.0, 6123456.0, 87.0};
    const double step = 0.012;  // a quarter of the point spacing
    Points p;
    std::set<std::array<long long, 3>> seen;
    std::size_t duplicates = 0;
    for (std::size_t i = 0; i < torus.size(); i += 3) {
      std::array<long long, 3> cell;
      for (int a = 0; a < 3; ++a) cell[a] = std::llround((torus[i + a] + offset[a]) / step);
      duplicates += !seen.insert(cell).second;
      for (int a = 0; a < 3; ++a) p.push_back(double(cell[a]) * step);
    }
    return make_case("torus in survey coordinates", p, duplicates);
  }();
  return c;
}

const Case &contour_stack_case() {
  // A torus cut by 30 parallel planes, three points per plane gap along each cut, as CT and MRI
  // segmentations deliver: before the spacing measured the gaps between cuts (neighbors.cpp),
  // the spheres of segments along a cut held few points of the next cut, and 85 boundary edges
  // stayed in 3 pieces.
  static const Case c = make_case("torus contour stack", torus_contour_stack(3));
  return c;
}

const Case &fine_contour_stack_case() {
  // Five points per plane gap: the first neighbour across a cut ranks about tenth, and with
  // lists of 20 the spheres held too few points of the next cut (226 boundary edges in 8
  // pieces, genus 2) before the lists of such a cloud were lengthened.
  static const Case c = make_case("torus contour stack, 5 points per gap", torus_contour_stack(5));
  return c;
}

const Case &sphere_contour_stack_case() {
  // A sphere cut by 60 planes, three points per plane gap: the first neighbour across a cut
  // ranks about sixth, and with lists of 20 the cuts near the poles, which lie several gaps
  // apart on the surface, were not joined (186 boundary edges in 9 pieces, genus 1) before such
  // a cloud's lists were lengthened from that rank on (8 before) and the lists near the poles
  // given points across.
  static const Case c = make_case("sphere contour stack", sphere_contour_stack(60, 3, 1));
  return c;
}

const Case &cylinder_contour_stack_case() {
  // A cylinder cut by 40 planes across its axis: its flat ends get no points but their rims,
  // loops 2 wide (50 spacings) that the width rule keeps open as borders; they lie in one cut
  // each and are capped in their plane (754 boundary edges in 2 loops before).
  static const Case c = make_case("cylinder contour stack", cylinder_contour_stack(40, 3, 1));
  return c;
}

const Case &dense_cylinder_contour_stack_case() {
  // Eight cuts, 20 points per plane gap along each: triangles across a gap are needles (3
  // degrees at one end), and neighbours side by side in a fan were taken for a duplicated fan
  // (the vertex-fold test): 1,189 boundary edges in 14 pieces, 148 points left out, before.
  static const Case c = make_case("dense cylinder contour stack", cylinder_contour_stack(8, 20, 1));
  return c;
}

// Marching-cubes vertices of a segmented CT volume, slices four times farther apart than the
// voxels in them (grid 96 x 96 x 24 over [-1, 1]^3). Where the surface runs across the slices
// the only points are on the slices' contours, and two pieces grew apart along the gap
// between two contours: the neighbour lists of the contours' points, filled by their own
// contour and the next one on their side, held none of the contour across, so the pieces'
// loops were not found side by side (torus: 934 boundary edges in 2 pieces; bumpy ellipsoid:
// 532 in 2). On the torus the zip by the shorter side across then stalled at a vertex of one
// contour standing out of its slice, and what was zipped in part left 38 boundary edges.
const int kCtGrid[3] = {96, 96, 24};

double ct_torus(double x, double y, double z) {
  const double ring = std::sqrt(x * x + y * y) - 0.6;
  return ring * ring + z * z - 0.25 * 0.25;
}

double ct_organ(double x, double y, double z) {
  return (x / 0.9) * (x / 0.9) + (y / 0.5) * (y / 0.5) + (z / 0.4) * (z / 0.4) - 1 +
         0.08 * std::sin(7 * x) * std::cos(5 * y);
}

const Case &ct_torus_case() {
  static const Case c = make_case("torus, marching-cubes vertices of a CT stack",
                                  shuffled(marching_cubes_vertices(ct_torus, kCtGrid), 71));
  return c;
}

// Slices six times farther apart (96 x 96 x 16): the contours on either side of the gap at the
// torus's equators lie 6-7 spacings apart, beyond the hole width; two loops running side by
// side along their whole length are zipped up to twice that (912 boundary edges in 2 pieces
// before).
const int kCoarseCtGrid[3] = {96, 96, 16};

const Case &ct_coarse_torus_case() {
  static const Case c = make_case("torus, marching-cubes vertices of a coarse CT stack",
                                  shuffled(marching_cubes_vertices(ct_torus, kCoarseCtGrid), 79));
  return c;
}

const Case &ct_organ_case() {
  static const Case c = make_case("bumpy ellipsoid, marching-cubes vertices of a CT stack",
                                  shuffled(marching_cubes_vertices(ct_organ, kCtGrid), 73));
  return c;
}

// A box 2 x 1 x 1.5 scanned from three cameras round it, 17 degrees (0.3 rad) alternately below
// and above it: its top is seen by one camera alone, at a grazing angle, in rows 3.4 times
// farther apart than the points along them, while the cloud as a whole is no contour stack.
// Before such lined regions were measured across their rows (neighbors.cpp), the segments'
// spheres along a row did not reach the next one: 175 boundary edges in one loop on the top.
const Case &scanned_box_case() {
  static const Case c =
      make_case("box, range scan from three views", scanned_box(1, 0.5, 0.75, 3, 100, 0.3));
  return c;
}

}  // namespace

MOA_CONTRACT_TESTS(fibonacci_sphere)
MOA_CONTRACT_TESTS(random_sphere)
MOA_CONTRACT_TESTS(torus_grid)
MOA_CONTRACT_TESTS(genus2)
MOA_CONTRACT_TESTS(genus3)
MOA_CONTRACT_TESTS(tetrahedron)
MOA_CONTRACT_TESTS(cone)
MOA_CONTRACT_TESTS(cone_take_in)
MOA_CONTRACT_TESTS(cube)
MOA_CONTRACT_TESTS(box)
MOA_CONTRACT_TESTS(cylinder)
MOA_CONTRACT_TESTS(thin_plate)
MOA_CONTRACT_TESTS(pipe)
MOA_CONTRACT_TESTS(drilled_plate)
MOA_CONTRACT_TESTS(sphere_duplicates)
MOA_CONTRACT_TESTS(noisy_torus)
MOA_CONTRACT_TESTS(noisy_genus2)
MOA_CONTRACT_TESTS(density_gradient)
MOA_CONTRACT_TESTS(survey_coordinates)
MOA_CONTRACT_TESTS(contour_stack)
MOA_CONTRACT_TESTS(fine_contour_stack)
MOA_CONTRACT_TESTS(sphere_contour_stack)
MOA_CONTRACT_TESTS(cylinder_contour_stack)
MOA_CONTRACT_TESTS(dense_cylinder_contour_stack)
MOA_CONTRACT_TESTS(ct_torus)
MOA_CONTRACT_TESTS(ct_organ)
MOA_CONTRACT_TESTS(ct_coarse_torus)
MOA_CONTRACT_TESTS(stretched_torus)
MOA_CONTRACT_TESTS(scanned_box)

static void test_fibonacci_sphere_closed_genus0(void **) { MOA_EXPECT(closed_failure(fibonacci_sphere_case(), 0)); }
static void test_random_sphere_closed_genus0(void **) { MOA_EXPECT(closed_failure(random_sphere_case(), 0)); }
static void test_torus_grid_closed_genus1(void **) { MOA_EXPECT(closed_failure(torus_grid_case(), 1)); }
static void test_genus2_closed_genus2(void **) { MOA_EXPECT(closed_failure(genus2_case(), 2)); }
static void test_genus3_closed_genus3(void **) { MOA_EXPECT(closed_failure(genus3_case(), 3)); }
static void test_cube_closed_genus0(void **) { MOA_EXPECT(closed_failure(cube_case(), 0)); }
static void test_box_closed_genus0(void **) { MOA_EXPECT(closed_failure(box_case(), 0)); }
static void test_cylinder_closed_genus0(void **) { MOA_EXPECT(closed_failure(cylinder_case(), 0)); }
static void test_thin_plate_closed_genus0(void **) { MOA_EXPECT(closed_failure(thin_plate_case(), 0)); }
static void test_pipe_closed_genus1(void **) { MOA_EXPECT(closed_failure(pipe_case(), 1)); }
static void test_drilled_plate_closed_genus5(void **) {
  MOA_EXPECT(closed_failure(drilled_plate_case(), 5));
}
// Clearing a hole's stars leaves its vertices to the take-in, which places nearly all again.
static void test_tetrahedron_closed_genus0(void **) {
  MOA_EXPECT(closed_failure(tetrahedron_case(), 0, 0.999));
}
static void test_cone_closed_genus0(void **) { MOA_EXPECT(closed_failure(cone_case(), 0, 0.999)); }
static void test_cone_take_in_closed_genus0(void **) {
  MOA_EXPECT(closed_failure(cone_take_in_case(), 0));
}
static void test_tetrahedron_take_in_closed_genus0(void **) {
  MOA_EXPECT(closed_failure(tetrahedron_take_in_case(), 0));
}
// Holes at a crease sharper than a right angle whose every patch crossed faces folded over from
// the crease beneath them, each closed by the last patch once it took those faces away with
// the faces around the hole (LoopFiller::excise_crossed_and_patch): 32 boundary edges in one
// loop on the cone, 3 on the tetrahedron and 5 on the prism before.
static void test_folds_at_sharp_creases_closed_genus0(void **) {
  const std::pair<Case, double> cases[] = {
      {make_case("random cone samples, seed 1", cone_samples(10000, 1)), 0.999},
      {make_case("random tetrahedron samples, seed 3", tetrahedron_samples(20000, 3)), 1.0},
      {make_case("random 60-degree prism samples, seed 1", triangular_prism_samples(20000, 1)),
       1.0}};
  for (const auto &[c, min_used] : cases) {
    MOA_EXPECT(contract_failure(c));
    MOA_EXPECT(determinism_failure(c));
    MOA_EXPECT(closed_failure(c, 0, min_used));
  }
}

// A cone whose base grew inside out relative to its side (joined by one edge, open along the
// rest of the rim, where the gap was mostly too wide for facing rims to be found across it):
// the inside-out repair turned it only once its 19 contradicting pairs outnumbered the 3 votes
// for it by far, not a share of its rim (377 boundary edges and genus 2 before).
static void test_cone_base_inside_out_turned(void **) {
  const Case c = make_case("random cone samples, seed 7", cone_samples(5000, 7));
  MOA_EXPECT(contract_failure(c));
  MOA_EXPECT(closed_failure(c, 0));
}

// A 40-degree blade whose far side Algorithm 1 carried round the blade inside out, tied to the
// rest along the whole blade (no small cut holds it): the rays' parity turned it
// (parity_orientation.cpp). 1,073 boundary edges and genus 3 before. (No second run with one
// thread: each face's vote depends on the face alone, and this file is among the longest
// under the sanitizers.)
static void test_blade_side_turned_by_ray_parity(void **) {
  const Case c = make_case("random 40-degree blade samples, seed 1", blade_samples(20000, 1));
  MOA_EXPECT(contract_failure(c));
  MOA_EXPECT(closed_failure(c, 0, 0.999));
}

// The 12 points (0, +-a, +-b) and their cyclic permutations.
static Points cyclic_corners(double a, double b) {
  Points p;
  for (double x : {-a, a})
    for (double y : {-b, b}) p.insert(p.end(), {0, x, y, x, y, 0, y, 0, x});
  return p;
}

// The 12 corners of a regular icosahedron: cyclic permutations of (0, +-1, +-phi).
static Points icosahedron_corners() { return cyclic_corners(1, (1 + std::sqrt(5.0)) / 2); }

// The 20 corners of a regular dodecahedron: a cube's 8 and cyclic permutations of
// (0, +-1/phi, +-phi).
static Points dodecahedron_corners() {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  Points p;
  for (int i = 0; i < 8; ++i)
    p.insert(p.end(), {i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  const Points rest = cyclic_corners(1 / phi, phi);
  p.insert(p.end(), rest.begin(), rest.end());
  return p;
}

// Polyhedra given by their corners alone, the first thing many users try: each face a polygon
// of a few points, the edges at most right angles. The faces grown first met the others across
// edges sharper than the fill passes reach (square pyramid 63 degrees, triangular prism 60,
// box 90): a face stayed open on the box, the pyramid and the prism. The dodecahedron's 20
// corners gave 1 triangle while lists holding the whole cloud served as neighbourhoods, for the
// normal test and the loop module's tangles (neighbors.hpp, lists_hold_half). The corners of
// a flat box (1 x 4 x 4) or a slab (1 x 1 x 0.3) gave one square of 4 points: the corners
// across the thin side passed for copies of one another (near_duplicates.cpp).
static Points box_corners(double dx, double dy, double dz) {
  Points p;
  for (int i = 0; i < 8; ++i) p.insert(p.end(), {dx * (i & 1), dy * (i >> 1 & 1), dz * (i >> 2)});
  return p;
}
static void test_polyhedron_corners_closed_genus0(void **) {
  Points pyramid = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1}, prism;
  for (double z : {0.0, 2.0}) prism.insert(prism.end(), {0, 0, z, 1, 0, z, 0.5, 0.8, z});
  const std::vector<std::pair<const char *, Points>> shapes = {
      {"box corners", box_corners(1, 2, 3)},
      {"flat box corners", box_corners(1, 4, 4)},
      {"slab corners", box_corners(1, 1, 0.3)},
      {"square pyramid corners", pyramid},
      {"triangular prism corners", prism},
      {"regular tetrahedron corners", {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1}},
      {"octahedron corners", {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1}},
      {"icosahedron corners", icosahedron_corners()},
      {"dodecahedron corners", dodecahedron_corners()}};
  for (const auto &[name, points] : shapes) {
    const Case c = make_case(name, points);
    MOA_EXPECT(contract_failure(c));
    MOA_EXPECT(closed_failure(c, 0));
  }
}
// Clouds of a few dozen points, where each point's list holds at least half of the cloud and
// reaches round the object: 280 random samples of a sphere with 7 to 41 points. 27 came out
// open or on a few of their points (21 points: 5 triangles) while the normal test judged by
// the planes of such lists; 4 of them (12-16 points) stayed so until their first faces no
// longer counted as a tangle (neighbors.hpp, lists_hold_half).
static void test_tiny_spheres_closed_genus0(void **) {
  for (std::size_t n = 7; n <= 41; ++n)
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      const Case c =
          make_case("sphere, " + std::to_string(n) + " random points, seed " + std::to_string(seed),
                    sphere_random(n, 1.0, seed));
      MOA_EXPECT(contract_failure(c));
      MOA_EXPECT(closed_failure(c, 0));
    }
}
// A tube of radius 1 given by `rings` rings of `per_ring` points spread over `length`, with a
// point at the centre of each end if `centres`: a coarse CAD tessellation's vertices.
static Points ring_tube(std::size_t per_ring, std::size_t rings, double length, bool centres) {
  Points p;
  for (std::size_t r = 0; r < rings; ++r)
    for (std::size_t j = 0; j < per_ring; ++j) {
      const double a = 2 * M_PI * double(j) / double(per_ring);
      p.insert(p.end(), {std::cos(a), std::sin(a), length * double(r) / double(rings - 1)});
    }
  if (centres) p.insert(p.end(), {0, 0, 0, 0, 0, length});
  return p;
}

// Tubes given by two rings 4 apart (15-41 times the spacing along a ring). The planes fitted
// to the lists (one ring, or the whole cloud) follow the wall nowhere, the normal test refused
// every triangle, and the result was empty (0 of 48-130 points used). Algorithm 1 now tries
// again without that test: closed cylinders.
static void test_far_rings_closed_genus0(void **) {
  std::vector<std::pair<std::string, Points>> tubes;
  for (std::size_t per_ring : {24, 32, 48, 64})
    for (bool centres : {false, true})
      tubes.push_back({std::to_string(per_ring) + " points per ring, 2 rings 4 apart" +
                           (centres ? ", end centres" : ""),
                       ring_tube(per_ring, 2, 4.0, centres)});
  for (const auto &[name, points] : tubes) {
    const Case c = make_case("tube, " + name, points);
    MOA_EXPECT(contract_failure(c));
    MOA_EXPECT(closed_failure(c, 0));
  }
}
static void test_sphere_duplicates_closed_genus0(void **) {
  MOA_EXPECT(closed_failure(sphere_duplicates_case(), 0));
}

static void test_scanned_box_closed_genus0(void **) {
  MOA_EXPECT(closed_failure(scanned_box_case(), 0));
}
static void test_noisy_torus_closed_genus1(void **) { MOA_EXPECT(closed_failure(noisy_torus_case(), 1)); }
static void test_noisy_genus2_closed_genus2(void **) { MOA_EXPECT(closed_failure(noisy_genus2_case(), 2)); }
static void test_density_gradient_closed_genus1(void **) {
  MOA_EXPECT(closed_failure(density_gradient_case(), 1));
}
static void test_stretched_torus_closed_genus1(void **) {
  MOA_EXPECT(closed_failure(stretched_torus_case(), 1));
}
static void test_survey_coordinates_closed_genus1(void **) {
  MOA_EXPECT(closed_failure(survey_coordinates_case(), 1));
}
static void test_contour_stack_closed_genus1(void **) { MOA_EXPECT(closed_failure(contour_stack_case(), 1)); }
static void test_fine_contour_stack_closed_genus1(void **) {
  MOA_EXPECT(closed_failure(fine_contour_stack_case(), 1));
}
static void test_sphere_contour_stack_closed_genus0(void **) {
  MOA_EXPECT(closed_failure(sphere_contour_stack_case(), 0));
}
static void test_cylinder_contour_stack_closed_genus0(void **) {
  MOA_EXPECT(closed_failure(cylinder_contour_stack_case(), 0));
}
static void test_dense_cylinder_contour_stack_closed_genus0(void **) {
  MOA_EXPECT(closed_failure(dense_cylinder_contour_stack_case(), 0));
}
static void test_ct_torus_closed_genus1(void **) { MOA_EXPECT(closed_failure(ct_torus_case(), 1)); }
static void test_ct_organ_closed_genus0(void **) { MOA_EXPECT(closed_failure(ct_organ_case(), 0)); }
static void test_ct_coarse_torus_closed_genus1(void **) {
  MOA_EXPECT(closed_failure(ct_coarse_torus_case(), 1));
}

// Near the poles of a contour stack the next cut can lie farther than a list reaches along a
// point's own cut: every list must still hold a point of another cut (neighbors.cpp), or the
// spheres of the segments there hold nothing to join the cuts with.
static void test_contour_lists_reach_across(void **) {
  const std::size_t slices = 60;
  const Points stack = sphere_contour_stack(slices, 2.5, 1);
  moa::PointSet points = moa::prepare_points(stack.data(), stack.size() / 3);
  moa::KdIndex index(points.work);
  const moa::Neighborhood nb = moa::compute_neighbors(index, 20, [](double) {});
  assert_true(nb.lined);
  // The cuts by height along the axis, in the work frame (an affine image of the input).
  const moa::Vec3 axis{1, 0.3, 0.2};
  std::vector<double> height(points.work.size());
  for (std::size_t i = 0; i < height.size(); ++i) height[i] = moa::dot(points.work[i], axis);
  const auto [lo, hi] = std::minmax_element(height.begin(), height.end());
  const double gap = (*hi - *lo) / double(slices - 1);
  std::size_t without = 0;
  for (uint32_t i = 0; i < height.size(); ++i) {
    const uint32_t *list = nb.of(i);
    bool across = false;
    for (unsigned j = 0; j < nb.k && !across; ++j)
      across = std::fabs(height[list[j]] - height[i]) > 0.5 * gap;
    without += !across;
  }
  if (without > 0)
    fail_msg("%zu of %zu lists hold no point of another cut", without, height.size());
}

int main(void) {
  const struct CMUnitTest tests[] = {
      MOA_CONTRACT_ENTRIES(fibonacci_sphere), cmocka_unit_test(test_fibonacci_sphere_closed_genus0),
      MOA_CONTRACT_ENTRIES(random_sphere),    cmocka_unit_test(test_random_sphere_closed_genus0),
      MOA_CONTRACT_ENTRIES(torus_grid),       cmocka_unit_test(test_torus_grid_closed_genus1),
      MOA_CONTRACT_ENTRIES(genus2),           cmocka_unit_test(test_genus2_closed_genus2),
      MOA_CONTRACT_ENTRIES(genus3),           cmocka_unit_test(test_genus3_closed_genus3),
      MOA_CONTRACT_ENTRIES(cube),             cmocka_unit_test(test_cube_closed_genus0),
      MOA_CONTRACT_ENTRIES(box),              cmocka_unit_test(test_box_closed_genus0),
      MOA_CONTRACT_ENTRIES(cylinder),         cmocka_unit_test(test_cylinder_closed_genus0),
      MOA_CONTRACT_ENTRIES(thin_plate),       cmocka_unit_test(test_thin_plate_closed_genus0),
      MOA_CONTRACT_ENTRIES(pipe),             cmocka_unit_test(test_pipe_closed_genus1),
      MOA_CONTRACT_ENTRIES(drilled_plate),
      cmocka_unit_test(test_drilled_plate_closed_genus5),
      MOA_CONTRACT_ENTRIES(tetrahedron),      cmocka_unit_test(test_tetrahedron_closed_genus0),
      cmocka_unit_test(test_tetrahedron_take_in_closed_genus0),
      cmocka_unit_test(test_folds_at_sharp_creases_closed_genus0),
      cmocka_unit_test(test_cone_base_inside_out_turned),
      cmocka_unit_test(test_blade_side_turned_by_ray_parity),
      cmocka_unit_test(test_polyhedron_corners_closed_genus0),
      cmocka_unit_test(test_tiny_spheres_closed_genus0),
      cmocka_unit_test(test_far_rings_closed_genus0),
      MOA_CONTRACT_ENTRIES(cone),             cmocka_unit_test(test_cone_closed_genus0),
      MOA_CONTRACT_ENTRIES(cone_take_in),     cmocka_unit_test(test_cone_take_in_closed_genus0),
      MOA_CONTRACT_ENTRIES(sphere_duplicates), cmocka_unit_test(test_sphere_duplicates_closed_genus0),
      MOA_CONTRACT_ENTRIES(noisy_torus),      cmocka_unit_test(test_noisy_torus_closed_genus1),
      MOA_CONTRACT_ENTRIES(noisy_genus2),     cmocka_unit_test(test_noisy_genus2_closed_genus2),
      MOA_CONTRACT_ENTRIES(density_gradient), cmocka_unit_test(test_density_gradient_closed_genus1),
      MOA_CONTRACT_ENTRIES(survey_coordinates),
      cmocka_unit_test(test_survey_coordinates_closed_genus1),
      MOA_CONTRACT_ENTRIES(stretched_torus),
      cmocka_unit_test(test_stretched_torus_closed_genus1),
      MOA_CONTRACT_ENTRIES(contour_stack),    cmocka_unit_test(test_contour_stack_closed_genus1),
      MOA_CONTRACT_ENTRIES(fine_contour_stack), cmocka_unit_test(test_fine_contour_stack_closed_genus1),
      MOA_CONTRACT_ENTRIES(sphere_contour_stack),
      cmocka_unit_test(test_sphere_contour_stack_closed_genus0),
      cmocka_unit_test(test_contour_lists_reach_across),
      MOA_CONTRACT_ENTRIES(cylinder_contour_stack),
      cmocka_unit_test(test_cylinder_contour_stack_closed_genus0),
      MOA_CONTRACT_ENTRIES(dense_cylinder_contour_stack),
      cmocka_unit_test(test_dense_cylinder_contour_stack_closed_genus0),
      MOA_CONTRACT_ENTRIES(ct_torus),
      cmocka_unit_test(test_ct_torus_closed_genus1),
      MOA_CONTRACT_ENTRIES(ct_organ),
      cmocka_unit_test(test_ct_organ_closed_genus0),
      MOA_CONTRACT_ENTRIES(ct_coarse_torus),
      cmocka_unit_test(test_ct_coarse_torus_closed_genus1),
      MOA_CONTRACT_ENTRIES(scanned_box),
      cmocka_unit_test(test_scanned_box_closed_genus0),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
