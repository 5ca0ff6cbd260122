// Crossing checks: Embree rays along the candidate's edges (a triangle crosses another when an
// edge of one, cast as a segment ray, hits the other), an Embree point query for faces whose
// edges could pierce the candidate, and the grid of recent faces; the exact predicates decide.
#include "core/intersection.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <mutex>
#include <new>

#include "core/morton.hpp"
#include "core/predicates.hpp"

namespace moa {
namespace {

// Padding of every broad-phase box in work units (the cloud spans a unit diagonal): this, or a
// tenth of the median spacing when that is smaller. A point far from the rest squeezes the
// cloud into a corner of the unit box, and boxes padded by more than the spacing would each
// cover much of the cloud: every crossing test would test every face.
constexpr double kPad = 1e-5;
// Embree sees the points in single precision, in a frame of its own: centred on the bulk of the
// cloud (a far point cannot move that centre) with a unit of one grid cell, so rounding stays
// a small fraction of the spacing however the cloud sits in its box. Its point queries are
// widened by this share of their coordinates' magnitude, above that rounding.
constexpr double kFloatSlack = 0x1p-19;
constexpr int kMaxCellsPerFace = 64;
// How many pending faces scanned one by one cost about as much as building one face into the
// Embree scene (a box test takes nanoseconds, a face's share of a BVH build far more). Scans
// go on until they have cost as much as a rebuild would: the rule of renting until the rent
// paid equals the price, which never costs more than twice the better choice. With this rule
// building.ply's run rebuilds 28 times instead of 114.
constexpr double kScansPerBuiltFace = 16;
// Removed faces stay in the mesh's records. The scene reads those records in place while few of
// them are removed; when more than this share are (the loop module's widenings and retries
// remove about as many faces as they add), it is built from a compact copy of the live faces
// instead, or every query wades through the dead ones: on cow's 2,904 vertices 80 % of the
// faces the queries proposed had been removed.
constexpr double kMaxDeadShare = 0.25;

struct CollectContext {
  RTCIntersectContext base;  // first member: Embree hands this pointer back to the filter
  std::vector<uint32_t> *hits;
};

void collect_filter(const RTCFilterFunctionNArguments *args) {
  auto *cc = reinterpret_cast<CollectContext *>(args->context);
  cc->hits->push_back(RTCHitN_primID(args->hit, args->N, 0));
  args->valid[0] = 0;  // keep traversing: we want every face along the segment
}

// A ray from o along d (Embree's frame) over [0, tfar], to be hit anywhere.
RTCRayHit ray_along(const Vec3 &o, const Vec3 &d, float tfar) {
  RTCRayHit rh{};
  rh.ray.org_x = float(o.x);
  rh.ray.org_y = float(o.y);
  rh.ray.org_z = float(o.z);
  rh.ray.dir_x = float(d.x);
  rh.ray.dir_y = float(d.y);
  rh.ray.dir_z = float(d.z);
  rh.ray.tnear = 0.f;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xffffffffu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

bool collect_point_query(RTCPointQueryFunctionArguments *args) {
  static_cast<std::vector<uint32_t> *>(args->userPtr)->push_back(args->primID);
  return false;
}

// Whether box [lo, hi] covers more grid cells than a face may be filed under. Counted in
// doubles: when the points crowd into a tiny part of the unit box (a dense patch and one far
// point) the cells are tiny, and an integer product of the three spans would overflow.
bool too_many_cells(const Vec3 &lo, const Vec3 &hi, double cell) {
  const double span = (std::floor(hi.x / cell) - std::floor(lo.x / cell) + 1) *
                      (std::floor(hi.y / cell) - std::floor(lo.y / cell) + 1) *
                      (std::floor(hi.z / cell) - std::floor(lo.z / cell) + 1);
  return !(span <= kMaxCellsPerFace);  // NaN counts as too many
}

// A cell's Morton code: cells near each other get codes near each other, which the grid keeps
// in nearby slots (face_grid.hpp).
uint64_t cell_key(int64_t x, int64_t y, int64_t z) {
  return morton_code(uint64_t(x), uint64_t(y), uint64_t(z));
}

// One Embree device for the whole process, made on first use and never released. Devices are
// thread-safe and costly to make; and releasing one after an allocation failed inside Embree
// can hang in its tasking system, which would turn an out-of-memory error into a hung host.
RTCDevice shared_device() {
  static std::mutex mutex;
  static RTCDevice device = nullptr;
  std::lock_guard<std::mutex> lock(mutex);
  if (!device) device = rtcNewDevice("verbose=0");  // a failure is retried on the next run
  if (!device) throw std::bad_alloc();
  return device;
}

}  // namespace

CrossingIndex::CrossingIndex(const PointSet &points, double cell_size,
                             std::shared_ptr<const EmbreePoints> shared)
    : points_(points), cell_(cell_size), pad_(std::min(kPad, 0.05 * cell_size)) {
  if (shared && shared->unit == 1.0 / cell_size && shared->xyz.size() == points.size() * 3 + 4) {
    embree_ = std::move(shared);
  } else {
    auto own = std::make_shared<EmbreePoints>();
    const std::vector<Vec3> &placed = points.placed();
    // Embree's frame: the median of up to 1,024 points spread through the (Morton-ordered)
    // cloud, one grid cell to the unit.
    const std::size_t n = points.size(), step = std::max<std::size_t>(1, n / 1024);
    std::vector<double> xs, ys, zs;
    for (std::size_t i = 0; i < n; i += step) {
      xs.push_back(placed[i].x);
      ys.push_back(placed[i].y);
      zs.push_back(placed[i].z);
    }
    auto median = [](std::vector<double> &v) {
      std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
      return v[v.size() / 2];
    };
    own->origin = {median(xs), median(ys), median(zs)};
    own->unit = 1.0 / cell_size;
    own->xyz.resize(n * 3 + 4);  // Embree reads 16 bytes at the last vertex
    embree_ = own;  // the frame, for in_frame
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 p = in_frame(placed[i]);
      own->xyz[3 * i] = float(p.x);
      own->xyz[3 * i + 1] = float(p.y);
      own->xyz[3 * i + 2] = float(p.z);
    }
  }
  device_ = shared_device();
}

CrossingIndex::~CrossingIndex() { release(); }

void CrossingIndex::release() {
  set_aside();
  embree_.reset();
  tested_.release();
  std::vector<uint32_t>().swap(found_);
}

void CrossingIndex::set_aside() {
  if (scene_) rtcReleaseScene(static_cast<RTCScene>(scene_));
  scene_ = nullptr;
  committed_ = 0;
  grid_.release();
  std::vector<uint32_t>().swap(oversized_);
  std::vector<uint32_t>().swap(scene_corners_);
  std::vector<uint32_t>().swap(scene_faces_);
}

void CrossingIndex::bounds(const Tri &t, Vec3 &lo, Vec3 &hi) const {
  const std::vector<Vec3> &placed = points_.placed();
  const Vec3 &a = placed[t[0]], &b = placed[t[1]], &c = placed[t[2]];
  lo = {std::min({a.x, b.x, c.x}) - pad_, std::min({a.y, b.y, c.y}) - pad_,
        std::min({a.z, b.z, c.z}) - pad_};
  hi = {std::max({a.x, b.x, c.x}) + pad_, std::max({a.y, b.y, c.y}) + pad_,
        std::max({a.z, b.z, c.z}) + pad_};
}

void CrossingIndex::grid_insert(uint32_t f, const Tri &t) {
  Vec3 lo, hi;
  bounds(t, lo, hi);
  if (too_many_cells(lo, hi, cell_)) {
    oversized_.push_back(f);
    return;
  }
  const FaceGrid::Box box(lo, hi);
  int64_t x0 = int64_t(std::floor(lo.x / cell_)), x1 = int64_t(std::floor(hi.x / cell_));
  int64_t y0 = int64_t(std::floor(lo.y / cell_)), y1 = int64_t(std::floor(hi.y / cell_));
  int64_t z0 = int64_t(std::floor(lo.z / cell_)), z1 = int64_t(std::floor(hi.z / cell_));
  for (int64_t x = x0; x <= x1; ++x)
    for (int64_t y = y0; y <= y1; ++y)
      for (int64_t z = z0; z <= z1; ++z) grid_.insert(cell_key(x, y, z), f, box);
}

void CrossingIndex::rebuild(MeshState &mesh) {
  auto device = static_cast<RTCDevice>(device_);
  if (scene_) rtcReleaseScene(static_cast<RTCScene>(scene_));
  scene_ = nullptr;  // no stale handle if building the new scene fails below
  // The pending faces go into the new scene; their grid is freed before Embree allocates its
  // build, so that the two never add up (a failed build ends the run, index and all).
  grid_.release();
  // Owns the new scene and geometry until they are complete, so that a failed allocation
  // releases them; Embree's device cannot be released while they are alive.
  std::unique_ptr<RTCSceneTy, void (*)(RTCScene)> scene(rtcNewScene(device), rtcReleaseScene);
  std::unique_ptr<RTCGeometryTy, void (*)(RTCGeometry)> geom(
      rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE), rtcReleaseGeometry);
  if (!scene || !geom) throw std::bad_alloc();
  rtcSetSceneFlags(scene.get(), RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION | RTC_SCENE_FLAG_ROBUST |
                                    RTC_SCENE_FLAG_COMPACT);
  rtcSetSceneBuildQuality(scene.get(), RTC_BUILD_QUALITY_MEDIUM);
  rtcSetSharedGeometryBuffer(geom.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                             const_cast<float *>(embree_->xyz.data()), 0, 3 * sizeof(float),
                             points_.size());  // read only
  // Embree reads the mesh's own face records rather than a copy (removed faces included: every
  // query skips them), so the index costs no memory; GrowthState::add_face rebuilds it when they
  // move. Past kMaxDeadShare removed faces, the scene holds a copy of the live ones instead.
  const std::size_t count = mesh.face_count();
  const std::size_t live = count - mesh.removed_count();  // a removed face never comes back
  if (double(count - live) > kMaxDeadShare * double(count)) {
    scene_corners_.clear();
    scene_faces_.clear();
    scene_corners_.reserve(3 * live);
    scene_faces_.reserve(live);
    for (uint32_t f = 0; f < count; ++f) {
      if (!mesh.alive(f)) continue;
      const Tri &t = mesh.stored(f);
      scene_corners_.insert(scene_corners_.end(), t.begin(), t.end());
      scene_faces_.push_back(f);
    }
    rtcSetSharedGeometryBuffer(geom.get(), RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               scene_corners_.data(), 0, 3 * sizeof(uint32_t), live);
  } else {
    std::vector<uint32_t>().swap(scene_corners_);
    std::vector<uint32_t>().swap(scene_faces_);
    rtcSetSharedGeometryBuffer(geom.get(), RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               mesh.records(), offsetof(FaceRecord, corners), sizeof(FaceRecord),
                               count);
  }
  rtcCommitGeometry(geom.get());
  rtcAttachGeometry(scene.get(), geom.get());
  geom.reset();  // the scene holds it now
  rtcCommitScene(scene.get());
  if (rtcGetDeviceError(device) != RTC_ERROR_NONE) throw std::bad_alloc();
  scene_ = scene.release();
  committed_ = uint32_t(count);
  removed_at_build_ = mesh.removed_count();
  scan_debt_ = 0;
  oversized_.clear();
  ++rebuilds_;
}

void CrossingIndex::face_added(uint32_t f, MeshState &mesh) {
  grid_insert(f, mesh.stored(f));
  // Faces removed since the build count too: the scene still holds them, and the queries
  // wade through them (the loop module removes about as many faces as it adds).
  const std::size_t pending = mesh.face_count() - committed_;
  const std::size_t removed = mesh.removed_count() - removed_at_build_;
  if (pending + removed > std::max<std::size_t>(4096, committed_ / 2)) rebuild(mesh);
}

bool CrossingIndex::meet_exactly(const Tri &t, const Tri &g) const {
  const Vec3 tp[3] = {points_.exact(t[0]), points_.exact(t[1]), points_.exact(t[2])};
  const Vec3 gp[3] = {points_.exact(g[0]), points_.exact(g[1]), points_.exact(g[2])};
  const unsigned ti[3] = {t[0], t[1], t[2]}, gi[3] = {g[0], g[1], g[2]};
  return triangles_cross(tp, ti, gp, gi);
}

bool CrossingIndex::test_exact(const Tri &t, uint32_t f, MeshState &mesh) {
  if (tested_.has(f) || !mesh.alive(f)) return false;
  tested_.set(f);
  return meet_exactly(t, mesh.stored(f));
}

void CrossingIndex::next_query() { tested_.clear(); }

template <class Visit>
bool CrossingIndex::visit_oversized(const MeshState &mesh, Visit &visit) {
  // Removed faces leave the list as they are met (the loop module removes about as many faces
  // as it adds, and they would be met again by every later query); the order does not matter.
  std::vector<uint32_t> &faces = oversized_;
  for (std::size_t i = 0; i < faces.size();) {
    const uint32_t f = faces[i];
    if (!mesh.alive(f)) {
      faces[i] = faces.back();
      faces.pop_back();
      continue;
    }
    if (visit(f)) return true;
    ++i;
  }
  return false;
}

template <class Visit>
bool CrossingIndex::visit_near(const Vec3 &lo, const Vec3 &hi, MeshState &mesh, Visit &&visit) {
  const bool huge = too_many_cells(lo, hi, cell_);
  // A box too large for the grid scans every pending face, and the oversized faces are always
  // scanned: with many of either (the loop module trying long triangles across a wide border)
  // those scans would add up quadratically, so once they have cost as much as a rebuild, the
  // pending faces go into the Embree scene.
  const std::size_t scans = (huge ? mesh.face_count() - committed_ : 0) + oversized_.size();
  scan_debt_ += double(scans);
  if (scans > 0 && scan_debt_ > kScansPerBuiltFace * double(mesh.face_count())) rebuild(mesh);
  // Committed faces: an Embree point query over the box's circumscribed sphere.
  if (scene_ && committed_ > 0) {
    found_.clear();
    const Vec3 c = in_frame(midpoint(lo, hi));
    double radius = (norm(hi - lo) * 0.5 + pad_) * embree_->unit;
    radius += kFloatSlack * (std::max({std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)}) + radius);
    RTCPointQuery pq;
    pq.x = float(c.x);
    pq.y = float(c.y);
    pq.z = float(c.z);
    pq.time = 0.f;
    pq.radius = float(radius);
    RTCPointQueryContext pctx;
    rtcInitPointQueryContext(&pctx);
    rtcPointQuery(static_cast<RTCScene>(scene_), &pq, &pctx, collect_point_query, &found_);
    for (uint32_t prim : found_)
      if (visit(face_of(prim))) return true;
  }
  // Pending faces: the grid cells the box touches.
  if (huge) {
    for (uint32_t f = committed_; f < mesh.face_count(); ++f)
      if (visit(f)) return true;
    return false;
  }
  int64_t x0 = int64_t(std::floor(lo.x / cell_)), x1 = int64_t(std::floor(hi.x / cell_));
  int64_t y0 = int64_t(std::floor(lo.y / cell_)), y1 = int64_t(std::floor(hi.y / cell_));
  int64_t z0 = int64_t(std::floor(lo.z / cell_)), z1 = int64_t(std::floor(hi.z / cell_));
  // Faces whose boxes miss the query's are left out here, unlooked-at: every caller drops
  // them anyway.
  const FaceGrid::Box query(lo, hi);
  for (int64_t x = x0; x <= x1; ++x)
    for (int64_t y = y0; y <= y1; ++y)
      for (int64_t z = z0; z <= z1; ++z)
        if (grid_.visit_live(cell_key(x, y, z), mesh, query, visit)) return true;
  return visit_oversized(mesh, visit);
}

bool CrossingIndex::crosses(const Tri &t, double pad, MeshState &mesh,
                            std::vector<uint32_t> &near) {
  auto start = std::chrono::steady_clock::now();
  struct Timer {
    std::chrono::steady_clock::time_point s;
    double &acc;
    ~Timer() { acc += std::chrono::duration<double>(std::chrono::steady_clock::now() - s).count(); }
  } timer{start, seconds_};

  next_query();
  near.clear();
  // Faces sharing a vertex: the common case, decided exactly without any index.
  for (uint32_t v : t)
    for (uint32_t f : mesh.faces_at(v)) {
      if (!tested_.has(f)) near.push_back(f);
      if (test_exact(t, f, mesh)) return true;
    }

  // Committed faces: rays along the three edges first; they find the usual crossing quickly.
  if (scene_ && committed_ > 0) {
    auto scene = static_cast<RTCScene>(scene_);
    found_.clear();
    CollectContext cc;
    rtcInitIntersectContext(&cc.base);
    cc.base.filter = collect_filter;
    cc.hits = &found_;
    for (int e = 0; e < 3; ++e) {
      const Vec3 &p = points_.placed()[t[e]], &q = points_.placed()[t[(e + 1) % 3]];
      // The segment, lengthened slightly at both ends so float rounding cannot shorten it.
      const Vec3 d = (q - p) * embree_->unit, o = in_frame(p) - d * 1e-4;
      RTCRayHit rh = ray_along(o, d, 1.0002f);
      rtcIntersect1(scene, &cc.base, &rh);
    }
    for (uint32_t prim : found_) {
      const uint32_t f = face_of(prim);
      if (!tested_.has(f) && mesh.alive(f)) near.push_back(f);
      if (test_exact(t, f, mesh)) return true;
    }
  }
  // Then every face near t: faces whose own edges could pierce it, and the pending ones. The
  // box is padded for the neighbourhood; only faces whose boxes meet t's are tested. The index
  // proposes a superset (a sphere around the box, whole grid cells); `near` keeps exactly the
  // faces whose boxes meet the padded box, so that no verdict depends on which faces happen
  // to be committed to the scene.
  Vec3 lo, hi;
  bounds(t, lo, hi);
  const Vec3 p{pad, pad, pad}, plo = lo - p, phi = hi + p;
  return visit_near(plo, phi, mesh, [&](uint32_t f) {
    if (tested_.has(f) || !mesh.alive(f)) return false;
    Vec3 flo, fhi;
    bounds(mesh.stored(f), flo, fhi);
    if (!boxes_meet(flo, fhi, plo, phi)) {
      tested_.set(f);
      return false;
    }
    near.push_back(f);
    if (!boxes_meet(flo, fhi, lo, hi)) {
      tested_.set(f);
      return false;
    }
    return test_exact(t, f, mesh);
  });
}

void CrossingIndex::faces_in_box(const Vec3 &lo, const Vec3 &hi, MeshState &mesh,
                                 std::vector<uint32_t> &out) {
  next_query();
  visit_near(lo, hi, mesh, [&](uint32_t f) {
    if (tested_.has(f) || !mesh.alive(f)) return false;
    tested_.set(f);
    Vec3 flo, fhi;
    bounds(mesh.stored(f), flo, fhi);
    if (boxes_meet(flo, fhi, lo, hi)) out.push_back(f);
    return false;
  });
}

void CrossingIndex::faces_crossed(const Tri &t, MeshState &mesh, std::vector<uint32_t> &out) {
  Vec3 lo, hi;
  bounds(t, lo, hi);
  const std::size_t first = out.size();
  faces_in_box(lo, hi, mesh, out);
  out.erase(std::remove_if(out.begin() + std::ptrdiff_t(first), out.end(),
                           [&](uint32_t f) { return !meet_exactly(t, mesh.stored(f)); }),
            out.end());
}

std::size_t CrossingIndex::faces_along_ray(const Vec3 &p, const Vec3 &d, uint32_t skip,
                                           const MeshState &mesh,
                                           std::vector<uint32_t> &hits) const {
  hits.clear();
  if (!scene_ || committed_ == 0) return 0;
  CollectContext cc;
  rtcInitIntersectContext(&cc.base);
  cc.base.filter = collect_filter;
  cc.hits = &hits;
  RTCRayHit rh = ray_along(in_frame(p), d, std::numeric_limits<float>::infinity());
  rtcIntersect1(static_cast<RTCScene>(scene_), &cc.base, &rh);
  for (uint32_t &prim : hits) prim = face_of(prim);
  std::sort(hits.begin(), hits.end());
  hits.erase(std::unique(hits.begin(), hits.end()), hits.end());
  return std::size_t(std::count_if(hits.begin(), hits.end(), [&](uint32_t f) {
    return f != skip && f < committed_ && mesh.alive(f);
  }));
}

}  // namespace moa
