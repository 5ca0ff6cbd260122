#include "core/smoothing.hpp"

#include <tbb/concurrent_vector.h>
#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include "core/kd_tree.hpp"
#include "core/neighbors.hpp"
#include "core/pca.hpp"

namespace moa {
namespace {

// Neighbourhood sizes the estimate compares; the first two are the "small" scale.
constexpr unsigned kScales[] = {10, 20, 40, 80, 160, 320};
constexpr int kSmallScales = 2;
// Points sampled for the estimate: enough for stable medians, few enough to cost little; a
// tenth of a small cloud (but at least kMinNoiseSamples), whose own reconstruction is quick.
constexpr std::size_t kNoiseSamples = 2000;
constexpr std::size_t kMinNoiseSamples = 500;
// A neighbourhood of more than this fraction of the cloud measures the object's shape, not its
// surface: on a small cloud it narrows again as it wraps around the whole object.
constexpr std::size_t kMaxScaleFraction = 20;
// A neighbourhood that reaches across a gap to another piece (separate objects a few spacings
// apart) measures how the pieces lie, not the surface: the scales beyond the first neighbour
// this many times farther than the one before it are left unmeasured for that point. Many
// small spheres scattered in a box (100 of 20-100 random points each) looked noisy so, their
// wider neighbourhoods flat across the spheres, and came out smoothed and open.
constexpr double kGapJump = 1.5;
// The cloud is noisy when some larger neighbourhood is flatter than this fraction of the
// roughest small one: a coarse but clean sample can dip by 10-15 % (a tube a few points
// round), noise that matters by 25 % and more.
constexpr double kNoisyDrop = 0.8;
// Below this median thickness / width at the small scale the scatter is too small to matter.
// A clean surface's own curvature gives 0.03-0.1 at 20 points, but that grows with the scale
// instead of dropping, so the drop test tells it apart; a scan whose faces are only slightly
// rough (ball.ply: 0.038, with a second layer half a spacing off in places) still gains.
constexpr double kMinRoughness = 0.03;
// At 10 points a clean plate or a pipe two or more spacings thick gives 0.000-0.018, one 1.7
// spacings thick 0.028 (its 10 nearest reach the far sheet now and then, and there the raw
// points leave a thousand boundary edges where the smoothed copy leaves 382); the noisy clouds
// measured give 0.037 (ball.ply) to 0.69.
constexpr double kFlatFinestScale = 0.02;
// Or the finest neighbourhood is far flatter than the next: two concentric spheres 3-5
// nearest-neighbour distances apart give 0.021-0.024 at 10 points and 0.56-0.76 at 20, where
// 20 points reach the other sphere. On 36 clean clouds not already flat at 10 points, 20
// points were at most 1.8 times rougher (curvature alone: about 1.4), but for scan lines six
// spacings apart (4.0, not noisy either way); on noisy clouds they are smoother.
constexpr double kFarSheetJump = 3.0;
// Thin walls whose finest neighbourhoods are this rough are noisy (noisy_thin_walls): two
// concentric spheres 2.8 spacings apart give 0.02 clean, 0.07, 0.13 and 0.25 with noise of
// 0.05, 0.1 and 0.2 spacings; only the last is left open unsmoothed.
constexpr double kNoisyWallRoughness = 0.15;
// ... and their medians jump by this factor from one size to the next where the far sheet
// comes in: 2.7-7.3 on noisy plates, pipes, cups and concentric spheres 3-4 spacings thick.
// Clean samples rough at 10 points (coarse or irregular ones) rise by at most 1.87, from 10
// points to 20 (elephant at 4k points). Past 20 points, where the far sheet of a wall 3.4-3.9
// spacings thick may come in over two sizes (2.05-2.27 at the steeper), kNoisyWideWallJump is
// enough: clean samples rise by at most 1.74 there (knot2 at 8k points, 160 to 320). From 10
// to 20 a rise of 2.0-2.4 is a wall of about two spacings, which the near-sheet smoothing does
// not help (the plane of a point's 16 nearest straddles it): a pipe 1.9 spacings thick went
// from 131 boundary edges to 2,075.
constexpr double kNoisyWallJump = 2.5;
constexpr double kNoisyWideWallJump = 2.0;
// Half-width of the band around the plane of a point's nearest kProbeNeighbors that its
// smoothing neighbourhood keeps on a noisy thin wall, in units of the distance to the farthest
// of them (about two spacings).
constexpr double kSheetBand = 0.6;
// Noise in part of the cloud (a region scanned from farther off, a second scanner) leaves the
// medians to the clean rest. A sample point looks noisy on its own when it is rough at the
// small scale and some larger neighbourhood is far flatter; the cloud is noisy in part when at
// least kNoisyPartShare of them do. Of 196 clouds the medians call clean (samples and vertex
// sets of the shared meshes, marching-cubes vertices, shells, lattices, gyroids, cones,
// density gradients, stray points) at most 11.4 % look so (a pretzel's marching-cubes
// vertices), 13.5 % with as many stray points as surface points, 25 % two concentric spheres
// 2 spacings apart (whose finest neighbourhoods stand alone, see below). With noise of 0.3-0.7
// nearest-neighbour distances on half of a 20,000-point sample of bunny, elephant, fandisk and
// homer: 11-38 %; building.ply: 41 %. Looser tests (rough above 0.03, a drop to 0.8) found
// 45-51 % on knot2's vertices and a gyroid. Not in clouds of thin walls (finest_alone in
// estimate_noise): 89-97 % of the points of plates and a pipe about two spacings thick look
// noisy so.
constexpr double kPartRoughness = 0.1;
constexpr double kPartDrop = 0.6;
constexpr double kNoisyPartShare = 0.15;
// In the caller's points, a point counts so only if its 20 nearest are also flatter than its 10
// nearest: noise keeps a neighbourhood's thickness as it widens, curvature makes it grow faster
// than the width. The vertices of clean meshes sampled coarsely and unevenly (CGAL's dino, elk,
// bones and Chinese dragon: limbs and toes a few spacings round, spacings varying tenfold) are
// rough at 10 points where the surface bends tightly, and flatter at 80-320 points that follow a
// limb's length: 15-25 % of their sample points looked noisy, and smoothed over 80-320 points
// dino's 3,916 vertices kept 820 boundary edges in 17 pieces (76 in 4 unsmoothed). With this test
// 3-7 % do. On 20,000-point samples of bunny, elephant and homer with noise of 0.3-0.7 spacings
// on half of them the share falls by at most 3 points (from 11-32 %). Not in a copy smoothed
// once already: a pass takes the finest scatter away, and what it leaves need not be flatter at
// 20 points (fandisk with noise of 0.7 spacings on half of it needs a second pass to close; with
// this test on the smoothed copy too, it stopped after one: test fandisk_half_noisy_closed).

// Clouds sampled along lines (neighbors.hpp: contour stacks, scanner stripes) whose points
// scatter off their lines: the scatter that matters is set against the short steps along a
// line, where a neighbourhood's width is set by the gaps between lines, and the drop test
// misses it. A cut or a stripe is a plane's section, so a clean line's points lie in one plane:
// the line is rough when the thickness of a point and its nearest neighbours along its line,
// over their length, exceeds kMinLineRoughness in the median. Contour stacks of the shared
// meshes give 0.0000; noise of 5 % of the slice gap 0.037.
constexpr double kMinLineRoughness = 0.02;
constexpr unsigned kLineProbe = 16;  // neighbours looked at for those along the line
constexpr unsigned kLinePoints = 8;  // of which at most this many make the line
constexpr unsigned kMinLinePoints = 4;

// Neighbours whose distances size the smoothing ball.
constexpr unsigned kProbeNeighbors = 16;
// One smoothing size serves the whole cloud, and at a part narrower than its ball (a neck, a
// handle, a tail) the ball wraps round the part: as thick as it is wide, it pulls the part's
// sheets into one quadric (noisy dumbbells smoothed over 320 points kept 434-593 boundary
// edges in 17-28 pieces round their necks). Where a point's whole ball is thicker than
// kWrappedBall (thickness over width: 0.5-1.0 round such necks, 0.05-0.3 on a noisy sheet,
// 0.5-0.6 along a noisy cube's edges, whose rounding does no harm), the quadric is fitted to a
// smaller ball of its nearest, halving from the whole: the largest at most kUnwrappedShare as
// thick (one side of the part), else the flattest if it is at most kFlatterShare as thick
// (where a neck meets a ball the concave joint keeps every ball somewhat thick: without it,
// 28-176 boundary edges stayed there on two of four noisy dumbbells). Such parts are a small
// share of a cloud (2-8 % of the points of noisy dumbbells, linked tori, building.ply, a ball
// with folds); where more than kMaxWrappedShare of the balls are that thick the size is the
// noise's own (concentric spheres 3.5 spacings apart with noise of 0.3 spacings: 44 %) and
// smaller balls would only be rougher, so none is unwrapped. Not on thin walls, whose balls
// keep the near sheet only (near_sheet_only).
constexpr double kWrappedBall = 0.6;
constexpr double kUnwrappedShare = 0.5;
constexpr double kFlatterShare = 0.9;
constexpr double kMaxWrappedShare = 0.25;
// Balls of fewer points (40: about 3.5 spacings in radius) wrap only parts a few spacings thick,
// whose sheets keep_raw_at_thin_parts sees to. There unwrapping helped a noisy ball with ten
// folds a little (666 -> 472 boundary edges, still open) and left one point of a bunny rounded
// to a grid out of its surface.
constexpr unsigned kMinWrappingBall = 80;

// How many of `others`, nearest first once this returns, the quadric of point `self` is
// fitted to when its whole ball, of thickness over width `ratio`, wraps round a part, with
// their frame in `frame`; 0 when no smaller ball is flat enough.
std::size_t unwrapped_size(const std::vector<Vec3> &p, uint32_t self, double ratio,
                           std::vector<uint32_t> &others, PcaFrame &frame) {
  const std::size_t all = others.size();
  if (all < 2 * kProbeNeighbors) return 0;
  const Vec3 &at = p[self];
  std::sort(others.begin(), others.end(), [&](uint32_t a, uint32_t b) {
    const double da = norm2(p[a] - at), db = norm2(p[b] - at);
    return da != db ? da < db : a < b;
  });
  std::size_t flattest = 0;
  double flattest_ratio = kFlatterShare * ratio;
  for (std::size_t size = all / 2; size >= kProbeNeighbors; size /= 2) {
    const PcaFrame f = pca_frame(p, self, others.data(), unsigned(size));
    const double r = flatness_ratio(f);
    if (r <= kUnwrappedShare * ratio) {
      frame = f;
      return size;
    }
    if (r < flattest_ratio) {
      flattest = size;
      flattest_ratio = r;
      frame = f;
    }
  }
  return flattest;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The point moved onto the quadric h(u, v) fitted to its neighbourhood in the frame's plane;
// onto the plane itself when the neighbourhood cannot support a quadric. `f`: the
// neighbourhood's frame.
Vec3 project_onto_quadric(const std::vector<Vec3> &p, uint32_t self, const uint32_t *nb,
                          unsigned k, const PcaFrame &f) {
  // Coordinates in units of the neighbourhood's width keep the system well scaled.
  const double width = std::sqrt(std::max(f.spread[2], 1e-300) / double(k + 1));
  const double to_width = 1.0 / width;
  const Vec3 n = f.axis[0] * to_width, e1 = f.axis[1] * to_width, e2 = f.axis[2] * to_width;
  // The normal equations of the fit in the monomials (u^2, uv, v^2, u, v, 1) hold only the 15
  // sums of u^a v^b with a + b <= 4 (m_ab), and their right side the 6 sums of h u^a v^b with
  // a + b <= 2 (h_ab): 21 sums per neighbour, not the 27 products of each row with itself and h.
  // At a million noisy points, with 320 neighbours each, this fit is the smoothing's main cost.
  double m40 = 0, m31 = 0, m22 = 0, m13 = 0, m04 = 0, m30 = 0, m21 = 0, m12 = 0, m03 = 0;
  double m20 = 0, m11 = 0, m02 = 0, m10 = 0, m01 = 0;
  double h20 = 0, h11 = 0, h02 = 0, h10 = 0, h01 = 0, h00 = 0;
  auto add = [&](uint32_t i) {
    const Vec3 d = p[i] - f.centroid;
    const double u = dot(d, e1), v = dot(d, e2), h = dot(d, n);
    const double uu = u * u, uv = u * v, vv = v * v;
    // clang-format off
    m40 += uu * uu; m31 += uu * uv; m22 += uu * vv; m13 += uv * vv; m04 += vv * vv;
    m30 += uu * u;  m21 += uu * v;  m12 += u * vv;  m03 += vv * v;
    m20 += uu;      m11 += uv;      m02 += vv;      m10 += u;       m01 += v;
    h20 += h * uu;  h11 += h * uv;  h02 += h * vv;  h10 += h * u;   h01 += h * v;  h00 += h;
    // clang-format on
  };
  add(self);
  for (unsigned j = 0; j < k; ++j) add(nb[j]);
  const Vec3 d = p[self] - f.centroid;
  const double u = dot(d, e1), v = dot(d, e2);
  double h = 0;
  if (k + 1 >= 10) {
    // Eigen's LDLT reads the lower triangle alone.
    Eigen::Matrix<double, 6, 6> normal_matrix;
    normal_matrix.col(0) << m40, m31, m22, m30, m21, m20;
    normal_matrix.col(1) << 0, m22, m13, m21, m12, m11;
    normal_matrix.col(2) << 0, 0, m04, m12, m03, m02;
    normal_matrix.col(3) << 0, 0, 0, m20, m11, m10;
    normal_matrix.col(4) << 0, 0, 0, 0, m02, m01;
    normal_matrix.col(5) << 0, 0, 0, 0, 0, double(k + 1);
    Eigen::Matrix<double, 6, 1> rhs;
    rhs << h20, h11, h02, h10, h01, h00;
    Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(normal_matrix);
    if (solver.info() == Eigen::Success && solver.isPositive()) {
      Eigen::Matrix<double, 6, 1> c = solver.solve(rhs);
      double fitted = c(0) * u * u + c(1) * u * v + c(2) * v * v + c(3) * u + c(4) * v + c(5);
      if (std::isfinite(fitted)) h = fitted;
    }
  }
  return f.centroid + (f.axis[1] * u + f.axis[2] * v + f.axis[0] * h) * width;
}

// Where the fitted quadrics cannot follow the surface, a whole region moves several times
// farther than the cloud's median point (a lone point far off, in the tail of the noise, moves
// far amid neighbours that do not). At a sharp crease they round it off, which does no harm:
// the crease's raw points stay the vertices. At a thin part (a bunny's ear) whose two sheets
// share one neighbourhood, a quadric through both pulls them into one, and the mesh chosen on
// that copy has holes there. A point of a thin part was pulled about halfway to the other
// sheet, so two or three times its move lands on that sheet; a point at a crease was pushed
// into the solid, where no points are. On noisy samples 24-70 % of the far-moved points of
// thin parts found the other sheet so, 1-19 % of those at the creases of fandisk and of a cube
// (the most under the heaviest noise). When a cloud's far-moved points find it often enough,
// they keep their raw place in the smoothed copy. Noise heavier than half the
// nearest-neighbour distance (in the median move) is left alone: there clusters of the
// noise's tail move as far as a thin part's sheets, and left raw they stay out of the mesh.
constexpr unsigned kMoveRegion = 10;     // neighbours whose moves are looked at with a point's
constexpr double kMaxRegionMove = 2.5;   // their median move over the cloud's, at most
constexpr double kMaxNoiseForRaw = 0.5;  // median move over median nearest distance, at most
constexpr double kMinThinShare = 0.215;  // far-moved points that find another sheet, at least

// Whether a raw point that the smoothing moved by `push` (of length `moved`) was pulled
// towards another sheet: a point lies two or three moves out, within half that distance (the
// pull need not have stopped halfway).
bool pulled_towards_other_sheet(const KdIndex &index, const Vec3 &raw, const Vec3 &push,
                                double moved) {
  for (double reach : {2.0, 3.0}) {
    uint32_t other;
    double d2;
    index.nearest(raw + push * reach, 1, &other, &d2);
    if (std::sqrt(d2) < 0.5 * reach * moved) return true;
  }
  return false;
}

// `nearest_distance`: the median distance of a point to its nearest neighbour.
void keep_raw_at_thin_parts(const KdIndex &index, double nearest_distance,
                            std::vector<Vec3> &smooth) {
  const std::vector<Vec3> &raw = index.points();
  const std::size_t n = raw.size();
  std::vector<double> moved(n);
  for (std::size_t i = 0; i < n; ++i) moved[i] = dist(raw[i], smooth[i]);
  const double typical = median(moved);
  if (typical > kMaxNoiseForRaw * nearest_distance) return;
  const double limit = kMaxRegionMove * typical;
  const unsigned k = unsigned(std::min<std::size_t>(kMoveRegion + 1, n));
  enum : uint8_t { kMovedLittle, kMovedFar, kFoundOtherSheet };
  std::vector<uint8_t> state(n, kMovedLittle);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t> &r) {
        std::vector<uint32_t> idx(k);
        std::vector<double> d2(k), around;
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          if (moved[i] <= limit) continue;  // a point that moved little stays
          const std::size_t got = index.nearest(raw[i], k, idx.data(), d2.data());
          around.clear();
          for (std::size_t j = 0; j < got; ++j) around.push_back(moved[idx[j]]);
          if (median(around) <= limit) continue;
          state[i] = pulled_towards_other_sheet(index, raw[i], smooth[i] - raw[i], moved[i])
                         ? kFoundOtherSheet
                         : kMovedFar;
        }
      });
  std::size_t far = 0, other_sheet = 0;
  for (uint8_t s : state) {
    far += s != kMovedLittle;
    other_sheet += s == kFoundOtherSheet;
  }
  if (far == 0 || double(other_sheet) < kMinThinShare * double(far)) return;
  for (std::size_t i = 0; i < n; ++i)
    if (state[i] != kMovedLittle) smooth[i] = raw[i];
}

constexpr std::size_t kScaleCount = std::size(kScales);
using ScaleMedians = std::array<double, kScaleCount>;

// `ratios`: thickness over width per sample and scale, -1 where not measured. The median of
// each scale over the samples that `take` (a sample's index) accepts; -1 where none is measured.
template <class Take>
ScaleMedians scale_medians(const std::vector<double> &ratios, std::size_t samples, Take take) {
  ScaleMedians medians;
  std::vector<double> col;
  for (std::size_t c = 0; c < kScaleCount; ++c) {
    col.clear();
    for (std::size_t s = 0; s < samples; ++s)
      if (ratios[s * kScaleCount + c] >= 0 && take(s)) col.push_back(ratios[s * kScaleCount + c]);
    medians[c] = col.empty() ? -1.0 : median(col);
  }
  return medians;
}

// The roughness at the small scale (10 points alone when they stand alone, else the rougher of
// 10 and 20) and the flattest larger scale below it: smoothing_k stays as it was when none is.
void set_scales(const ScaleMedians &m, bool finest_alone, NoiseEstimate &est) {
  est.small_scale = finest_alone ? m[0] : std::max(m[0], m[1]);
  est.large_scale = est.small_scale;
  for (std::size_t c = kSmallScales; c < kScaleCount; ++c)
    if (m[c] >= 0 && m[c] < est.large_scale) {
      est.large_scale = m[c];
      est.smoothing_k = kScales[c];
    }
}

// The cloud is noisy in part when enough of its sample points look noisy on their own (see
// kNoisyPartShare); then the smoothing scale is the one at which those look flattest.
void noisy_in_part(const std::vector<double> &ratios, std::size_t samples, bool smoothed,
                   NoiseEstimate &est) {
  std::vector<char> noisy(samples, 0);
  std::size_t measured = 0, noisy_count = 0;
  for (std::size_t s = 0; s < samples; ++s) {
    const double *r = &ratios[s * kScaleCount];
    if (r[0] < 0 || r[1] < 0) continue;
    ++measured;
    const double small = std::max(r[0], r[1]);
    double large = small;
    for (std::size_t c = kSmallScales; c < kScaleCount; ++c)
      if (r[c] >= 0) large = std::min(large, r[c]);
    noisy[s] = small > kPartRoughness && large < kPartDrop * small && (smoothed || r[1] < r[0]);
    noisy_count += noisy[s];
  }
  if (measured == 0 || double(noisy_count) < kNoisyPartShare * double(measured)) return;
  NoiseEstimate part;
  set_scales(scale_medians(ratios, samples, [&](std::size_t s) { return noisy[s] != 0; }),
             false, part);
  if (part.smoothing_k == 0) return;
  part.noisy = true;
  est = part;
}

// Thin walls with noise on their sheets. Where the neighbourhoods reach the far sheet their
// roughness jumps (kNoisyWallJump, kNoisyWideWallJump), and no larger neighbourhood is ever as
// flat as the noisy finest ones: the drop test cannot see the noise, or sees it at a size
// spanning both sheets and smooths them into one. When the medians jump and the finest scale
// is rough, the cloud is noisy; it is smoothed over the largest neighbourhood short of the
// jump, on the near sheet only (smoothed_points). Returns whether it decided so.
bool noisy_thin_walls(const ScaleMedians &m, NoiseEstimate &est) {
  if (!(m[0] >= kNoisyWallRoughness)) return false;
  for (std::size_t c = 0; c + 1 < kScaleCount && m[c] >= 0 && m[c + 1] >= 0; ++c)
    if (m[c + 1] > (c == 0 ? kNoisyWallJump : kNoisyWideWallJump) * m[c]) {
      est.noisy = true;
      est.thin_walls = true;
      est.smoothing_k = kScales[c];
      est.small_scale = m[0];
      est.large_scale = m[c];
      return true;
    }
  return false;
}

}  // namespace

NoiseEstimate estimate_noise(const KdIndex &index, bool smoothed) {
  const std::vector<Vec3> &work = index.points();
  NoiseEstimate est;
  const std::size_t n = work.size();
  const std::size_t limit = n / kMaxScaleFraction;
  if (limit < kScales[kSmallScales]) return est;
  const unsigned largest = unsigned(std::min<std::size_t>(kScales[std::size(kScales) - 1], limit));
  const std::size_t wanted = std::clamp(n / 10, kMinNoiseSamples, kNoiseSamples);
  const std::size_t step = std::max<std::size_t>(1, n / wanted);
  const std::size_t samples = (n + step - 1) / step;
  std::vector<double> ratios(samples * kScaleCount, -1.0);
  std::vector<double> line_roughness(samples, -1.0);  // -1: not on a line
  tbb::parallel_for(std::size_t(0), samples, [&](std::size_t s) {
    const std::size_t i = s * step;
    std::vector<std::pair<uint32_t, double>> found;
    index.nearest_many(work[i], largest + 1, found);
    std::vector<uint32_t> others;
    for (const auto &f : found)
      if (f.first != i) others.push_back(f.first);
    std::size_t reach = others.size();
    for (std::size_t j = kScales[0] + 1; j < found.size(); ++j)
      if (found[j].second > kGapJump * kGapJump * found[j - 1].second) {
        reach = std::min(reach, j - 1);  // found[0] is the point itself
        break;
      }
    for (std::size_t c = 0; c < kScaleCount; ++c)
      if (kScales[c] <= reach)
        ratios[s * kScaleCount + c] =
            flatness_ratio(pca_frame(work, uint32_t(i), others.data(), kScales[c]));
    const unsigned m = unsigned(std::min<std::size_t>(others.size(), kScales[1]));
    const LineMeasure line = measure_line(work, uint32_t(i), others.data(), m);
    if (on_a_line(line.spacing, line.across_gap)) {
      std::vector<uint32_t> along;
      const Vec3 first = work[others[0]] - work[i];
      const std::size_t probe = std::min<std::size_t>(others.size(), kLineProbe);
      for (std::size_t j = 0; j < probe && along.size() < kLinePoints; ++j)
        if (!off_line(work[others[j]] - work[i], first)) along.push_back(others[j]);
      line_roughness[s] = 0;
      if (along.size() >= kMinLinePoints) {
        const PcaFrame f = pca_frame(work, uint32_t(i), along.data(), unsigned(along.size()));
        if (f.spread[2] > 0)
          line_roughness[s] = std::sqrt(std::max(0.0, f.spread[0]) / f.spread[2]);
      }
    }
  });
  std::vector<double> on_lines;
  for (double r : line_roughness)
    if (r >= 0) on_lines.push_back(r);
  const bool rough_lines = double(on_lines.size()) >= kLinedShare * double(samples) &&
                           median(on_lines) > kMinLineRoughness;
  const ScaleMedians medians = scale_medians(ratios, samples, [](std::size_t) { return true; });
  if (noisy_thin_walls(medians, est)) return est;
  // Finest neighbourhoods that are flat have no scatter that matters, however rough the next
  // size looks: what 20 points add to 10 there is the far sheet of a thin wall (a plate or a
  // pipe two or three spacings thick), and smoothing would fold the two sheets into one.
  const bool finest_alone = medians[0] >= 0 && (medians[0] <= kFlatFinestScale ||
                                                 medians[1] > kFarSheetJump * medians[0]);
  set_scales(medians, finest_alone, est);
  est.noisy = (est.smoothing_k != 0 && est.small_scale > kMinRoughness &&
               est.large_scale < kNoisyDrop * est.small_scale) ||
              rough_lines;
  // Where the finest neighbourhoods stand alone, the rough ones are a thin wall's, not noise:
  // there the 10 nearest of some points straddle both sheets and look just as noise does. So
  // too where the far sheet comes in at 40 points (a wall about two and a half spacings
  // thick): there the 20 nearest of some points reach it (clean concentric spheres 2.5
  // spacings apart, 0.023 and 0.031 at 10 and 20 points, 0.79 at 40, were smoothed into one
  // surface zigzagging between them).
  const bool far_sheet_at_40 = medians[1] >= 0 && medians[2] > kFarSheetJump * medians[1];
  if (!est.noisy && !finest_alone && !far_sheet_at_40)
    noisy_in_part(ratios, samples, smoothed, est);
  return est;
}

std::vector<Vec3> smoothed_points(const KdIndex &index, unsigned k, bool near_sheet_only,
                                  const std::function<void(double)> &tick) {
  const std::vector<Vec3> &work = index.points();
  const std::size_t n = work.size();
  k = unsigned(std::min<std::size_t>(k, n - 1));
  const unsigned probe = std::min(kProbeNeighbors, k);
  std::vector<Vec3> out(n);
  // Nearest-neighbour distances of every step-th point, which the search below finds anyway,
  // for keep_raw_at_thin_parts (-1 until found).
  const std::size_t step = std::max<std::size_t>(1, n / kNoiseSamples);
  std::vector<double> nearest((n + step - 1) / step, -1.0);
  // Points whose ball wraps round a part, each with its place on the quadric of one side.
  std::atomic<std::size_t> wrapped{0};
  tbb::concurrent_vector<std::pair<uint32_t, Vec3>> unwrapped;
  const std::size_t block = 16384;
  for (std::size_t start = 0; start < n; start += block) {
    const std::size_t end = std::min(n, start + block);
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(start, end, 64),
        [&](const tbb::blocked_range<std::size_t> &r) {
          std::vector<uint32_t> idx(probe + 1), others;
          std::vector<double> d2(probe + 1);
          std::vector<std::pair<uint32_t, double>> found;
          for (std::size_t i = r.begin(); i != r.end(); ++i) {
            // A k-NN query for hundreds of points costs k^2 in nanoflann; the ball that holds
            // about k points of a surface, sized from the nearest few, costs k.
            std::size_t got = index.nearest(work[i], probe + 1, idx.data(), d2.data());
            if (i % step == 0 && got >= 2) nearest[i / step] = std::sqrt(d2[1]);
            const double radius2 = d2[got - 1] * double(k) / double(got - 1);
            index.within(work[i], radius2, found);
            // A thick noisy shell holds more than k points in that ball: every s-th will do.
            const std::size_t stride = std::max<std::size_t>(1, found.size() / (2 * k));
            others.clear();
            // On a thin wall, only the points within a band around the nearest ones' plane:
            // the far sheet lies beyond it.
            PcaFrame sheet{};
            double band = 0;
            if (near_sheet_only && got >= 4) {
              sheet = pca_frame(work, uint32_t(i), idx.data() + 1, unsigned(got - 1));
              band = kSheetBand * std::sqrt(d2[got - 1]);
            }
            for (std::size_t j = 0; j < found.size(); j += stride) {
              if (found[j].first == i) continue;
              if (band > 0 &&
                  std::fabs(dot(work[found[j].first] - sheet.centroid, sheet.axis[0])) > band)
                continue;
              others.push_back(found[j].first);
            }
            const unsigned all = unsigned(others.size());
            const PcaFrame whole = pca_frame(work, uint32_t(i), others.data(), all);
            out[i] = project_onto_quadric(work, uint32_t(i), others.data(), all, whole);
            const double ratio = flatness_ratio(whole);
            if (near_sheet_only || k < kMinWrappingBall || !(ratio > kWrappedBall)) continue;
            // Past the share, nothing will be unwrapped: the work is saved.
            if (double(++wrapped) > kMaxWrappedShare * double(n)) continue;
            PcaFrame part;
            if (const std::size_t size = unwrapped_size(work, uint32_t(i), ratio, others, part)) {
              const Vec3 moved =
                  project_onto_quadric(work, uint32_t(i), others.data(), unsigned(size), part);
              unwrapped.push_back({uint32_t(i), moved});
            }
          }
        });
    tick(double(end) / double(n));
  }
  if (double(wrapped) <= kMaxWrappedShare * double(n))
    for (const auto &[i, moved] : unwrapped) out[i] = moved;
  nearest.erase(std::remove(nearest.begin(), nearest.end(), -1.0), nearest.end());
  keep_raw_at_thin_parts(index, median(nearest), out);
  return out;
}

}  // namespace moa
