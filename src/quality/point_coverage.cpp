// How many input points ended up as mesh vertices (`moa check --points`). Mesh files may store
// single precision, so points match vertices within a small tolerance found with a hash grid.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "quality/quality.hpp"

namespace moa {
namespace {

struct CellHash {
  size_t operator()(const std::array<int64_t, 3> &c) const {
    uint64_t h = uint64_t(c[0]) * 0x9E3779B97F4A7C15ull;
    h ^= uint64_t(c[1]) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= uint64_t(c[2]) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return size_t(h);
  }
};

}  // namespace

void add_point_coverage(MeshReport &r, const double *points, size_t point_count,
                        const double *xyz, size_t vertex_count, const uint32_t *tri,
                        size_t triangle_count) {
  r.has_input_points = true;
  r.input_points = point_count;
  r.input_points_on_mesh = 0;

  std::vector<uint8_t> used(vertex_count, 0);
  for (size_t i = 0; i < 3 * triangle_count; ++i)
    if (tri[i] < vertex_count) used[tri[i]] = 1;

  // Float rounding moves a coordinate by at most 2^-24 of its magnitude.
  double largest = 0;
  for (size_t v = 0; v < vertex_count; ++v)
    if (used[v])
      for (int k = 0; k < 3; ++k)
        if (std::isfinite(xyz[3 * v + k])) largest = std::max(largest, std::fabs(xyz[3 * v + k]));
  const double tol = std::max(largest * 0x1p-21, 1e-300);

  std::unordered_map<std::array<int64_t, 3>, std::vector<uint32_t>, CellHash> grid;
  auto cell_of = [&](const double *p) {
    return std::array<int64_t, 3>{int64_t(std::floor(p[0] / tol)), int64_t(std::floor(p[1] / tol)),
                                  int64_t(std::floor(p[2] / tol))};
  };
  auto finite = [](const double *p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  };
  for (size_t v = 0; v < vertex_count; ++v)
    if (used[v] && finite(xyz + 3 * v)) grid[cell_of(xyz + 3 * v)].push_back(uint32_t(v));

  const double tol2 = tol * tol;
  for (size_t i = 0; i < point_count; ++i) {
    const double *p = points + 3 * i;
    if (!finite(p) || std::fabs(p[0]) > 2 * largest + tol || std::fabs(p[1]) > 2 * largest + tol ||
        std::fabs(p[2]) > 2 * largest + tol)
      continue;  // far outside the mesh (and safe from integer overflow below)
    const auto c = cell_of(p);
    bool found = false;
    for (int dx = -1; dx <= 1 && !found; ++dx)
      for (int dy = -1; dy <= 1 && !found; ++dy)
        for (int dz = -1; dz <= 1 && !found; ++dz) {
          auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (uint32_t v : it->second) {
            const double *q = xyz + 3 * size_t(v);
            const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                              (p[2] - q[2]) * (p[2] - q[2]);
            if (d2 <= tol2) { found = true; break; }
          }
        }
    r.input_points_on_mesh += found;
  }
}

}  // namespace moa
