// Small meshes made in the tests, and pixel facts about pictures of them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/render.hpp"

namespace moa::test {

struct Mesh {
  std::vector<double> xyz;
  std::vector<uint32_t> tri;
  void vertex(double x, double y, double z) { xyz.insert(xyz.end(), {x, y, z}); }
  void face(uint32_t a, uint32_t b, uint32_t c) { tri.insert(tri.end(), {a, b, c}); }
  size_t vertices() const { return xyz.size() / 3; }
  size_t faces() const { return tri.size() / 3; }

  // As an OFF file.
  std::string off() const {
    std::string s = "OFF\n" + std::to_string(vertices()) + " " + std::to_string(faces()) + " 0\n";
    for (size_t v = 0; v < vertices(); ++v)
      s += std::to_string(xyz[3 * v]) + " " + std::to_string(xyz[3 * v + 1]) + " " +
           std::to_string(xyz[3 * v + 2]) + "\n";
    for (size_t f = 0; f < faces(); ++f)
      s += "3 " + std::to_string(tri[3 * f]) + " " + std::to_string(tri[3 * f + 1]) + " " +
           std::to_string(tri[3 * f + 2]) + "\n";
    return s;
  }
};

// The cube [-1, 1]^3, faces outward; vertex x + 2y + 4z has coordinate -1 or +1 on each axis
// as its bit is 0 or 1. Faces 2 and 3 make the +z side, the one the front view looks at.
inline Mesh cube() {
  Mesh m;
  for (int v = 0; v < 8; ++v) m.vertex(v & 1 ? 1 : -1, v & 2 ? 1 : -1, v & 4 ? 1 : -1);
  m.face(0, 2, 3), m.face(0, 3, 1);  // -z
  m.face(4, 5, 7), m.face(4, 7, 6);  // +z
  m.face(0, 1, 5), m.face(0, 5, 4);  // -y
  m.face(2, 6, 7), m.face(2, 7, 3);  // +y
  m.face(0, 4, 6), m.face(0, 6, 2);  // -x
  m.face(1, 3, 7), m.face(1, 7, 5);  // +x
  return m;
}

// The cube without its +z side: a box open towards the front view.
inline Mesh open_cube() {
  Mesh m = cube();
  m.tri.erase(m.tri.begin() + 6, m.tri.begin() + 12);
  return m;
}

inline int brightness(render::Rgb c) { return c.r + c.g + c.b; }

inline size_t count_colour(const render::Image &image, render::Rgb colour) {
  size_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += image.at(x, y) == colour;
  return n;
}

inline bool corners_are_background(const render::Image &image) {
  const int w = image.width - 1, h = image.height - 1;
  return image.at(0, 0) == render::kBackground && image.at(w, 0) == render::kBackground &&
         image.at(0, h) == render::kBackground && image.at(w, h) == render::kBackground;
}

// The side of a face that its normal points to is lit blue-grey: blue stands out and the
// light is more than the ambient part alone.
inline bool lit_front(render::Rgb c) {
  return c != render::kBackground && c.b > c.r + 20 && c.b > render::kFrontAlbedo.b / 2;
}

// The other side is sand: red above blue.
inline bool lit_back(render::Rgb c) {
  return c != render::kBackground && c.r > c.b + 20 && c.r > render::kBackAlbedo.r / 2;
}

}  // namespace moa::test
