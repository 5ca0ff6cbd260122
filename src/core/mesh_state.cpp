#include "core/mesh_state.hpp"

#include <algorithm>
#include <utility>

namespace moa {

MeshState::MeshState(std::size_t vertex_count) : around_(vertex_count) {
  // A closed surface has about two faces per vertex; the loop module adds and removes some.
  // Reserved address space costs no memory until used, and a move of the faces costs a copy
  // and a rebuild of the crossing index, which reads them in place.
  const std::size_t expected_faces = vertex_count * 2 + vertex_count / 4 + 64;
  faces_.reserve(expected_faces);
  // The per-face vectors too: grown by doubling, each would leave its old copies as holes in
  // the heap.
  alive_.reserve(expected_faces);
  parent_.reserve(expected_faces);
  flip_.reserve(expected_faces);
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
  Tri t = faces_[f].corners;
  if (parity) std::swap(t[1], t[2]);
  return t;
}

int MeshState::edge_faces(uint32_t u, uint32_t v, uint32_t out[2]) const {
  // Both lists are in the order the faces were added: walk the shorter one.
  if (around_[v].count < around_[u].count) std::swap(u, v);
  out[0] = out[1] = kNone;
  if (around_[u].count == 0) return 0;  // (its `first` means nothing then)
  int n = 0;
  for (uint32_t f = around_[u].first; f != kNone && n < 2;) {
    const FaceRecord &r = faces_[f];
    if (r.corners[0] == v || r.corners[1] == v || r.corners[2] == v) out[n++] = f;
    f = r.next_around(u);
  }
  return n;
}

void MeshState::link(uint32_t f, uint32_t v) {
  VertexFaces &a = around_[v];
  if (a.count == 0)
    a.first = f;
  else
    faces_[a.last].next_slot(v) = f;
  faces_[f].next_slot(v) = kNone;
  a.last = f;
  ++a.count;
}

void MeshState::unlink(uint32_t f, uint32_t v) {
  VertexFaces &a = around_[v];
  const uint32_t next = faces_[f].next_around(v);
  uint32_t prev = kNone;
  if (a.first == f) {
    a.first = next;
  } else {
    prev = a.first;
    while (faces_[prev].next_around(v) != f) prev = faces_[prev].next_around(v);
    faces_[prev].next_slot(v) = next;
  }
  if (a.last == f) a.last = prev;
  if (--a.count == 0) a.last = f;
}

int MeshState::mismatch(const Tri &t, uint32_t g) const {
  // Stored orders only; the parities are folded in by the caller.
  for (int i = 0; i < 3; ++i) {
    uint32_t u = t[i], v = t[(i + 1) % 3];
    if (has_directed(faces_[g].corners, u, v)) return 1;  // same direction on the shared edge
    if (has_directed(faces_[g].corners, v, u)) return 0;
  }
  return 0;
}

bool MeshState::same_chain(uint32_t v, uint32_t w1, uint32_t w2) const {
  // Walk the fan at v from boundary edge v-w1 through interior edges to the chain's other end.
  uint32_t fs[2];
  edge_faces(v, w1, fs);
  uint32_t f = fs[0], w = w1;
  for (std::size_t steps = 0; steps <= around_[v].count; ++steps) {
    const Tri &t = faces_[f].corners;
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
  int adjacent = 0, faces_on[3];  // faces on edge t[i] t[i + 1]
  for (int i = 0; i < 3; ++i) {
    uint32_t fs[2];
    const int n = faces_on[i] = edge_faces(t[i], t[(i + 1) % 3], fs);
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
    // Edge v-a is edge i of t, edge b-v edge i + 2.
    const bool ea = faces_on[i] == 1, eb = faces_on[(i + 2) % 3] == 1;
    if (strict_fans_ && is_used(v) && !ea && !eb) return TopologyVerdict::VertexFan;
    if (ea && eb && same_chain(v, a, b)) {
      uint32_t chains = around_[v].edges - around_[v].count;
      if (chains != 1) return TopologyVerdict::VertexFan;
    }
  }
  return TopologyVerdict::Ok;
}

uint32_t MeshState::add(const Tri &t) {
  // The face already on each edge, looked up before t joins the lists.
  uint32_t on_edge[3];
  for (int i = 0; i < 3; ++i) {
    uint32_t fs[2];
    edge_faces(t[i], t[(i + 1) % 3], fs);
    on_edge[i] = fs[0];
  }
  uint32_t id = uint32_t(faces_.size());
  faces_.push_back({t, {kNone, kNone, kNone}});
  alive_.push_back(1);
  parent_.push_back(id);
  flip_.push_back(0);
  for (int i = 0; i < 3; ++i) {
    uint32_t u = t[i], v = t[(i + 1) % 3], g = on_edge[i];
    if (g == kNone) {
      ++around_[u].edges;
      ++around_[v].edges;
      continue;
    }
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
  for (uint32_t v : t) link(id, v);
  return id;
}

void MeshState::remove(uint32_t f) {
  if (!alive_[f]) return;
  alive_[f] = 0;
  ++removed_;
  const Tri t = faces_[f].corners;
  for (uint32_t v : t) unlink(f, v);
  for (int i = 0; i < 3; ++i) {
    uint32_t u = t[i], v = t[(i + 1) % 3], fs[2];
    if (edge_faces(u, v, fs) == 0) {
      --around_[u].edges;
      --around_[v].edges;
    }
  }
}

uint32_t MeshState::fan_closing_blocked(const Tri &t) const {
  for (int i = 0; i < 3; ++i) {
    uint32_t v = t[i], a = t[(i + 1) % 3], b = t[(i + 2) % 3], fs[2];
    if (fan_closed(v) || edge_faces(v, a, fs) != 1 || edge_faces(v, b, fs) != 1) continue;
    if (same_chain(v, a, b) && around_[v].edges - around_[v].count != 1) return v;
  }
  return kNone;
}

std::size_t MeshState::remove_other_fans(uint32_t v, uint32_t keep) {
  // Collect keep's fan by crossing the interior edges at v, then drop every other face at v.
  std::vector<uint32_t> fan{keep}, others;
  for (std::size_t k = 0; k < fan.size(); ++k)
    for (uint32_t x : faces_[fan[k]].corners) {
      if (x == v) continue;
      uint32_t fs[2];
      if (edge_faces(v, x, fs) != 2) continue;
      for (uint32_t g : fs)
        if (std::find(fan.begin(), fan.end(), g) == fan.end()) fan.push_back(g);
    }
  for (uint32_t f : faces_at(v))
    if (std::find(fan.begin(), fan.end(), f) == fan.end()) others.push_back(f);
  for (uint32_t f : others) remove(f);
  return others.size();
}

void MeshState::reverse_faces(const std::vector<uint32_t> &faces) {
  // Each face's stored order becomes its orientation, reversed for the listed faces, with
  // parity 0 under its old root: the classes stay as they were, so the reversed faces stay
  // tied to the rest of their class, now the other way round.
  const uint32_t n = uint32_t(faces_.size());
  std::vector<uint8_t> turned(n, 0);
  std::vector<uint32_t> roots(n);
  for (uint32_t f = 0; f < n; ++f) {
    uint32_t parity;
    roots[f] = find(f, parity);
    turned[f] = uint8_t(parity);
  }
  for (uint32_t f : faces) turned[f] ^= 1;
  for (uint32_t f = 0; f < n; ++f) {
    if (turned[f]) {
      std::swap(faces_[f].corners[1], faces_[f].corners[2]);
      std::swap(faces_[f].next[1], faces_[f].next[2]);
    }
    parent_[f] = roots[f];
    flip_[f] = 0;
  }
}

std::vector<uint32_t> MeshState::faces_across() const {
  std::vector<uint32_t> across(3 * faces_.size(), kNone);
  for (uint32_t f = 0; f < faces_.size(); ++f) {
    if (!alive_[f]) continue;
    const Tri &t = faces_[f].corners;
    for (int i = 0; i < 3; ++i) {
      uint32_t fs[2];
      if (edge_faces(t[i], t[(i + 1) % 3], fs) == 2) across[3 * f + i] = fs[0] == f ? fs[1] : fs[0];
    }
  }
  return across;
}

}  // namespace moa
