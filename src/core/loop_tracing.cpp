// The loop module's first step: the boundary loops of the mesh, traced from its hole edges (the
// inner and outer loops of one hole alike, a vertex met twice counted twice), and which of them
// are holes to fill rather than borders to keep: a loop is a hole when it is narrow, or short
// and bent across a crease; each hole gets its pool of candidate apexes.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/loop_filler.hpp"
#include "core/neighbors.hpp"
#include "core/pca.hpp"

namespace moa {
namespace {

// Loops longer than this are borders unless the solid setting makes every loop a hole: measuring
// their width costs a quadratic number of distances.
constexpr std::size_t kMaxMeasuredLoop = 4096;
// A loop's waist joins two of its vertices whose path along the loop is at least this many
// times their distance (widest_waist): pi/2 across a circle, 1 between neighbours. On 192 test
// clouds (before the smoothing below) 1.5 closed one fewer than 1.3, and 1.2 none more.
constexpr double kShortcutRatio = 1.3;
// Vertices each way over which the loop is smoothed before its waists are measured; at most
// one kWaistSmoothingShare-th of the loop, as the mean of 7 of a short loop's vertices lies
// well inside it (at 0.46 of the radius of a round loop of 11: a hole 12 spacings across,
// its rim a few long edges, measured about half as wide and filled as narrow).
constexpr std::size_t kWaistSmoothing = 3;
constexpr std::size_t kWaistSmoothingShare = 8;
// A loop at most this share of the square root of its surface's vertex count long, and at most
// kSmallLoopWidths times the hole width wide, is a hole torn along a crease (see
// classify_and_pool) when it bends across one: the planes at two of its vertices at most two
// steps apart stand at least kCreaseAngle apart. A round hole through a smooth part of the
// surface is a border however short, and its planes turn gradually: 0 degrees on a flat ring,
// at most 20 within two steps on a sphere and a cylinder with holes 8-20 spacings across
// (47 across the whole loop). The loops of the quality sweep that this rule closed turn by
// 25-90 degrees within two steps, but for 57 of building.ply's 654, which now stay open.
// The two vertices must lie within kCreaseReach spacings: a crease turns the planes at once, a
// curved surface gradually. A random 20,000-point bunny with round holes 8-12 spacings across
// cut out has planes 25 degrees apart at vertices 2.3-3.8 spacings apart on three of its hole
// loops (their edges are long), which closed with faces 12 spacings long; the 42 loops along
// creases that this rule closed on 47 clouds (samples and vertex sets of the shared meshes,
// cones, prisms, cubes) have such a pair within 0.2-1.3 spacings.
constexpr double kSmallLoopShare = 0.5;
constexpr double kSmallLoopWidths = 3.0;
constexpr double kCreaseAngle = 25.0;
constexpr double kCreaseReach = 2.0;
// The rim of an open tube's end is short too, and the planes fitted at its points (their lists
// one-sided, on a tightly curved wall) turn by 25 degrees and more within two steps here and
// there: random open tubes 6-12 spacings in radius had their ends capped. Unlike a tear, which
// bends with the surface across the crease, such a rim lies flat (its thickness under
// kRimFlatness of its middle spread: 0.03-0.09 on the tubes) and the surface stands across its
// plane (the median |cos| of the angle between the rim's axis and its points' planes under
// kRimAcross: 0.03-0.09). Of the 205 loops that the crease rule closed on 181 clouds (the
// benchmark's 22 inputs under a million points but building.ply, the vertices of the 138
// meshes of CGAL's demo data, the shared point files, cubes, cones, prisms, tori and tubes),
// none but the tubes' rims was both: flat ones stood at 0.33 and more, and those standing
// that far across were 0.2 thick or more.
constexpr double kRimFlatness = 0.15;
constexpr double kRimAcross = 0.2;
// A loop lies in one cut of a lined cloud (in_one_cut) when its vertices stand off their plane
// by at most this many spacings (root mean square; a strip between two cuts: half a gap, about
// 0.6 spacings, as the spacing of a point on a line is about 0.8 gaps), and at least half of
// them have a neighbour at least kCutBeside spacings off it (on the next cut).
constexpr double kCutFlatness = 0.1;
constexpr double kCutBeside = 0.5;

}  // namespace

std::size_t LoopFiller::count_loops() {
  collect_hole_edges();
  return trace_loops().size();
}

// Live faces of each piece of the mesh (orientation component), by its representative.
std::unordered_map<uint32_t, std::size_t> LoopFiller::faces_per_component() {
  return count_live_faces(g_.mesh, [this](uint32_t f) { return g_.mesh.component(f); });
}

bool LoopFiller::still_open(const std::vector<uint32_t> &loop) const {
  const std::size_t n = loop.size();
  for (std::size_t j = 0; j < n; ++j) {
    uint32_t fs[2];
    if (g_.mesh.edge_faces(loop[j], loop[(j + 1) % n], fs) != 1) return false;
  }
  return true;
}

bool LoopFiller::simple_and_untangled(const std::vector<uint32_t> &loop,
                                      std::vector<uint32_t> &sorted) const {
  sorted = loop;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;  // pinched
  return std::none_of(loop.begin(), loop.end(), [&](uint32_t x) { return g_.in_tangle(x); });
}

// Hole edges: the reverse of each boundary edge of a face, so that a face filling the hole
// along it keeps the orientation.
void LoopFiller::collect_hole_edges() {
  out_.clear();
  // Only a vertex whose fan is open has a hole edge: the faces around those, each edge
  // a -> b (as its face runs) found from a, recorded in face order as a scan of every face
  // would (the order decides how loops are traced through a vertex on two of them).
  std::vector<std::pair<uint32_t, int>> edges;  // (face, index of a in it)
  for (uint32_t a = 0; a < g_.points.size(); ++a) {
    if (!g_.mesh.is_used(a) || g_.mesh.fan_closed(a)) continue;
    for (uint32_t f : g_.mesh.faces_at(a)) {
      const Tri t = g_.mesh.oriented(f);
      const int i = int(std::find(t.begin(), t.end(), a) - t.begin());
      uint32_t fs[2];
      if (g_.mesh.edge_faces(a, t[(i + 1) % 3], fs) == 1) edges.push_back({f, i});
    }
  }
  std::sort(edges.begin(), edges.end());
  for (const auto &[f, i] : edges) {
    const Tri t = g_.mesh.oriented(f);
    out_[t[(i + 1) % 3]].push_back(t[i]);
  }
}

// Next hole edge at v after arriving from u: the first one met turning clockwise from vu
// (the face on uv lies counter-clockwise of it, the hole clockwise).
uint32_t LoopFiller::pick_next(uint32_t u, uint32_t v, std::vector<uint32_t> &outs) {
  if (outs.size() == 1) return 0;
  uint32_t fs[2];
  g_.mesh.edge_faces(u, v, fs);
  Tri f = g_.mesh.oriented(fs[0]);
  const auto &w = g_.points.work;
  Vec3 n = normalized(cross(w[f[1]] - w[f[0]], w[f[2]] - w[f[0]]));
  Vec3 d0 = w[u] - w[v];
  d0 = d0 - n * dot(d0, n);
  uint32_t best = 0;
  double best_angle = 1e9;
  for (uint32_t k = 0; k < outs.size(); ++k) {
    Vec3 d = w[outs[k]] - w[v];
    d = d - n * dot(d, n);
    double ccw = std::atan2(dot(n, cross(d0, d)), dot(d0, d));
    double cw = ccw > 0 ? 2 * kPi - ccw : -ccw;
    if (cw < best_angle) {
      best_angle = cw;
      best = k;
    }
  }
  return best;
}

// Traces the loops through the hole edges in out_, starting from `from` when given (the
// vertices of one hole, whose loop is then traced first and whole), else from every vertex.
std::vector<Loop> LoopFiller::trace_loops(const std::vector<uint32_t> *from) {
  std::vector<Loop> loops;
  std::vector<uint32_t> starts;
  if (from != nullptr) {
    for (uint32_t v : *from)
      if (out_.count(v)) starts.push_back(v);
  } else {
    for (auto &kv : out_) starts.push_back(kv.first);
    std::sort(starts.begin(), starts.end());  // deterministic order
  }
  for (uint32_t s : starts) {
    while (!out_[s].empty()) {
      Loop loop;
      uint32_t prev = s, cur = out_[s].back();
      out_[s].pop_back();
      loop.vertices.push_back(s);
      while (cur != s || !out_[s].empty()) {
        auto &outs = out_[cur];
        if (outs.empty()) break;
        if (cur == s) break;
        loop.vertices.push_back(cur);
        uint32_t k = pick_next(prev, cur, outs);
        uint32_t next = outs[k];
        outs.erase(outs.begin() + k);
        prev = cur;
        cur = next;
      }
      loops.push_back(std::move(loop));
    }
  }
  return loops;
}

// How wide a loop is: for each vertex, the distance to the nearest vertex at least a quarter
// of the loop away; the largest of these. A gap left between growing fronts is narrow
// however long it is; a true border (the rim of an open scan) is as wide as the surface.
double LoopFiller::loop_width(const std::vector<uint32_t> &loop) const {
  const auto &w = g_.points.work;
  const std::size_t n = loop.size();
  if (n <= 3) return 0;
  if (n > kMaxMeasuredLoop) return std::numeric_limits<double>::infinity();
  const std::size_t quarter = std::max<std::size_t>(1, n / 4);
  double width = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = quarter; k <= n - quarter; ++k)
      nearest = std::min(nearest, norm2(w[loop[i]] - w[loop[(i + k) % n]]));
    width = std::max(width, nearest);
  }
  return std::sqrt(width);
}

// The face along the loop's first edge (from its second vertex to its first).
uint32_t LoopFiller::face_along(const std::vector<uint32_t> &loop) const {
  uint32_t fs[2];
  g_.mesh.edge_faces(loop[1 % loop.size()], loop[0], fs);
  return fs[0];
}

// The widest waist of a loop. The waist at vertex i is its distance to the nearest vertex j
// the loop reaches from i only the long way round: by a path at least kShortcutRatio times
// the straight distance ij (pi/2 across a circle, far more across a narrow strip). A strip
// torn open along a sharp edge has waists as narrow as the strip, however long it is, where
// loop_width sees its length from the vertices near its ends. Vertices with no such j (the
// tip of a wedge) have no waist.
double LoopFiller::widest_waist(const std::vector<uint32_t> &loop) const {
  const auto &w = g_.points.work;
  const std::size_t n = loop.size();
  if (n <= 3) return 0;
  if (n > kMaxMeasuredLoop) return std::numeric_limits<double>::infinity();
  // A loop that meets itself is a chain of holes joined at pinches (two pieces touching at
  // points along a rim), which open_pinched_vertices parts into loops of their own.
  std::vector<uint32_t> sorted(loop);
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    return std::numeric_limits<double>::infinity();
  // The loop smoothed over a few vertices each way: a staircase (the rim of a grid) has a
  // shortcut at every step, the smoothed one none.
  std::vector<Vec3> at(n);
  const std::size_t reach = std::min<std::size_t>(kWaistSmoothing, n / kWaistSmoothingShare);
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 sum{0, 0, 0};
    for (std::size_t k = n - reach; k <= n + reach; ++k) sum = sum + w[loop[(i + k) % n]];
    at[i] = sum * (1.0 / double(2 * reach + 1));
  }
  std::vector<double> along(n + 1, 0.0);  // path length from at[0] to at[i]
  for (std::size_t i = 0; i < n; ++i) along[i + 1] = along[i] + dist(at[i], at[(i + 1) % n]);
  const double round = along[n];
  const double ratio2 = kShortcutRatio * kShortcutRatio;
  double width = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < n; ++j) {
      const double forward = std::abs(along[j] - along[i]);
      const double path = std::min(forward, round - forward);
      const double d2 = norm2(at[i] - at[j]);
      if (path * path >= ratio2 * d2 && d2 < nearest && j != i) nearest = d2;
    }
    if (nearest != std::numeric_limits<double>::infinity()) width = std::max(width, nearest);
  }
  return std::sqrt(width);
}

// Whether a loop is the rim of an open end (kRimFlatness, kRimAcross): it lies flat, and the
// surface around it stands across its plane. Not in a cloud sampled along lines, where a
// flat loop in one cut has its own rule (in_one_cut).
bool LoopFiller::open_rim(const std::vector<uint32_t> &loop) const {
  const std::size_t n = loop.size();
  if (g_.nb.lined || n < 4) return false;
  const PcaFrame f = pca_frame(g_.points.work, loop[0], loop.data() + 1, unsigned(n - 1));
  if (!(f.spread[0] <= kRimFlatness * kRimFlatness * f.spread[1])) return false;
  std::vector<double> across(n);
  for (std::size_t i = 0; i < n; ++i)
    across[i] = std::fabs(dot(plane_normal(g_.points, g_.nb, loop[i]), f.axis[0]));
  std::nth_element(across.begin(), across.begin() + std::ptrdiff_t(n / 2), across.end());
  return across[n / 2] < kRimAcross;
}

// Whether a loop bends across a crease (kCreaseAngle, within kCreaseReach). In a cloud
// sampled along lines any such turn counts: there a short loop is the unsampled surface
// between two lines, a hole however gradually it turns (where the surface runs nearly
// parallel to the lines; a noisy torus contour stack kept four such, 100 boundary edges).
bool LoopFiller::bends(const std::vector<uint32_t> &loop) const {
  const auto &w = g_.points.work;
  const std::size_t n = loop.size();
  std::vector<Vec3> normals;
  for (uint32_t v : loop) normals.push_back(plane_normal(g_.points, g_.nb, v));
  const double cos_crease = std::cos(degrees_to_radians(kCreaseAngle));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t step : {1, 2}) {
      const uint32_t a = loop[i], b = loop[(i + step) % n];
      const double reach = kCreaseReach * 0.5 * (g_.nb.spacing[a] + g_.nb.spacing[b]);
      if (std::fabs(dot(normals[i], normals[(i + step) % n])) <= cos_crease &&
          (g_.nb.lined || norm2(w[a] - w[b]) <= reach * reach))
        return true;
    }
  return false;
}

// Whether a loop of a cloud sampled along lines lies in the plane of one cut, with other cuts
// beside it: a face parallel to the slices, which gets no points but its rim (an object's
// flat top or bottom, or one cut off by the scan's field), is such a loop. A strip between
// two cuts spans the gap between them, and a flat open surface's border has no point off
// its plane.
bool LoopFiller::in_one_cut(const std::vector<uint32_t> &loop, double spacing) const {
  const auto &w = g_.points.work;
  const std::size_t n = loop.size();
  if (n < 3) return false;
  const PcaFrame f = pca_frame(w, loop[0], loop.data() + 1, unsigned(n - 1));
  const double thickness = std::sqrt(std::max(0.0, f.spread[0]) / double(n));
  if (!(thickness <= kCutFlatness * spacing)) return false;
  std::size_t beside = 0;
  for (uint32_t v : loop) {
    const uint32_t *nb = g_.nb.of(v);
    for (unsigned j = 0; j < g_.nb.k; ++j)
      if (std::fabs(dot(w[nb[j]] - w[v], f.axis[0])) > kCutBeside * spacing) {
        ++beside;
        break;
      }
  }
  return 2 * beside >= n;
}

// A loop is a hole, to be filled, when it is narrow (at most hole_size spacings wide, or its
// widest waist is: a gap left between growing fronts, a strip torn along a sharp edge), or
// when it is short next to the surface it bounds and not too wide (a hole torn at a sharp
// edge or a crease of a large surface). A border of an open scan runs around the whole
// surface: its length is of the order of the square root of the surface's vertex count or
// more, however the scan is shaped.
void LoopFiller::classify_and_pool() {
  std::unordered_map<uint32_t, uint32_t> &loop_of_vertex = loop_of_vertex_;
  // Counted only if a loop gets as far as the test that needs it: a pass over every face.
  std::unordered_map<uint32_t, std::size_t> faces_of_component;
  bool counted = false;
  auto surface_vertices = [&](uint32_t piece) {
    if (!counted) faces_of_component = faces_per_component();
    counted = true;
    return 0.5 * double(faces_of_component[piece]);
  };
  const double sparse_spacing = kSparseSpacings * g_.spacing;
  for (uint32_t l = 0; l < loops_.size(); ++l) {
    Loop &loop = loops_[l];
    double spacing = 0;
    const std::size_t n = loop.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      uint32_t a = loop.vertices[i], b = loop.vertices[(i + 1) % n];
      spacing += g_.nb.spacing[a];
      hole_loop_[hole_edge_key(a, b)] = l;
      loop_of_vertex.emplace(a, l);
    }
    spacing /= double(n);
    loop.piece = g_.mesh.component(face_along(loop.vertices));
    // A loop that touches a tangle runs through it or along its edge.
    loop.tangled = std::any_of(loop.vertices.begin(), loop.vertices.end(),
                               [&](uint32_t v) { return g_.in_tangle(v); });
    if (loop.tangled) continue;
    const double width = loop_width(loop.vertices);
    const double hole_width = loop.hole_width = g_.params.hole_size * spacing;
    // Narrow, or else small; a strip is narrow by its waists too, the spacing capped where
    // the loop runs among stray points: their own spacing would make a gap of any width among
    // them look narrow. The dearer tests come last: the waists take a quadratic number of
    // distances, the bend a fitted plane per vertex.
    loop.fillable =
        g_.params.solid != 0 || width <= hole_width ||
        widest_waist(loop.vertices) <= g_.params.hole_size * std::min(spacing, sparse_spacing) ||
        (double(n) <= kSmallLoopShare * std::sqrt(surface_vertices(loop.piece)) &&
         width <= kSmallLoopWidths * hole_width && bends(loop.vertices) &&
         !open_rim(loop.vertices));
    loop.flat_cut = !loop.fillable && g_.nb.lined && in_one_cut(loop.vertices, spacing);
  }
  // Candidates of a loop: its own vertices, and the neighbours of its vertices that lie on
  // another loop (the outer loop around an island, Fig. 9 (2), whose lists the paper
  // combines) or that Algorithm 1 left out (step 1 of §3.5.2).
  const bool take_in = g_.params.take_in_points != 0;
  std::vector<uint32_t> mark(g_.points.size(), kNone);
  for (uint32_t l = 0; l < loops_.size(); ++l) {
    Loop &loop = loops_[l];
    if (loop.tangled) continue;
    loop.pool = loop.vertices;
    for (uint32_t v : loop.vertices) mark[v] = l;
    for (uint32_t v : loop.vertices) {
      const uint32_t *nb = g_.nb.of(v);
      for (unsigned j = 0; j < g_.nb.k; ++j) {
        uint32_t p = nb[j];
        if (mark[p] == l) continue;
        if (!g_.mesh.is_used(p)) {
          if (!take_in || g_.nb.alone(p)) continue;
          mark[p] = l;
          loop.pool.push_back(p);
        } else if (loop_of_vertex.count(p) && !g_.in_tangle(p)) {
          mark[p] = l;
          loop.outer.push_back(p);
        }
      }
    }
  }
}

}  // namespace moa
