// The growing mesh shared by Algorithm 1 and the loop module: faces, the faces around each
// vertex (which also tell the faces on an edge), per-vertex fan bookkeeping and a parity
// union-find that keeps the orientation consistent while separately seeded patches grow into
// each other (paper §3.3, Type 2 and Type 3).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

#include "core/zeroed_array.hpp"

namespace moa {

using Tri = std::array<uint32_t, 3>;
constexpr uint32_t kNone = 0xffffffffu;

// The corner of t that is neither u nor v.
inline uint32_t third_vertex(const Tri &t, uint32_t u, uint32_t v) {
  for (uint32_t x : t)
    if (x != u && x != v) return x;
  return kNone;
}

// Whether t, in its stored order, runs from u to v along one of its edges.
inline bool has_directed(const Tri &t, uint32_t u, uint32_t v) {
  for (int i = 0; i < 3; ++i)
    if (t[i] == u && t[(i + 1) % 3] == v) return true;
  return false;
}

// A face and, per corner, the next face around that corner's vertex: the faces around each
// vertex form a list threaded through the faces themselves, oldest first. 24 bytes per face
// and 16 per vertex hold what a vector per vertex and an edge-to-face hash map held in about
// 200 bytes per point.
struct FaceRecord {
  Tri corners;
  uint32_t next[3];
  int corner_of(uint32_t v) const { return corners[0] == v ? 0 : corners[1] == v ? 1 : 2; }
  uint32_t next_around(uint32_t v) const { return next[corner_of(v)]; }
  uint32_t &next_slot(uint32_t v) { return next[corner_of(v)]; }
};

// The faces around one vertex, oldest first (a forward range over face indices).
class FacesAround {
 public:
  class iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = uint32_t;
    using difference_type = std::ptrdiff_t;
    using pointer = const uint32_t *;
    using reference = uint32_t;
    iterator(const FaceRecord *faces, uint32_t v, uint32_t f) : faces_(faces), v_(v), f_(f) {}
    uint32_t operator*() const { return f_; }
    iterator &operator++() {
      f_ = faces_[f_].next_around(v_);
      return *this;
    }
    iterator operator++(int) {
      iterator old = *this;
      ++*this;
      return old;
    }
    bool operator==(const iterator &o) const { return f_ == o.f_; }
    bool operator!=(const iterator &o) const { return f_ != o.f_; }

   private:
    const FaceRecord *faces_;
    uint32_t v_, f_;
  };

  FacesAround(const FaceRecord *faces, uint32_t v, uint32_t first, uint32_t count)
      : faces_(faces), v_(v), first_(first), count_(count) {}
  iterator begin() const { return {faces_, v_, count_ != 0 ? first_ : kNone}; }
  iterator end() const { return {faces_, v_, kNone}; }
  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  // The oldest face; only for a vertex that has faces.
  uint32_t front() const { return first_; }

 private:
  const FaceRecord *faces_;
  uint32_t v_, first_, count_;
};

// Why a candidate triangle was refused by the mesh's own rules.
enum class TopologyVerdict { Ok, EdgeFull, VertexFan, Orientation };

class MeshState {
 public:
  explicit MeshState(std::size_t vertex_count);

  // Faces ever added, removed ones included; check alive() when iterating.
  std::size_t face_count() const { return faces_.size(); }
  bool alive(uint32_t f) const { return alive_[f] != 0; }
  // Faces removed so far.
  std::size_t removed_count() const { return removed_; }
  const Tri &stored(uint32_t f) const { return faces_[f].corners; }
  // Every face ever added, in order, for Embree to read in place. add() may move them.
  const FaceRecord *records() const { return faces_.data(); }
  // The face as currently oriented (stored order, reversed when its component was flipped).
  Tri oriented(uint32_t f);

  // Representative of the face's orientation class: faces with the same component are
  // oriented relative to each other.
  uint32_t component(uint32_t f) {
    uint32_t parity;
    return find(f, parity);
  }

  // Faces on edge uv: 0, 1 or 2 of them, oldest first, written to out.
  int edge_faces(uint32_t u, uint32_t v, uint32_t out[2]) const;
  // The face across each edge of each live face, 3 per face (edge i from corner i of the
  // stored order); kNone on an open edge and for removed faces.
  std::vector<uint32_t> faces_across() const;
  // The live face with these three corners, in any order, or kNone.
  uint32_t face_with(const Tri &t) const {
    uint32_t fs[2];
    const int n = edge_faces(t[0], t[1], fs);
    for (int i = 0; i < n; ++i)
      if (third_vertex(faces_[fs[i]].corners, t[0], t[1]) == t[2]) return fs[i];
    return kNone;
  }
  FacesAround faces_at(uint32_t v) const {
    const VertexFaces &a = around_[v];
    return {faces_.data(), v, a.count != 0 ? a.first : a.last, a.count};
  }
  bool fan_closed(uint32_t v) const {
    return around_[v].count != 0 && around_[v].edges == around_[v].count;
  }
  bool is_used(uint32_t v) const { return around_[v].count != 0; }
  // Calls visit(f, i) for each open edge (one face), as corners i, i + 1 of face f's stored
  // order, faces in order. Edges at a vertex with a closed fan are skipped unlooked-at: they
  // all have two faces, and a finished mesh has few open fans.
  template <class Visit>
  void for_each_open_edge(Visit &&visit) const {
    for (uint32_t f = 0; f < faces_.size(); ++f) {
      if (!alive_[f]) continue;
      const Tri &t = faces_[f].corners;
      for (int i = 0; i < 3; ++i) {
        const uint32_t u = t[i], v = t[(i + 1) % 3];
        uint32_t fs[2];
        if (!fan_closed(u) && !fan_closed(v) && edge_faces(u, v, fs) == 1) visit(f, i);
      }
    }
  }

  // Would oriented triangle t keep every edge at most two faces, every vertex one fan
  // (or separate open fans that may still join) and the surface orientable?
  TopologyVerdict check(const Tri &t);
  // Adds t (which must have passed check) and returns its face index.
  uint32_t add(const Tri &t);
  // Whether the next add moves the face records (face_count() reached their capacity).
  bool full() const { return faces_.size() == faces_.capacity(); }
  // Removes face f; its index is never reused.
  void remove(uint32_t f);
  // The corner of t where adding t would close one fan of a vertex that has other fans too
  // (the one rule of check() that the loop module can cure), or kNone.
  uint32_t fan_closing_blocked(const Tri &t) const;
  // Removes the faces around v that are not in the fan of face `keep`; returns how many.
  std::size_t remove_other_fans(uint32_t v, uint32_t keep);
  // Separate fans around v (0 for an unused vertex, 1 for a disk or a half-disk).
  uint32_t fan_count(uint32_t v) const {
    if (around_[v].count == 0) return 0;
    return fan_closed(v) ? 1 : around_[v].edges - around_[v].count;
  }

  // Turns the faces listed the other way round within their orientation classes (which stay
  // as they are), and makes every face's stored order its current orientation.
  void reverse_faces(const std::vector<uint32_t> &faces);

  // When set, a vertex that has faces accepts only faces that share an edge with its fan.
  void set_strict_fans(bool on) { strict_fans_ = on; }

 private:
  uint32_t find(uint32_t f, uint32_t &parity);
  bool same_chain(uint32_t v, uint32_t w1, uint32_t w2) const;
  // Orientation of t relative to face g across their shared edge uv: 0 consistent, 1 not.
  int mismatch(const Tri &t, uint32_t g) const;

  // Per vertex: the ends of its list of faces, their number, and the number of edges at the
  // vertex that have at least one face (a closed fan has as many edges as faces). The ends
  // mean something only while the list has faces (all zero bytes is an unused vertex), but
  // once it is empty again, `last` keeps the face removed last (FacesAround::front).
  struct VertexFaces {
    uint32_t first, last, count, edges;
  };
  void link(uint32_t f, uint32_t v);
  void unlink(uint32_t f, uint32_t v);

  std::vector<FaceRecord> faces_;
  std::vector<uint8_t> alive_;
  std::size_t removed_ = 0;
  std::vector<uint32_t> parent_;
  std::vector<uint8_t> flip_;  // parity to parent
  ZeroedArray<VertexFaces> around_;  // per vertex of the whole cloud; a part writes a tenth
  bool strict_fans_ = false;
};

}  // namespace moa
