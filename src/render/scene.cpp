// The mesh in single precision, the camera per view and the Embree scene.
#include "render/scene.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace moa::render::detail {
namespace {

// Line widths in pixels, as ribbon radii.
constexpr float kBoundaryRadius = 1.5f;
constexpr float kDefectRadius = 1.0f;
// Blank space around the mesh, as a share of the picture.
constexpr float kMargin = 0.04f;

bool finite3(const double *p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

}  // namespace

MeshCopy copy_mesh(const double *xyz, size_t vertex_count, const uint32_t *tri,
                   size_t triangle_count) {
  MeshCopy m;
  m.vertex_count = vertex_count;
  // Faces without a repeated index, out-of-range index or non-finite corner can be drawn.
  std::vector<uint8_t> keep(triangle_count);
  const size_t kept = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, triangle_count), size_t(0),
      [&](const tbb::blocked_range<size_t> &range, size_t n) {
        for (size_t f = range.begin(); f != range.end(); ++f) {
          const uint32_t *t = tri + 3 * f;
          keep[f] = t[0] < vertex_count && t[1] < vertex_count && t[2] < vertex_count &&
                    t[0] != t[1] && t[1] != t[2] && t[2] != t[0] &&
                    finite3(xyz + 3 * size_t(t[0])) && finite3(xyz + 3 * size_t(t[1])) &&
                    finite3(xyz + 3 * size_t(t[2]));
          n += keep[f];
        }
        return n;
      },
      std::plus<size_t>());
  m.prim_count = kept;
  if (kept == triangle_count) {
    m.faces = tri;
  } else {
    m.kept_faces.reserve(3 * kept);
    m.face_of_prim.reserve(kept);
    for (size_t f = 0; f < triangle_count; ++f) {
      if (!keep[f]) continue;
      m.kept_faces.insert(m.kept_faces.end(), tri + 3 * f, tri + 3 * f + 3);
      m.face_of_prim.push_back(uint32_t(f));
    }
    m.faces = m.kept_faces.data();
  }
  m.used.assign(vertex_count, 0);
  for (size_t i = 0; i < 3 * kept; ++i) m.used[m.faces[i]] = 1;

  // The bounding box of the drawn vertices, its centre and half diagonal.
  using Box = std::array<double, 6>;  // lo x y z, hi x y z
  const double inf = std::numeric_limits<double>::infinity();
  const Box box = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, vertex_count), Box{inf, inf, inf, -inf, -inf, -inf},
      [&](const tbb::blocked_range<size_t> &range, Box b) {
        for (size_t v = range.begin(); v != range.end(); ++v) {
          if (!m.used[v]) continue;
          for (int k = 0; k < 3; ++k) {
            b[k] = std::min(b[k], xyz[3 * v + k]);
            b[k + 3] = std::max(b[k + 3], xyz[3 * v + k]);
          }
        }
        return b;
      },
      [](Box a, const Box &b) {
        for (int k = 0; k < 3; ++k)
          a[k] = std::min(a[k], b[k]), a[k + 3] = std::max(a[k + 3], b[k + 3]);
        return a;
      });
  double centre[3] = {0, 0, 0}, scale = 1;
  if (kept > 0) {
    double diagonal2 = 0;
    for (int k = 0; k < 3; ++k) {
      centre[k] = 0.5 * (box[k] + box[k + 3]);
      diagonal2 += (box[k + 3] - box[k]) * (box[k + 3] - box[k]);
    }
    if (diagonal2 > 0 && std::isfinite(diagonal2)) scale = 0.5 * std::sqrt(diagonal2);
  }
  // One float of padding: Embree reads 16 bytes at the last vertex.
  m.vertices.resize(3 * vertex_count + 1, 0.0f);
  const double inverse = 1 / scale;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_count), [&](const auto &range) {
    for (size_t v = range.begin(); v != range.end(); ++v)
      for (int k = 0; k < 3; ++k)
        m.vertices[3 * v + k] = float((xyz[3 * v + k] - centre[k]) * inverse);
  });
  return m;
}

Camera fit_camera(const MeshCopy &mesh, View view, int width, int height) {
  Camera c;
  c.width = width;
  c.height = height;
  Vec3 forward{0, 0, -1}, up{0, 1, 0};
  switch (view) {
    case View::Front:
      break;
    case View::Back:
      forward = {0, 0, 1};
      break;
    case View::Left:
      forward = {1, 0, 0};
      break;
    case View::Right:
      forward = {-1, 0, 0};
      break;
    case View::Top:
      forward = {0, -1, 0};
      up = {0, 0, -1};
      break;
    case View::Bottom:
      forward = {0, 1, 0};
      up = {0, 0, 1};
      break;
    case View::Iso:
      forward = normalized({-1, -1, -1});
      break;
  }
  c.forward = forward;
  c.right = normalized(cross(forward, up));
  c.up = cross(c.right, forward);

  // The extent of the drawn vertices across and along the view.
  float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
  for (size_t v = 0; v < mesh.vertex_count; ++v) {
    if (!mesh.used[v]) continue;
    const Vec3 p = mesh.vertex(uint32_t(v));
    const float s[3] = {dot(p, c.right), dot(p, c.up), dot(p, c.forward)};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], s[k]);
      hi[k] = std::max(hi[k], s[k]);
    }
  }
  if (lo[0] > hi[0]) {  // nothing to draw: any camera will do
    for (int k = 0; k < 3; ++k) lo[k] = -1, hi[k] = 1;
  }
  const float fit = std::max((hi[0] - lo[0]) / float(width), (hi[1] - lo[1]) / float(height));
  c.pixel = std::max(fit / (1 - 2 * kMargin), 1e-6f);
  c.centre =
      0.5f * (lo[0] + hi[0]) * c.right + 0.5f * (lo[1] + hi[1]) * c.up + (lo[2] - 1.0f) * c.forward;
  return c;
}

Scene::Scene(const MeshCopy &mesh, const Highlights *highlights, float pixel) {
  device_.reset(rtcNewDevice(nullptr));
  if (!device_) throw RenderError("cannot create an Embree device");
  scene_.reset(rtcNewScene(device_.get()));
  check("creating the scene");
  // One picture, one ray per pixel: building the tree fast matters more than a tight tree.
  rtcSetSceneBuildQuality(scene_.get(), RTC_BUILD_QUALITY_LOW);
  if (mesh.prims() > 0) {
    RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(g, RTC_BUILD_QUALITY_LOW);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               mesh.vertices.data(), 0, 3 * sizeof(float), mesh.vertex_count);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.faces, 0,
                               3 * sizeof(uint32_t), mesh.prims());
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(scene_.get(), g, kFaces);
    rtcReleaseGeometry(g);
  }
  if (highlights && mesh.prims() > 0) {
    add_ribbons(kBoundary, mesh, highlights->boundary_edges, kBoundaryRadius * pixel);
    if (!highlights->defective_faces.empty()) {
      // Mark the drawn faces among the defective ones and outline them: a defect smaller than
      // a pixel still shows.
      std::vector<uint8_t> by_input(size_t(mesh.input_face(mesh.prims() - 1)) + 1, 0);
      for (uint32_t f : highlights->defective_faces)
        if (f < by_input.size()) by_input[f] = 1;
      defective_.assign(mesh.prims(), 0);
      std::vector<std::pair<uint32_t, uint32_t>> outline;
      for (size_t p = 0; p < mesh.prims(); ++p) {
        if (!by_input[mesh.input_face(p)]) continue;
        defective_[p] = 1;
        for (int k = 0; k < 3; ++k)
          outline.push_back({mesh.faces[3 * p + k], mesh.faces[3 * p + (k + 1) % 3]});
      }
      add_ribbons(kDefects, mesh, outline, kDefectRadius * pixel);
    }
  }
  rtcCommitScene(scene_.get());
  check("building the scene");
}

void Scene::add_ribbons(unsigned id, const MeshCopy &mesh,
                        const std::vector<std::pair<uint32_t, uint32_t>> &edges, float radius) {
  std::vector<std::pair<uint32_t, uint32_t>> drawn;
  for (const auto &e : edges)
    if (e.first < mesh.vertex_count && e.second < mesh.vertex_count && mesh.used[e.first] &&
        mesh.used[e.second])
      drawn.push_back(e);
  if (drawn.empty()) return;
  RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_FLAT_LINEAR_CURVE);
  auto *points = static_cast<float *>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 2 * drawn.size()));
  auto *segments = static_cast<uint32_t *>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(uint32_t), drawn.size()));
  if (!points || !segments) {
    rtcReleaseGeometry(g);
    check("allocating lines");
    throw RenderError("cannot allocate the lines of the picture");
  }
  for (size_t i = 0; i < drawn.size(); ++i) {
    const Vec3 a = mesh.vertex(drawn[i].first), b = mesh.vertex(drawn[i].second);
    float *p = points + 8 * i;
    p[0] = a.x, p[1] = a.y, p[2] = a.z, p[3] = radius;
    p[4] = b.x, p[5] = b.y, p[6] = b.z, p[7] = radius;
    segments[i] = uint32_t(2 * i);
  }
  rtcCommitGeometry(g);
  rtcAttachGeometryByID(scene_.get(), g, id);
  rtcReleaseGeometry(g);
}

void Scene::check(const char *what) const {
  const RTCError e = rtcGetDeviceError(device_.get());
  if (e != RTC_ERROR_NONE)
    throw RenderError(std::string("Embree error ") + std::to_string(int(e)) + " " + what);
}

}  // namespace moa::render::detail
