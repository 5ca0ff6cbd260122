// The growing mesh shared by Algorithm 1 and the loop module: faces, the edge-to-face map,
// per-vertex fan bookkeeping and a parity union-find that keeps the orientation consistent
// while separately seeded patches grow into each other (paper §3.3, Type 2 and Type 3).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace moa {

using Tri = std::array<uint32_t, 3>;
constexpr uint32_t kNone = 0xffffffffu;

// Open-addressing map from an undirected edge to its (at most two) faces.
class EdgeMap {
 public:
  struct Slot {
    uint64_t key;
    uint32_t face[2];
  };
  explicit EdgeMap(std::size_t expected_edges);
  const Slot *find(uint32_t u, uint32_t v) const;
  Slot &insert(uint32_t u, uint32_t v);  // finds or creates
  std::size_t memory_bytes() const { return slots_.size() * sizeof(Slot); }

 private:
  static uint64_t key_of(uint32_t u, uint32_t v);
  std::size_t index_of(uint64_t key) const;
  void grow();
  std::vector<Slot> slots_;
  std::size_t used_ = 0;
  int shift_ = 0;
};

// Why a candidate triangle was refused by the mesh's own rules.
enum class TopologyVerdict { Ok, EdgeFull, VertexFan, Orientation };

class MeshState {
 public:
  explicit MeshState(std::size_t vertex_count);

  // Faces ever added, removed ones included; check alive() when iterating.
  std::size_t face_count() const { return faces_.size(); }
  bool alive(uint32_t f) const { return alive_[f] != 0; }
  const Tri &stored(uint32_t f) const { return faces_[f]; }
  // The face as currently oriented (stored order, reversed when its component was flipped).
  Tri oriented(uint32_t f);

  // Representative of the face's orientation class: faces with the same component are
  // oriented relative to each other.
  uint32_t component(uint32_t f) {
    uint32_t parity;
    return find(f, parity);
  }

  // Faces on edge uv: 0, 1 or 2 of them, written to out.
  int edge_faces(uint32_t u, uint32_t v, uint32_t out[2]) const;
  const std::vector<uint32_t> &faces_at(uint32_t v) const { return vertex_faces_[v]; }
  bool fan_closed(uint32_t v) const {
    return !vertex_faces_[v].empty() && vertex_edges_[v] == vertex_faces_[v].size();
  }
  bool is_used(uint32_t v) const { return !vertex_faces_[v].empty(); }

  // Would oriented triangle t keep every edge at most two faces, every vertex one fan
  // (or separate open fans that may still join) and the surface orientable?
  TopologyVerdict check(const Tri &t);
  // Adds t (which must have passed check) and returns its face index.
  uint32_t add(const Tri &t);
  // Removes face f; its index is never reused.
  void remove(uint32_t f);
  // The corner of t where adding t would close one fan of a vertex that has other fans too
  // (the one rule of check() that the loop module can cure), or kNone.
  uint32_t fan_closing_blocked(const Tri &t) const;
  // Removes the faces around v that are not in the fan of face `keep`; returns how many.
  std::size_t remove_other_fans(uint32_t v, uint32_t keep);
  // Separate fans around v (0 for an unused vertex, 1 for a disk or a half-disk).
  uint32_t fan_count(uint32_t v) const {
    if (vertex_faces_[v].empty()) return 0;
    return fan_closed(v) ? 1 : vertex_edges_[v] - uint32_t(vertex_faces_[v].size());
  }

  std::size_t memory_bytes() const;
  // When set, a vertex that has faces accepts only faces that share an edge with its fan.
  void set_strict_fans(bool on) { strict_fans_ = on; }

 private:
  uint32_t find(uint32_t f, uint32_t &parity);
  bool same_chain(uint32_t v, uint32_t w1, uint32_t w2) const;
  // Orientation of t relative to face g across their shared edge uv: 0 consistent, 1 not.
  int mismatch(const Tri &t, uint32_t g) const;

  std::vector<Tri> faces_;
  std::vector<uint8_t> alive_;
  std::vector<uint32_t> parent_;
  std::vector<uint8_t> flip_;  // parity to parent
  EdgeMap edges_;
  std::vector<std::vector<uint32_t>> vertex_faces_;
  std::vector<uint32_t> vertex_edges_;  // edges at the vertex with at least one face
  bool strict_fans_ = false;
};

}  // namespace moa
