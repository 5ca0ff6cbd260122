// Crossing checks for the topology judgment (paper §3.3, Type 1 intersections), backed by
// Embree. Layout of the index as the mesh grows:
//   - a committed Embree scene (BVH) over the bulk of the faces, rebuilt when the faces added
//     or removed since the last build outnumber half of those in it, so rebuilds cost
//     O(F log F) in all;
//     it reads the mesh's face records in place, or a compact copy of the live faces once many
//     have been removed;
//   - a hash grid over the faces added since the last build.
// Embree is the broad phase only: every face it proposes is decided by the exact predicates on
// the caller's coordinates, so float rounding inside Embree can never let a crossing through.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/face_grid.hpp"
#include "core/marks.hpp"
#include "core/mesh_state.hpp"
#include "core/point_set.hpp"

namespace moa {

// The points as Embree sees them: in single precision, in a frame of its own (see kFloatSlack
// in intersection.cpp). They depend on the points and the cell size alone, so the parts of
// Algorithm 1's parallel pass share the whole cloud's copy: a copy per part cost 12 bytes per
// point of the whole cloud for every part running at once (a million points on 8 threads:
// 96 MB).
struct EmbreePoints {
  Vec3 origin{};
  double unit = 1;
  std::vector<float> xyz;
};

class CrossingIndex {
 public:
  // `shared`: the points of another index over the same points and cell size, if there is one.
  CrossingIndex(const PointSet &points, double cell_size,
                std::shared_ptr<const EmbreePoints> shared = nullptr);
  ~CrossingIndex();
  CrossingIndex(const CrossingIndex &) = delete;
  CrossingIndex &operator=(const CrossingIndex &) = delete;

  // True when triangle t would meet an existing face anywhere other than in shared vertices
  // and edges. On false, `near` holds every face whose bounding box comes within `pad` (work
  // units) of t's, faces sharing a vertex with t included: the neighbourhood the judgment
  // then searches for overlapping layers, found by the same queries.
  bool crosses(const Tri &t, double pad, MeshState &mesh, std::vector<uint32_t> &near);
  // Appends to `out` the live faces whose bounding boxes meet the box lo..hi.
  void faces_in_box(const Vec3 &lo, const Vec3 &hi, MeshState &mesh, std::vector<uint32_t> &out);
  // Appends to `out` every live face that triangle t would meet anywhere other than in shared
  // vertices and edges (all of them, where crosses stops at the first).
  void faces_crossed(const Tri &t, MeshState &mesh, std::vector<uint32_t> &out);
  // How many live faces other than `skip` the ray from p along d (work units) meets, each
  // counted once. Every face must be committed (add_all, no face_added since); safe to call
  // from several threads at once. `hits` is scratch space.
  std::size_t faces_along_ray(const Vec3 &p, const Vec3 &d, uint32_t skip, const MeshState &mesh,
                              std::vector<uint32_t> &hits) const;
  // Registers face f (already added to mesh). The scene reads the mesh's face records in place:
  // an add that moves them is followed by add_all instead (GrowthState::add_face).
  void face_added(uint32_t f, MeshState &mesh);
  // Registers every face of the mesh at once (one Embree build), after faces were added to
  // the mesh without face_added.
  void add_all(MeshState &mesh) { rebuild(mesh); }
  // t's bounding box in the coordinates the index tests, padded as every broad-phase box is.
  void bounds(const Tri &t, Vec3 &lo, Vec3 &hi) const;

  // Frees the Embree scene and the grid of recent faces for a while (their memory is wanted
  // elsewhere); no query may follow until add_all builds them again.
  void set_aside();
  // Frees the Embree scene and the index's buffers once the mesh is complete; no query may
  // follow.
  void release();

  // For another index over the same points and cell size (null after release()).
  std::shared_ptr<const EmbreePoints> embree_points() const { return embree_; }

  std::size_t rebuilds() const { return rebuilds_; }
  double milliseconds() const { return seconds_ * 1000.0; }

 private:
  void rebuild(MeshState &mesh);
  // The face behind an Embree primitive of the committed scene.
  uint32_t face_of(uint32_t prim) const { return scene_faces_.empty() ? prim : scene_faces_[prim]; }
  void grid_insert(uint32_t f, const Tri &t);
  // Whether t and g meet other than in shared vertices and edges (exact predicates).
  bool meet_exactly(const Tri &t, const Tri &g) const;
  bool test_exact(const Tri &t, uint32_t f, MeshState &mesh);
  void next_query();
  // Calls visit(face) for the live oversized faces, dropping the removed ones.
  template <class Visit>
  bool visit_oversized(const MeshState &mesh, Visit &visit);
  // Calls visit(face) for committed faces near the sphere and pending faces near the box.
  template <class Visit>
  bool visit_near(const Vec3 &lo, const Vec3 &hi, MeshState &mesh, Visit &&visit);

  // A point in Embree's frame (see kFloatSlack in intersection.cpp).
  Vec3 in_frame(const Vec3 &p) const { return (p - embree_->origin) * embree_->unit; }

  const PointSet &points_;
  std::shared_ptr<const EmbreePoints> embree_;  // Embree's shared vertex buffer
  void *device_ = nullptr;
  void *scene_ = nullptr;
  uint32_t committed_ = 0;               // faces [0, committed_) are in the scene
  std::size_t removed_at_build_ = 0;     // the mesh's removed_count() then
  std::vector<uint32_t> scene_corners_;  // a compacted scene's copy of the live faces' corners
  std::vector<uint32_t> scene_faces_;    // and the face of each of the scene's primitives
  double cell_ = 0;
  double pad_ = 0;  // of every broad-phase box (kPad in intersection.cpp)
  FaceGrid grid_;
  std::vector<uint32_t> oversized_;  // pending faces spanning too many cells
  double scan_debt_ = 0;             // pending faces scanned one by one since the last build
  IndexMarks tested_;                // faces the current query has tested or ruled out
  std::vector<uint32_t> found_;
  std::size_t rebuilds_ = 0;
  double seconds_ = 0;
};

}  // namespace moa
