// Smoothest triangulation of a hole's loop by dynamic programming (see hole_patch.hpp).
#include "core/hole_patch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace moa {
namespace {

// Corners wider than this make a triangle too thin to count as a patch face.
const double kMinCornerCos = std::cos(degrees_to_radians(178.0));

// Cost of a (partial) patch: its worst dihedral angle, then its area. Compared in that order,
// so a patch that folds nowhere beats any smaller one that folds somewhere.
struct Cost {
  double worst_angle = std::numeric_limits<double>::infinity();
  double area = std::numeric_limits<double>::infinity();
  bool operator<(const Cost &o) const {
    if (worst_angle != o.worst_angle) return worst_angle < o.worst_angle;
    return area < o.area;
  }
};

bool thin(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  const Vec3 *p[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    Vec3 u = *p[(i + 1) % 3] - *p[i], w = *p[(i + 2) % 3] - *p[i];
    double lu = norm(u), lw = norm(w);
    if (lu == 0 || lw == 0 || dot(u, w) < kMinCornerCos * lu * lw) return true;
  }
  return false;
}

}  // namespace

std::vector<Tri> smoothest_patch(const std::vector<Vec3> &points, const std::vector<uint32_t> &loop,
                                 const std::vector<Vec3> &rim_normals,
                                 const std::function<bool(uint32_t, uint32_t)> &is_edge) {
  const std::size_t n = loop.size();
  if (n < 3) return {};
  std::vector<uint32_t> sorted(loop);
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return {};

  // cost[i][k], apex[i][k]: best patch of the sub-polygon loop[i..k] closed by the edge k -> i,
  // and the third corner of its triangle on that edge. normal[i][k]: that triangle's normal.
  std::vector<Cost> cost(n * n);
  std::vector<uint32_t> apex(n * n, 0);
  std::vector<Vec3> normal(n * n, Vec3{0, 0, 0});
  auto at = [n](std::size_t i, std::size_t k) { return i * n + k; };
  for (std::size_t i = 0; i + 1 < n; ++i) cost[at(i, i + 1)] = Cost{0, 0};
  // A chord that is an edge of the mesh already would get a third face.
  std::vector<char> chord_taken(n * n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = i + 2; k < n; ++k)
      if (!(i == 0 && k == n - 1)) chord_taken[at(i, k)] = is_edge(loop[i], loop[k]);

  for (std::size_t gap = 2; gap < n; ++gap) {
    for (std::size_t i = 0; i + gap < n; ++i) {
      const std::size_t k = i + gap;
      if (chord_taken[at(i, k)]) continue;
      const Vec3 &pi = points[loop[i]], &pk = points[loop[k]];
      for (std::size_t m = i + 1; m < k; ++m) {
        const Cost &left = cost[at(i, m)], &right = cost[at(m, k)];
        if (!std::isfinite(left.area) || !std::isfinite(right.area)) continue;
        const Vec3 &pm = points[loop[m]];
        if (thin(pi, pm, pk)) continue;
        Vec3 c = cross(pm - pi, pk - pi);
        double twice_area = norm(c);
        Vec3 nt = c * (1.0 / twice_area);
        // Neighbours across i-m and m-k: the mesh's faces on the rim, or the sub-patches' tops.
        const Vec3 &nl = m == i + 1 ? rim_normals[i] : normal[at(i, m)];
        const Vec3 &nr = k == m + 1 ? rim_normals[m] : normal[at(m, k)];
        Cost total;
        total.worst_angle = std::max(
            {left.worst_angle, right.worst_angle, angle_between(nt, nl), angle_between(nt, nr)});
        if (i == 0 && k == n - 1)  // the top triangle also meets the rim along k -> i
          total.worst_angle = std::max(total.worst_angle, angle_between(nt, rim_normals[n - 1]));
        total.area = left.area + right.area + 0.5 * twice_area;
        if (total < cost[at(i, k)]) {
          cost[at(i, k)] = total;
          apex[at(i, k)] = uint32_t(m);
          normal[at(i, k)] = nt;
        }
      }
    }
  }
  if (!std::isfinite(cost[at(0, n - 1)].area)) return {};

  // Unwind the choices; each triangle keeps the loop's direction, so the mesh's orientation.
  std::vector<Tri> patch;
  std::vector<std::pair<std::size_t, std::size_t>> todo{{0, n - 1}};
  while (!todo.empty()) {
    auto [i, k] = todo.back();
    todo.pop_back();
    if (k < i + 2) continue;
    const std::size_t m = apex[at(i, k)];
    patch.push_back({loop[i], loop[m], loop[k]});
    todo.push_back({i, m});
    todo.push_back({m, k});
  }
  return patch;
}

std::vector<Tri> smoothest_patch(MeshState &mesh, const std::vector<Vec3> &points,
                                 const std::vector<uint32_t> &loop) {
  std::vector<Vec3> rim(loop.size());
  for (std::size_t j = 0; j < loop.size(); ++j) {
    uint32_t fs[2];
    if (mesh.edge_faces(loop[j], loop[(j + 1) % loop.size()], fs) != 1) return {};
    const Tri f = mesh.oriented(fs[0]);
    rim[j] = normalized(cross(points[f[1]] - points[f[0]], points[f[2]] - points[f[0]]));
  }
  return smoothest_patch(points, loop, rim, [&mesh](uint32_t a, uint32_t b) {
    uint32_t fs[2];
    return mesh.edge_faces(a, b, fs) > 0;
  });
}

}  // namespace moa
