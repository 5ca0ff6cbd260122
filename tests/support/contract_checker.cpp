// The contract checker: C1 by exact tests per face, C2/C4 from a sorted half-edge list, C3 by
// grouping the faces around each vertex into fans, C4's volume by a filtered exact sum, C5 by
// intersection_scan. All containers are sorted, so the report is the same on every run.
#include "support/contract_checker.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include <gmpxx.h>

#include "support/exact_predicates.hpp"
#include "support/intersection_scan.hpp"

namespace moa::test {

namespace {

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) {
    for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Keeps the first few offences of each kind.
class Sampler {
 public:
  Sampler(std::vector<std::string> &out, std::size_t limit) : out_(out), limit_(limit) {}
  bool wants(const std::string &kind) { return seen_[kind]++ < limit_; }
  void add(const std::string &kind, const std::string &text) { out_.push_back(kind + ": " + text); }

 private:
  std::vector<std::string> &out_;
  std::size_t limit_;
  std::map<std::string, std::size_t> seen_;
};

std::string face_text(std::size_t f, const std::uint32_t *t) {
  std::ostringstream s;
  s << "face " << f << " (" << t[3 * f] << ' ' << t[3 * f + 1] << ' ' << t[3 * f + 2] << ')';
  return s.str();
}

struct HalfEdge {
  std::uint32_t lo, hi, face;
  bool forward;  // the face walks lo -> hi
  bool operator<(const HalfEdge &o) const {
    return lo != o.lo ? lo < o.lo : (hi != o.hi ? hi < o.hi : face < o.face);
  }
};

// Sign of six times the volume enclosed by the faces, about the reference point o.
int volume_sign(const double *xyz, const std::uint32_t *t, const std::vector<std::uint32_t> &faces,
                const Vec3 &o) {
  double sum = 0, permanent = 0;
  bool safe = true;  // every non-zero difference in [1e-90, 1e90]: no underflow in the products
  auto check = [&safe](double d) {
    const double m = std::fabs(d);
    safe = safe && (m == 0 || (m >= 1e-90 && m <= 1e90));
  };
  for (std::uint32_t f : faces) {
    const Vec3 a = point(xyz, t[3 * f]), b = point(xyz, t[3 * f + 1]), c = point(xyz, t[3 * f + 2]);
    const double ax = a.x - o.x, ay = a.y - o.y, az = a.z - o.z;
    const double bx = b.x - o.x, by = b.y - o.y, bz = b.z - o.z;
    const double cx = c.x - o.x, cy = c.y - o.y, cz = c.z - o.z;
    for (double d : {ax, ay, az, bx, by, bz, cx, cy, cz}) check(d);
    sum += ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
    permanent += std::fabs(ax) * (std::fabs(by * cz) + std::fabs(bz * cy)) +
                 std::fabs(ay) * (std::fabs(bz * cx) + std::fabs(bx * cz)) +
                 std::fabs(az) * (std::fabs(bx * cy) + std::fabs(by * cx));
  }
  // Rounding of each term plus the running sum: generous bound, exact sum when in doubt.
  const double bound = (16.0 + double(faces.size())) * 2.3e-16 * permanent;
  if (safe && std::fabs(sum) > bound) return sum > 0 ? 1 : -1;
  mpq_class exact = 0;
  const mpq_class ox(o.x), oy(o.y), oz(o.z);
  for (std::uint32_t f : faces) {
    const Vec3 a = point(xyz, t[3 * f]), b = point(xyz, t[3 * f + 1]), c = point(xyz, t[3 * f + 2]);
    const mpq_class ax = a.x - ox, ay = a.y - oy, az = a.z - oz;
    const mpq_class bx = b.x - ox, by = b.y - oy, bz = b.z - oz;
    const mpq_class cx = c.x - ox, cy = c.y - oy, cz = c.z - oz;
    exact += ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
  }
  return sgn(exact);
}

// Number of fans among the faces around one vertex: faces joined across shared edges.
std::size_t fan_count(std::uint32_t v, const std::uint32_t *t, const std::uint32_t *faces,
                      std::size_t k, std::vector<std::pair<std::uint32_t, std::uint32_t>> &scratch) {
  scratch.clear();
  for (std::size_t i = 0; i < k; ++i)
    for (int c = 0; c < 3; ++c)
      if (t[3 * faces[i] + c] != v) scratch.emplace_back(t[3 * faces[i] + c], std::uint32_t(i));
  std::sort(scratch.begin(), scratch.end());
  UnionFind uf(k);
  for (std::size_t i = 1; i < scratch.size(); ++i)
    if (scratch[i].first == scratch[i - 1].first) uf.unite(scratch[i].second, scratch[i - 1].second);
  std::size_t fans = 0;
  for (std::size_t i = 0; i < k; ++i) fans += uf.find(std::uint32_t(i)) == i;
  return fans;
}

}  // namespace

ContractReport check_contract(const double *xyz, std::size_t point_count,
                              const std::uint32_t *t, std::size_t face_count,
                              const CheckOptions &options) {
  ContractReport r;
  Sampler sample(r.samples, options.samples_per_kind);

  // C1, face by face. valid: three distinct in-range indices; usable: also non-degenerate.
  std::vector<std::uint8_t> valid(face_count, 0), usable(face_count, 0);
  for (std::size_t f = 0; f < face_count; ++f) {
    const std::uint32_t a = t[3 * f], b = t[3 * f + 1], c = t[3 * f + 2];
    if (a >= point_count || b >= point_count || c >= point_count) {
      ++r.bad_indices;
      if (sample.wants("C1 bad index")) sample.add("C1 bad index", face_text(f, t));
    } else if (a == b || b == c || a == c) {
      ++r.repeated_vertices;
      if (sample.wants("C1 repeated vertex")) sample.add("C1 repeated vertex", face_text(f, t));
    } else {
      valid[f] = 1;
      if (collinear3d(point(xyz, a), point(xyz, b), point(xyz, c))) {
        ++r.zero_area_faces;
        if (sample.wants("C1 zero area")) sample.add("C1 zero area", face_text(f, t));
      } else {
        usable[f] = 1;
      }
    }
  }
  std::vector<std::pair<std::array<std::uint32_t, 3>, std::uint32_t>> sorted_faces;
  for (std::size_t f = 0; f < face_count; ++f) {
    if (!valid[f]) continue;
    std::array<std::uint32_t, 3> key{t[3 * f], t[3 * f + 1], t[3 * f + 2]};
    std::sort(key.begin(), key.end());
    sorted_faces.push_back({key, std::uint32_t(f)});
  }
  std::sort(sorted_faces.begin(), sorted_faces.end());
  for (std::size_t i = 1; i < sorted_faces.size(); ++i) {
    if (sorted_faces[i].first != sorted_faces[i - 1].first) continue;
    ++r.duplicate_faces;
    if (sample.wants("C1 duplicate face"))
      sample.add("C1 duplicate face", face_text(sorted_faces[i].second, t) + " repeats " +
                                          face_text(sorted_faces[i - 1].second, t));
  }

  // Vertices and components (by shared vertices), numbered in order of first face.
  std::vector<std::uint8_t> used(point_count, 0);
  UnionFind comp_uf(point_count);
  std::vector<std::uint32_t> valid_faces;
  for (std::size_t f = 0; f < face_count; ++f) {
    if (!valid[f]) continue;
    valid_faces.push_back(std::uint32_t(f));
    for (int c = 0; c < 3; ++c) used[t[3 * f + c]] = 1;
    comp_uf.unite(t[3 * f], t[3 * f + 1]);
    comp_uf.unite(t[3 * f], t[3 * f + 2]);
  }
  r.faces = valid_faces.size();
  const std::uint32_t none = ~std::uint32_t(0);
  std::vector<std::uint32_t> comp_of_root(point_count, none);
  std::vector<std::vector<std::uint32_t>> comp_faces;
  for (std::uint32_t f : valid_faces) {
    std::uint32_t &id = comp_of_root[comp_uf.find(t[3 * f])];
    if (id == none) {
      id = std::uint32_t(comp_faces.size());
      comp_faces.emplace_back();
    }
    comp_faces[id].push_back(f);
  }
  auto comp_of_vertex = [&](std::uint32_t v) { return comp_of_root[comp_uf.find(v)]; };
  r.components = comp_faces.size();
  std::vector<long> comp_chi(r.components, 0);
  std::vector<std::uint8_t> comp_closed(r.components, 1);
  for (std::size_t v = 0; v < point_count; ++v) {
    if (!used[v]) continue;
    ++r.vertices_used;
    ++comp_chi[comp_of_vertex(std::uint32_t(v))];
  }
  for (std::size_t c = 0; c < r.components; ++c) comp_chi[c] += long(comp_faces[c].size());

  // C2 and C4 (edge directions), boundary edges, per-component edge counts.
  std::vector<HalfEdge> half;
  half.reserve(3 * valid_faces.size());
  for (std::uint32_t f : valid_faces)
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t from = t[3 * f + c], to = t[3 * f + (c + 1) % 3];
      half.push_back({std::min(from, to), std::max(from, to), f, from < to});
    }
  std::sort(half.begin(), half.end());
  UnionFind loop_uf(point_count);
  std::vector<std::uint8_t> on_boundary(point_count, 0);
  for (std::size_t begin = 0; begin < half.size();) {
    std::size_t end = begin + 1;
    while (end < half.size() && half[end].lo == half[begin].lo && half[end].hi == half[begin].hi) ++end;
    const HalfEdge &e = half[begin];
    const std::size_t n = end - begin;
    const std::uint32_t comp = comp_of_vertex(e.lo);
    ++r.edges;
    --comp_chi[comp];
    auto edge_text = [&] { return "edge " + std::to_string(e.lo) + '-' + std::to_string(e.hi); };
    if (n == 1) {
      ++r.boundary_edges;
      comp_closed[comp] = 0;
      loop_uf.unite(e.lo, e.hi);
      on_boundary[e.lo] = on_boundary[e.hi] = 1;
    } else if (n > 2) {
      ++r.non_manifold_edges;
      comp_closed[comp] = 0;
      if (sample.wants("C2 non-manifold edge"))
        sample.add("C2 non-manifold edge", edge_text() + " has " + std::to_string(n) + " faces");
    } else if (half[begin].forward == half[begin + 1].forward) {
      ++r.misoriented_edges;
      if (sample.wants("C4 misoriented edge"))
        sample.add("C4 misoriented edge", edge_text() + " walked the same way by " +
                                              face_text(half[begin].face, t) + " and " +
                                              face_text(half[begin + 1].face, t));
    }
    begin = end;
  }
  for (std::size_t v = 0; v < point_count; ++v)
    r.boundary_loops += on_boundary[v] && loop_uf.find(std::uint32_t(v)) == v;
  r.euler_characteristic = long(r.vertices_used) - long(r.edges) + long(r.faces);

  // C3: the faces around each vertex, joined across shared edges, must form one fan.
  std::vector<std::uint32_t> start(point_count + 1, 0), incident(3 * valid_faces.size());
  for (std::uint32_t f : valid_faces)
    for (int c = 0; c < 3; ++c) ++start[t[3 * f + c] + 1];
  for (std::size_t v = 0; v < point_count; ++v) start[v + 1] += start[v];
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t f : valid_faces)
      for (int c = 0; c < 3; ++c) incident[fill[t[3 * f + c]]++] = f;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> scratch;
  for (std::size_t v = 0; v < point_count; ++v) {
    const std::size_t k = start[v + 1] - start[v];
    if (k < 2) continue;
    const std::size_t fans = fan_count(std::uint32_t(v), t, incident.data() + start[v], k, scratch);
    if (fans > 1) {
      ++r.non_manifold_vertices;
      if (sample.wants("C3 non-manifold vertex"))
        sample.add("C3 non-manifold vertex", "vertex " + std::to_string(v) + " has " +
                                                 std::to_string(fans) + " fans");
    }
  }

  // Closed components: genus from chi, and they must enclose a positive volume (C4).
  for (std::size_t c = 0; c < r.components; ++c) {
    if (!comp_closed[c]) continue;
    ++r.closed_components;
    const long genus = (2 - comp_chi[c]) / 2;
    r.closed_genus.push_back(genus);
    r.genus_sum += genus;
    const Vec3 o = point(xyz, t[3 * comp_faces[c][0]]);
    const int sign = volume_sign(xyz, t, comp_faces[c], o);
    if (sign <= 0) {
      ++r.inward_components;
      if (sample.wants("C4 inward component"))
        sample.add("C4 inward component", "closed component of " + face_text(comp_faces[c][0], t) +
                                              (sign == 0 ? " has zero volume" : " faces inward"));
    }
  }

  // C5.
  if (options.check_intersections) {
    r.intersecting_pairs = scan_intersections(xyz, t, usable, [&](std::size_t f, std::size_t g, int shared) {
      if (sample.wants("C5 intersection"))
        sample.add("C5 intersection", face_text(f, t) + " and " + face_text(g, t) + " (sharing " +
                                          std::to_string(shared) + " vertices)");
    });
  }
  return r;
}

std::string ContractReport::describe() const {
  std::ostringstream s;
  auto verdict = [](bool ok) { return ok ? "ok" : "FAIL"; };
  s << "contract: C1 " << verdict(c1()) << ", C2 " << verdict(c2()) << ", C3 " << verdict(c3())
    << ", C4 " << verdict(c4()) << ", C5 " << verdict(c5()) << '\n';
  s << "  faces " << faces << ", vertices used " << vertices_used << ", edges " << edges
    << ", boundary edges " << boundary_edges << " in " << boundary_loops << " loops\n";
  s << "  components " << components << " (closed " << closed_components << "), euler "
    << euler_characteristic << ", genus sum " << genus_sum;
  if (!closed_genus.empty()) {
    s << " [";
    for (std::size_t i = 0; i < closed_genus.size() && i < 10; ++i) s << (i ? " " : "") << closed_genus[i];
    s << (closed_genus.size() > 10 ? " ...]" : "]");
  }
  s << '\n';
  s << "  C1: bad indices " << bad_indices << ", repeated vertices " << repeated_vertices
    << ", duplicate faces " << duplicate_faces << ", zero-area faces " << zero_area_faces << '\n';
  s << "  C2: non-manifold edges " << non_manifold_edges << "; C3: non-manifold vertices "
    << non_manifold_vertices << '\n';
  s << "  C4: misoriented edges " << misoriented_edges << ", inward closed components "
    << inward_components << "; C5: intersecting pairs " << intersecting_pairs << '\n';
  for (const std::string &line : samples) s << "    " << line << '\n';
  return s.str();
}

}  // namespace moa::test
