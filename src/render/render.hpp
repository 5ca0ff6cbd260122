// Pictures of meshes for people without a viewer (`moa render`, `moa reconstruct --render`,
// `moa check --report`): an Embree ray caster with an orthographic camera fitted to the mesh,
// PNG files through libpng, and a small histogram plotter.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace moa::render {

// A file that cannot be written or read, or an Embree failure. what() names the file.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where the camera looks from, +y up: front looks from +z, back from -z, right from +x, left
// from -x, iso from (1, 1, 1). Top looks down from +y with -z at the top of the picture, bottom
// up from -y with +z at the top.
enum class View { Front, Back, Left, Right, Top, Bottom, Iso };

// "front" ... "iso"; false for another name.
bool view_from_name(const std::string &name, View &view);
const char *view_name(View view);
// "front|back|left|right|top|bottom|iso", for messages and help texts.
const char *view_names();

struct Rgb {
  uint8_t r, g, b;
  bool operator==(const Rgb &o) const { return r == o.r && g == o.g && b == o.b; }
  bool operator!=(const Rgb &o) const { return !(*this == o); }
};

// The colours a picture is made of. Boundary edges are drawn unlit, so their colour is exact.
inline constexpr Rgb kBackground{255, 255, 255};
inline constexpr Rgb kBoundaryColour{220, 30, 30};  // edges with one face
inline constexpr Rgb kDefectColour{200, 40, 220};   // non-manifold or self-intersecting faces
inline constexpr Rgb kFrontAlbedo{176, 194, 222};   // the side the face's normal points to
inline constexpr Rgb kBackAlbedo{222, 200, 160};    // the other side (seen through holes)
inline constexpr Rgb kWireColour{35, 40, 55};

// 8-bit RGB pixels, rows from the top.
struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
  Image() = default;
  Image(int w, int h, Rgb fill);
  Rgb at(int x, int y) const {
    const uint8_t *p = &rgb[3 * (size_t(y) * size_t(width) + size_t(x))];
    return {p[0], p[1], p[2]};
  }
  void set(int x, int y, Rgb c) {
    uint8_t *p = &rgb[3 * (size_t(y) * size_t(width) + size_t(x))];
    p[0] = c.r;
    p[1] = c.g;
    p[2] = c.b;
  }
};

struct Options {
  View view = View::Iso;
  int width = 1024, height = 1024;
  bool wireframe = false;  // the triangles' edges over the shading
};

// What to point out in a picture: edges as vertex pairs, faces by index.
struct Highlights {
  std::vector<std::pair<uint32_t, uint32_t>> boundary_edges;  // drawn as lines, kBoundaryColour
  std::vector<uint32_t> defective_faces;  // filled and outlined in kDefectColour
};

// Largest width or height accepted, so that an image fits in memory comfortably.
constexpr int kMaxSide = 8192;

// Ray casts the mesh (xyz: x y z per vertex, tri: 3 indices per triangle) on all cores: one ray
// per pixel, Lambert shading of both sides under one light plus ambient. Faces with an index
// out of range or a non-finite corner are left out; an empty mesh gives the background only.
Image render_mesh(const double *xyz, size_t vertex_count, const uint32_t *tri,
                  size_t triangle_count, const Options &options,
                  const Highlights *highlights = nullptr);

// Parses "WxH" (or "N" for a square), each side in [1, kMaxSide]; false when malformed.
bool parse_size(const std::string &text, int &width, int &height);

// True when the path ends in ".png", whatever the case.
bool has_png_extension(const std::string &path);

// PNG files (8-bit RGB) through libpng. Throw RenderError naming the file.
void write_png(const std::string &path, const Image &image);
Image read_png(const std::string &path);

// A bar chart of counts per bin, with the bins' edges labelled below (first_edge, first_edge +
// edge_step, ...) and the y axis in percent of the total.
Image plot_histogram(const std::vector<size_t> &counts, double first_edge, double edge_step,
                     int width = 640, int height = 360);

}  // namespace moa::render
