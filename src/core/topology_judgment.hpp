// The topology judgment of paper §3.4: a candidate triangle is accepted only when
//   - it is not degenerate (exactly collinear corners, or a needle),
//   - the mesh stays edge- and vertex-manifold and orientable (MeshState::check),
//   - its plane agrees with the local reference planes of its corners,
//   - no triangle sharing one of its edges folds onto it (angle alpha, Fig. 8 (2)),
//   - no triangle sharing only a vertex duplicates its fan (angles alpha, beta, gamma, Fig. 8 (1)),
//   - the function T is small for every point in its sphere (Fig. 7),
//   - it crosses no existing triangle (Type 1, decided exactly; CrossingIndex).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/intersection.hpp"
#include "core/mesh_state.hpp"
#include "core/neighbors.hpp"
#include "core/parameters.hpp"
#include "core/point_set.hpp"
#include "moa/moa.h"

namespace moa {

enum class Verdict {
  Accept,
  Degenerate,
  Manifold,
  Orientation,
  Flatness,
  EdgeFold,
  VertexFold,
  Intersection
};

class TopologyJudge {
 public:
  TopologyJudge(const PointSet &points, const Neighborhood &nb, const Params &params,
                MeshState &mesh, CrossingIndex &crossings);

  // Judges oriented triangle t. `sphere` lists the points inside the candidate sphere, the
  // population the function T is evaluated over; pass count 0 to skip T. `relaxed` skips the
  // local-plane tests (T and the normal deviation), as the loop module does on its last pass;
  // the manifold, orientation, fold and crossing tests always run. `layers_allowed` also skips
  // the test for faces lying close over t: for the cut of a flattened bridge (handle_cut.cpp),
  // and for the patches and take-ins still refused with it, which the faces across a sharp
  // crease can overlap in projection without crossing them (hole_repair.cpp, loop_pieces.cpp,
  // take_in.cpp).
  // `flat_corners` lets a relaxed judgment pass corners up to just short of 180 degrees (only
  // collinear corners are degenerate then): the caps of flat faces in contour stacks
  // (cut_cap.hpp), whose rims run round many points in a plane.
  Verdict judge(const Tri &t, const uint32_t *sphere, std::size_t count, bool relaxed = false,
                bool layers_allowed = false, bool flat_corners = false);
  // Records a verdict in the run statistics.
  static void count(Verdict v, moa_stats &stats);
  // Leaves the normal test out of every later judgment (build_mesh, when it refused all).
  void drop_normal_test() { cos_normal_ = cos_thin_wall_normal_ = 0; }
  // While on, an edge fold passes down to kSharpFoldDegrees (topology_judgment.cpp) rather than
  // edge_fold_angle: for the loop module's last patches (LoopFiller::patch_last_holes).
  void allow_sharp_folds(bool on) { sharp_folds_ = on; }
  // How far (work units) around t's bounding box judge() looks at faces: the crossing test's
  // neighbourhood, which the layer test searches too.
  double reach(const Tri &t) const;

 private:
  bool degenerate(const Tri &t, bool relaxed, bool flat_corners = false) const;
  bool is_sliver(const Tri &t) const;
  bool normal_deviates(const Tri &t) const;
  // The face on each edge t[i] t[i + 1] (kNone for none): once t has passed the manifold
  // check there is at most one, and the tests below share one lookup.
  struct EdgeFaces {
    uint32_t face[3];
  };
  EdgeFaces faces_on_edges(const Tri &t) const;
  bool edge_folds(const Tri &t, const EdgeFaces &edges, double cos_fold) const;
  bool merges_across_a_bend(const Tri &t, const EdgeFaces &edges);
  bool vertex_folds(const Tri &t) const;
  // The components t will be joined to through its edges, and whether each one's orientation
  // is flipped relative to t (sign -1) or not (+1).
  struct Frame {
    uint32_t roots[3];
    double sign[3];
    int linked = 0;
    double sign_of(uint32_t root) const {
      for (int k = 0; k < linked; ++k)
        if (roots[k] == root) return sign[k];
      return 0;
    }
  };
  Frame frame_of(const Tri &t, const EdgeFaces &edges) const;
  bool faces_backwards(const Tri &t, const Frame &frame) const;
  bool overlaps_layer(const Tri &t, const Frame &frame, const std::vector<uint32_t> &near) const;
  bool flatness_fails(const Tri &t, const uint32_t *sphere, std::size_t count) const;

  const PointSet &points_;
  const Neighborhood &nb_;
  MeshState &mesh_;
  CrossingIndex &crossings_;
  double flatness_a_, flatness_c_;
  double cos_edge_fold_, cos_vertex_fold_, cos_vertex_open_, cos_normal_, cos_thin_wall_normal_;
  double cos_sharp_fold_;  // the fold limit allow_sharp_folds sets
  bool sharp_folds_ = false;
  mutable std::vector<uint32_t> near_;
  // Local planes of recently judged corners, direct-mapped by point index: the growth
  // front stays within a few Morton blocks, so nearly every corner is found here.
  struct CachedPlane {
    uint32_t point = kNone;
    LocalPlane plane;
  };
  const LocalPlane &plane_at(uint32_t v) const;
  mutable std::vector<CachedPlane> planes_;
};

}  // namespace moa
