// Property tests on inputs that are not well sampled: noise, random clumps and gaps, sheets
// closer than the spacing, a slab thinner than the spacing, sharp random-sampled edges, stray
// points in the volume around a surface, a cloud given twice, two rings threaded close through
// each other, surfaces no manifold mesh can follow (one-sided, or crossing itself). The
// reconstruction may leave holes here, but the contract C1-C6 holds on every input.
#include "core_harness.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

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

Points noisy(Points p, double fraction, std::uint64_t seed) {
  add_noise(p, fraction, seed);
  return p;
}

const Case &noisy_sphere_case() {
  // Noise of 0.3% of the diagonal: about a tenth of the point spacing.
  static const Case c = make_case("noisy sphere", noisy(shuffled(fibonacci_sphere(2000), 31), 0.003, 31));
  return c;
}

const Case &noisy_torus_case() {
  // Noise of 1% of the diagonal: close to half the point spacing.
  static const Case c = make_case("very noisy torus", noisy(torus_random(2000, 1.0, 0.4, 32), 0.01, 32));
  return c;
}

const Case &random_torus_case() {
  static const Case c = make_case("uniform random torus", torus_random(2000, 1.0, 0.4, 33));
  return c;
}

const Case &random_ellipsoid_case() {
  static const Case c = make_case("uniform random ellipsoid", ellipsoid_random(1500, 2.0, 1.0, 0.5, 34));
  return c;
}

const Case &parallel_sheets_case() {
  // Two sheets 0.02 apart, points 0.08 apart within each sheet.
  static const Case c = make_case("parallel sheets", shuffled(parallel_sheets(2.0, 0.08, 0.02, 35), 35));
  return c;
}

const Case &thin_slab_case() {
  // A closed 3 x 3 x 0.06 box sampled on a 0.1 grid: thinner than the spacing.
  static const Case c = make_case("thin slab", shuffled(box_grid(3.0, 3.0, 0.06, 0.1), 36));
  return c;
}

const Case &octahedron_samples_case() {
  const std::vector<double> v = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  const std::vector<std::uint32_t> t = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                        2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  static const Case c = make_case("random octahedron samples", sample_mesh(v, t, 1500, 37));
  return c;
}

constexpr std::size_t kTorusPoints = 20000;
constexpr double kTorusR = 1.0, kTorusTube = 0.35;

// Distance from p to the torus surface.
double torus_distance(const double *p) {
  const double ring = std::hypot(p[0], p[1]) - kTorusR;
  return std::fabs(std::hypot(ring, p[2]) - kTorusTube);
}

// `percent` % of stray points, uniform in the volume a fifth larger than the torus's box, as a
// photogrammetry cloud holds them.
Case make_torus_outliers(std::size_t percent) {
  Points p = torus_random(kTorusPoints, kTorusR, kTorusTube, 38);
  Rng rng(38);
  const double half[3] = {1.2 * (kTorusR + kTorusTube), 1.2 * (kTorusR + kTorusTube),
                          1.2 * kTorusTube};
  for (std::size_t i = 0; i < kTorusPoints * percent / 100; ++i)
    for (double h : half) p.push_back(rng.uniform(-h, h));
  return make_case("torus with " + std::to_string(percent) + " % stray points", p);
}

// 5 %: they used to span triangles among themselves, hang from the surface by a vertex and take
// more in: 6 pieces, 112 boundary edges, genus 3.
const Case &torus_outliers_case() {
  static const Case c = make_torus_outliers(5);
  return c;
}

// 15 %: most stray points lie among each other, where they used to span faces that the loop
// module filled and widened round after round (2.1 s, now 0.9 s). The contract and determinism
// only: in this flat box (the torus's, a fifth larger) the stray points crowd within a few
// spacings of the surface, the cloud looks noisy, the smoothed copy pulls them onto the
// surface, and about a thousand are woven in, before as now (272 over four spacings off it).
const Case &many_outliers_case() {
  static const Case c = make_torus_outliers(15);
  return c;
}

// Closed with genus 1 (the independent checker's verdict) and every torus point (the first
// `surface` points) used; no stray point more than four spacings off the surface is a vertex:
// those near it are taken in as any noisy point would be.
std::string torus_outliers_failure(const Case &c, std::size_t surface = kTorusPoints) {
  const std::string closed = closed_failure(c, 1, double(surface) / double(c.points.size() / 3));
  if (!closed.empty()) return closed;
  // The mean spacing: the torus's area over its points, square-rooted (0.026 at 20,000).
  const double spacing = 2 * M_PI * std::sqrt(kTorusR * kTorusTube / double(surface));
  std::vector<char> used(c.points.size() / 3, 0);
  for (std::uint32_t v : c.run.triangles) used[v] = 1;
  std::size_t torus_unused = 0, far_used = 0;
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (i < surface)
      torus_unused += used[i] == 0;
    else if (used[i] && torus_distance(&c.points[3 * i]) > 4 * spacing)
      ++far_used;
  }
  if (torus_unused != 0)
    return c.name + ": " + std::to_string(torus_unused) + " torus points unused";
  if (far_used != 0)
    return c.name + ": " + std::to_string(far_used) + " stray points far off the surface used";
  return "";
}

// As many stray points as surface points, uniform in a cube a fifth wider than the torus: so
// many that a stray point's neighbours are other stray points only 3.6 times sparser than the
// surface in the median, and the cloud's median spacing rises towards theirs. Closed with
// genus 1, every torus point used, no stray point far off the surface a vertex
// (torus_outliers_failure); before the test for cluttered clouds: 1,824 boundary edges in 41
// pieces, 7,992 stray points woven in, 18 s.
constexpr std::size_t kClutteredTorusPoints = 10000;

const Case &cluttered_torus_case() {
  static const Case c = [] {
    Points p = torus_random(kClutteredTorusPoints, kTorusR, kTorusTube, 39);
    Rng rng(39);
    const double half = 1.2 * (kTorusR + kTorusTube);
    for (std::size_t i = 0; i < 3 * kClutteredTorusPoints; ++i)
      p.push_back(rng.uniform(-half, half));
    return make_case("torus in a cube of as many stray points", p);
  }();
  return c;
}

// Every point given twice, the second copy rounded to single precision (a cloud joined from a
// double and a float file): each pair becomes one point, the one given first, and the torus
// closes with the mesh of the torus given once. Without the merge it fell apart (2,470
// boundary edges, 78 pieces).
constexpr std::size_t kTwinTorusPoints = 3000;

const Case &twin_torus_case() {
  static const Case c = [] {
    Points p = torus_random(kTwinTorusPoints, 1.0, 0.4, 38);
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) p.push_back(double(float(p[i])));
    return make_case("torus given twice, once in single precision", p, kTwinTorusPoints);
  }();
  return c;
}

std::string twin_torus_failure(const Case &c) {
  const std::string closed = closed_failure(c, 1, 1.0);
  if (!closed.empty()) return closed;
  for (std::uint32_t v : c.run.triangles)
    if (v >= kTwinTorusPoints)
      return c.name + ": the second copy of point " + std::to_string(v - kTwinTorusPoints) +
             " is a vertex";
  if (c.run.stats.near_duplicate_points != kTwinTorusPoints)
    return c.name + ": " + std::to_string(c.run.stats.near_duplicate_points) +
           " near duplicates counted, expected " + std::to_string(kTwinTorusPoints);
  // The copies gone, what is left is the torus given once, and so is its mesh.
  const Run once = run_reconstruct(torus_random(kTwinTorusPoints, 1.0, 0.4, 38), 2, c.params);
  if (!once.error.empty()) return c.name + ": the torus given once threw: " + once.error;
  if (once.triangles != c.run.triangles) return c.name + ": not the mesh of the torus given once";
  return "";
}

// Copies of the points of `p` whose x is below `below_x`, each moved by `fraction` of the median
// nearest-neighbour distance in a random direction, after all of `p`: a second scan of that
// region, registered to within a fraction of the spacing.
Points with_jittered_copies(Points p, double below_x, double fraction, std::uint64_t seed) {
  const double step = fraction * median_nearest_distance(p);
  Rng rng(seed);
  const std::size_t n = p.size() / 3;
  for (std::size_t i = 0; i < n; ++i) {
    if (p[3 * i] >= below_x) continue;
    double d[3], len = 0;
    do {
      for (double &x : d) x = rng.normal();
      len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    } while (len == 0);
    for (int a = 0; a < 3; ++a) p.push_back(p[3 * i + a] + step * d[a] / len);
  }
  return p;
}

// A random torus sample without its closest pairs (none closer than half the median
// nearest-neighbour distance, which drops 8 % of the points): jittered copies of its points are
// then nearly always closer to their own point than to any other (two points within a few
// jitters of each other make a cluster of four, merged into one). Still a random sample: given
// twice so, it fell apart without the merge (172 boundary edges in 3 loops with seed 39).
Points thinned_torus(std::uint64_t seed) {
  const Points p = torus_random(3000, 1.0, 0.4, seed);
  return thin_points(p, 0.5 * median_nearest_distance(p));
}

// Every point given twice, the copy moved by a tenth of the nearest-neighbour distance: too far
// for the rule above (a fiftieth), but every point sits in a tight pair.
constexpr std::uint64_t kJitteredSeed = 39;

const Case &jittered_torus_case() {
  static const Case c = [] {
    const Points once = thinned_torus(kJitteredSeed);
    return make_case("torus given twice, the copy jittered",
                     with_jittered_copies(once, HUGE_VAL, 0.1, kJitteredSeed), once.size() / 3);
  }();
  return c;
}

// Closed with genus 1, the copies gone: the torus given once, jittered_torus's property.
std::string jittered_failure(const Case &c) {
  const Points once = thinned_torus(kJitteredSeed);
  const std::size_t copies = c.points.size() / 3 - once.size() / 3;
  const std::string closed = closed_failure(c, 1, 1.0);
  if (!closed.empty()) return closed;
  for (std::uint32_t v : c.run.triangles)
    if (v >= once.size() / 3) return c.name + ": copy " + std::to_string(v) + " is a vertex";
  if (c.run.stats.near_duplicate_points != copies)
    return c.name + ": " + std::to_string(c.run.stats.near_duplicate_points) +
           " near duplicates counted for " + std::to_string(copies) + " copies";
  const Run run = run_reconstruct(once, 2, c.params);
  if (!run.error.empty()) return c.name + ": the torus given once threw: " + run.error;
  if (run.triangles != c.run.triangles) return c.name + ": not the mesh of the torus given once";
  return "";
}

// A third of the torus (x < -0.6) given twice so, as where two scans overlap: over the whole
// cloud tight pairs are too few to tell copies, so each region is judged. Pairs whose
// neighbourhood straddles the border of the region may stay unmerged, so the count of near
// duplicates is not exact: the case checks the contract and determinism, and the property below.
constexpr std::uint64_t kOverlapSeed = 40;

const Case &overlap_torus_case() {
  static const Case c =
      make_case("torus with a third of it given twice, jittered",
                with_jittered_copies(thinned_torus(kOverlapSeed), -0.6, 0.1, kOverlapSeed));
  return c;
}

// Closed with genus 1; at least 99 % of the points given once are vertices, at most 5 % of the
// copies (pairs at the region's border, whose neighbourhoods are half single, may stay).
std::string overlap_failure(const Case &c) {
  if (!c.run.error.empty()) return c.name + ": " + c.run.error;
  const std::size_t once = thinned_torus(kOverlapSeed).size() / 3;
  const std::size_t copies = c.points.size() / 3 - once;
  const ContractReport &r = c.report;
  if (!r.closed() || r.components != 1 || r.genus_sum != 1)
    return c.name + ": not one closed surface of genus 1\n" + r.describe();
  std::vector<char> used(c.points.size() / 3, 0);
  for (std::uint32_t v : c.run.triangles) used[v] = 1;
  std::size_t once_used = 0, copies_used = 0;
  for (std::size_t i = 0; i < used.size(); ++i) (i < once ? once_used : copies_used) += used[i];
  if (100 * once_used < 99 * once || 20 * copies_used > copies)
    return c.name + ": " + std::to_string(once_used) + " of " + std::to_string(once) +
           " points given once and " + std::to_string(copies_used) + " of " +
           std::to_string(copies) + " copies are vertices";
  return "";
}

// `pieces` separate closed pieces, each of genus `genus`, using all `points` points; "" when
// the result is that, else a message naming what it is instead.
std::string closed_pieces_failure(const Case &c, std::size_t pieces, long genus,
                                  std::size_t points) {
  const ContractReport &r = c.report;
  const bool each_genus = std::all_of(r.closed_genus.begin(), r.closed_genus.end(),
                                      [&](long g) { return g == genus; });
  if (r.components != pieces || r.closed_components != pieces || r.boundary_edges != 0 ||
      !each_genus)
    return c.name + ": " + std::to_string(r.components) + " pieces (" +
           std::to_string(r.closed_components) + " closed), " + std::to_string(r.boundary_edges) +
           " boundary edges, genus " + std::to_string(r.genus_sum) + "; expected " +
           std::to_string(pieces) + " closed pieces of genus " + std::to_string(genus);
  if (r.vertices_used != points)
    return c.name + ": " + std::to_string(r.vertices_used) + " points used of " +
           std::to_string(points);
  return "";
}

// Many small objects apart: 100 unit spheres of 50 random points each, scattered through a box
// 100 wide at least 5 apart. Each closes on its own. The noise estimate's wider neighbourhoods
// reached across to the next spheres, flat across several of them where a sphere's own 10
// nearest are curved, so the clean cloud looked noisy and came out smoothed and open (none of
// the 100 spheres closed, 1,959 boundary edges).
constexpr std::size_t kScatteredSpheres = 100;
constexpr std::size_t kScatteredSpherePoints = 50;

const Case &scattered_spheres_case() {
  static const Case c = [] {
    Points p, centres;
    Rng rng(63);
    while (centres.size() < 3 * kScatteredSpheres) {
      const double x = rng.uniform(0, 100), y = rng.uniform(0, 100), z = rng.uniform(0, 100);
      bool apart = true;
      for (std::size_t j = 0; j < centres.size(); j += 3)
        apart &= std::hypot(x - centres[j], y - centres[j + 1], z - centres[j + 2]) >= 5;
      if (!apart) continue;
      centres.insert(centres.end(), {x, y, z});
      const Points s = sphere_random(kScatteredSpherePoints, 1.0, centres.size());
      for (std::size_t i = 0; i < s.size(); ++i)
        p.push_back(s[i] + centres[centres.size() - 3 + i % 3]);
    }
    return make_case("100 small spheres scattered in a box", p);
  }();
  return c;
}

// Every sphere closed with genus 0, every point used, and the cloud not smoothed.
std::string scattered_spheres_failure(const Case &c) {
  const std::string closed =
      closed_pieces_failure(c, kScatteredSpheres, 0, kScatteredSpheres * kScatteredSpherePoints);
  if (!closed.empty()) return closed;
  if (c.run.stats.smoothing_passes != 0)
    return c.name + ": smoothed as a noisy cloud (" +
           std::to_string(c.run.stats.smoothing_passes) + " passes)";
  return "";
}

// A coarse object beside a fine one: a unit sphere of 8,000 random points and, 4 away, one of
// 100 evenly spread points, which Algorithm 1 closes. Its edges are about nine times the
// cloud's median spacing, and it was dropped whole as a piece spanned among stray points (100
// points left out); closed, it stays.
constexpr std::size_t kFineSpherePoints = 8000;
constexpr std::size_t kCoarseSpherePoints = 100;

const Case &coarse_beside_fine_case() {
  static const Case c = [] {
    Points p = sphere_random(kFineSpherePoints, 1.0, 61);
    const Points coarse = fibonacci_sphere(kCoarseSpherePoints);
    for (std::size_t i = 0; i < coarse.size(); ++i)
      p.push_back(coarse[i] + (i % 3 == 0 ? 4 : 0));  // moved 4 along x
    return make_case("a coarse sphere beside a fine one", p);
  }();
  return c;
}

// Two closed spheres of genus 0, every point of both used.
std::string coarse_beside_fine_failure(const Case &c) {
  return closed_pieces_failure(c, 2, 0, kFineSpherePoints + kCoarseSpherePoints);
}

// Two linked rings: tori of tube radius 0.43 threaded through each other, one in the xy-plane
// and one in the xz-plane, so that each tube passes through the other's hole. Where they pass,
// the surfaces come within 0.14 of each other along a curved stretch: 2.7 point spacings (the
// mean distance to a point's six nearest, about 0.05), five nearest-neighbour distances. With a
// tube radius of 0.46 (0.08 apart, 1.5 spacings) the neighbour lists reach across, their planes
// tilt, and the rings come out joined.
constexpr std::size_t kLinkedTorusPoints = 6000;

const Case &linked_tori_case() {
  static const Case c = [] {
    Points p = torus_random(kLinkedTorusPoints, 1.0, 0.43, 65);
    const Points other = torus_random(kLinkedTorusPoints, 1.0, 0.43, 66);
    for (std::size_t i = 0; i < other.size(); i += 3)  // turned into the xz-plane, moved by 1 in x
      p.insert(p.end(), {other[i] + 1.0, other[i + 2], other[i + 1]});
    return make_case("two linked tori", shuffled(p, 67));
  }();
  return c;
}

// Two closed rings of genus 1 each, every point used.
std::string linked_tori_failure(const Case &c) {
  return closed_pieces_failure(c, 2, 1, 2 * kLinkedTorusPoints);
}

// Surfaces that no mesh meeting the contract can follow. A Moebius strip is one-sided: an
// oriented mesh of it must be cut across somewhere, and a strip cut once is a disk (on five
// samples of 4,000 points, each came out as one disk with every point). Two spheres crossing
// each other meet along a circle: a mesh of both must stop short of that circle on one of them
// (5,949-5,999 of 6,000 points used on five samples, in 4-10 boundary loops).
constexpr std::size_t kMobiusPoints = 4000;

const Case &mobius_strip_case() {
  static const Case c = [] {
    Points p;
    Rng rng(86);
    for (std::size_t i = 0; i < kMobiusPoints; ++i) {
      // Width 0.6 across a centre circle of radius 1, turning half a turn on the way round.
      const double u = rng.uniform(0, 2 * M_PI), v = rng.uniform(-0.3, 0.3);
      const double rho = 1 + v * std::cos(u / 2);
      p.insert(p.end(), {rho * std::cos(u), rho * std::sin(u), v * std::sin(u / 2)});
    }
    return make_case("Moebius strip", p);
  }();
  return c;
}

constexpr std::size_t kCrossingSpherePoints = 3000;

const Case &crossing_spheres_case() {
  static const Case c = [] {
    Points p = sphere_random(kCrossingSpherePoints, 1.0, 87);
    const Points other = sphere_random(kCrossingSpherePoints, 1.0, 88);
    for (std::size_t i = 0; i < other.size(); i += 3)  // its centre 1 away: they cross
      p.insert(p.end(), {other[i] + 1.0, other[i + 1], other[i + 2]});
    return make_case("two unit spheres crossing, centres 1 apart", p);
  }();
  return c;
}

// Most points used: the contract checks say the rest.
std::string crossing_spheres_failure(const Case &c) {
  if (!c.run.error.empty()) return c.name + ": " + c.run.error;
  const std::size_t all = 2 * kCrossingSpherePoints;
  if (100 * c.report.vertices_used < 99 * all)
    return c.name + ": " + std::to_string(c.report.vertices_used) + " of " + std::to_string(all) +
           " points used";
  return "";
}

}  // namespace

MOA_CONTRACT_TESTS(noisy_sphere)
MOA_CONTRACT_TESTS(noisy_torus)
MOA_CONTRACT_TESTS(random_torus)
MOA_CONTRACT_TESTS(random_ellipsoid)
MOA_CONTRACT_TESTS(parallel_sheets)
MOA_CONTRACT_TESTS(thin_slab)
MOA_CONTRACT_TESTS(octahedron_samples)
MOA_CONTRACT_TESTS(torus_outliers)
MOA_CONTRACT_TESTS(many_outliers)
MOA_CONTRACT_TESTS(cluttered_torus)
MOA_CONTRACT_TESTS(twin_torus)
MOA_CONTRACT_TESTS(jittered_torus)
// Its stats are checked by the other cases: how many of its pairs merge is not known exactly.
static void test_overlap_torus_contract(void **) { MOA_EXPECT(contract_failure(overlap_torus_case())); }
static void test_overlap_torus_deterministic(void **) {
  MOA_EXPECT(determinism_failure(overlap_torus_case()));
}

MOA_CONTRACT_TESTS(scattered_spheres)
MOA_CONTRACT_TESTS(coarse_beside_fine)
MOA_CONTRACT_TESTS(linked_tori)
MOA_CONTRACT_TESTS(mobius_strip)
MOA_CONTRACT_TESTS(crossing_spheres)

static void test_coarse_beside_fine_both_closed(void **) {
  MOA_EXPECT(coarse_beside_fine_failure(coarse_beside_fine_case()));
}

static void test_scattered_spheres_each_closed(void **) {
  MOA_EXPECT(scattered_spheres_failure(scattered_spheres_case()));
}

static void test_linked_tori_apart_and_closed(void **) {
  MOA_EXPECT(linked_tori_failure(linked_tori_case()));
}

static void test_mobius_strip_one_disk(void **) { MOA_EXPECT(disk_failure(mobius_strip_case())); }

static void test_crossing_spheres_points_used(void **) {
  MOA_EXPECT(crossing_spheres_failure(crossing_spheres_case()));
}

static void test_torus_outliers_left_out(void **) {
  MOA_EXPECT(torus_outliers_failure(torus_outliers_case()));
}

static void test_cluttered_torus_left_out(void **) {
  MOA_EXPECT(torus_outliers_failure(cluttered_torus_case(), kClutteredTorusPoints));
}

static void test_twin_torus_merged_and_closed(void **) {
  MOA_EXPECT(twin_torus_failure(twin_torus_case()));
}

static void test_jittered_torus_merged_and_closed(void **) {
  MOA_EXPECT(jittered_failure(jittered_torus_case()));
}

static void test_overlap_torus_merged_and_closed(void **) {
  MOA_EXPECT(overlap_failure(overlap_torus_case()));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      MOA_CONTRACT_ENTRIES(noisy_sphere),     MOA_CONTRACT_ENTRIES(noisy_torus),
      MOA_CONTRACT_ENTRIES(random_torus),     MOA_CONTRACT_ENTRIES(random_ellipsoid),
      MOA_CONTRACT_ENTRIES(parallel_sheets),  MOA_CONTRACT_ENTRIES(thin_slab),
      MOA_CONTRACT_ENTRIES(octahedron_samples),
      MOA_CONTRACT_ENTRIES(torus_outliers),
      cmocka_unit_test(test_torus_outliers_left_out),
      MOA_CONTRACT_ENTRIES(many_outliers),
      MOA_CONTRACT_ENTRIES(cluttered_torus),
      cmocka_unit_test(test_cluttered_torus_left_out),
      MOA_CONTRACT_ENTRIES(twin_torus),
      cmocka_unit_test(test_twin_torus_merged_and_closed),
      MOA_CONTRACT_ENTRIES(jittered_torus),
      cmocka_unit_test(test_jittered_torus_merged_and_closed),
      cmocka_unit_test(test_overlap_torus_contract),
      cmocka_unit_test(test_overlap_torus_deterministic),
      cmocka_unit_test(test_overlap_torus_merged_and_closed),
      MOA_CONTRACT_ENTRIES(scattered_spheres),
      cmocka_unit_test(test_scattered_spheres_each_closed),
      MOA_CONTRACT_ENTRIES(coarse_beside_fine),
      cmocka_unit_test(test_coarse_beside_fine_both_closed),
      MOA_CONTRACT_ENTRIES(linked_tori),
      cmocka_unit_test(test_linked_tori_apart_and_closed),
      MOA_CONTRACT_ENTRIES(mobius_strip),
      cmocka_unit_test(test_mobius_strip_one_disk),
      MOA_CONTRACT_ENTRIES(crossing_spheres),
      cmocka_unit_test(test_crossing_spheres_points_used),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
