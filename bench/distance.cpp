// Sampled two-sided distance between two triangle meshes (see distance.hpp).
//
// Embree's tree is built over single-precision boxes rounded outward, so it never drops a
// triangle that could be the closest; the distance to each candidate triangle is computed in
// double precision from the original coordinates.
#include "distance.hpp"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace moa::bench {
namespace {

struct Vec {
  double x, y, z;
};
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator*(double s, Vec a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

struct Mesh {
  const std::vector<double> &xyz;
  const std::vector<uint32_t> &tri;
  Vec vertex(size_t t, int corner) const {
    const double *p = &xyz[3 * size_t(tri[3 * t + corner])];
    return {p[0], p[1], p[2]};
  }
};

double segment_distance2(Vec p, Vec a, Vec b) {
  const Vec ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  const Vec d = p - (a + t * ab);
  return dot(d, d);
}

// Squared distance from p to triangle abc: the distance to the plane when p projects inside
// the triangle, otherwise to the nearest edge. Degenerate triangles are their edges.
double triangle_distance2(Vec p, Vec a, Vec b, Vec c) {
  const Vec n = cross(b - a, c - a);
  const double nn = dot(n, n);
  if (nn > 0) {
    // Inside when p lies on the inner side of all three edges, seen along the normal.
    const bool inside = dot(cross(b - a, p - a), n) >= 0 && dot(cross(c - b, p - b), n) >= 0 &&
                        dot(cross(a - c, p - c), n) >= 0;
    if (inside) {
      const double h = dot(p - a, n);
      return h * h / nn;
    }
  }
  return std::min({segment_distance2(p, a, b), segment_distance2(p, b, c), segment_distance2(p, c, a)});
}

// An Embree scene over one mesh's triangles, answering closest-distance queries.
class DistanceTree {
 public:
  explicit DistanceTree(const Mesh &mesh) : mesh_(mesh) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw std::runtime_error("cannot create an Embree device");
    scene_ = rtcNewScene(device_);
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(mesh.tri.size() / 3));
    rtcSetGeometryUserData(geometry, this);
    rtcSetGeometryBoundsFunction(geometry, bounds, nullptr);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
    const RTCError error = rtcGetDeviceError(device_);
    if (error != RTC_ERROR_NONE)
      throw std::runtime_error("Embree error " + std::to_string(int(error)) + " building the distance tree");
  }
  ~DistanceTree() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  DistanceTree(const DistanceTree &) = delete;
  DistanceTree &operator=(const DistanceTree &) = delete;

  // Distance from p to the closest point of the mesh.
  double distance(Vec p) const {
    Query q{this, p, std::numeric_limits<double>::infinity()};
    RTCPointQuery query{};
    query.x = float(p.x);
    query.y = float(p.y);
    query.z = float(p.z);
    query.time = 0;
    query.radius = std::numeric_limits<float>::infinity();
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    rtcPointQuery(scene_, &query, &context, visit, &q);
    return std::sqrt(q.best2);
  }

 private:
  struct Query {
    const DistanceTree *tree;
    Vec p;
    double best2;
  };

  static void bounds(const RTCBoundsFunctionArguments *args) {
    const auto *self = static_cast<const DistanceTree *>(args->geometryUserPtr);
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::numeric_limits<double>::infinity();
      hi[k] = -lo[k];
    }
    for (int corner = 0; corner < 3; ++corner) {
      const double *p = &self->mesh_.xyz[3 * size_t(self->mesh_.tri[3 * size_t(args->primID) + corner])];
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
    // Rounded outward so that the float box contains the double triangle.
    const float inf = std::numeric_limits<float>::infinity();
    RTCBounds *b = args->bounds_o;
    b->lower_x = std::nextafter(float(lo[0]), -inf);
    b->lower_y = std::nextafter(float(lo[1]), -inf);
    b->lower_z = std::nextafter(float(lo[2]), -inf);
    b->upper_x = std::nextafter(float(hi[0]), inf);
    b->upper_y = std::nextafter(float(hi[1]), inf);
    b->upper_z = std::nextafter(float(hi[2]), inf);
  }

  static bool visit(RTCPointQueryFunctionArguments *args) {
    auto *q = static_cast<Query *>(args->userPtr);
    const Mesh &m = q->tree->mesh_;
    const size_t t = args->primID;
    const double d2 = triangle_distance2(q->p, m.vertex(t, 0), m.vertex(t, 1), m.vertex(t, 2));
    if (d2 >= q->best2) return false;
    q->best2 = d2;
    // Shrink the search sphere, keeping a margin for the query point's rounding to float.
    const double d = std::sqrt(d2);
    const double slack = 1e-6 * (d + std::fabs(q->p.x) + std::fabs(q->p.y) + std::fabs(q->p.z));
    args->query->radius = std::nextafter(float(d + slack), std::numeric_limits<float>::infinity());
    return true;
  }

  const Mesh &mesh_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

// splitmix64: a tiny, well-mixed generator, seeded per triangle so that sampling runs in
// parallel and stays deterministic.
uint64_t mix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}
double unit(uint64_t &state) {
  state = mix(state);
  return double(state >> 11) * 0x1.0p-53;
}

struct OneSided {
  double max = 0, mean = 0;
  size_t samples = 0;
};

// Samples `from` (its vertices plus k area-weighted points per triangle) and measures each
// sample's distance to `to`.
OneSided one_sided(const Mesh &from, const DistanceTree &to, size_t min_samples, uint64_t seed) {
  const size_t triangles = from.tri.size() / 3, vertices = from.xyz.size() / 3;
  const size_t k = std::max<size_t>(1, (min_samples + triangles - 1) / std::max<size_t>(triangles, 1));
  struct Partial {
    double max = 0, weighted = 0, area = 0;
  };
  // Per-triangle results, reduced in order afterwards so that the sums do not depend on the
  // way the work was split between threads.
  std::vector<Partial> per_triangle(triangles);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, triangles, 256), [&](const tbb::blocked_range<size_t> &range) {
    for (size_t t = range.begin(); t != range.end(); ++t) {
      const Vec a = from.vertex(t, 0), b = from.vertex(t, 1), c = from.vertex(t, 2);
      const Vec n = cross(b - a, c - a);
      const double area = 0.5 * std::sqrt(dot(n, n));
      Partial &part = per_triangle[t];
      part.area = area;
      if (!(area > 0)) continue;  // a degenerate triangle covers no surface
      uint64_t state = seed ^ mix(t);
      for (size_t s = 0; s < k; ++s) {
        const double r1 = std::sqrt(unit(state)), r2 = unit(state);
        const Vec p = (1 - r1) * a + (r1 * (1 - r2)) * b + (r1 * r2) * c;
        const double d = to.distance(p);
        part.max = std::max(part.max, d);
        part.weighted += d * area / double(k);
      }
    }
  });
  std::vector<double> vertex_distance(vertices, 0.0);
  std::vector<uint8_t> used(vertices, 0);
  for (uint32_t v : from.tri) used[v] = 1;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, vertices, 1024), [&](const tbb::blocked_range<size_t> &range) {
    for (size_t v = range.begin(); v != range.end(); ++v)
      if (used[v]) vertex_distance[v] = to.distance({from.xyz[3 * v], from.xyz[3 * v + 1], from.xyz[3 * v + 2]});
  });

  OneSided out;
  double area = 0, weighted = 0;
  for (const Partial &p : per_triangle) {
    out.max = std::max(out.max, p.max);
    weighted += p.weighted;
    area += p.area;
    out.samples += p.area > 0 ? k : 0;
  }
  for (size_t v = 0; v < vertices; ++v) {
    out.max = std::max(out.max, vertex_distance[v]);
    out.samples += used[v];
  }
  out.mean = area > 0 ? weighted / area : 0;
  return out;
}

bool has_area(const Mesh &m) {
  for (size_t t = 0; t < m.tri.size() / 3; ++t) {
    const Vec n = cross(m.vertex(t, 1) - m.vertex(t, 0), m.vertex(t, 2) - m.vertex(t, 0));
    if (dot(n, n) > 0) return true;
  }
  return false;
}

}  // namespace

SurfaceDistance surface_distance(const std::vector<double> &mesh_xyz,
                                 const std::vector<uint32_t> &mesh_tri,
                                 const std::vector<double> &ref_xyz,
                                 const std::vector<uint32_t> &ref_tri, size_t min_samples,
                                 uint64_t seed) {
  const Mesh mesh{mesh_xyz, mesh_tri}, ref{ref_xyz, ref_tri};
  for (uint32_t v : mesh_tri)
    if (size_t(v) >= mesh_xyz.size() / 3) throw std::runtime_error("distance: a vertex index is out of range");
  if (!has_area(mesh)) throw std::runtime_error("distance: the mesh has no triangle of positive area");
  if (!has_area(ref)) throw std::runtime_error("distance: the reference has no triangle of positive area");

  SurfaceDistance out;
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::numeric_limits<double>::infinity();
    hi[k] = -lo[k];
  }
  for (size_t i = 0; i < ref_xyz.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], ref_xyz[i]);
    hi[i % 3] = std::max(hi[i % 3], ref_xyz[i]);
  }
  out.diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                           (hi[2] - lo[2]) * (hi[2] - lo[2]));

  {
    const DistanceTree ref_tree(ref);
    const OneSided to = one_sided(mesh, ref_tree, min_samples, seed);
    out.max_to_reference = to.max;
    out.mean_to_reference = to.mean;
    out.samples_mesh = to.samples;
  }
  {
    const DistanceTree mesh_tree(mesh);
    const OneSided from = one_sided(ref, mesh_tree, min_samples, mix(seed));
    out.max_from_reference = from.max;
    out.mean_from_reference = from.mean;
    out.samples_reference = from.samples;
  }
  return out;
}

}  // namespace moa::bench
