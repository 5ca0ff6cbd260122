// Broad phase: faces go into the cells of a uniform grid that their boxes cover; a pair is
// judged only in the cell holding the low corner of the boxes' overlap, so each pair is judged
// once without a pair set. The cell size follows the mean face size and grows until the number
// of (cell, face) entries stays linear in the face count, so a few huge faces cannot explode it.
#include "support/intersection_scan.hpp"

#include <algorithm>
#include <cmath>

#include "support/triangle_intersection.hpp"

namespace moa::test {

namespace {

struct Box {
  double lo[3], hi[3];
};

struct Grid {
  double origin[3];
  double cell;
  std::uint32_t cells[3];
  std::uint32_t index(double v, int axis) const {
    const double t = std::floor((v - origin[axis]) / cell);
    if (!(t > 0)) return 0;
    return std::min<std::uint32_t>(cells[axis] - 1, static_cast<std::uint32_t>(std::min(t, 4e9)));
  }
};

std::uint64_t cell_key(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  return std::uint64_t(x) | (std::uint64_t(y) << 21) | (std::uint64_t(z) << 42);
}

std::size_t entry_count(const Grid &g, const std::vector<Box> &boxes,
                        const std::vector<std::uint32_t> &ids) {
  std::size_t total = 0;
  for (std::uint32_t f : ids) {
    std::size_t n = 1;
    for (int a = 0; a < 3; ++a) n *= g.index(boxes[f].hi[a], a) - g.index(boxes[f].lo[a], a) + 1;
    total += n;
  }
  return total;
}

// Exact narrow phase for one pair; returns true on a conflict and the number of shared indices.
bool judge_pair(const double *xyz, const std::uint32_t *t, const std::uint32_t *u, int &shared) {
  int ti[3], ui[3];  // positions of shared indices in t and u
  shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (t[i] == u[j]) {
        ti[shared] = i;
        ui[shared] = j;
        ++shared;
      }
  if (shared == 3) return false;  // same vertex set: a duplicate face, reported under C1
  if (shared == 2) {
    const int ta = 3 - ti[0] - ti[1], ua = 3 - ui[0] - ui[1];
    return shared_edge_conflict(point(xyz, t[ti[0]]), point(xyz, t[ti[1]]), point(xyz, t[ta]),
                                point(xyz, u[ua]));
  }
  if (shared == 1) {
    const int t1 = (ti[0] + 1) % 3, t2 = (ti[0] + 2) % 3;
    const int u1 = (ui[0] + 1) % 3, u2 = (ui[0] + 2) % 3;
    return shared_vertex_conflict(point(xyz, t[ti[0]]), point(xyz, t[t1]), point(xyz, t[t2]),
                                  point(xyz, u[u1]), point(xyz, u[u2]));
  }
  const Vec3 a[3] = {point(xyz, t[0]), point(xyz, t[1]), point(xyz, t[2])};
  const Vec3 b[3] = {point(xyz, u[0]), point(xyz, u[1]), point(xyz, u[2])};
  return triangles_meet(a, b);
}

}  // namespace

std::size_t scan_intersections(const double *xyz, const std::uint32_t *triangles,
                               const std::vector<std::uint8_t> &usable,
                               const std::function<void(std::size_t, std::size_t, int)> &on_hit) {
  std::vector<std::uint32_t> ids;
  std::vector<Box> boxes(usable.size());
  Box all{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  double extent_sum = 0;
  for (std::size_t f = 0; f < usable.size(); ++f) {
    if (!usable[f]) continue;
    ids.push_back(static_cast<std::uint32_t>(f));
    Box &b = boxes[f];
    double extent = 0;
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = b.hi[a] = xyz[3 * triangles[3 * f] + a];
      for (int k = 1; k < 3; ++k) {
        const double v = xyz[3 * triangles[3 * f + k] + a];
        b.lo[a] = std::min(b.lo[a], v);
        b.hi[a] = std::max(b.hi[a], v);
      }
      all.lo[a] = std::min(all.lo[a], b.lo[a]);
      all.hi[a] = std::max(all.hi[a], b.hi[a]);
      extent = std::max(extent, b.hi[a] - b.lo[a]);
    }
    extent_sum += extent;
  }
  if (ids.size() < 2) return 0;

  Grid grid{};
  double span = 0;
  for (int a = 0; a < 3; ++a) {
    grid.origin[a] = all.lo[a];
    span = std::max(span, all.hi[a] - all.lo[a]);
  }
  grid.cell = std::max(extent_sum / double(ids.size()), span / 1e6);
  const std::size_t budget = 16 * ids.size() + (std::size_t(1) << 20);
  for (;;) {
    for (int a = 0; a < 3; ++a)
      grid.cells[a] = static_cast<std::uint32_t>(std::floor((all.hi[a] - all.lo[a]) / grid.cell)) + 1;
    if (entry_count(grid, boxes, ids) <= budget) break;
    grid.cell *= 1.5;
  }

  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
  entries.reserve(entry_count(grid, boxes, ids));
  for (std::uint32_t f : ids) {
    const Box &b = boxes[f];
    std::uint32_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = grid.index(b.lo[a], a);
      hi[a] = grid.index(b.hi[a], a);
    }
    for (std::uint32_t x = lo[0]; x <= hi[0]; ++x)
      for (std::uint32_t y = lo[1]; y <= hi[1]; ++y)
        for (std::uint32_t z = lo[2]; z <= hi[2]; ++z) entries.emplace_back(cell_key(x, y, z), f);
  }
  std::sort(entries.begin(), entries.end());

  // Hits are collected and sorted so the report does not depend on the grid's cell order.
  std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, int>> hits;
  for (std::size_t begin = 0; begin < entries.size();) {
    std::size_t end = begin + 1;
    while (end < entries.size() && entries[end].first == entries[begin].first) ++end;
    const std::uint64_t key = entries[begin].first;
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint32_t f = entries[i].second;
      const Box &bf = boxes[f];
      for (std::size_t j = i + 1; j < end; ++j) {
        const std::uint32_t g = entries[j].second;
        const Box &bg = boxes[g];
        bool overlap = true;
        std::uint32_t low[3];
        for (int a = 0; a < 3 && overlap; ++a) {
          overlap = bf.lo[a] <= bg.hi[a] && bg.lo[a] <= bf.hi[a];
          low[a] = grid.index(std::max(bf.lo[a], bg.lo[a]), a);
        }
        if (!overlap || cell_key(low[0], low[1], low[2]) != key) continue;
        int shared = 0;
        if (judge_pair(xyz, triangles + 3 * std::size_t(f), triangles + 3 * std::size_t(g), shared))
          hits.push_back({{std::min(f, g), std::max(f, g)}, shared});
      }
    }
    begin = end;
  }
  std::sort(hits.begin(), hits.end());
  for (const auto &h : hits) on_hit(h.first.first, h.first.second, h.second);
  return hits.size();
}

}  // namespace moa::test
