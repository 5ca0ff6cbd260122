// Stage 2: neighbours. A nanoflann kd-tree over the Morton-ordered points answers the k-NN
// queries in parallel blocks; each point also gets its spacing. The PCA plane of a point and its
// neighbours is the topology judgment's local reference plane.
#include "core/neighbors.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/kd_tree.hpp"
#include "core/pca.hpp"

namespace moa {
namespace {

// Anisotropic samples: CT and MRI contour stacks, scanner stripes. Points lie close together
// along lines that are several times farther apart, so a point's nearest neighbours all lie on
// its own line, and their mean distance measures the line, not the gaps between lines, which
// the sphere of a segment must reach across. A neighbour is "across" when the direction to it
// makes more than 30 degrees with the line through the nearest one (cos^2 30 = 0.75). In such
// a cloud the spacing is at least kAcrossShare of the distance to the nearest across.
constexpr double kAlongCos2 = 0.75;
constexpr double kAcrossShare = 0.8;
// The sphere of a segment takes its points from the lists of the segment's ends, which must
// reach a few points into the next lines. In a lined cloud whose first neighbour across comes
// at this (0-based) rank or deeper in half of the lists, the lists are recomputed
// kAcrossListFactor times that long, at most kMaxLinedNeighbors: a bunny stack of 60 slices
// with 5 points per slice gap has it at rank 10, and closes with lists of 50 (with 20: 2,507
// boundary edges in 61 pieces). With 3 points per gap it comes at rank 5-6: from 8 down to 5,
// sphere stacks of 40-80 slices at 3 per gap went from 54-244 boundary edges to closed, and a
// bunny cut by 60 oblique slices from 154 to closed.
constexpr unsigned kDeepAcrossRank = 5;
constexpr unsigned kAcrossListFactor = 5;
constexpr std::size_t kMaxLinedNeighbors = 96;
// Near an object's top and bottom the surface runs nearly along the slices, and the next line
// can lie farther than a list reaches along the point's own line. Such a point's list gives its
// last 1/kAcrossInList to the nearest points across, found among its nearest kDeepAcrossQuery
// (a half: more boundary edges on the stacks tried; all of the list: more again).
constexpr unsigned kAcrossInList = 4;
constexpr std::size_t kDeepAcrossQuery = 384;
// A point on a line in a cloud that is not lined as a whole is in a lined region when at least
// this share of its neighbours lie on lines too (widen_lined_regions).
constexpr double kLinedRegionShare = 0.5;
static_assert(kMaxLinedNeighbors < 256, "a rank must fit the byte knn_pass keeps it in");

// Thin walls (a plate, a pipe two or three spacings thick): the far sheet fills a quarter of
// a point's list, whose thickness then rivals its width, and the list's fitted "normal" may lie
// in the wall. There the nearest kNearPlaneNeighbors, on the point's own sheet, give the plane.
// A list counts as distorted so when its smallest spread exceeds kThickList of the middle one
// (a clean surface gives a few percent, a right-angled crease about 0.28), and the nearest give
// a clean plane (not a line) at least 30 degrees from the list's, with every other neighbour
// off that plane on one side of it at about one height: a second sheet parallel to the first.
// At a crease or a sharp edge the far face rises steadily from the near one instead.
constexpr unsigned kNearPlaneNeighbors = 10;
constexpr double kThickList = 0.3;
constexpr double kCleanPlane = 0.05;      // smallest spread over the middle one, at most
constexpr double kNotALine = 0.1;         // middle spread over the largest, at least
constexpr double kSameNormalCos2 = 0.75;  // cos^2 30
constexpr double kOffPlaneSin2 = 0.25;    // sin^2 30: farther off the plane is on the far sheet
constexpr double kParallelSheet = 0.6;    // lowest over highest height off the plane, at least
constexpr unsigned kMinFarSheet = 2;      // points off the plane that make a far sheet, at least
constexpr unsigned kMinNearSheet = 2;     // and neighbours left on the point's own sheet
constexpr unsigned kMaxListLength = 256;  // longest list refitted as two sheets
// A list holding at least half of a small cloud whose smallest spread is at least this share of
// its largest has no plane (LocalPlane::undirected). A regular dodecahedron's corners: 1; the
// corners of boxes 1 x 2 x 3 and 2 x 3 x 5: 0.11 and 0.16, where the plane of the two largest
// sides still leads the growth right (at 0.1 they opened). Of 189 clouds of 4-41 points
// (polyhedra, boxes, random spheres and ellipsoids) 173 close on every point, 172 at 0.5, 171
// with no point undirected (and a sphere of 39 random points of core test tiny_spheres opens).
constexpr double kUndirectedSpread = 0.25;
// The nearest neighbours' plane serves only in a cloud of thin walls, where at least this share
// of the points see a far sheet so (8-26 % on plates, pipes and bowls two to three spacings
// thick). On other clouds 0-2 % do, at a thin flap or where a coarse sample's neighbours happen
// to line up; there the few changed normals mostly changed which samples of a family closed
// (57 of 72 coarse samples of four shapes closed with their genus with the rule everywhere,
// 58 without).
constexpr double kThinWallShare = 0.05;
constexpr std::size_t kThinWallSamples = 2000;
// In a cloud of thin walls the far sheet takes up to half of a point's list, and a list of the
// parameter's length leaves too few points of the near sheet for the third vertices and the
// spheres of Algorithm 1 (concentric spheres 1.8-2.2 spacings apart, 20k points: 955-1,107
// boundary edges with genus 35-40 at 1.8, and joined into one surface at 2.0-2.2). There the
// lists are kThinWallListFactor times as long: 37-187 boundary edges at 1.8, two closed
// spheres at 2.0-2.2 (1.5 times: 235-443 and closed; 2.5 and 3 times about the same as 2).
constexpr unsigned kThinWallListFactor = 2;

// The neighbours of point i off the plane through it with normal n (over 30 degrees up): on
// the far sheet of a thin wall, or past a crease. How many, whether all on one side of the
// plane (counting stops at the first on the other), and their lowest and highest height;
// far[j], when given, marks each of them.
struct OffPlane {
  unsigned count = 0;
  bool one_side = true;
  double low = 0, high = 0;
};
OffPlane off_plane_neighbours(const std::vector<Vec3> &p, uint32_t i, const uint32_t *list,
                              unsigned k, const Vec3 &n, bool *far = nullptr) {
  OffPlane off;
  int side = 0;
  for (unsigned j = 0; j < k; ++j) {
    const Vec3 d = p[list[j]] - p[i];
    const double h = dot(d, n);
    const bool is_off = h * h > kOffPlaneSin2 * norm2(d);
    if (far) far[j] = is_off;
    if (!is_off) continue;
    if (side != 0 && (h > 0 ? 1 : -1) != side) {
      off.one_side = false;
      return off;
    }
    side = h > 0 ? 1 : -1;
    off.low = off.count == 0 ? std::fabs(h) : std::min(off.low, std::fabs(h));
    off.high = std::max(off.high, std::fabs(h));
    ++off.count;
  }
  return off;
}

// Whether the neighbours off the plane through point i with normal n lie on one side of it at
// about one height: a second sheet parallel to the point's own.
bool far_sheet_parallel(const std::vector<Vec3> &p, uint32_t i, const uint32_t *list, unsigned k,
                        const Vec3 &n) {
  const OffPlane off = off_plane_neighbours(p, i, list, k, n);
  return off.one_side && off.count >= kMinFarSheet && off.low >= kParallelSheet * off.high;
}

// Point i's plane, when its list is distorted by a far sheet: the normal of its nearest.
bool near_sheet_normal(const std::vector<Vec3> &p, uint32_t i, const uint32_t *list, unsigned k,
                       const PcaFrame &all, Vec3 &normal) {
  if (k <= kNearPlaneNeighbors || !(all.spread[0] > kThickList * all.spread[1])) return false;
  const PcaFrame nearest = pca_frame(p, i, list, kNearPlaneNeighbors);
  const Vec3 &n = nearest.axis[0];
  const double agree = dot(all.axis[0], n);
  if (!(nearest.spread[0] < kCleanPlane * nearest.spread[1]) ||
      !(nearest.spread[1] > kNotALine * nearest.spread[2]) || agree * agree > kSameNormalCos2)
    return false;
  if (!far_sheet_parallel(p, i, list, k, n)) return false;
  normal = n;
  return true;
}

// Point i's plane, when its list holds both sheets of a thin wall in a way that tilts the
// list's plane (the far sheet's share off to one side), refitted from the list's normal n as
// two parallel sheets: the neighbours off the plane through i make the far sheet. Two rounds,
// each sorting the neighbours by the plane of the round before. False when the far sheet is
// too small or lies on both sides (a crease or a curved surface, not a wall).
bool two_sheet_normal(const std::vector<Vec3> &p, uint32_t i, const uint32_t *list, unsigned k,
                      Vec3 &n) {
  std::array<bool, kMaxListLength> far;
  if (k > far.size()) return false;
  for (int round = 0; round < 2; ++round) {
    const OffPlane off = off_plane_neighbours(p, i, list, k, n, far.data());
    if (!off.one_side || off.count < kMinFarSheet || k - off.count < kMinNearSheet) return false;
    n = pca_frame_two_sheets(p, i, list, k, far.data()).axis[0];
  }
  return true;
}

// Whether enough of an even sample of the points see a far sheet.
bool has_thin_walls(const std::vector<Vec3> &p, const Neighborhood &nb) {
  const std::size_t n = p.size(), step = std::max<std::size_t>(1, n / kThinWallSamples);
  std::size_t seen = 0, sampled = 0;
  Vec3 normal;
  for (std::size_t i = 0; i < n; i += step, ++sampled) {
    const PcaFrame all = pca_frame(p, uint32_t(i), nb.of(uint32_t(i)), nb.k);
    seen += near_sheet_normal(p, uint32_t(i), nb.of(uint32_t(i)), nb.k, all, normal);
  }
  return double(seen) >= kThinWallShare * double(sampled);
}

// One k-NN pass with nb.k neighbours per point: the lists, the spacing (mean distance to the
// nearest kSpacingNeighbors) and, per point, the rank of its first neighbour across (nb.k when
// none is) and the distance to it (0 when none is).
void knn_pass(const KdIndex &index, Neighborhood &nb, std::vector<uint8_t> &across_rank,
              std::vector<float> &across_gap, const std::function<void(double)> &tick) {
  const std::vector<Vec3> &p = index.points();
  const std::size_t n = p.size();
  nb.knn.assign(n * nb.k, 0);
  nb.spacing.assign(n, 0.0f);
  across_rank.assign(n, uint8_t(nb.k));
  across_gap.assign(n, 0.0f);
  const unsigned want = nb.k + 1;  // the point itself comes back too
  const std::size_t block = 16384;
  for (std::size_t start = 0; start < n; start += block) {
    const std::size_t end = std::min(n, start + block);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(start, end, 256),
                      [&](const tbb::blocked_range<std::size_t> &r) {
                        std::vector<uint32_t> idx(want);
                        std::vector<double> d2(want);
                        std::vector<std::pair<double, uint32_t>> list;
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          std::size_t got = index.nearest(p[i], want, idx.data(), d2.data());
                          list.clear();
                          for (std::size_t j = 0; j < got && list.size() < nb.k; ++j)
                            if (idx[j] != i) list.push_back({norm2(p[idx[j]] - p[i]), idx[j]});
                          // Ties at equal distance come back in tree order; sorted by (distance,
                          // index) the lists are canonical.
                          std::sort(list.begin(), list.end());
                          if (list.empty()) continue;  // a single point
                          uint32_t *out = nb.knn.data() + i * nb.k;
                          const unsigned m = unsigned(list.size());
                          for (unsigned j = 0; j < m; ++j) out[j] = list[j].second;
                          const LineMeasure line = measure_line(p, uint32_t(i), out, m);
                          nb.spacing[i] = float(line.spacing);
                          across_gap[i] = float(line.across_gap);
                          across_rank[i] = uint8_t(line.across_rank);
                        }
                      });
    tick(double(end) / double(n));
  }
}

// Points on lines whose lists hold no neighbour across (`short_of_across`): the last part of
// each list goes to the nearest points across (kAcrossInList), and the spacing spans the gap
// to them. With `lined_around`, only where the nearest point across is marked in it.
void reach_across(const KdIndex &index, Neighborhood &nb,
                  const std::vector<uint32_t> &short_of_across,
                  const std::vector<uint8_t> *lined_around = nullptr) {
  const std::vector<Vec3> &p = index.points();
  const unsigned most = std::max(1u, nb.k / kAcrossInList);
  const std::size_t want = std::min(kDeepAcrossQuery + 1, p.size());
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, short_of_across.size(), 64),
      [&](const tbb::blocked_range<std::size_t> &r) {
        std::vector<std::pair<uint32_t, double>> near;  // (point, squared distance), nearest first
        std::vector<uint32_t> across;
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          const uint32_t i = short_of_across[t];
          uint32_t *list = nb.knn.data() + std::size_t(i) * nb.k;
          const Vec3 along = p[list[0]] - p[i];
          index.nearest_many(p[i], want, near);
          across.clear();
          double gap2 = 0;
          for (const auto &[j, d2] : near) {
            if (j == i || !off_line(p[j] - p[i], along)) continue;
            if (across.empty()) gap2 = d2;
            across.push_back(j);
            if (across.size() == most) break;
          }
          if (lined_around && !across.empty() && !(*lined_around)[across[0]]) continue;
          // All of them lie beyond the list: in place of its farthest, it stays nearest first.
          std::copy(across.begin(), across.end(), list + (nb.k - across.size()));
          if (!across.empty())
            nb.spacing[i] = std::max(nb.spacing[i], float(kAcrossShare * std::sqrt(gap2)));
        }
      });
}

// Lined regions of a cloud that is not lined as a whole: where a range scan met a face at a
// grazing angle, its rows of points lie several spacings apart there and nowhere else, and a
// spacing measured along them keeps the segments' spheres from reaching the next row (the
// top of fandisk scanned by three cameras at 17 degrees, `moa_bench scan`: 1,125 boundary
// edges and 3,455 points left out). A point on a line at least kLinedRegionShare of whose neighbours lie on
// lines too is treated there as in a lined cloud, where the nearest point across is in such a
// neighbourhood as well: its spacing spans the gap across, and a list that holds no point
// across reaches over to the nearest ones. Points that line up by chance in an even sample
// (about 3 %) have few such neighbours; a row of points standing off a surface (a wire) has
// none across.
void widen_lined_regions(const KdIndex &index, Neighborhood &nb,
                         const std::vector<uint8_t> &across_rank,
                         const std::vector<float> &across_gap) {
  const std::size_t n = index.points().size();
  std::vector<uint8_t> on(n), among(n);
  for (std::size_t i = 0; i < n; ++i) on[i] = on_a_line(nb.spacing[i], across_gap[i]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                    [&](const tbb::blocked_range<std::size_t> &r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) {
                        const uint32_t *list = nb.of(uint32_t(i));
                        unsigned lined = 0;
                        for (unsigned j = 0; j < nb.k; ++j) lined += on[list[j]];
                        among[i] = double(lined) >= kLinedRegionShare * double(nb.k);
                      }
                    });
  std::vector<uint32_t> short_of_across;
  for (uint32_t i = 0; i < n; ++i) {
    if (!on[i] || !among[i]) continue;
    if (across_gap[i] == 0) {
      short_of_across.push_back(i);
    } else if (among[nb.of(i)[across_rank[i]]]) {
      nb.spacing[i] = std::max(nb.spacing[i], float(kAcrossShare * across_gap[i]));
    }
  }
  reach_across(index, nb, short_of_across, &among);
}

}  // namespace

Neighborhood compute_neighbors(const KdIndex &index, unsigned k,
                               const std::function<void(double)> &tick) {
  const std::size_t n = index.points().size();
  Neighborhood nb;
  nb.k = unsigned(std::min<std::size_t>(k, n - 1));
  std::vector<uint8_t> across_rank;
  std::vector<float> across_gap;
  knn_pass(index, nb, across_rank, across_gap, tick);

  std::size_t lined = 0;
  for (std::size_t i = 0; i < n; ++i) lined += on_a_line(nb.spacing[i], across_gap[i]);
  if (double(lined) < kLinedShare * double(n)) {
    // Only here: in a cloud sampled along lines a point's nearest lie on a line, not a plane.
    nb.thin_walls = has_thin_walls(index.points(), nb);
    const unsigned longer = unsigned(std::min<std::size_t>(kThinWallListFactor * nb.k, n - 1));
    if (nb.thin_walls && longer > nb.k) {
      nb.k = longer;
      knn_pass(index, nb, across_rank, across_gap, [&](double) { tick(1.0); });
    }
    widen_lined_regions(index, nb, across_rank, across_gap);
    return nb;
  }
  nb.lined = true;
  std::vector<uint8_t> ranks(across_rank);
  std::nth_element(ranks.begin(), ranks.begin() + std::ptrdiff_t(n / 2), ranks.end());
  const unsigned median_rank = ranks[n / 2];
  if (median_rank >= kDeepAcrossRank) {
    const unsigned wider = unsigned(std::min<std::size_t>(
        {std::size_t(kAcrossListFactor * median_rank), kMaxLinedNeighbors, n - 1}));
    if (wider > nb.k) {
      nb.k = wider;
      knn_pass(index, nb, across_rank, across_gap, [&](double) { tick(1.0); });
    }
  }
  std::vector<uint32_t> short_of_across;
  for (std::size_t i = 0; i < n; ++i) {
    nb.spacing[i] = std::max(nb.spacing[i], float(kAcrossShare * across_gap[i]));
    if (across_gap[i] == 0) short_of_across.push_back(uint32_t(i));
  }
  reach_across(index, nb, short_of_across);
  return nb;
}

bool off_line(const Vec3 &offset, const Vec3 &to_nearest) {
  const double c = dot(offset, to_nearest);
  return c * c < kAlongCos2 * norm2(offset) * norm2(to_nearest);
}

LineMeasure measure_line(const std::vector<Vec3> &p, uint32_t i, const uint32_t *nb,
                         unsigned m) {
  LineMeasure line;
  line.across_rank = m;
  if (m == 0) return line;
  const Vec3 first = p[nb[0]] - p[i];
  const unsigned ns = std::min(kSpacingNeighbors, m);
  double sum = 0;
  for (unsigned j = 0; j < m; ++j) {
    if (j < ns) sum += dist(p[nb[j]], p[i]);
    if (line.across_gap == 0 && off_line(p[nb[j]] - p[i], first)) {
      line.across_gap = dist(p[nb[j]], p[i]);
      line.across_rank = j;
    }
  }
  line.spacing = sum / ns;
  return line;
}

bool on_a_line(double spacing, double across_gap) {
  return across_gap == 0 || kAcrossShare * across_gap > spacing;
}

double median_spacing(const Neighborhood &nb) {
  std::vector<float> s;
  if (nb.isolated.empty()) {
    s = nb.spacing;
  } else {
    s.reserve(nb.spacing.size());
    for (uint32_t i = 0; i < nb.spacing.size(); ++i)
      if (!nb.alone(i)) s.push_back(nb.spacing[i]);
    if (s.empty()) s = nb.spacing;
  }
  std::nth_element(s.begin(), s.begin() + std::ptrdiff_t(s.size() / 2), s.end());
  return std::max(1e-9, double(s[s.size() / 2]));
}

LocalPlane local_plane(const PointSet &points, const Neighborhood &nb, uint32_t i) {
  const std::vector<Vec3> &p = points.work;
  const PcaFrame all = pca_frame(p, i, nb.of(i), nb.k);
  if (lists_hold_half(nb, p.size()) && all.spread[0] >= kUndirectedSpread * all.spread[2])
    return {all.axis[0], false, true};
  Vec3 normal;
  if (!nb.thin_walls) return {all.axis[0], false};
  if (near_sheet_normal(p, i, nb.of(i), nb.k, all, normal)) return {normal, true};
  normal = all.axis[0];
  if (two_sheet_normal(p, i, nb.of(i), nb.k, normal) &&
      far_sheet_parallel(p, i, nb.of(i), nb.k, normal))
    return {normal, true};
  return {all.axis[0], false};
}

Vec3 plane_normal(const PointSet &points, const Neighborhood &nb, uint32_t i) {
  return local_plane(points, nb, i).normal;
}

}  // namespace moa
