// Stage 1: points. Exact duplicates collapse onto their first occurrence so that every output
// index is a caller's index; the Morton order makes neighbour queries and the growing mesh
// cache-friendly.
#include "core/point_set.hpp"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>

#include "core/morton.hpp"
#include "core/predicates.hpp"
#include "core/reconstruct.hpp"

namespace moa {
namespace {

// Beyond this magnitude squared distances overflow; the caller must rescale.
constexpr double kMaxMagnitude = 1e150;

void check_finite(const double *xyz, std::size_t count) {
  for (std::size_t i = 0; i < count * 3; ++i) {
    if (!std::isfinite(xyz[i]))
      throw Error(MOA_ERROR_INVALID_INPUT,
                  "point " + std::to_string(i / 3) + " has a non-finite coordinate");
    if (std::fabs(xyz[i]) > kMaxMagnitude)
      throw Error(MOA_ERROR_INVALID_INPUT,
                  "point " + std::to_string(i / 3) +
                      " has a coordinate beyond 1e150 in magnitude; rescale the input");
  }
}

// The caller's point i.
Vec3 point_at(const double *xyz, uint32_t i) {
  const double *p = xyz + 3 * std::size_t(i);
  return {p[0], p[1], p[2]};
}

void swap_points(double *xyz, std::size_t i, std::size_t j) {
  for (int a = 0; a < 3; ++a) std::swap(xyz[3 * i + a], xyz[3 * j + a]);
}

void check_not_collinear(const double *xyz, const std::vector<uint32_t> &unique) {
  // The points are distinct, so the first two define a line.
  const Vec3 a = point_at(xyz, unique[0]), b = point_at(xyz, unique[1]);
  for (std::size_t c = 2; c < unique.size(); ++c)
    if (!collinear(a, b, point_at(xyz, unique[c]))) return;
  throw Error(MOA_ERROR_INVALID_INPUT, "all points are collinear: no surface passes through them");
}

}  // namespace

PointSet prepare_points(const double *xyz, std::size_t count,
                        const std::vector<uint32_t> &merged) {
  if (count < 3)
    throw Error(MOA_ERROR_INVALID_INPUT,
                "at least 3 points are needed, got " + std::to_string(count));
  check_finite(xyz, count);

  PointSet ps;
  ps.input_count = count;

  // Merge exact duplicates: sort by coordinates, index breaking ties, keep the first of a run.
  std::vector<uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  tbb::parallel_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    const double *pa = xyz + 3 * std::size_t(a), *pb = xyz + 3 * std::size_t(b);
    if (pa[0] != pb[0]) return pa[0] < pb[0];
    if (pa[1] != pb[1]) return pa[1] < pb[1];
    if (pa[2] != pb[2]) return pa[2] < pb[2];
    return a < b;
  });
  std::vector<uint32_t> unique, repeated;
  unique.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    if (k > 0) {
      const double *pa = xyz + 3 * std::size_t(order[k]), *pb = xyz + 3 * std::size_t(order[k - 1]);
      if (pa[0] == pb[0] && pa[1] == pb[1] && pa[2] == pb[2]) {
        repeated.push_back(order[k]);
        continue;
      }
    }
    unique.push_back(order[k]);
  }
  std::vector<uint32_t>().swap(order);
  if (!merged.empty()) {
    std::vector<char> drop(count, 0);
    for (uint32_t i : merged) drop[i] = 1;
    auto kept = std::stable_partition(unique.begin(), unique.end(),
                                      [&](uint32_t i) { return drop[i] == 0; });
    repeated.insert(repeated.end(), kept, unique.end());
    unique.erase(kept, unique.end());
  }
  ps.duplicates = repeated.size();
  if (unique.size() < 3)
    throw Error(MOA_ERROR_INVALID_INPUT,
                "only " + std::to_string(unique.size()) +
                    (unique.size() == 1 ? " distinct point" : " distinct points") +
                    " after merging duplicates; at least 3 are needed");

  Vec3 lo = point_at(xyz, unique[0]), hi = lo;
  for (uint32_t i : unique) {
    Vec3 p = point_at(xyz, i);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  Vec3 center = midpoint(lo, hi);
  double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(extent > 1e-280))
    throw Error(MOA_ERROR_INVALID_INPUT,
                "the points span less than 1e-280: too small to be told apart; rescale the input");
  double diag = extent * norm((hi - lo) * (1.0 / extent));  // scaled: no underflow at 1e-300

  // Morton order over the bounding cube; ties (same cell) keep the caller's order.
  std::vector<std::pair<uint64_t, uint32_t>> keyed(unique.size());
  const double cells = double(1 << 21) - 1;
  for (std::size_t k = 0; k < unique.size(); ++k) {
    Vec3 p = point_at(xyz, unique[k]);
    auto q = [&](double v, double l) {
      return std::uint64_t(std::clamp((v - l) / extent * cells, 0.0, cells));
    };
    const std::uint64_t key = morton_code(q(p.x, lo.x), q(p.y, lo.y), q(p.z, lo.z));
    keyed[k] = {key, unique[k]};
  }
  tbb::parallel_sort(keyed.begin(), keyed.end());

  // The exact predicates multiply up to three coordinate differences: at extents far from 1
  // those products underflow or overflow and their signs are lost. Scaling by a power of two is
  // exact and keeps every sign, so bring such clouds to an extent near 1.
  const int shift = (extent < 0x1p-100 || extent > 0x1p100) ? -std::ilogb(extent) : 0;

  check_not_collinear(xyz, unique);
  ps.input = xyz;
  ps.shift = shift;
  ps.work.resize(keyed.size());
  ps.original.resize(count);
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    Vec3 p = point_at(xyz, keyed[k].second);
    ps.work[k] = (p - center) * (1.0 / diag);
    ps.original[k] = keyed[k].second;
  }
  std::copy(repeated.begin(), repeated.end(), ps.original.begin() + std::ptrdiff_t(keyed.size()));
  return ps;
}

// Both directions follow the cycles of the permutation, so each point moves once.
InternalOrder::InternalOrder(const PointSet &points, double *xyz)
    : from_(points.original), xyz_(xyz), moved_(from_.size()) {
  for (std::size_t start = 0; start < from_.size(); ++start) {
    if (moved_[start]) continue;
    std::size_t k = start;
    while (from_[k] != start) {
      swap_points(xyz_, k, from_[k]);  // position k gets its point; k's old one moves on
      moved_[k] = true;
      k = from_[k];
    }
    moved_[k] = true;
  }
}

InternalOrder::~InternalOrder() {
  // Every flag is set: clearing one marks its point as back in the caller's place.
  for (std::size_t start = 0; start < from_.size(); ++start) {
    if (!moved_[start]) continue;
    for (std::size_t k = from_[start]; k != start; k = from_[k]) {
      swap_points(xyz_, start, k);  // start's point goes home to k; k's comes to start
      moved_[k] = false;
    }
    moved_[start] = false;
  }
}

}  // namespace moa
