// A mesh built by hand, loaded into the growth state the loop module works on, as if Algorithm 1
// had made it: for tests of single steps of the loop module on a known mesh; and the counts
// those tests check the result by.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "core/growth_state.hpp"
#include "core/kd_tree.hpp"
#include "core/neighbors.hpp"
#include "core/point_set.hpp"

namespace moa::test {

// Everything the growth state refers to, in the order it is made; `faces` index `xyz` (the
// caller's order) and must each pass the mesh's topology check as they are added.
class HandMesh {
 public:
  HandMesh(std::vector<double> xyz, const std::vector<Tri> &faces)
      : xyz_(std::move(xyz)),
        points_(prepare_points(xyz_.data(), xyz_.size() / 3)),
        internal_(internal_indices(points_, xyz_.size() / 3)),
        order_(points_, xyz_.data()),
        index_(points_.work),
        nb_(compute_neighbors(index_, 20, [](double) {})),
        g(points_, nb_, params_, median_spacing(nb_), stats_) {
    for (const Tri &f : faces) {
      const Tri t = internal(f);
      ok_ &= g.mesh.check(t) == TopologyVerdict::Ok;
      g.add_face(t);
    }
  }
  HandMesh(const HandMesh &) = delete;
  HandMesh &operator=(const HandMesh &) = delete;

  // Whether every point is a point of its own (no duplicates) and every face passed the check.
  bool loaded() const { return ok_ && points_.size() == xyz_.size() / 3; }
  // A face given in the caller's indices, in the growth state's.
  Tri internal(const Tri &f) const { return {internal_[f[0]], internal_[f[1]], internal_[f[2]]}; }

 private:
  static std::vector<uint32_t> internal_indices(const PointSet &points, std::size_t count) {
    std::vector<uint32_t> internal(count, kNone);
    for (uint32_t k = 0; k < points.size(); ++k) internal[points.original[k]] = k;
    return internal;
  }

  std::vector<double> xyz_;
  PointSet points_;
  std::vector<uint32_t> internal_;
  InternalOrder order_;
  KdIndex index_;
  Neighborhood nb_;
  Params params_;
  moa_stats stats_{};
  bool ok_ = true;

 public:
  GrowthState g;
};

// Triangle a b c of `xyz` (x y z per point), its corners ordered so that it faces away from
// `centre`: a face of a convex solid meshed by hand, facing outward.
inline Tri facing_away(const std::vector<double> &xyz, uint32_t a, uint32_t b, uint32_t c,
                       const double (&centre)[3]) {
  const double *p = &xyz[3 * a], *q = &xyz[3 * b], *r = &xyz[3 * c];
  const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  const double w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
  const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                       u[0] * w[1] - u[1] * w[0]};
  const double out[3] = {p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
  if (n[0] * out[0] + n[1] * out[1] + n[2] * out[2] >= 0) return {a, b, c};
  return {a, c, b};
}

// The live faces of a mesh counted by their edges and vertices.
struct MeshCounts {
  std::size_t faces = 0, edges = 0, vertices_used = 0;
  std::size_t open_edges = 0;       // edges of one face
  std::size_t over_full_edges = 0;  // edges of three faces or more
  long euler_characteristic() const { return long(vertices_used) - long(edges) + long(faces); }
};

inline MeshCounts count_mesh(const MeshState &mesh) {
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  std::set<uint32_t> used;
  MeshCounts c;
  for (uint32_t f = 0; f < mesh.face_count(); ++f) {
    if (!mesh.alive(f)) continue;
    ++c.faces;
    const Tri &t = mesh.stored(f);
    for (int i = 0; i < 3; ++i) {
      const uint32_t a = t[i], b = t[(i + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
      used.insert(a);
    }
  }
  for (const auto &[edge, count] : edges) {
    c.open_edges += count == 1;
    c.over_full_edges += count > 2;
  }
  c.edges = edges.size();
  c.vertices_used = used.size();
  return c;
}

}  // namespace moa::test
