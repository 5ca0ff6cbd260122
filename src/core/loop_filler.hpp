// The loop module's working state (Algorithm 2, paper §3.5.2), shared by its stages:
//   loop_tracing.cpp  the boundary loops, and which of them are holes to fill;
//   loop_filler.cpp   filling them by MOA among their own vertices, and the stage's order;
//   hole_repair.cpp   widening and patching the holes the filling could not close;
//   loop_pieces.cpp   stray pieces dropped, strips between two pieces zipped shut;
//   slit_closing.cpp  holes of next to no area along one edge, closed by splitting its face;
//   band_stitching.cpp  the band between two contours of a contour stack, stitched.
// Internal to the library: fill_loops (growth_state.hpp) is the stage's entry point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <queue>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/disjoint_sets.hpp"
#include "core/growth_state.hpp"
#include "core/kd_tree.hpp"

namespace moa {

// A piece counts as sparse (its corners stray points) when its median edge is longer than
// this many median point spacings of the cloud; a loop running among such points has its
// spacing capped at this many (loop_pieces.cpp, loop_tracing.cpp).
constexpr double kSparseSpacings = 4.0;

inline uint64_t hole_edge_key(uint32_t u, uint32_t v) { return (uint64_t(u) << 32) | v; }

struct Loop {
  std::vector<uint32_t> vertices;  // in order; a hole edge runs from each to the next
  std::vector<uint32_t> pool;      // candidate apexes: the loop's vertices and nearby free points
  std::vector<uint32_t> outer;     // vertices of other loops next to this one, tried last
  double hole_width = 0;           // hole_size times the mean spacing of its vertices
  uint32_t piece = kNone;          // the component of the faces along it
  bool fillable = false;
  bool flat_cut = false;  // too wide, but lying in one cut of a contour stack (capped)
  bool tangled = false;   // runs through a tangle (GrowthState::tangled): left as it is
};

// Every vertex of the loops with its loop, in a kd-tree: which loops pass near a point
// (zip_parallel_loops). A vertex on two loops is listed once for each.
struct LoopVertices {
  LoopVertices(const std::vector<Loop> &loops, const std::vector<Vec3> &work);
  std::vector<Vec3> at;
  std::vector<uint32_t> loop;
  KdIndex index;  // over `at`, built last
};

struct HoleEdge {
  double length;
  uint32_t from, to;
  bool operator>(const HoleEdge &o) const {
    if (length != o.length) return length > o.length;
    if (from != o.from) return from > o.from;
    return to > o.to;
  }
};

// The live faces under each key (a piece, a component). Faces of one key mostly come in a run
// (the main piece holds most of them), so the map is looked up once per run, not per face.
template <class KeyOf>
std::unordered_map<uint32_t, std::size_t> count_live_faces(const MeshState &mesh, KeyOf key_of) {
  std::unordered_map<uint32_t, std::size_t> count;
  uint32_t last = kNone;
  std::size_t *n = nullptr;
  for (uint32_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.alive(f)) {
      const uint32_t key = key_of(f);
      if (key != last) n = &count[last = key];
      ++*n;
    }
  return count;
}

// The pieces of the live faces, joined through shared vertices. Not the orientation
// components: their union-find never splits, so a piece cut off by removed faces would still
// count as part of the other. Four bytes per point.
class Pieces {
 public:
  explicit Pieces(const MeshState &mesh, std::size_t points) : mesh_(mesh) {
    DisjointSets sets(points);
    for (uint32_t f = 0; f < mesh.face_count(); ++f)
      if (mesh.alive(f)) {
        const Tri &t = mesh.stored(f);
        sets.join(t[1], t[0]);
        sets.join(t[2], t[0]);
      }
    piece_ = sets.take_roots();  // each vertex's root: its piece
    faces_ = count_live_faces(mesh, [this](uint32_t f) { return of(f); });
  }
  uint32_t of(uint32_t face) const { return piece_[mesh_.stored(face)[0]]; }
  // The piece of a vertex that has faces.
  uint32_t of_vertex(uint32_t v) const { return piece_[v]; }
  std::size_t faces(uint32_t piece) const { return faces_.at(piece); }

 private:
  const MeshState &mesh_;
  std::vector<uint32_t> piece_;                      // by vertex
  std::unordered_map<uint32_t, std::size_t> faces_;  // by piece: few pieces, one large
};

class LoopFiller {
 public:
  explicit LoopFiller(GrowthState &g) : g_(g) {}

  // One round: traces the loops, classifies them and fills the holes (loop_filler.cpp).
  void run(const std::function<void(double)> &tick);
  // The last try at holes whose closing needs an edge of a right angle or sharper.
  void close_at_sharp_edges(const std::function<void(double)> &tick);
  // The boundary loops of the mesh as it is (loop_tracing.cpp).
  std::size_t count_loops();
  // Repairs after the rounds (hole_repair.cpp): the faces along holes that stayed open go;
  // the last holes are patched whole; at the very end, once more with sharper folds allowed
  // (and after clearing the faces folded over the hole, if the patch crosses them).
  std::size_t widen_open_holes();
  std::size_t patch_open_holes();
  std::size_t patch_last_holes();
  // The points patch_last_holes left without faces (excise_crossed_and_patch).
  const std::vector<uint32_t> &excised_points() const { return excised_points_; }
  // Pieces (loop_pieces.cpp): strips between two pieces closed; stray pieces removed.
  std::size_t zip_parallel_loops();
  std::size_t drop_stray_pieces(bool layers = true);
  // Slits (slit_closing.cpp): holes lying along one of their edges, closed by splitting the
  // face across it.
  std::size_t close_slits();
  // Bands (band_stitching.cpp): a contour stack's holes between two contours, stitched.
  std::size_t stitch_bands();

 private:
  // loop_tracing.cpp
  void collect_hole_edges();
  uint32_t pick_next(uint32_t u, uint32_t v, std::vector<uint32_t> &outs);
  std::vector<Loop> trace_loops(const std::vector<uint32_t> *from = nullptr);
  double loop_width(const std::vector<uint32_t> &loop) const;
  // The face along the loop's first edge (from its second vertex to its first).
  uint32_t face_along(const std::vector<uint32_t> &loop) const;
  double widest_waist(const std::vector<uint32_t> &loop) const;
  bool bends(const std::vector<uint32_t> &loop) const;
  bool open_rim(const std::vector<uint32_t> &loop) const;
  bool in_one_cut(const std::vector<uint32_t> &loop, double spacing) const;
  void classify_and_pool();
  std::unordered_map<uint32_t, std::size_t> faces_per_component();
  bool still_open(const std::vector<uint32_t> &loop) const;
  // Whether the loop passes each vertex once and none of a tangle; `sorted` gets its vertices
  // in order.
  bool simple_and_untangled(const std::vector<uint32_t> &loop, std::vector<uint32_t> &sorted) const;

  // loop_filler.cpp
  void cap_flat_cuts();
  void push(uint32_t from, uint32_t to);
  std::size_t fill_pass(bool relaxed);
  bool fill_edge(uint32_t u, uint32_t v, uint32_t loop_id, bool relaxed);
  bool try_candidates(uint32_t u, uint32_t v, uint32_t z, Vec3 side,
                      const std::vector<uint32_t> &pool, uint32_t loop_id, bool relaxed);
  bool joins_another_loop(const Tri &t, uint32_t loop_id) const;
  bool closes_hole(const Tri &t) const;
  Verdict clear_pinch_and_retry(const Tri &t);
  void merge_loop_of(uint32_t vertex, uint32_t loop_id);
  std::size_t remove_open_groups(uint32_t first);

  // hole_repair.cpp
  std::vector<const Loop *> trace_patchable_holes();
  // How a hole is widened: the faces on its edges, those a vertex needs to stay in the mesh
  // excepted or not; or every face at its vertices.
  enum class Widening { KeepingVertices, Rims, Stars };
  bool patch_or_widen(const std::vector<uint32_t> &hole, bool layers_allowed,
                      std::size_t &widenings);
  bool patch_after_clearing_stars(const std::vector<uint32_t> &hole, bool layers_allowed,
                                  std::size_t &widenings);
  bool widen_and_patch(const std::vector<uint32_t> &hole, Widening widening, int rings,
                       bool layers_allowed, std::size_t &widenings);
  bool clear_spike_and_patch(const std::vector<uint32_t> &hole);
  bool excise_crossed_and_patch(const std::vector<uint32_t> &hole, bool layers_allowed);
  std::vector<uint32_t> single_loop_around(std::vector<uint32_t> corners);
  std::size_t open_edges_around(const std::vector<uint32_t> &vertices);
  bool patch_pieces(const std::vector<uint32_t> &loop, bool layers_allowed);
  bool patch(const std::vector<uint32_t> &loop, bool layers_allowed);
  std::vector<Tri> remove_stars(const std::vector<uint32_t> &loop);
  std::vector<Tri> remove_rim(const std::vector<uint32_t> &loop, bool keep_vertices);
  std::vector<Tri> remove_faces(std::vector<uint32_t> faces, bool keep_vertices);
  std::vector<uint32_t> loop_around(const std::vector<uint32_t> &old, const std::vector<Tri> &rim);

  // loop_pieces.cpp
  uint32_t partner_loop(uint32_t l, const LoopVertices &near) const;
  std::vector<Tri> zipped_strip(const std::vector<uint32_t> &a, const std::vector<uint32_t> &b,
                                bool by_share) const;

  GrowthState &g_;
  std::unordered_map<uint32_t, std::vector<uint32_t>> out_;  // the hole edges leaving a vertex
  std::vector<Loop> loops_;
  std::unordered_map<uint64_t, uint32_t> hole_loop_;       // hole edge -> its loop
  std::unordered_map<uint32_t, uint32_t> loop_of_vertex_;  // a vertex's (first) loop
  std::unordered_set<uint64_t> merged_;  // (loop, island loop merged into it) pairs
  std::priority_queue<HoleEdge, std::vector<HoleEdge>, std::greater<HoleEdge>> queue_;
  std::vector<uint32_t> near_, sphere_;
  std::vector<Candidate> ranked_;
  bool behind_ = false;  // apexes from behind the rim face only (close_at_sharp_edges)
  std::vector<uint32_t> excised_points_;
};

// Removes, at every vertex whose faces form several fans, the faces of all fans but the
// largest (hole_repair.cpp); returns how many.
std::size_t open_pinched_vertices(GrowthState &g);

}  // namespace moa
