#include "core/finish.hpp"

#include <algorithm>

#include "core/disjoint_sets.hpp"

namespace moa {
namespace {

// Vertex -> incident alive faces, in compressed rows.
struct Incidence {
  std::vector<uint32_t> start, faces;
  Incidence(std::size_t nv, const std::vector<Tri> &tris, const std::vector<char> &alive) {
    start.assign(nv + 1, 0);
    for (std::size_t f = 0; f < tris.size(); ++f)
      if (alive[f])
        for (uint32_t v : tris[f]) ++start[v + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    faces.resize(start.back());
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < tris.size(); ++f)
      if (alive[f])
        for (uint32_t v : tris[f]) faces[fill[v]++] = uint32_t(f);
  }
};

bool share_other_vertex(const Tri &a, const Tri &b, uint32_t v) {
  for (uint32_t x : a)
    if (x != v && (x == b[0] || x == b[1] || x == b[2])) return true;
  return false;
}

// Whether the n faces at v, all alive, form one fan: walked from the first across shared
// vertices, each reaches the rest. `others` is scratch space. The common case, decided on a
// copy of the faces' other two corners rather than by the pairwise test below.
bool one_live_fan(uint32_t v, const uint32_t *faces, uint32_t n, const std::vector<Tri> &tris,
                  const std::vector<char> &alive, std::vector<uint32_t> &others) {
  others.clear();
  for (uint32_t i = 0; i < n; ++i) {
    if (!alive[faces[i]]) return false;
    for (uint32_t x : tris[faces[i]])
      if (x != v) others.push_back(x);
  }
  if (others.size() != 2 * std::size_t(n)) return false;  // a face with v twice
  // Faces reached so far are others[0, 2 * reached); the rest are swapped in as they are met.
  uint32_t reached = 1;
  for (uint32_t k = 0; k < 2 * reached; ++k)
    for (uint32_t j = reached; j < n; ++j)
      if (others[2 * j] == others[k] || others[2 * j + 1] == others[k]) {
        std::swap(others[2 * j], others[2 * reached]);
        std::swap(others[2 * j + 1], others[2 * reached + 1]);
        ++reached;
      }
  return reached == n;
}

// Removes, at every vertex whose faces form several fans, all fans but the largest. Removal
// can split fans elsewhere, so repeat until nothing changes. Returns faces removed.
std::size_t enforce_single_fans(std::size_t nv, const std::vector<Tri> &tris,
                                std::vector<char> &alive) {
  std::size_t removed = 0;
  DisjointSets fan;  // reused from vertex to vertex, as are size and others
  std::vector<uint32_t> size, others;
  for (bool changed = true; changed;) {
    changed = false;
    Incidence inc(nv, tris, alive);
    for (uint32_t v = 0; v < nv; ++v) {
      uint32_t b = inc.start[v], e = inc.start[v + 1], n = e - b;
      if (n < 2 || one_live_fan(v, &inc.faces[b], n, tris, alive, others)) continue;
      fan.reset(n);
      auto root = [&](uint32_t x) { return fan.root(x); };
      for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j)
          if (alive[inc.faces[b + i]] && alive[inc.faces[b + j]] &&
              share_other_vertex(tris[inc.faces[b + i]], tris[inc.faces[b + j]], v))
            fan.join(i, j);
      // The largest fan of live faces stays (of equal ones, that with the lower root). A face
      // removed earlier in the pass is no fan: counted as one, it outranked a lone live face
      // listed after it, whose removal then went on along the faces beyond.
      size.assign(n, 0);
      uint32_t best = kNone;
      for (uint32_t i = 0; i < n; ++i)
        if (alive[inc.faces[b + i]]) ++size[root(i)];
      for (uint32_t i = 0; i < n; ++i)
        if (alive[inc.faces[b + i]] &&
            (best == kNone || size[root(i)] > size[best] ||
             (size[root(i)] == size[best] && root(i) < best)))
          best = root(i);
      for (uint32_t i = 0; i < n; ++i)
        if (root(i) != best && alive[inc.faces[b + i]]) {
          alive[inc.faces[b + i]] = 0;
          ++removed;
          changed = true;
        }
    }
  }
  return removed;
}

// Turns every component so that its signed volume is positive: closed ones face outward.
// Returns the number of boundary edges, which the walk joining faces across their edges meets
// on the way (an edge no other face shares).
std::size_t orient_outward(const PointSet &points, std::vector<Tri> &tris,
                           const std::vector<char> &alive) {
  const std::size_t nf = tris.size();
  DisjointSets comp(nf);
  auto root = [&](uint32_t x) { return comp.root(x); };
  std::size_t boundary = 0;
  {
    Incidence inc(points.size(), tris, alive);
    for (uint32_t f = 0; f < nf; ++f) {
      if (!alive[f]) continue;
      for (int i = 0; i < 3; ++i) {
        uint32_t u = tris[f][i], w = tris[f][(i + 1) % 3];
        bool shared = false;
        for (uint32_t k = inc.start[u]; k < inc.start[u + 1]; ++k) {
          uint32_t h = inc.faces[k];
          if (h == f) continue;
          const Tri &t = tris[h];
          if (t[0] == w || t[1] == w || t[2] == w) {
            if (h > f) comp.join(f, h);  // each pair once: h meets f on this edge too
            shared = true;
          }
        }
        boundary += !shared;
      }
    }
  }
  // Number the components densely, in order of their root, so that the sums below take an
  // entry per component rather than per face (at a million points, 70 MB less at the end).
  std::vector<uint32_t> component(nf, kNone);
  uint32_t components = 0;
  for (uint32_t f = 0; f < nf; ++f)
    if (alive[f] && root(f) == f) component[f] = components++;
  for (uint32_t f = 0; f < nf; ++f)
    if (alive[f]) component[f] = component[root(f)];
  // Signed volume of each component, measured from the component's centre: the same as from
  // any point for a closed component; for an open one (a scan with a border, a surface with a
  // hole left open) it still tells the side that bulges out, so its normals face the same way.
  const std::vector<Vec3> &placed = points.placed();
  std::vector<Vec3> centre(components, Vec3{0, 0, 0});
  std::vector<uint32_t> corners(components, 0);
  for (uint32_t f = 0; f < nf; ++f) {
    if (!alive[f]) continue;
    for (int i = 0; i < 3; ++i) centre[component[f]] = centre[component[f]] + placed[tris[f][i]];
    corners[component[f]] += 3;
  }
  for (uint32_t c = 0; c < components; ++c) centre[c] = centre[c] * (1.0 / corners[c]);
  std::vector<double> volume(components, 0.0);
  for (uint32_t f = 0; f < nf; ++f) {
    if (!alive[f]) continue;
    const Vec3 &o = centre[component[f]];
    const Vec3 a = placed[tris[f][0]] - o, b = placed[tris[f][1]] - o, c = placed[tris[f][2]] - o;
    volume[component[f]] += dot(a, cross(b, c));
  }
  for (uint32_t f = 0; f < nf; ++f)
    if (alive[f] && volume[component[f]] < 0) std::swap(tris[f][1], tris[f][2]);
  return boundary;
}

}  // namespace

std::vector<Tri> oriented_faces(MeshState &mesh) {
  std::vector<Tri> out;
  out.reserve(mesh.face_count());
  for (uint32_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.alive(f)) out.push_back(mesh.oriented(f));
  return out;
}

void finish_mesh(const PointSet &points, std::vector<Tri> &faces, moa_stats &stats) {
  std::vector<char> alive(faces.size(), 1);
  stats.triangles_removed += enforce_single_fans(points.size(), faces, alive);
  stats.boundary_edges = orient_outward(points, faces, alive);
  std::size_t kept = 0;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (alive[f]) faces[kept++] = faces[f];
  faces.resize(kept);
  faces.shrink_to_fit();
}

}  // namespace moa
