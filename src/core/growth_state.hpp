// What Algorithm 1 and the loop module share: the points, the growing mesh, its crossing index,
// the judgment and the statistics.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "core/intersection.hpp"
#include "core/mesh_state.hpp"
#include "core/neighbors.hpp"
#include "core/opposite_angle.hpp"
#include "core/point_set.hpp"
#include "core/topology_judgment.hpp"

namespace moa {

// Steps (candidate edges, points) between two calls of GrowthState::poll; a power of two.
constexpr std::size_t kPollEvery = 256;

struct GrowthState {
  // `typical_spacing` is the cloud's median point spacing (median_spacing); `embree_points`,
  // the single-precision points of another state's crossing index over the same cloud, to
  // share (a part of Algorithm 1's parallel pass gets the whole cloud's).
  GrowthState(const PointSet &p, const Neighborhood &n, const Params &par, double typical_spacing,
              moa_stats &st, std::shared_ptr<const EmbreePoints> embree_points = nullptr)
      : points(p),
        nb(n),
        params(par),
        spacing(typical_spacing),
        mesh(p.size()),
        // The crossing index's grid of recent faces has cells two median spacings wide.
        crossings(p, 2.0 * typical_spacing, std::move(embree_points)),
        judge(p, n, par, mesh, crossings),
        search(p, n, par),
        stats(st) {}

  uint32_t add_face(const Tri &t) {
    // Face records that are full move as they grow, and the Embree scene reads them in place:
    // the scene goes first and is built again after the move, so that it and both copies of
    // the records are never alive together (edge flips on a noisy million-point cloud: 415 MB
    // at the peak, 362 with this).
    const bool moves = mesh.full();
    if (moves) crossings.set_aside();
    const uint32_t f = mesh.add(t);
    if (moves)
      crossings.add_all(mesh);
    else
      crossings.face_added(f, mesh);
    return f;
  }

  // Adds the triangles first..last in order while each passes the relaxed judgment (see
  // TopologyJudge::judge for layers_allowed and flat_corners), counting the verdicts; appends
  // the faces added to `added`.
  template <class It>
  void add_while_accepted(It first, It last, std::vector<uint32_t> &added,
                          bool layers_allowed = false, bool flat_corners = false) {
    for (; first != last; ++first) {
      const Verdict v = judge.judge(*first, nullptr, 0, true, layers_allowed, flat_corners);
      TopologyJudge::count(v, stats);
      if (v != Verdict::Accept) return;
      added.push_back(add_face(*first));
    }
  }

  // Adds the triangles in order if each passes the relaxed judgment (the loop module's patches
  // and splits), counting the verdicts; if one fails, takes back those added and returns false.
  bool add_all_or_none(const std::vector<Tri> &tris, bool layers_allowed = false,
                       bool flat_corners = false) {
    std::vector<uint32_t> added;
    add_while_accepted(tris.begin(), tris.end(), added, layers_allowed, flat_corners);
    if (added.size() == tris.size()) return true;
    for (uint32_t f : added) mesh.remove(f);
    return false;
  }

  // Reports progress again at the fraction last reached, from loops that can run for seconds
  // on bad input (the loop module's passes, patches and take-in): each report gives the
  // progress callback its chance to cancel. The loop module sets it; a no-op otherwise.
  std::function<void()> poll = [] {};

  const PointSet &points;
  const Neighborhood &nb;
  const Params &params;
  const double spacing;  // the cloud's median point spacing, work units
  MeshState mesh;
  CrossingIndex crossings;
  TopologyJudge judge;
  OppositeAngleSearch search;
  moa_stats &stats;
  // The vertices of tangles: pieces of Algorithm 1's mesh that fill a volume rather than line a
  // surface (mark_tangles, loop_filler.cpp). The loop module fills no hole among them and
  // takes in no point next to them. Empty when there is none.
  std::vector<uint8_t> tangled;
  bool in_tangle(uint32_t v) const { return !tangled.empty() && tangled[v] != 0; }
  // Embree rebuilds and crossing-test time of the parallel first pass's parts (build_mesh),
  // summed over the parts.
  std::size_t parts_rebuilds = 0;
  double parts_crossing_ms = 0;
};

// Hands the heap's free memory back to the system (reconstruct.cpp).
void return_free_memory();

// Algorithm 1 (paper §3.5.1). `tick(fraction)` reports progress and may throw Cancelled. When it
// makes no triangle at all, it runs again with the normal test left out for the rest of the run.
void build_mesh(GrowthState &g, const std::function<void(double)> &tick);

// Finds pieces of the mesh that a join turned inside out (their seam with the rest can never
// close), cuts them free and turns them round; returns how many (orientation_repair.cpp).
// `contradicting`, if given, receives the number of open-edge pairs found contradicting.
std::size_t repair_inside_out_patches(GrowthState &g, std::size_t *contradicting = nullptr);
// Finds regions that face the wrong way by the parity of rays cast from their faces, cuts
// them free and turns them round; returns how many (parity_orientation.cpp).
std::size_t turn_regions_against_ray_parity(GrowthState &g);

// Cuts the bridges that made a handle with a waist of three or four edges, near the faces
// numbered from first_face on (see handle_cut.cpp); returns how many.
std::size_t cut_thin_handles(GrowthState &g, std::size_t first_face);
// Cuts the handles made by a channel of air about a spacing wide (under a bridge across a
// narrow gap) whose waist is five to eight edges, near the faces numbered from first_face
// on; returns how many.
std::size_t cut_narrow_tunnels(GrowthState &g, std::size_t first_face);

// Algorithm 2, the loop module (paper §3.5.2).
void fill_loops(GrowthState &g, const std::function<void(double)> &tick);

// Splits a triangle under each point left out (or each of `only` that is), where the
// judgment allows; returns how many points were taken in.
std::size_t take_in_points(GrowthState &g, const std::vector<uint32_t> *only = nullptr);

// Flips edges to the other diagonal of their quad where that widens the smallest angle
// (edge_flips.cpp); returns how many. `tick(fraction)` reports progress and may throw Cancelled.
std::size_t flip_edges(GrowthState &g, const std::function<void(double)> &tick);

}  // namespace moa
