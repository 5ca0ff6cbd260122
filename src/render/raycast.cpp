// render_mesh: one ray per pixel in packets of 8, tiles spread over the cores by TBB, then
// four more rays in the pixels on a silhouette or a depth jump, so that outlines are smooth.
#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/render.hpp"
#include "render/scene.hpp"

namespace moa::render {
namespace {

using detail::Camera;
using detail::MeshCopy;
using detail::Scene;
using detail::Vec3;

constexpr int kTile = 16;
constexpr uint8_t kMiss = 255;
// Light: ambient, a key light above left of the camera, a weaker one from the camera itself
// so that the side away from the key light keeps its shape.
constexpr float kAmbient = 0.25f, kKey = 0.55f, kHead = 0.25f;
constexpr float kWireOpacity = 0.85f;
// A depth step larger than this many pixels between neighbours is an outline.
constexpr float kDepthJump = 3.0f;
// Where the extra rays of an outline pixel go (a rotated grid), in pixels from its centre.
constexpr float kSubsample[4][2] = {
    {-0.125f, -0.375f}, {0.375f, -0.125f}, {0.125f, 0.375f}, {-0.375f, 0.125f}};

struct Colour {
  float r = 0, g = 0, b = 0;
};

Colour colour_of(Rgb c) { return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f}; }

Rgb to_rgb(Colour c) {
  auto byte = [](float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return {byte(c.r), byte(c.g), byte(c.b)};
}

Colour mix(Colour a, Colour b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

class Shader {
 public:
  Shader(const MeshCopy &mesh, const Scene &scene, const Camera &camera, bool wireframe)
      : mesh_(mesh), scene_(scene), camera_(camera), wireframe_(wireframe) {
    key_ =
        detail::normalized((-1.0f) * camera.forward + 0.6f * camera.up + (-0.45f) * camera.right);
  }

  // The colour of a ray's hit from its geometry, primitive and barycentric coordinates.
  Colour shade(unsigned geometry, uint32_t prim, float u, float v) const {
    if (geometry == RTC_INVALID_GEOMETRY_ID) return colour_of(kBackground);
    if (geometry == Scene::kBoundary) return colour_of(kBoundaryColour);
    if (geometry == Scene::kDefects) return colour_of(kDefectColour);

    const uint32_t *t = mesh_.faces + 3 * size_t(prim);
    const Vec3 p0 = mesh_.vertex(t[0]), p1 = mesh_.vertex(t[1]), p2 = mesh_.vertex(t[2]);
    Vec3 n = detail::normalized(detail::cross(p1 - p0, p2 - p0));
    // Two-sided: light the side we see; the back side gets its own colour.
    const bool back = detail::dot(n, camera_.forward) > 0;
    if (back) n = (-1.0f) * n;
    const Rgb albedo = scene_.defective(prim) ? kDefectColour : back ? kBackAlbedo : kFrontAlbedo;
    const float light = kAmbient + kKey * std::max(0.0f, detail::dot(n, key_)) +
                        kHead * std::max(0.0f, -detail::dot(n, camera_.forward));
    Colour c = colour_of(albedo);
    c = {c.r * light, c.g * light, c.b * light};
    if (wireframe_)
      c = mix(c, colour_of(kWireColour), kWireOpacity * wire_coverage(u, v, p0, p1, p2));
    return c;
  }

 private:
  // How much of the pixel a one-pixel line along the nearest edge covers: the barycentric
  // coordinate of the hit times the triangle's height over that edge on screen is the distance
  // to the edge in pixels.
  float wire_coverage(float u, float v, Vec3 p0, Vec3 p1, Vec3 p2) const {
    const float inv = 1.0f / camera_.pixel;
    auto screen = [&](Vec3 p) {
      return std::pair<float, float>(detail::dot(p, camera_.right) * inv,
                                     detail::dot(p, camera_.up) * inv);
    };
    const auto [x0, y0] = screen(p0);
    const auto [x1, y1] = screen(p1);
    const auto [x2, y2] = screen(p2);
    const float twice_area = std::fabs((x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0));
    const float len0 = std::hypot(x2 - x1, y2 - y1);  // opposite p0
    const float len1 = std::hypot(x0 - x2, y0 - y2);
    const float len2 = std::hypot(x1 - x0, y1 - y0);
    const float w = 1 - u - v;  // u, v, w: the weights of p1, p2, p0
    float d = std::numeric_limits<float>::infinity();
    if (len0 > 0) d = std::min(d, w * twice_area / len0);
    if (len1 > 0) d = std::min(d, u * twice_area / len1);
    if (len2 > 0) d = std::min(d, v * twice_area / len2);
    return std::clamp(1.0f - d, 0.0f, 1.0f);
  }

  const MeshCopy &mesh_;
  const Scene &scene_;
  const Camera &camera_;
  bool wireframe_;
  Vec3 key_;
};

// Up to 8 parallel rays: fills their origins, traces them, and hands each hit to `use`.
template <class Use>
void trace8(const Scene &scene, const Camera &camera, int count, const float (*at)[2], Use use) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // parallel rays, side by side
  alignas(32) int valid[8];
  RTCRayHit8 rh;
  for (int i = 0; i < 8; ++i) {
    valid[i] = i < count ? -1 : 0;
    const Vec3 o = i < count ? camera.origin(at[i][0], at[i][1]) : camera.centre;
    rh.ray.org_x[i] = o.x, rh.ray.org_y[i] = o.y, rh.ray.org_z[i] = o.z;
    rh.ray.dir_x[i] = camera.forward.x, rh.ray.dir_y[i] = camera.forward.y;
    rh.ray.dir_z[i] = camera.forward.z;
    rh.ray.tnear[i] = 0;
    rh.ray.tfar[i] = std::numeric_limits<float>::infinity();
    rh.ray.time[i] = 0;
    rh.ray.mask[i] = ~0u;
    rh.ray.id[i] = 0;
    rh.ray.flags[i] = 0;
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect8(valid, scene.handle(), &context, &rh);
  for (int i = 0; i < count; ++i) use(i, rh);
}

}  // namespace

Image render_mesh(const double *xyz, size_t vertex_count, const uint32_t *tri,
                  size_t triangle_count, const Options &options, const Highlights *highlights) {
  const int width = options.width, height = options.height;
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
    throw RenderError("image size out of range: " + std::to_string(width) + "x" +
                      std::to_string(height));
  Image image(width, height, kBackground);
  const MeshCopy mesh = detail::copy_mesh(xyz, vertex_count, tri, triangle_count);
  if (mesh.prims() == 0) return image;
  const Camera camera = detail::fit_camera(mesh, options.view, width, height);
  const Scene scene(mesh, highlights, camera.pixel);
  const Shader shader(mesh, scene, camera, options.wireframe);
  const tbb::blocked_range2d<int> tiles(0, height, kTile, 0, width, kTile);

  // Pass 1: a ray through each pixel's centre, in 4x2 packets; keep what was hit and where.
  std::vector<float> depth(size_t(width) * size_t(height));
  std::vector<uint8_t> what(depth.size());  // geometry id, or kMiss
  tbb::parallel_for(tiles, [&](const tbb::blocked_range2d<int> &tile) {
    for (int y0 = tile.rows().begin(); y0 < tile.rows().end(); y0 += 2)
      for (int x0 = tile.cols().begin(); x0 < tile.cols().end(); x0 += 4) {
        float at[8][2];
        int pixel[8][2], count = 0;
        for (int i = 0; i < 8; ++i) {
          const int x = x0 + i % 4, y = y0 + i / 4;
          if (x >= tile.cols().end() || y >= tile.rows().end()) continue;
          at[count][0] = float(x) + 0.5f, at[count][1] = float(y) + 0.5f;
          pixel[count][0] = x, pixel[count][1] = y;
          ++count;
        }
        trace8(scene, camera, count, at, [&](int i, const RTCRayHit8 &rh) {
          const int x = pixel[i][0], y = pixel[i][1];
          const size_t p = size_t(y) * size_t(width) + size_t(x);
          what[p] = rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID ? kMiss : uint8_t(rh.hit.geomID[i]);
          depth[p] = rh.ray.tfar[i];
          image.set(
              x, y,
              to_rgb(shader.shade(rh.hit.geomID[i], rh.hit.primID[i], rh.hit.u[i], rh.hit.v[i])));
        });
      }
  });

  // Pass 2: where a neighbour shows something else, or lies much nearer or farther, average
  // the centre with four more rays.
  const float jump = kDepthJump * camera.pixel;
  tbb::parallel_for(tiles, [&](const tbb::blocked_range2d<int> &tile) {
    for (int y = tile.rows().begin(); y < tile.rows().end(); ++y)
      for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) {
        const size_t p = size_t(y) * size_t(width) + size_t(x);
        bool outline = false;
        for (const auto &[dx, dy] :
             {std::pair(1, 0), std::pair(-1, 0), std::pair(0, 1), std::pair(0, -1)}) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          const size_t q = size_t(ny) * size_t(width) + size_t(nx);
          // Misses have infinite depth; they differ from hits by `what` already.
          outline |=
              what[q] != what[p] || (what[p] != kMiss && std::fabs(depth[q] - depth[p]) > jump);
        }
        if (!outline) continue;
        float at[4][2];
        for (int i = 0; i < 4; ++i) {
          at[i][0] = float(x) + 0.5f + kSubsample[i][0];
          at[i][1] = float(y) + 0.5f + kSubsample[i][1];
        }
        const Colour centre = colour_of(image.at(x, y));
        Colour sum = centre;
        trace8(scene, camera, 4, at, [&](int i, const RTCRayHit8 &rh) {
          const Colour c =
              shader.shade(rh.hit.geomID[i], rh.hit.primID[i], rh.hit.u[i], rh.hit.v[i]);
          sum = {sum.r + c.r, sum.g + c.g, sum.b + c.b};
        });
        image.set(x, y, to_rgb({sum.r / 5, sum.g / 5, sum.b / 5}));
      }
  });
  return image;
}

}  // namespace moa::render
