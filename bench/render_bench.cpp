// Speed of `moa render` (issue: a 1024x1024 picture of a 1M-triangle mesh in well under a
// second): renders a closed torus of about a million triangles, shaded and with the wireframe,
// several times, and prints the wall time of each picture (scene build + ray casting) and of
// writing it as PNG. Usage: render_bench [TRIANGLES] [REPEATS] [OUT.png]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "render/render.hpp"

namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// A torus of rings x segments quads, two triangles each, outward facing.
void torus(int rings, int segments, std::vector<double> &xyz, std::vector<uint32_t> &tri) {
  const double two_pi = 6.283185307179586;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double u = two_pi * i / rings, v = two_pi * j / segments;
      xyz.insert(xyz.end(), {(3 + std::cos(v)) * std::cos(u), std::sin(v),
                             (3 + std::cos(v)) * std::sin(u)});
    }
  auto id = [&](int i, int j) { return uint32_t((i % rings) * segments + (j % segments)); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j)
      tri.insert(tri.end(), {id(i, j), id(i + 1, j + 1), id(i + 1, j), id(i, j), id(i, j + 1),
                             id(i + 1, j + 1)});
}

}  // namespace

int main(int argc, char **argv) {
  const double wanted = argc > 1 ? std::atof(argv[1]) : 1e6;
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  const std::string out = argc > 3 ? argv[3] : "";
  const int segments = 250, rings = std::max(3, int(std::lround(wanted / (2.0 * segments))));
  std::vector<double> xyz;
  std::vector<uint32_t> tri;
  torus(rings, segments, xyz, tri);
  std::printf("mesh: torus, %zu vertices, %zu triangles; picture 1024x1024, iso view\n",
              xyz.size() / 3, tri.size() / 3);
  for (bool wireframe : {false, true}) {
    moa::render::Options options;
    options.wireframe = wireframe;
    std::vector<double> times;
    moa::render::Image image;
    for (int r = 0; r < repeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      image = moa::render::render_mesh(xyz.data(), xyz.size() / 3, tri.data(), tri.size() / 3,
                                       options);
      times.push_back(ms_since(start));
    }
    std::sort(times.begin(), times.end());
    std::printf("%-10s render: median %.1f ms, best %.1f ms, worst %.1f ms over %d runs\n",
                wireframe ? "wireframe" : "shaded", times[times.size() / 2], times.front(),
                times.back(), repeats);
    if (!out.empty() && !wireframe) {
      const auto start = std::chrono::steady_clock::now();
      moa::render::write_png(out, image);
      std::printf("           PNG written to %s in %.1f ms\n", out.c_str(), ms_since(start));
    }
  }
  return 0;
}
