// Deterministic point sets for the property tests. Random shapes draw from a seeded
// std::mt19937_64 through distributions implemented here, so the points are the same with every
// standard library. Points are interleaved x y z; no generator emits exact duplicates.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace moa::test {

using Points = std::vector<double>;

// Our own distributions on top of the engine (whose output sequence the standard fixes).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  double uniform();                              // [0, 1) with 53 random bits
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double normal();                               // standard normal, Marsaglia polar method
  std::uint64_t below(std::uint64_t n);          // uniform integer in [0, n), unbiased

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0;
};

// Closed surfaces.
Points fibonacci_sphere(std::size_t n, double radius = 1.0);
Points sphere_random(std::size_t n, double radius, std::uint64_t seed);
// Uniform by area on the ellipsoid with semi-axes a, b, c.
Points ellipsoid_random(std::size_t n, double a, double b, double c, std::uint64_t seed);
// Torus about the z axis: R to the tube's centre, r the tube radius.
Points torus_random(std::size_t n, double R, double r, std::uint64_t seed);
Points torus_grid(std::size_t nu, std::size_t nv, double R, double r);
// The triangles of torus_grid's points, two per grid cell, facing outward.
std::vector<std::uint32_t> torus_grid_triangles(std::size_t nu, std::size_t nv);
// A smooth closed surface of genus 1, 2 or 3 (tori in a row, blended where they meet), sampled
// with minimum spacing `spacing` and no gap much wider than that.
Points genus_surface(int genus, double spacing, std::uint64_t seed);
// The surface of the box [0,lx] x [0,ly] x [0,lz] on a grid of about `spacing`, with its sharp
// edges and corners sampled; cube_grid(n) is the box [-1,1]^3 with n cells along each edge.
Points box_grid(double lx, double ly, double lz, double spacing);
Points cube_grid(std::size_t n);

// Open patches.
Points flat_grid(std::size_t nx, std::size_t ny, double spacing = 1.0);  // z = 0, all ties
Points hemisphere(std::size_t n, double radius = 1.0);                   // z > 0 half of a sphere
// z = x^2 - y^2 over [-1,1]^2, blue-noise samples at about `spacing` in 3-D, border sampled.
Points saddle(double spacing, std::uint64_t seed);
// Two blue-noise sheets over [0,side]^2 at z = 0 and z = gap (gap below the spacing).
Points parallel_sheets(double side, double spacing, double gap, std::uint64_t seed);

// Thin walls sampled uniformly (sample_mesh): a box side x side x thickness, and a pipe of outer
// radius 1 (a 96-sided prism with a prism-shaped hole, closed at both ends by rings; genus 1).
Points plate_samples(double side, double thickness, std::size_t n, std::uint64_t seed);
Points pipe_samples(double thickness, double length, std::size_t n, std::uint64_t seed);
// A cube 2 * half on a side, centred on the origin, with walls `wall` thick: its outer and inner
// faces (not oriented: only the points are used).
Points hollow_box_samples(double half, double wall, std::size_t n, std::uint64_t seed);
// A plate 1 x 1 x 0.1 with five round bores of radius `bore` through it (the five of a die),
// sampled uniformly by area: flat faces, right-angled edges round the rim and the bores' mouths,
// and genus 5.
Points drilled_plate_samples(double bore, std::size_t n, std::uint64_t seed);
// A dumbbell along x sampled uniformly (sample_mesh): balls of radius 0.6 centred at x = -1 and
// x = 1, joined by a neck of radius `neck`, the joints rounded over about 0.05.
Points dumbbell_samples(double neck, std::size_t n, std::uint64_t seed);

// Helpers.
void add_noise(Points &p, double fraction_of_diagonal, std::uint64_t seed);
// Gaussian noise of standard deviation `sigma` on each coordinate of the points whose x exceeds
// `x`, the others left as they are: a region scanned from farther off.
void add_noise_beyond(Points &p, double x, double sigma, std::uint64_t seed);
// The median distance from a point to its nearest other point (exact; a duplicate counts as 0).
double median_nearest_distance(const Points &p);
// The angle (radians) at point c of triangle a b c, under which c sees the segment ab.
double angle_at(const Points &p, std::uint32_t c, std::uint32_t a, std::uint32_t b);
// How many of the triangles (3 point indices each) have an angle smaller than `degrees`.
std::size_t faces_below(const Points &p, const std::vector<std::uint32_t> &triangles,
                        double degrees);
// Keeps each point with a chance that grows with the square of its x across the bounding box,
// from 1 / ratio at the low end to 1 at the high end: a density `ratio` times higher on one side,
// as a scanner leaves it on the near and far sides of an object.
Points density_gradient(const Points &p, double ratio, std::uint64_t seed);
void shuffle(Points &p, std::uint64_t seed);
double bbox_diagonal(const Points &p);
// n points uniform by area on a triangle mesh.
Points sample_mesh(const std::vector<double> &vertices, const std::vector<std::uint32_t> &triangles,
                   std::size_t n, std::uint64_t seed);
// A contour stack, as CT and MRI segmentations deliver: the mesh cut by `slices` parallel planes
// (normal `axis`, evenly spaced across the mesh) and each cut sampled at random along its length,
// `per_gap` points per plane gap on average: the points lie on lines that far apart.
Points contour_stack(const std::vector<double> &vertices, const std::vector<std::uint32_t> &triangles,
                     const double axis[3], std::size_t slices, double per_gap, std::uint64_t seed);
// The torus_grid(120, 48, 1.0, 0.4) mesh as a contour stack: 30 planes across the axis
// (1, 0.3, 0.2), `per_gap` points per plane gap, seed 1.
Points torus_contour_stack(double per_gap);
// The unit sphere as a contour stack: `slices` planes across the axis (1, 0.3, 0.2) at the
// middles of even bands, each circle sampled evenly from a random start, `per_gap` points per
// plane gap. Near the poles the circles lie several gaps apart on the surface.
Points sphere_contour_stack(std::size_t slices, double per_gap, std::uint64_t seed);
// A cylinder of radius 1 round the same axis, 2 long, cut the same way: its flat ends lie
// beyond the first and last circles and get no points.
Points cylinder_contour_stack(std::size_t slices, double per_gap, std::uint64_t seed);
// The vertices marching cubes puts on the surface f = 0 of a segmented CT or MRI volume: the
// point where f, linear along each edge of an n[0] x n[1] x n[2] grid over the cube [-1, 1]^3,
// changes sign. With n[2] below n[0] and n[1], slices lie farther apart than the voxels in
// them, as in most CT scans.
Points marching_cubes_vertices(double (*f)(double x, double y, double z), const int n[3]);
// A range scan of the box [-hx, hx] x [-hy, hy] x [-hz, hz]: `views` cameras round the y axis,
// 4 half-diagonals away, at `elevation` radians alternately below and above the box, each
// casting a resolution x resolution grid of rays and keeping the first hit. A face that only a
// camera at a grazing angle sees is sampled in rows 1 / sin(angle) times farther apart than
// the points along them.
Points scanned_box(double hx, double hy, double hz, int views, int resolution, double elevation);
// Greedy blue-noise thinning: keeps candidates (in order) at least min_distance from all kept.
Points thin_points(const Points &candidates, double min_distance);

}  // namespace moa::test
