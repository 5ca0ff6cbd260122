// Noisy clouds (src/core/smoothing.hpp): the noise estimate must tell scatter from curvature,
// and clouds whose scatter reaches the point spacing must still come out closed with their
// genus (or as one disk, for an open patch), every point a vertex and the contract held on the
// caller's coordinates.
#include "core/kd_tree.hpp"
#include "core/neighbors.hpp"
#include "core/point_set.hpp"
#include "core/smoothing.hpp"
#include "core_harness.hpp"

// cmocka last: its macros (fail, ...) clash with names in the standard headers.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

#include <algorithm>
#include <cmath>

using namespace moa::test;

namespace {

Points noisy(Points p, double fraction, std::uint64_t seed) {
  add_noise(p, fraction, seed);
  return p;
}

// The unit sphere's points pushed out by 0.05 sin(15x) sin(15y) sin(15z): at 6000 points (0.046
// apart) bumps about four spacings across, nine from one to the next. Clean, but where the
// surface bends that tightly a point's 10 nearest are as rough as noise makes them, and larger
// neighbourhoods are flatter; only the step from 10 to 20 points, which curvature makes rougher
// and noise flatter, tells the two apart (noisy_in_part in smoothing.cpp).
Points bumpy_sphere(std::size_t n) {
  Points p = fibonacci_sphere(n);
  for (std::size_t i = 0; i < p.size(); i += 3) {
    const double s =
        1 + 0.05 * std::sin(15 * p[i]) * std::sin(15 * p[i + 1]) * std::sin(15 * p[i + 2]);
    for (int k = 0; k < 3; ++k) p[i + k] *= s;
  }
  return p;
}

moa::NoiseEstimate estimate_of(const Points &p) {
  moa::PointSet points = moa::prepare_points(p.data(), p.size() / 3);
  moa::KdIndex index(points.work);
  return moa::estimate_noise(index);
}

// 6000 points on the unit sphere are 0.046 apart; the diagonal is 3.46: noise of 2 % of it is
// a standard deviation of 1.5 spacings, as in a rough scan of a ball.
const Case &rough_sphere_case() {
  static const Case c = make_case("sphere, noise 1.5 spacings", noisy(sphere_random(6000, 1.0, 71), 0.02, 71));
  return c;
}

// 8000 points on a torus (R 1, r 0.4) are 0.044 apart; diagonal 4.04: 0.8 % is 0.7 spacings.
const Case &rough_torus_case() {
  static const Case c = make_case("torus, noise 0.7 spacings", noisy(torus_random(8000, 1.0, 0.4, 72), 0.008, 72));
  return c;
}

// A genus-3 surface sampled 0.05 apart, noise of half a spacing.
const Case &rough_genus3_case() {
  Points p = genus_surface(3, 0.05, 73);
  add_noise(p, 0.5 * 0.05 / bbox_diagonal(p), 73);
  static const Case c = make_case("genus-3 surface, noise 0.5 spacings", p);
  return c;
}

// An open surface: its border must stay open. 3000 points on the unit hemisphere are 0.046
// apart; the box diagonal is 3: noise of 1.5 % of it is a standard deviation of one spacing.
const Case &rough_hemisphere_case() {
  static const Case c = make_case("hemisphere, noise 1 spacing", noisy(hemisphere(3000), 0.015, 81));
  return c;
}

// Sharp edges and corners under noise: a cube sampled on a 30 x 30 grid per face (spacing
// 0.034, diagonal 1.73), noise of 1 % of the diagonal, half a spacing.
const Case &rough_cube_case() {
  static const Case c = make_case("cube, noise 0.5 spacings", noisy(cube_grid(30), 0.01, 82));
  return c;
}

// A thin part under noise: 8000 points on a flat ellipsoid (semi-axes 1, 1 and 0.15; 0.03
// apart), noise of 0.3 % of the diagonal (0.3 spacings). Near the rim its two sheets share a
// neighbourhood, and quadrics fitted through both pulled the points of both into the middle:
// 296 boundary edges, genus 2, when every smoothed point was kept.
const Case &rough_flat_ellipsoid_case() {
  static const Case c = make_case("flat ellipsoid, noise 0.3 spacings",
                                  noisy(ellipsoid_random(8000, 1.0, 1.0, 0.15, 5), 0.003, 5));
  return c;
}

void test_rough_flat_ellipsoid_closed(void **) {
  assert_true(rough_flat_ellipsoid_case().run.stats.smoothing_passes >= 1);
  MOA_EXPECT(closed_failure(rough_flat_ellipsoid_case(), 0, 0.999));
}

// Sharp edges under noise: 60000 random points on the unit cube's faces, noise of 0.2 % of
// the diagonal (0.4 nearest-neighbour distances). The quadrics round the edges off and the
// regions along them move far, like a thin part's sheets; but there the smoothed copy serves,
// and putting the raw points back left 30 boundary edges.
const Case &noisy_cube_sample_case() {
  static const Case c = [] {
    const std::vector<double> corners = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                         0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    const std::vector<std::uint32_t> faces = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                              1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    return make_case("cube sample, noise 0.4 nearest distances",
                     noisy(sample_mesh(corners, faces, 60000, 7), 0.002, 7));
  }();
  return c;
}

void test_noisy_cube_sample_closed(void **) {
  MOA_EXPECT(contract_failure(noisy_cube_sample_case()));
  assert_true(noisy_cube_sample_case().run.stats.smoothing_passes >= 1);
  MOA_EXPECT(closed_failure(noisy_cube_sample_case(), 0));
}

void test_clean_clouds_are_not_noisy(void **) {
  // Curvature, coarse sampling, sharp edges, grid ties and thin walls, but no scatter.
  const Points clean[] = {sphere_random(3000, 1.0, 74), torus_random(4000, 1.0, 0.3, 75),
                          torus_grid(24, 8, 1.0, 0.3),   fibonacci_sphere(500),
                          cube_grid(20),                 genus_surface(2, 0.1, 76),
                          hemisphere(1500),              flat_grid(60, 60),
                          torus_contour_stack(3),                torus_contour_stack(5),
                          // Curvature that 10 points see as noise (bumpy_sphere).
                          bumpy_sphere(6000),
                          // Thin walls: a far sheet within 20 neighbours, not within 10;
                          // in the thinner, within the 10 of some points, which look as a
                          // noisy point does (noisy_in_part).
                          plate_samples(1.0, 0.022, 20000, 22),
                          pipe_samples(0.07, 1.0, 12000, 23),
                          plate_samples(1.0, 0.018, 20000, 24),
                          pipe_samples(0.062, 1.0, 12000, 25)};
  for (const Points &p : clean) {
    moa::NoiseEstimate e = estimate_of(p);
    if (e.noisy)
      fail_msg("a clean cloud of %zu points looked noisy: thickness/width %.3f at 10-20 points, "
               "%.3f at %u", p.size() / 3, e.small_scale, e.large_scale, e.smoothing_k);
  }
}

// The far-sheet rule for local planes (neighbors.cpp) is for clouds of thin walls only, and
// only theirs get lists twice the parameter's length.
void test_thin_walls_seen_only_on_thin_walls(void **) {
  auto thin_walls = [](const Points &p) {
    moa::PointSet points = moa::prepare_points(p.data(), p.size() / 3);
    moa::KdIndex index(points.work);
    const moa::Neighborhood nb = moa::compute_neighbors(index, 20, [](double) {});
    if (nb.k != (nb.thin_walls ? 40u : 20u))
      fail_msg("lists of %u neighbours with thin walls %d", nb.k, int(nb.thin_walls));
    return nb.thin_walls;
  };
  assert_true(thin_walls(plate_samples(1.0, 0.022, 20000, 22)));
  assert_true(thin_walls(pipe_samples(0.07, 1.0, 12000, 23)));
  const Points others[] = {sphere_random(3000, 1.0, 74), torus_random(4000, 1.0, 0.3, 75),
                           cube_grid(20), genus_surface(3, 0.05, 73),
                           ellipsoid_random(8000, 1.0, 1.0, 0.15, 5), flat_grid(60, 60)};
  for (const Points &p : others)
    if (thin_walls(p))
      fail_msg("a cloud of %zu points without thin walls was said to have them", p.size() / 3);
}

void test_noisy_clouds_are_noisy(void **) {
  const Points rough[] = {noisy(sphere_random(6000, 1.0, 77), 0.02, 77),
                          noisy(torus_random(8000, 1.0, 0.4, 78), 0.008, 78),
                          noisy(flat_grid(80, 80), 0.005, 79)};
  for (const Points &p : rough) {
    moa::NoiseEstimate e = estimate_of(p);
    if (!e.noisy)
      fail_msg("a noisy cloud of %zu points was not seen as noisy: %.3f at 10-20 points, %.3f "
               "at %u", p.size() / 3, e.small_scale, e.large_scale, e.smoothing_k);
    assert_true(e.smoothing_k > 20);
  }
}

// Noise in part of a cloud (a region scanned from farther off): 8000 points on a torus (R 1,
// r 0.4; 0.022 from the nearest in the mean), noise of deviation `sigma` on the half with
// x > 0 only. The estimate's medians fell on the clean half, which looked clean.
Points half_noisy_torus(double sigma, std::uint64_t seed) {
  Points p = torus_random(8000, 1.0, 0.4, seed);
  add_noise_beyond(p, 0, sigma, seed);
  return p;
}

void test_noisy_in_part_is_noisy(void **) {
  for (double sigma : {0.009, 0.013, 0.018}) {
    const moa::NoiseEstimate e = estimate_of(half_noisy_torus(sigma, 84));
    if (!e.noisy)
      fail_msg("a torus with noise of %.3f on half of it was not seen as noisy", sigma);
    assert_true(e.smoothing_k > 20);
  }
}

// Noise of 0.6 nearest-neighbour distances on half: not smoothed, 95 boundary edges in 2 loops.
const Case &half_noisy_torus_case() {
  static const Case c = make_case("torus, noise 0.6 nearest distances on half",
                                  half_noisy_torus(0.013, 84));
  return c;
}

void test_half_noisy_torus_closed(void **) {
  assert_true(half_noisy_torus_case().run.stats.smoothing_passes >= 1);
  MOA_EXPECT(closed_failure(half_noisy_torus_case(), 1, 0.999));
}

// Noise on a contour stack that the drop test misses (its neighbourhoods are as wide as the
// gaps between cuts) but that matters next to the short steps along a cut: the cuts are no
// longer plane curves. The drop test alone calls this stack clean.
void test_rough_lines_are_noisy(void **) {
  const Points p = noisy(torus_contour_stack(3), 0.0005, 99);
  assert_true(estimate_of(p).noisy);
}

// With five points per gap the drop test sees the noise, but only before the first smoothing
// pass; the rough cuts still call for the next two. With one pass the stack below kept 799
// boundary edges in 14 loops.

const Case &rough_stack_case() {
  static const Case c = make_case("noisy torus contour stack", noisy(torus_contour_stack(5), 0.0016, 99));
  return c;
}

void test_rough_stack_closed(void **) { MOA_EXPECT(closed_failure(rough_stack_case(), 1)); }

// Smoothing moves the judgment's copy only: every smoothed point stays within a few noise
// deviations of its raw position, and the copy is thinner than the raw cloud.
void test_smoothing_thins_the_cloud(void **) {
  Points p = noisy(sphere_random(6000, 1.0, 80), 0.02, 80);
  moa::PointSet points = moa::prepare_points(p.data(), p.size() / 3);
  moa::KdIndex index(points.work);
  moa::NoiseEstimate e = moa::estimate_noise(index);
  assert_true(e.noisy);
  std::vector<moa::Vec3> smooth =
      moa::smoothed_points(index, e.smoothing_k, e.thin_walls, [](double) {});
  assert_int_equal(smooth.size(), points.work.size());
  // The sphere's centre and radius in work units: the mean of the raw points and their mean
  // distance from it.
  moa::Vec3 centre{};
  for (const moa::Vec3 &q : points.work) centre = centre + q * (1.0 / double(points.work.size()));
  auto radial_spread = [&](const std::vector<moa::Vec3> &v) {
    double sum = 0, sum2 = 0;
    for (const moa::Vec3 &q : v) {
      double r = moa::dist(q, centre);
      sum += r;
      sum2 += r * r;
    }
    double mean = sum / double(v.size());
    return std::sqrt(std::max(0.0, sum2 / double(v.size()) - mean * mean));
  };
  const double raw = radial_spread(points.work), smoothed = radial_spread(smooth);
  if (!(smoothed < 0.35 * raw))
    fail_msg("radial spread %.5f after smoothing, %.5f before: not thinned enough", smoothed, raw);
  const double noise = 0.02;  // 2 % of the diagonal, which is 1 in work units
  for (std::size_t i = 0; i < smooth.size(); ++i)
    if (moa::dist(smooth[i], points.work[i]) > 6 * noise)
      fail_msg("point %zu moved %.4f, more than six noise deviations", i,
               moa::dist(smooth[i], points.work[i]));
}

// The statistics say whether the cloud was smoothed.
void test_smoothing_reported(void **) {
  assert_true(rough_sphere_case().run.stats.smoothing_passes >= 1);
  Run clean = run_reconstruct(sphere_random(3000, 1.0, 83), 2);
  assert_true(clean.error.empty());
  assert_int_equal(clean.stats.smoothing_passes, 0);
}

// Stray points: 6000 points on the unit sphere (0.046 apart) and 50 more scattered 0.3 to 1.0
// off it, inside and out, 6 to 20 spacings from any other point. They lie on no surface: none
// may become a vertex (each would raise a spike), and the sphere must still close with every
// one of its own points. The take-in once measured a stray point's height over the surface in
// its own spacing, which for a stray point is its distance to the surface, and took it in.
const Case &sphere_with_strays_case() {
  static const Case c = [] {
    Points p = sphere_random(6000, 1.0, 91);
    const Points dirs = sphere_random(50, 1.0, 92);
    for (std::size_t i = 0; i < 50; ++i) {
      const double radius = i % 5 == 0 ? 0.3 + 0.08 * double(i % 4) : 1.3 + 0.7 * double(i) / 50;
      for (int k = 0; k < 3; ++k) p.push_back(dirs[3 * i + k] * radius);
    }
    return make_case("sphere with 50 stray points", p);
  }();
  return c;
}

void test_stray_points_left_out(void **) {
  const Case &c = sphere_with_strays_case();
  MOA_EXPECT(contract_failure(c));
  MOA_EXPECT(closed_failure(c, 0, 6000.0 / 6050.0));
  for (std::uint32_t v : c.run.triangles)
    if (v >= 6000) fail_msg("stray point %u is a vertex of the mesh", v);
  assert_int_equal(c.run.stats.unused_points, 50);
}

// A hollow ball: two concentric random spheres (radii 1 and 1.157, 6000 points in all, each
// sphere as dense as the other) 4.8 nearest-neighbour distances apart. A point's 10 nearest lie
// on its own sphere, its 20 nearest reach the other, so the 20-point neighbourhoods look far
// rougher than the 10-point ones, as a noisy cloud's 10-point ones do. Smoothed as noise, such
// spheres become one surface zigzagging between them (20,000 points 5 apart: 1 component, 68 %
// of its faces joining the spheres). Clean, they are two closed spheres.
constexpr double kInnerRadius = 1.0, kOuterRadius = 1.157;

// Concentric random spheres of radii kInnerRadius and outer_radius, each as dense as the
// other, `total` points in all, with Gaussian noise of standard deviation `noise` (none at 0).
Points concentric_spheres(double outer_radius, std::size_t total, double noise,
                          std::uint64_t seed) {
  const std::size_t inner = std::size_t(double(total) / (1 + outer_radius * outer_radius));
  Points p = sphere_random(inner, kInnerRadius, seed);
  const Points outer = sphere_random(total - inner, outer_radius, seed + 1);
  p.insert(p.end(), outer.begin(), outer.end());
  add_noise(p, noise / bbox_diagonal(p), seed + 2);
  return p;
}

const Case &hollow_ball_case() {
  static const Case c = make_case("hollow ball", concentric_spheres(kOuterRadius, 6000, 0.0, 93));
  return c;
}

void test_hollow_ball_is_not_noisy(void **) {
  const moa::NoiseEstimate e = estimate_of(hollow_ball_case().points);
  if (e.noisy)
    fail_msg("a hollow ball looked noisy: %.3f at 10-20 points, %.3f at %u", e.small_scale,
             e.large_scale, e.smoothing_k);
}

// Two closed spheres of genus 0, no face joining them, and at least the share min_used of the
// points used.
std::string two_spheres_failure(const Case &c, double min_used) {
  const ContractReport &r = c.report;
  if (r.closed() && r.components == 2 && r.genus_sum == 0 &&
      double(r.vertices_used) >= min_used * double(c.points.size() / 3))
    return "";
  return c.name + ": not two closed spheres using the points\n" + r.describe();
}

// Every point used.
void test_hollow_ball_two_spheres(void **) {
  MOA_EXPECT(two_spheres_failure(hollow_ball_case(), 1.0));
}

// The same two spheres, 12,000 points 0.05 apart (the gap is 3.1 spacings), with noise of a
// fifth of a spacing. Each point's 10 and 20 nearest look noisy, its 40 nearest reach the far
// sphere and look far rougher, so no neighbourhood looks flatter than the finest: unsmoothed,
// the raw points left 48 boundary edges in one piece joining the spheres. Smoothed over 20
// neighbours on the near sheet only, they are two closed spheres again.
const Case &noisy_hollow_ball_case() {
  static const Case c = make_case("hollow ball, noise 0.2 spacings",
                                  concentric_spheres(kOuterRadius, 12000, 0.01, 95));
  return c;
}

// Spheres 0.18 apart (3.6 spacings): the far sheet comes in over two sizes, the medians rising
// 2 to 2.5 times from 40 points to 80 and less before. Smoothed as plain noise over 40 points,
// they were joined into one closed surface.
const Case &noisy_wide_hollow_ball_case() {
  static const Case c = make_case("hollow ball 3.6 spacings thick, noise 0.2 spacings",
                                  concentric_spheres(1.18, 12000, 0.01, 95));
  return c;
}

void test_noisy_wide_hollow_ball_two_spheres(void **) {
  MOA_EXPECT(two_spheres_failure(noisy_wide_hollow_ball_case(), 0.999));
}

void test_noisy_hollow_ball_is_noisy_thin_walls(void **) {
  const moa::NoiseEstimate e = estimate_of(noisy_hollow_ball_case().points);
  if (!e.noisy || !e.thin_walls || e.smoothing_k > 20)
    fail_msg("a noisy hollow ball: noisy %d, thin walls %d, smoothing over %u points",
             int(e.noisy), int(e.thin_walls), e.smoothing_k);
}

void test_noisy_hollow_ball_two_spheres(void **) {
  MOA_EXPECT(two_spheres_failure(noisy_hollow_ball_case(), 0.999));
}

// Clean spheres 0.073 apart, 20,000 points 0.037 apart (the gap is 2 spacings): the far sphere
// fills up to half of a point's 20 nearest, and too few are left on its own for Algorithm 1
// (165 boundary edges, genus 9, the spheres joined). A cloud of thin walls gets lists twice
// as long (neighbors.cpp), and these are two closed spheres.
const Case &thin_hollow_ball_case() {
  static const Case c =
      make_case("hollow ball 2 spacings thick", concentric_spheres(1.073, 20000, 0.0, 95));
  return c;
}

void test_thin_hollow_ball_two_spheres(void **) {
  MOA_EXPECT(two_spheres_failure(thin_hollow_ball_case(), 1.0));
}

// Spheres 0.093 apart (2.5 spacings): the far sphere comes in at 40 points (medians 0.023,
// 0.033, 0.79 at 10, 20, 40), and enough points whose 20 nearest reach it looked noisy on
// their own: smoothed as noise in part, the two became one closed surface zigzagging between
// them.
void test_hollow_ball_far_sheet_at_40_two_spheres(void **) {
  const Case c =
      make_case("hollow ball 2.5 spacings thick", concentric_spheres(1.093, 20000, 0.0, 96));
  assert_int_equal(c.run.stats.smoothing_passes, 0);
  MOA_EXPECT(contract_failure(c));
  MOA_EXPECT(two_spheres_failure(c, 1.0));
}

// Spheres 0.066 apart (1.8 spacings): where the fronts on one sphere meet, a front's edge has
// its own sphere filled on both sides, and the next best third vertices are on the other.
// Triangles bridging the two at 46-66 degrees off the true normals passed the normal test
// (55 degrees) where a point's plane leaned toward them; the spheres were joined, with 521
// boundary edges and genus 13. With their corners' planes fitted to the two sheets, and held
// within 40 degrees of them (topology_judgment.cpp), the spheres close apart.
void test_hollow_ball_1_8_spacings_two_spheres(void **) {
  const Case c =
      make_case("hollow ball 1.8 spacings thick", concentric_spheres(1.066, 20000, 0.0, 96));
  MOA_EXPECT(contract_failure(c));
  MOA_EXPECT(two_spheres_failure(c, 1.0));
}

// The planes of that hollow ball's points (neighbors.cpp): those that see the other sphere in
// their lists are marked as in a thin wall, with normals fitted to the two sheets; on a
// thin-walled box, not those beside its creases, where triangles round the crease stand 45
// degrees off the faces' planes.
void test_thin_wall_planes(void **) {
  struct Planes {
    std::vector<moa::Vec3> work;
    std::vector<moa::LocalPlane> planes;
  };
  auto planes_of = [](const Points &p) {
    moa::PointSet points = moa::prepare_points(p.data(), p.size() / 3);
    moa::KdIndex index(points.work);
    const moa::Neighborhood nb = moa::compute_neighbors(index, 20, [](double) {});
    assert_true(nb.thin_walls);
    Planes out{points.work, {}};
    for (uint32_t i = 0; i < points.work.size(); ++i)
      out.planes.push_back(moa::local_plane(points, nb, i));
    return out;
  };
  // The hollow ball: centred where the work frame's points average.
  const Planes ball = planes_of(concentric_spheres(1.066, 20000, 0.0, 96));
  moa::Vec3 centre{0, 0, 0};
  for (const moa::Vec3 &q : ball.work) centre = centre + q * (1.0 / double(ball.work.size()));
  std::size_t marked = 0, off = 0;
  for (std::size_t i = 0; i < ball.work.size(); ++i) {
    if (!ball.planes[i].in_thin_wall) continue;
    ++marked;
    const moa::Vec3 radial = moa::normalized(ball.work[i] - centre);
    off += std::fabs(moa::dot(radial, ball.planes[i].normal)) < std::cos(10 * M_PI / 180);
  }
  // Measured: 19,420 of 20,000 marked, 7 % of them over 10 degrees off (median 0.5); the
  // plane of the whole list stands 12 degrees off in the median.
  print_message("hollow ball: %zu of %zu points in a thin wall, %zu of them over 10 degrees "
                "off\n", marked, ball.work.size(), off);
  assert_true(marked * 20 > ball.work.size() * 19);
  assert_true(off * 10 < marked);

  // A box 2 x 2 x 2 with walls 0.096 thick (two spacings of its 20,000 points).
  const double t = 0.096, hi = 1 - t;
  const Planes box = planes_of(hollow_box_samples(1.0, t, 20000, 1));
  // Work units per caller unit: the work frame spans the box's diagonal, 2 sqrt 3, as 1.
  const double spacing = 0.048 / (2 * std::sqrt(3.0));
  std::size_t near_crease = 0, marked_there = 0;
  for (std::size_t i = 0; i < box.work.size(); ++i) {
    const moa::Vec3 &q = box.work[i];
    double a[3] = {std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)};
    std::sort(a, a + 3);
    // On a crease two coordinates are at the wall's extreme: the outer or the inner one.
    const double wall = a[2] > (1 - t / 2) / (2 * std::sqrt(3.0)) ? 1.0 : hi;
    if (wall / (2 * std::sqrt(3.0)) - a[1] > 0.5 * spacing) continue;
    ++near_crease;
    marked_there += box.planes[i].in_thin_wall;
  }
  // Measured: 3 of 939 marked.
  print_message("thin-walled box: %zu of %zu points within half a spacing of a crease marked\n",
                marked_there, near_crease);
  assert_true(near_crease > 500);
  assert_true(marked_there * 20 < near_crease);
}

// A pipe with walls 0.1 thick (outer radius 1, length 1; 12,000 points about 0.033 apart, so
// the wall is about 3 spacings), noise of a fifth of a spacing: closed, genus 1. Unsmoothed,
// the raw points left 50 boundary edges in 3 loops.
const Case &noisy_pipe_case() {
  static const Case c = [] {
    Points p = pipe_samples(0.1, 1.0, 12000, 98);
    add_noise(p, 0.2 * 0.033 / bbox_diagonal(p), 99);
    return make_case("pipe, walls 3 spacings, noise 0.2 spacings", p);
  }();
  return c;
}

void test_noisy_pipe_closed(void **) { MOA_EXPECT(closed_failure(noisy_pipe_case(), 1, 0.999)); }

// A dumbbell (balls of radius 0.6, a neck of radius 0.12) sampled with 20,000 points 0.022
// apart, so the neck is 5.5 spacings round, with noise of half a spacing. The cloud is smoothed
// over 320 points, a ball wider than the neck: wrapped round it, it pulled the neck's sheets
// together (454 boundary edges in 40 loops; 447-593 on four other samples). Fitted to the
// smaller, flatter balls there, it closes.
const Case &noisy_dumbbell_case() {
  static const Case c = [] {
    Points p = dumbbell_samples(0.12, 20000, 3);
    add_noise(p, 0.5 * 0.022 / bbox_diagonal(p), 4);
    return make_case("dumbbell, neck 5.5 spacings round, noise 0.5 spacings", p);
  }();
  return c;
}

void test_noisy_dumbbell_closed(void **) {
  MOA_EXPECT(closed_failure(noisy_dumbbell_case(), 0, 0.999));
}

// Two scans registered imperfectly: every second point of 8000 on a torus (R 1, r 0.4; a
// point's six nearest 0.043 away in the median) moved outward along the surface normal by
// 1.5 spacings. Two interleaved layers, each as sparse as the gap between them: the noise test
// must see them as scatter and smooth them into one surface (without smoothing, two other
// such samples kept 3,876 and 4,141 boundary edges). Shifted by 0.25 to 2.5 spacings, three
// other samples came out as one closed torus with every point; by 3, as two nested ones.
const Case &misregistered_torus_case() {
  static const Case c = [] {
    constexpr double kR = 1.0, kTube = 0.4, kShift = 1.5 * 0.043;
    Points p = torus_random(8000, kR, kTube, 85);
    for (std::size_t i = 0; i < p.size(); i += 6) {
      const double rho = std::hypot(p[i], p[i + 1]);
      // The unit normal: from the nearest point of the tube's core circle, r away.
      const double n[3] = {(p[i] - kR * p[i] / rho) / kTube,
                           (p[i + 1] - kR * p[i + 1] / rho) / kTube, p[i + 2] / kTube};
      for (int k = 0; k < 3; ++k) p[i + k] += kShift * n[k];
    }
    return make_case("torus, every second point 1.5 spacings off along the normal", p);
  }();
  return c;
}

void test_misregistered_torus_closed(void **) {
  assert_true(misregistered_torus_case().run.stats.smoothing_passes >= 1);
  MOA_EXPECT(closed_failure(misregistered_torus_case(), 1));
}

// The mechanism itself: the noise estimate asks for 320 points, and smoothed over that many the
// neck's points (radius 0.12) stay on the neck: 0.118 from the axis in the median, where the
// balls wrapped round it pulled them to 0.070.
void test_smoothing_keeps_a_narrow_neck(void **) {
  const Points &p = noisy_dumbbell_case().points;
  std::vector<moa::Vec3> v;
  for (std::size_t i = 0; i + 2 < p.size(); i += 3) v.push_back({p[i], p[i + 1], p[i + 2]});
  const moa::KdIndex index(v);
  const moa::NoiseEstimate e = moa::estimate_noise(index);
  if (!e.noisy || e.thin_walls || e.smoothing_k != 320)
    fail_msg("a noisy dumbbell: noisy %d, thin walls %d, smoothing over %u points", int(e.noisy),
             int(e.thin_walls), e.smoothing_k);
  const std::vector<moa::Vec3> s = moa::smoothed_points(index, e.smoothing_k, false, [](double) {});
  std::vector<double> radii;
  for (const moa::Vec3 &q : s)
    if (std::fabs(q.x) < 0.25) radii.push_back(std::hypot(q.y, q.z));
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  const double median = radii[radii.size() / 2];
  print_message("neck points %zu, median distance from the axis %.4f\n", radii.size(), median);
  assert_true(median > 0.1 && median < 0.14);
}

void test_rough_sphere_closed(void **) { MOA_EXPECT(closed_failure(rough_sphere_case(), 0)); }
void test_rough_genus3_closed(void **) { MOA_EXPECT(closed_failure(rough_genus3_case(), 3)); }

void test_rough_hemisphere_disk(void **) { MOA_EXPECT(disk_failure(rough_hemisphere_case())); }

// A point standing two or three deviations off its surface may be too far off every face to be
// taken in: 99.9 % of the points must be used.
void test_rough_torus_closed(void **) { MOA_EXPECT(closed_failure(rough_torus_case(), 1, 0.999)); }
void test_rough_cube_closed(void **) { MOA_EXPECT(closed_failure(rough_cube_case(), 0, 0.999)); }

}  // namespace

MOA_CONTRACT_TESTS(rough_hemisphere)
MOA_CONTRACT_TESTS(rough_cube)
MOA_CONTRACT_TESTS(rough_sphere)
MOA_CONTRACT_TESTS(rough_torus)
MOA_CONTRACT_TESTS(rough_genus3)
MOA_CONTRACT_TESTS(rough_stack)
MOA_CONTRACT_TESTS(rough_flat_ellipsoid)
MOA_CONTRACT_TESTS(hollow_ball)
MOA_CONTRACT_TESTS(noisy_hollow_ball)
MOA_CONTRACT_TESTS(noisy_pipe)
MOA_CONTRACT_TESTS(noisy_wide_hollow_ball)
MOA_CONTRACT_TESTS(half_noisy_torus)
MOA_CONTRACT_TESTS(noisy_dumbbell)
MOA_CONTRACT_TESTS(thin_hollow_ball)
MOA_CONTRACT_TESTS(misregistered_torus)

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_clean_clouds_are_not_noisy),
      cmocka_unit_test(test_thin_walls_seen_only_on_thin_walls),
      cmocka_unit_test(test_noisy_clouds_are_noisy),
      cmocka_unit_test(test_smoothing_thins_the_cloud),
      cmocka_unit_test(test_smoothing_reported),
      cmocka_unit_test(test_rough_sphere_closed),
      cmocka_unit_test(test_rough_torus_closed),
      cmocka_unit_test(test_rough_genus3_closed),
      cmocka_unit_test(test_rough_hemisphere_disk),
      cmocka_unit_test(test_rough_cube_closed),
      cmocka_unit_test(test_stray_points_left_out),
      cmocka_unit_test(test_rough_lines_are_noisy),
      cmocka_unit_test(test_rough_stack_closed),
      cmocka_unit_test(test_rough_flat_ellipsoid_closed),
      cmocka_unit_test(test_noisy_cube_sample_closed),
      cmocka_unit_test(test_hollow_ball_is_not_noisy),
      cmocka_unit_test(test_hollow_ball_two_spheres),
      MOA_CONTRACT_ENTRIES(rough_hemisphere),
      MOA_CONTRACT_ENTRIES(rough_cube),
      MOA_CONTRACT_ENTRIES(rough_sphere),
      MOA_CONTRACT_ENTRIES(rough_torus),
      MOA_CONTRACT_ENTRIES(rough_genus3),
      MOA_CONTRACT_ENTRIES(rough_stack),
      MOA_CONTRACT_ENTRIES(rough_flat_ellipsoid),
      MOA_CONTRACT_ENTRIES(hollow_ball),
      cmocka_unit_test(test_noisy_hollow_ball_is_noisy_thin_walls),
      cmocka_unit_test(test_noisy_hollow_ball_two_spheres),
      MOA_CONTRACT_ENTRIES(noisy_hollow_ball),
      cmocka_unit_test(test_noisy_pipe_closed),
      MOA_CONTRACT_ENTRIES(noisy_pipe),
      cmocka_unit_test(test_noisy_wide_hollow_ball_two_spheres),
      MOA_CONTRACT_ENTRIES(noisy_wide_hollow_ball),
      cmocka_unit_test(test_noisy_in_part_is_noisy),
      cmocka_unit_test(test_half_noisy_torus_closed),
      MOA_CONTRACT_ENTRIES(half_noisy_torus),
      cmocka_unit_test(test_noisy_dumbbell_closed),
      cmocka_unit_test(test_smoothing_keeps_a_narrow_neck),
      MOA_CONTRACT_ENTRIES(noisy_dumbbell),
      cmocka_unit_test(test_misregistered_torus_closed),
      MOA_CONTRACT_ENTRIES(misregistered_torus),
      cmocka_unit_test(test_thin_hollow_ball_two_spheres),
      MOA_CONTRACT_ENTRIES(thin_hollow_ball),
      cmocka_unit_test(test_hollow_ball_far_sheet_at_40_two_spheres),
      cmocka_unit_test(test_hollow_ball_1_8_spacings_two_spheres),
      cmocka_unit_test(test_thin_wall_planes),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
