// The crossing index's grid of recent faces: face lists keyed by cell, in one open-addressing
// table and one array of list entries. A hash map of vectors cost a node, a vector and a heap
// block per cell, and its lookups (a division, pointer chasing and a cache miss each) were a
// tenth of Algorithm 1's time: a query looks up about 9 cells. Each entry carries its face's
// bounding box: a query's cells hold about four times as many faces as its box meets, and
// reading a face's corners to rule it out cost three cache misses each.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/geometry.hpp"
#include "core/mesh_state.hpp"

namespace moa {

class FaceGrid {
 public:
  // A box in single precision, rounded outward: it contains the double box it was made from,
  // so ruling a face out by it never rules out one that the double box would keep.
  struct Box {
    float lo[3], hi[3];
    Box() = default;
    Box(const Vec3 &l, const Vec3 &h)
        : lo{down(l.x), down(l.y), down(l.z)}, hi{up(h.x), up(h.y), up(h.z)} {}
    bool meets(const Box &o) const {
      return hi[0] >= o.lo[0] && lo[0] <= o.hi[0] && hi[1] >= o.lo[1] && lo[1] <= o.hi[1] &&
             hi[2] >= o.lo[2] && lo[2] <= o.hi[2];
    }

   private:
    static float down(double v) {
      const float f = float(v);
      return double(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
    }
    static float up(double v) {
      const float f = float(v);
      return double(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
    }
  };

  // Files face f, whose bounding box is `box`, under cell `key` (keys below 2^63).
  void insert(uint64_t key, uint32_t f, const Box &box) {
    if (2 * (used_ + 1) > slots_.size()) grow();
    Slot &s = slots_[find_slot(key)];
    if (s.key == kEmpty) {
      s.key = key;
      ++used_;
    }
    entries_.push_back({f, s.head, box});
    s.head = uint32_t(entries_.size() - 1);
  }

  // Calls visit(face) for the live faces filed under `key` whose boxes meet `query`, newest
  // first, until it returns true; removed faces leave the list as they are met, so later
  // queries skip them for free.
  template <class Visit>
  bool visit_live(uint64_t key, const MeshState &mesh, const Box &query, Visit &visit) {
    if (used_ == 0) return false;
    Slot &s = slots_[find_slot(key)];
    if (s.key == kEmpty) return false;
    for (uint32_t *link = &s.head; *link != kNone;) {
      Entry &e = entries_[*link];
      if (!mesh.alive(e.face)) {
        *link = e.next;
        continue;
      }
      if (e.box.meets(query) && visit(e.face)) return true;
      link = &e.next;
    }
    return false;
  }

  // Forgets every face and frees the memory.
  void release() {
    std::vector<Slot>().swap(slots_);
    std::vector<Entry>().swap(entries_);
    used_ = 0;
  }
  std::size_t memory_bytes() const {
    return slots_.capacity() * sizeof(Slot) + entries_.capacity() * sizeof(Entry);
  }

 private:
  static constexpr uint64_t kEmpty = ~uint64_t(0);
  static constexpr int kBlockBits = 3;
  static constexpr uint64_t kBlockMask = (uint64_t(1) << kBlockBits) - 1;
  struct Slot {
    uint64_t key = kEmpty;
    uint32_t head = kNone;  // newest entry of the cell's list
  };
  struct Entry {
    uint32_t face, next;
    Box box;
  };

  // Linear probing; the table is never more than half full. Keys are Morton codes: the cells
  // of an aligned block of 2x2x2 keep their order in consecutive slots (two cache lines), so
  // the cells around a query share a few cache lines (at a million points a cache miss per
  // cell lookup was the largest single cost inside the crossing test). The blocks are
  // scattered by a multiplicative hash: indexing by the code alone would let a dense region
  // fill a long run of slots that every lookup landing in it would probe through. Larger
  // blocks do that too, on a smaller scale: a surface fills a thin slice of each block, in
  // runs of consecutive codes, and where a few blocks land on the same stretch of slots their
  // runs collide. With blocks of 8x8x8 a lookup probed 17 slots on average on a million-point
  // sample of bunny and 43 on a noisy sphere; with 2x2x2, 2.2 and 2.4.
  std::size_t find_slot(uint64_t key) const {
    const std::size_t mask = slots_.size() - 1;
    const uint64_t block = ((key >> kBlockBits) * 0x9e3779b97f4a7c15ull) >> 24;
    std::size_t i = std::size_t((block << kBlockBits) | (key & kBlockMask)) & mask;
    while (slots_[i].key != key && slots_[i].key != kEmpty) i = (i + 1) & mask;
    return i;
  }
  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    slots_.assign(old.empty() ? 1024 : 2 * old.size(), Slot{});
    for (const Slot &s : old)
      if (s.key != kEmpty) slots_[find_slot(s.key)] = s;
  }

  std::vector<Slot> slots_;  // a power of two in size
  std::vector<Entry> entries_;
  uint32_t used_ = 0;
};

}  // namespace moa
