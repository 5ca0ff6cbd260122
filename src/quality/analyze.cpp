// analyze_mesh: classifies the faces (C1), then runs the topology, the self-intersection test
// and the angle statistics.
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "quality/analysis.hpp"
#include "quality/exact_predicates.hpp"

namespace moa {
namespace {

using quality::kFaceFlat;
using quality::kFaceInvalid;
using quality::kFaceOk;
using quality::kFaceRepeated;

bool finite3(const double *p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

std::vector<uint8_t> classify_faces(const double *xyz, size_t vertex_count, const uint32_t *tri,
                                    size_t triangle_count) {
  std::vector<uint8_t> cls(triangle_count);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, triangle_count), [&](const auto &range) {
    for (size_t f = range.begin(); f != range.end(); ++f) {
      const uint32_t *t = tri + 3 * f;
      if (t[0] >= vertex_count || t[1] >= vertex_count || t[2] >= vertex_count) {
        cls[f] = kFaceInvalid;
      } else if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
        cls[f] = kFaceRepeated;
      } else {
        const double *a = xyz + 3 * size_t(t[0]), *b = xyz + 3 * size_t(t[1]),
                     *c = xyz + 3 * size_t(t[2]);
        const bool flat = !finite3(a) || !finite3(b) || !finite3(c) || quality::collinear(a, b, c);
        cls[f] = flat ? kFaceFlat : kFaceOk;
      }
    }
  });
  return cls;
}

// Faces with the same vertex set as an earlier face, in either orientation.
size_t count_duplicates(const uint32_t *tri, size_t triangle_count,
                        const std::vector<uint8_t> &cls) {
  std::vector<std::array<uint32_t, 3>> keys;
  keys.reserve(triangle_count);
  for (size_t f = 0; f < triangle_count; ++f) {
    if (cls[f] > kFaceFlat) continue;
    std::array<uint32_t, 3> k = {tri[3 * f], tri[3 * f + 1], tri[3 * f + 2]};
    std::sort(k.begin(), k.end());
    keys.push_back(k);
  }
  tbb::parallel_sort(keys.begin(), keys.end());
  size_t duplicates = 0;
  for (size_t i = 1; i < keys.size(); ++i) duplicates += keys[i] == keys[i - 1];
  return duplicates;
}

// Smallest angle of a triangle in degrees: the one opposite the shortest side.
double smallest_angle(const double *a, const double *b, const double *c) {
  const double *p[3] = {a, b, c};
  double len2[3];
  for (int k = 0; k < 3; ++k) {
    const double *u = p[(k + 1) % 3], *w = p[(k + 2) % 3];  // side opposite corner k
    len2[k] = (u[0] - w[0]) * (u[0] - w[0]) + (u[1] - w[1]) * (u[1] - w[1]) +
              (u[2] - w[2]) * (u[2] - w[2]);
  }
  const int k = len2[0] <= len2[1] ? (len2[0] <= len2[2] ? 0 : 2) : (len2[1] <= len2[2] ? 1 : 2);
  const double *o = p[k], *u = p[(k + 1) % 3], *w = p[(k + 2) % 3];
  const double e1[3] = {u[0] - o[0], u[1] - o[1], u[2] - o[2]};
  const double e2[3] = {w[0] - o[0], w[1] - o[1], w[2] - o[2]};
  const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
               cz = e1[0] * e2[1] - e1[1] * e2[0];
  const double d = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), d) * (180.0 / 3.14159265358979323846);
}

void angle_statistics(const double *xyz, const uint32_t *tri, size_t triangle_count,
                      const std::vector<uint8_t> &cls, MeshReport &r) {
  size_t n = 0, below10 = 0, below20 = 0, below30 = 0;
  double sum = 0, lowest = 180;
  for (size_t f = 0; f < triangle_count; ++f) {
    if (cls[f] > kFaceFlat) continue;
    const uint32_t *t = tri + 3 * f;
    double angle = 0;  // collinear and non-finite faces count as zero angles
    if (cls[f] == kFaceOk)
      angle = smallest_angle(xyz + 3 * size_t(t[0]), xyz + 3 * size_t(t[1]), xyz + 3 * size_t(t[2]));
    ++n;
    sum += angle;
    lowest = std::min(lowest, angle);
    below10 += angle < 10;
    below20 += angle < 20;
    below30 += angle < 30;
    const size_t bin = std::min<size_t>(static_cast<size_t>(angle / 5.0), r.min_angle_histogram.size() - 1);
    ++r.min_angle_histogram[bin];
  }
  if (n == 0) return;
  r.min_angle = lowest;
  r.mean_min_angle = sum / double(n);
  r.share_below_10 = double(below10) / double(n);
  r.share_below_20 = double(below20) / double(n);
  r.share_below_30 = double(below30) / double(n);
}

}  // namespace

MeshReport analyze_mesh(const double *xyz, size_t vertex_count, const uint32_t *tri,
                        size_t triangle_count) {
  const auto start = std::chrono::steady_clock::now();
  MeshReport r;
  r.vertices = vertex_count;
  r.triangles = triangle_count;
  const std::vector<uint8_t> cls = classify_faces(xyz, vertex_count, tri, triangle_count);
  for (uint8_t c : cls) {
    r.invalid_faces += c == kFaceInvalid;
    r.degenerate_faces += c == kFaceFlat || c == kFaceRepeated;
  }
  r.duplicate_faces = count_duplicates(tri, triangle_count, cls);
  quality::analyze_topology(xyz, vertex_count, tri, triangle_count, cls, r);
  quality::find_self_intersections(xyz, tri, triangle_count, cls, r);
  angle_statistics(xyz, tri, triangle_count, cls, r);
  r.analysis_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace moa
