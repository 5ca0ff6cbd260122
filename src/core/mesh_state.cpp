#include "core/mesh_state.hpp"

#include <algorithm>
#include <utility>

namespace moa {

// ---------------------------------------------------------------- EdgeMap

EdgeMap::EdgeMap(std::size_t expected_edges) {
  std::size_t cap = 1024;
  while (cap * 7 < expected_edges * 10) cap *= 2;  // at most 70 % full
  slots_.assign(cap, Slot{~0ULL, {kNone, kNone}});
  shift_ = 64;
  for (std::size_t c = cap; c > 1; c >>= 1) --shift_;
}

uint64_t EdgeMap::key_of(uint32_t u, uint32_t v) {
  if (u > v) std::swap(u, v);
  return (uint64_t(u) << 32) | v;
}

std::size_t EdgeMap::index_of(uint64_t key) const {
  return std::size_t((key * 0x9E3779B97F4A7C15ULL) >> shift_);
}

const EdgeMap::Slot *EdgeMap::find(uint32_t u, uint32_t v) const {
  uint64_t key = key_of(u, v);
  std::size_t mask = slots_.size() - 1;
  for (std::size_t i = index_of(key);; i = (i + 1) & mask) {
    if (slots_[i].key == key) return &slots_[i];
    if (slots_[i].key == ~0ULL) return nullptr;
  }
}

EdgeMap::Slot &EdgeMap::insert(uint32_t u, uint32_t v) {
  if ((used_ + 1) * 10 > slots_.size() * 7) grow();
  uint64_t key = key_of(u, v);
  std::size_t mask = slots_.size() - 1;
  for (std::size_t i = index_of(key);; i = (i + 1) & mask) {
    if (slots_[i].key == key) return slots_[i];
    if (slots_[i].key == ~0ULL) {
      ++used_;
      slots_[i].key = key;
      return slots_[i];
    }
  }
}

void EdgeMap::grow() {
  std::vector<Slot> old;
  old.swap(slots_);
  slots_.assign(old.size() * 2, Slot{~0ULL, {kNone, kNone}});
  --shift_;
  std::size_t mask = slots_.size() - 1;
  for (const Slot &s : old) {
    if (s.key == ~0ULL) continue;
    std::size_t i = index_of(s.key);
    while (slots_[i].key != ~0ULL) i = (i + 1) & mask;
    slots_[i] = s;
  }
}

// ---------------------------------------------------------------- MeshState

MeshState::MeshState(std::size_t vertex_count)
    : edges_(vertex_count * 3), vertex_faces_(vertex_count), vertex_edges_(vertex_count, 0) {
  faces_.reserve(vertex_count * 2);
}

uint32_t MeshState::find(uint32_t f, uint32_t &parity) {
  // Two passes: find the root and the parity, then compress the path.
  uint32_t root = f, p = 0;
  while (parent_[root] != root) {
    p ^= flip_[root];
    root = parent_[root];
  }
  parity = p;
  uint32_t cur = f, cur_parity = p;
  while (parent_[cur] != root && parent_[cur] != cur) {
    uint32_t next = parent_[cur];
    uint32_t next_parity = cur_parity ^ flip_[cur];
    parent_[cur] = root;
    flip_[cur] = uint8_t(cur_parity);
    cur = next;
    cur_parity = next_parity;
  }
  return root;
}

Tri MeshState::oriented(uint32_t f) {
  uint32_t parity;
  find(f, parity);
  Tri t = faces_[f];
  if (parity) std::swap(t[1], t[2]);
  return t;
}

int MeshState::edge_faces(uint32_t u, uint32_t v, uint32_t out[2]) const {
  const EdgeMap::Slot *s = edges_.find(u, v);
  if (!s) {
    out[0] = out[1] = kNone;
    return 0;
  }
  out[0] = s->face[0];
  out[1] = s->face[1];
  return (s->face[0] != kNone) + (s->face[1] != kNone);
}

static bool has_directed(const Tri &t, uint32_t u, uint32_t v) {
  for (int i = 0; i < 3; ++i)
    if (t[i] == u && t[(i + 1) % 3] == v) return true;
  return false;
}

int MeshState::mismatch(const Tri &t, uint32_t g) const {
  // Stored orders only; the parities are folded in by the caller.
  for (int i = 0; i < 3; ++i) {
    uint32_t u = t[i], v = t[(i + 1) % 3];
    if (has_directed(faces_[g], u, v)) return 1;  // same direction on the shared edge
    if (has_directed(faces_[g], v, u)) return 0;
  }
  return 0;
}

bool MeshState::same_chain(uint32_t v, uint32_t w1, uint32_t w2) const {
  // Walk the fan at v from boundary edge v-w1 through interior edges to the chain's other end.
  uint32_t fs[2];
  edge_faces(v, w1, fs);
  uint32_t f = fs[0], w = w1;
  for (std::size_t steps = 0; steps <= vertex_faces_[v].size(); ++steps) {
    const Tri &t = faces_[f];
    uint32_t next = kNone;
    for (uint32_t x : t)
      if (x != v && x != w) next = x;
    int n = edge_faces(v, next, fs);
    if (n < 2) return next == w2;
    f = fs[0] == f ? fs[1] : fs[0];
    w = next;
  }
  return false;
}

TopologyVerdict MeshState::check(const Tri &t) {
  // Edges: at most two faces, and a consistent orientation with the face already there.
  uint32_t roots[3], need[3];
  int adjacent = 0;
  for (int i = 0; i < 3; ++i) {
    uint32_t fs[2];
    int n = edge_faces(t[i], t[(i + 1) % 3], fs);
    if (n >= 2) return TopologyVerdict::EdgeFull;
    if (n == 1) {
      uint32_t parity;
      uint32_t root = find(fs[0], parity);
      uint32_t x = uint32_t(mismatch(t, fs[0])) ^ parity;
      for (int j = 0; j < adjacent; ++j)
        if (roots[j] == root && need[j] != x) return TopologyVerdict::Orientation;
      roots[adjacent] = root;
      need[adjacent] = x;
      ++adjacent;
    }
  }
  // Vertices: no face may join a closed fan; closing a chain is allowed only when it is the
  // vertex's only chain, so a disk never coexists with another fan.
  for (int i = 0; i < 3; ++i) {
    uint32_t v = t[i], a = t[(i + 1) % 3], b = t[(i + 2) % 3];
    if (fan_closed(v)) return TopologyVerdict::VertexFan;
    uint32_t fs[2];
    bool ea = edge_faces(v, a, fs) == 1, eb = edge_faces(v, b, fs) == 1;
    if (strict_fans_ && is_used(v) && !ea && !eb) return TopologyVerdict::VertexFan;
    if (ea && eb && same_chain(v, a, b)) {
      uint32_t chains = vertex_edges_[v] - uint32_t(vertex_faces_[v].size());
      if (chains != 1) return TopologyVerdict::VertexFan;
    }
  }
  return TopologyVerdict::Ok;
}

uint32_t MeshState::add(const Tri &t) {
  uint32_t id = uint32_t(faces_.size());
  faces_.push_back(t);
  alive_.push_back(1);
  parent_.push_back(id);
  flip_.push_back(0);
  for (int i = 0; i < 3; ++i) {
    uint32_t u = t[i], v = t[(i + 1) % 3];
    EdgeMap::Slot &s = edges_.insert(u, v);
    if (s.face[0] == kNone) {
      s.face[0] = id;
      ++vertex_edges_[u];
      ++vertex_edges_[v];
    } else {
      uint32_t g = s.face[0];
      s.face[1] = id;
      // Join orientation classes so that t and g agree on uv.
      uint32_t pt, pg;
      uint32_t rt = find(id, pt), rg = find(g, pg);
      if (rt != rg) {
        uint8_t x = uint8_t(uint32_t(mismatch(t, g)) ^ pt ^ pg);
        // Link the younger class under the older: path compression keeps chains short.
        if (rt > rg) std::swap(rt, rg);
        parent_[rg] = rt;
        flip_[rg] = x;
      }
    }
  }
  for (uint32_t v : t) vertex_faces_[v].push_back(id);
  return id;
}

void MeshState::remove(uint32_t f) {
  if (!alive_[f]) return;
  alive_[f] = 0;
  const Tri &t = faces_[f];
  for (int i = 0; i < 3; ++i) {
    uint32_t u = t[i], v = t[(i + 1) % 3];
    EdgeMap::Slot &s = edges_.insert(u, v);
    if (s.face[0] == f) {
      s.face[0] = s.face[1];
      s.face[1] = kNone;
    } else if (s.face[1] == f) {
      s.face[1] = kNone;
    }
    if (s.face[0] == kNone) {
      --vertex_edges_[u];
      --vertex_edges_[v];
    }
  }
  for (uint32_t v : t) {
    auto &list = vertex_faces_[v];
    list.erase(std::find(list.begin(), list.end(), f));
  }
}

uint32_t MeshState::fan_closing_blocked(const Tri &t) const {
  for (int i = 0; i < 3; ++i) {
    uint32_t v = t[i], a = t[(i + 1) % 3], b = t[(i + 2) % 3], fs[2];
    if (fan_closed(v) || edge_faces(v, a, fs) != 1 || edge_faces(v, b, fs) != 1) continue;
    if (same_chain(v, a, b) && vertex_edges_[v] - uint32_t(vertex_faces_[v].size()) != 1) return v;
  }
  return kNone;
}

std::size_t MeshState::remove_other_fans(uint32_t v, uint32_t keep) {
  // Collect keep's fan by crossing the interior edges at v, then drop every other face at v.
  std::vector<uint32_t> fan{keep}, others;
  for (std::size_t k = 0; k < fan.size(); ++k)
    for (uint32_t x : faces_[fan[k]]) {
      if (x == v) continue;
      uint32_t fs[2];
      if (edge_faces(v, x, fs) != 2) continue;
      for (uint32_t g : fs)
        if (std::find(fan.begin(), fan.end(), g) == fan.end()) fan.push_back(g);
    }
  for (uint32_t f : vertex_faces_[v])
    if (std::find(fan.begin(), fan.end(), f) == fan.end()) others.push_back(f);
  for (uint32_t f : others) remove(f);
  return others.size();
}

std::size_t MeshState::memory_bytes() const {
  std::size_t bytes = faces_.capacity() * sizeof(Tri) + parent_.capacity() * 4 + flip_.capacity() +
                      edges_.memory_bytes() + vertex_edges_.capacity() * 4;
  for (const auto &v : vertex_faces_) bytes += sizeof(v) + v.capacity() * 4;
  return bytes;
}

}  // namespace moa
