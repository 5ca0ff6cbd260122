// C5, all pairs: Embree's BVH collider (rtcCollide on a scene of box primitives) proposes the
// pairs of faces whose bounding boxes overlap; each is decided by the exact test.
#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "quality/analysis.hpp"
#include "quality/triangle_intersection.hpp"

namespace moa::quality {
namespace {

struct Box {
  double lo[3], hi[3];
};

struct Local {
  size_t candidates = 0;
  std::vector<std::pair<uint32_t, uint32_t>> hits;
};

struct Context {
  const double *xyz;
  const uint32_t *tri;
  std::vector<uint32_t> faces;  // primitive id -> face index
  std::vector<Box> boxes;       // per primitive, in double
  tbb::enumerable_thread_specific<Local> local;
};

// Rounds outward so that the float box contains the double box: touching faces must stay
// candidates.
float down(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, -INFINITY);
  return f;
}
float up(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, INFINITY);
  return f;
}

void bounds(const RTCBoundsFunctionArguments *args) {
  const Context &c = *static_cast<const Context *>(args->geometryUserPtr);
  const Box &b = c.boxes[args->primID];
  RTCBounds *o = args->bounds_o;
  o->lower_x = down(b.lo[0]);
  o->lower_y = down(b.lo[1]);
  o->lower_z = down(b.lo[2]);
  o->upper_x = up(b.hi[0]);
  o->upper_y = up(b.hi[1]);
  o->upper_z = up(b.hi[2]);
}

bool overlap(const Box &a, const Box &b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

Face face_of(const Context &c, uint32_t f) {
  Face out;
  for (int k = 0; k < 3; ++k) {
    out.v[k] = c.tri[3 * size_t(f) + k];
    out.p[k] = c.xyz + 3 * size_t(out.v[k]);
  }
  return out;
}

// Called by Embree, possibly from several threads at once. The collider reports each ordered
// pair of primitives from overlapping leaves; the pair (i, j) is kept once, as i < j.
void collide(void *user, RTCCollision *collisions, unsigned count) {
  Context &c = *static_cast<Context *>(user);
  Local &local = c.local.local();
  for (unsigned n = 0; n < count; ++n) {
    const uint32_t i = collisions[n].primID0, j = collisions[n].primID1;
    if (i >= j || !overlap(c.boxes[i], c.boxes[j])) continue;
    ++local.candidates;
    const uint32_t fi = c.faces[i], fj = c.faces[j];
    if (faces_intersect(face_of(c, fi), face_of(c, fj)))
      local.hits.push_back({std::min(fi, fj), std::max(fi, fj)});
  }
}

// Owns the device and scene, so that an error cannot leak them.
struct Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~Embree() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
  void check() const {
    const RTCError e = rtcGetDeviceError(device);
    if (e != RTC_ERROR_NONE)
      throw std::runtime_error("Embree error " + std::to_string(static_cast<int>(e)) +
                               " in the self-intersection test");
  }
};

}  // namespace

void find_self_intersections(const double *xyz, const uint32_t *tri, size_t triangle_count,
                             const std::vector<uint8_t> &face_class, MeshReport &r,
                             size_t max_listed) {
  const auto start = std::chrono::steady_clock::now();
  Context c;
  c.xyz = xyz;
  c.tri = tri;
  for (size_t f = 0; f < triangle_count; ++f)
    if (face_class[f] == kFaceOk) c.faces.push_back(static_cast<uint32_t>(f));
  c.boxes.resize(c.faces.size());
  for (size_t i = 0; i < c.faces.size(); ++i) {
    Box &b = c.boxes[i];
    const Face t = face_of(c, c.faces[i]);
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::min({t.p[0][k], t.p[1][k], t.p[2][k]});
      b.hi[k] = std::max({t.p[0][k], t.p[1][k], t.p[2][k]});
    }
  }

  std::vector<std::pair<uint32_t, uint32_t>> hits;
  if (c.faces.size() >= 2) {
    Embree embree;
    embree.device = rtcNewDevice(nullptr);
    if (!embree.device) throw std::runtime_error("cannot create an Embree device");
    embree.scene = rtcNewScene(embree.device);
    // The tree serves one query: a fast build beats a tighter tree.
    rtcSetSceneBuildQuality(embree.scene, RTC_BUILD_QUALITY_LOW);
    RTCGeometry geometry = rtcNewGeometry(embree.device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(c.faces.size()));
    rtcSetGeometryUserData(geometry, &c);
    rtcSetGeometryBoundsFunction(geometry, bounds, nullptr);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(embree.scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(embree.scene);
    embree.check();
    rtcCollide(embree.scene, embree.scene, collide, &c);
    embree.check();
  }
  for (Local &local : c.local) {
    r.candidate_pairs += local.candidates;
    hits.insert(hits.end(), local.hits.begin(), local.hits.end());
  }
  tbb::parallel_sort(hits.begin(), hits.end());
  r.self_intersecting_pairs = hits.size();
  if (hits.size() > max_listed) hits.resize(max_listed);
  r.intersecting_pairs = std::move(hits);
  r.intersection_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace moa::quality
