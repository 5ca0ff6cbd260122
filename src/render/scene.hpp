// Inside the renderer: the mesh in single precision, the camera fitted to it, and the Embree
// scene of its faces and highlighted lines.
#pragma once

#include <embree3/rtcore.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "render/render.hpp"

namespace moa::render::detail {

struct Vec3 {
  float x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(float s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Vec3 normalized(Vec3 a) {
  const float n = std::sqrt(dot(a, a));
  return n > 0 ? (1.0f / n) * a : a;
}

// The faces that can be drawn, in coordinates centred on their bounding box and scaled to
// about [-1, 1], so that float precision does not depend on where the mesh lies.
struct MeshCopy {
  std::vector<float> vertices;  // x y z per input vertex (non-finite ones stay NaN), + padding
  std::vector<uint8_t> used;    // per input vertex: a corner of a drawn face
  size_t vertex_count = 0;
  // The drawn faces: the input's own array when every face can be drawn (no copy), else a
  // copy of those that can, with their input indices.
  const uint32_t *faces = nullptr;
  size_t prim_count = 0;
  std::vector<uint32_t> kept_faces, face_of_prim;

  Vec3 vertex(uint32_t v) const {
    return {vertices[3 * v], vertices[3 * v + 1], vertices[3 * v + 2]};
  }
  size_t prims() const { return prim_count; }
  uint32_t input_face(size_t prim) const {
    return face_of_prim.empty() ? uint32_t(prim) : face_of_prim[prim];
  }
};

MeshCopy copy_mesh(const double *xyz, size_t vertex_count, const uint32_t *tri,
                   size_t triangle_count);

// An orthographic camera: parallel rays along `forward`, one per pixel.
struct Camera {
  Vec3 right, up, forward;  // orthonormal
  Vec3 centre;              // origin of the ray through the picture's centre, before the mesh
  float pixel = 1;          // scene units per pixel
  int width = 1, height = 1;
  // Origin of the ray through the point (x, y) of the picture, in pixels from its top-left
  // corner (the centre of pixel (i, j) is at (i + 0.5, j + 0.5)).
  Vec3 origin(float x, float y) const {
    const float sx = (x - 0.5f * float(width)) * pixel;
    const float sy = (0.5f * float(height) - y) * pixel;
    return centre + sx * right + sy * up;
  }
};

Camera fit_camera(const MeshCopy &mesh, View view, int width, int height);

// The Embree scene: the faces (geometry kFaces), the boundary edges and the outlines of the
// defective faces as ribbons a few pixels wide that always face the camera.
class Scene {
 public:
  static constexpr unsigned kFaces = 0, kBoundary = 1, kDefects = 2;

  Scene(const MeshCopy &mesh, const Highlights *highlights, float pixel);
  Scene(const Scene &) = delete;
  Scene &operator=(const Scene &) = delete;

  RTCScene handle() const { return scene_.get(); }
  // Per drawn face: it is one of the highlighted defective faces.
  bool defective(uint32_t prim) const { return !defective_.empty() && defective_[prim]; }

 private:
  void add_ribbons(unsigned id, const MeshCopy &mesh,
                   const std::vector<std::pair<uint32_t, uint32_t>> &edges, float radius);
  void check(const char *what) const;

  // Released in reverse order, also when the constructor throws.
  std::unique_ptr<RTCDeviceTy, void (*)(RTCDevice)> device_{nullptr, rtcReleaseDevice};
  std::unique_ptr<RTCSceneTy, void (*)(RTCScene)> scene_{nullptr, rtcReleaseScene};
  std::vector<uint8_t> defective_;
};

}  // namespace moa::render::detail
