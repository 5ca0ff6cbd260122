#include "core/cut_cap.hpp"

#include <algorithm>
#include <cmath>

#include "core/pca.hpp"

namespace moa {
namespace {

struct Point2 {
  double x, y;
};

double cross2(const Point2 &o, const Point2 &a, const Point2 &b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

}  // namespace

std::vector<Tri> flat_cap(const std::vector<Vec3> &points, const std::vector<uint32_t> &loop) {
  const std::size_t n = loop.size();
  if (n < 3) return {};
  const PcaFrame f = pca_frame(points, loop[0], loop.data() + 1, unsigned(n - 1));
  std::vector<Point2> q(n);
  double area = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = points[loop[i]] - f.centroid;
    q[i] = {dot(d, f.axis[1]), dot(d, f.axis[2])};
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 &a = q[i], &b = q[(i + 1) % n];
    area += a.x * b.y - a.y * b.x;
  }
  if (area == 0) return {};
  const double turn = area > 0 ? 1 : -1;  // the sign of a convex corner

  // The polygon as a ring of the corners not clipped yet.
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  std::vector<bool> clipped(n, false);
  std::vector<double> quality(n);  // the ear's smallest angle; negative when i is no ear
  auto measure = [&](std::size_t i) {
    const std::size_t a = prev[i], c = next[i];
    quality[i] = -1;
    if (!(turn * cross2(q[a], q[i], q[c]) > 0)) return;  // reflex, or flat
    for (std::size_t j = next[c]; j != a; j = next[j]) {
      // No other corner inside the ear or on its sides.
      const double s0 = turn * cross2(q[a], q[i], q[j]), s1 = turn * cross2(q[i], q[c], q[j]),
                   s2 = turn * cross2(q[c], q[a], q[j]);
      if (s0 >= 0 && s1 >= 0 && s2 >= 0) return;
    }
    quality[i] = smallest_angle(points[loop[a]], points[loop[i]], points[loop[c]]);
  };
  for (std::size_t i = 0; i < n; ++i) measure(i);

  std::vector<Tri> tris;
  tris.reserve(n - 2);
  for (std::size_t left = n; left > 3; --left) {
    std::size_t best = n;
    for (std::size_t i = 0; i < n; ++i)
      if (!clipped[i] && quality[i] >= 0 && (best == n || quality[i] > quality[best])) best = i;
    if (best == n) return {};
    const std::size_t a = prev[best], c = next[best];
    tris.push_back({loop[a], loop[best], loop[c]});
    clipped[best] = true;
    next[a] = c;
    prev[c] = a;
    measure(a);
    measure(c);
  }
  std::size_t i = 0;
  while (clipped[i]) ++i;
  const std::size_t a = prev[i], c = next[i];
  if (!(turn * cross2(q[a], q[i], q[c]) > 0)) return {};
  tris.push_back({loop[a], loop[i], loop[c]});
  return tris;
}

}  // namespace moa
