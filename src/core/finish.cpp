#include "core/finish.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <utility>

#include "core/disjoint_sets.hpp"

namespace moa {
namespace {

// Vertex -> incident alive faces, in compressed rows.
struct Incidence {
  std::vector<uint32_t> start, faces;
  Incidence() = default;
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
// can split fans elsewhere, so repeat until nothing changes. Returns faces removed, and leaves
// in `inc` the incidence of the faces kept.
std::size_t enforce_single_fans(std::size_t nv, const std::vector<Tri> &tris,
                                std::vector<char> &alive, Incidence &inc) {
  std::size_t removed = 0;
  DisjointSets fan;  // reused from vertex to vertex, as are size and others
  std::vector<uint32_t> size, others;
  std::vector<char> to_judge(nv);
  for (bool changed = true; changed;) {
    changed = false;
    inc = Incidence(nv, tris, alive);
    auto several_fans = [&](uint32_t v, std::vector<uint32_t> &scratch) {
      const uint32_t b = inc.start[v], n = inc.start[v + 1] - b;
      return n >= 2 && !one_live_fan(v, &inc.faces[b], n, tris, alive, scratch);
    };
    // The vertices in several fans are found in parallel (nearly every vertex has one fan:
    // telling that is most of the work), then judged one by one in vertex order, each as the
    // removals at the vertices before it left its faces, as a pass over every vertex in order
    // would: a vertex that lost a face in this pass is judged at its turn too.
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(nv), 4096),
                      [&](const tbb::blocked_range<uint32_t> &r) {
                        std::vector<uint32_t> scratch;
                        for (uint32_t v = r.begin(); v != r.end(); ++v)
                          to_judge[v] = several_fans(v, scratch);
                      });
    for (uint32_t v = 0; v < nv; ++v) {
      if (!to_judge[v] || !several_fans(v, others)) continue;
      const uint32_t b = inc.start[v], n = inc.start[v + 1] - b;
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
      for (uint32_t i = 0; i < n; ++i) {
        const uint32_t f = inc.faces[b + i];
        if (root(i) != best && alive[f]) {
          alive[f] = 0;
          ++removed;
          changed = true;
          for (uint32_t x : tris[f])
            if (x > v) to_judge[x] = 1;
        }
      }
    }
  }
  return removed;
}

// Joins in `comp` the faces on each edge, and returns the number of edges with one face. Each
// edge is looked at from its lower vertex, whose faces holding its upper one are those on it:
// in parallel over blocks of vertices, each block's findings kept apart, then joined on one
// thread.
std::size_t join_across_edges(const std::vector<Tri> &tris, const Incidence &inc,
                              DisjointSets &comp) {
  const uint32_t nv = uint32_t(inc.start.size() - 1);
  constexpr uint32_t kBlock = 4096;
  struct Found {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;  // faces sharing an edge
    std::size_t boundary = 0;
  };
  std::vector<Found> found((std::size_t(nv) + kBlock - 1) / kBlock);
  tbb::parallel_for(std::size_t(0), found.size(), [&](std::size_t block) {
    Found &out = found[block];
    std::vector<std::pair<uint32_t, uint32_t>> ends;  // (upper end, face)
    const uint32_t end = uint32_t(std::min<std::size_t>(nv, (block + 1) * kBlock));
    for (uint32_t u = uint32_t(block * kBlock); u < end; ++u) {
      ends.clear();
      for (uint32_t k = inc.start[u]; k < inc.start[u + 1]; ++k)
        for (uint32_t w : tris[inc.faces[k]])
          if (w > u) ends.push_back({w, inc.faces[k]});
      std::sort(ends.begin(), ends.end());
      for (std::size_t i = 0, j; i < ends.size(); i = j) {
        for (j = i + 1; j < ends.size() && ends[j].first == ends[i].first; ++j)
          out.pairs.push_back({ends[j - 1].second, ends[j].second});
        out.boundary += j == i + 1;
      }
    }
  });
  std::size_t boundary = 0;
  for (Found &f : found) {
    for (const auto &[a, b] : f.pairs) comp.join(a, b);
    boundary += f.boundary;
    std::vector<std::pair<uint32_t, uint32_t>>().swap(f.pairs);
  }
  return boundary;
}

// Turns every component so that its signed volume is positive: closed ones face outward.
// Returns the number of boundary edges. `inc` is the incidence of the alive faces; it is freed
// once read.
std::size_t orient_outward(const PointSet &points, std::vector<Tri> &tris,
                           const std::vector<char> &alive, Incidence &inc) {
  const std::size_t nf = tris.size();
  DisjointSets comp(nf);
  auto root = [&](uint32_t x) { return comp.root(x); };
  const std::size_t boundary = join_across_edges(tris, inc, comp);
  inc = Incidence();
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
  Incidence inc;
  stats.triangles_removed += enforce_single_fans(points.size(), faces, alive, inc);
  stats.boundary_edges = orient_outward(points, faces, alive, inc);
  std::size_t kept = 0;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (alive[f]) faces[kept++] = faces[f];
  faces.resize(kept);
  faces.shrink_to_fit();
}

}  // namespace moa
