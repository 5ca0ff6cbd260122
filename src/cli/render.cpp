// `moa render`: a picture of a mesh for people without a viewer (servers, CI, notebooks), and
// the picture `moa reconstruct --render` draws of its result.
#include "render/render.hpp"

#include <chrono>
#include <cstdio>
#include <string>

#include "cli/cli.hpp"
#include "io/io.hpp"
#include "quality/defects.hpp"

namespace moa::cli {

const char *const kRenderHelp =
    "Usage: moa render MESH -o IMAGE.png [options]\n"
    "\n"
    "Draws the triangle mesh MESH (.ply .off .obj .stl) into a PNG picture: ray cast on all\n"
    "cores, both sides of the faces lit (the side the normals point to in blue-grey, the other\n"
    "side in sand), the camera fitted to the mesh.\n"
    "\n"
    "Options:\n"
    "  -o, --output FILE.png    the picture to write (required)\n"
    "      --view NAME          front, back, left, right, top, bottom or iso (default iso);\n"
    "                           +y is up, front looks from +z, right from +x, top from +y\n"
    "      --size WxH           picture size in pixels, up to 8192 a side (default 1024x1024;\n"
    "                           N for NxN)\n"
    "      --wireframe          draw the edges of the triangles\n"
    "      --highlight-defects  boundary edges in red; faces on a non-manifold edge or vertex\n"
    "                           or crossing another face in purple (the crossings are decided\n"
    "                           exactly, which takes as long as moa check)\n"
    "  -q, --quiet              no summary line\n"
    "  -h, --help               this text\n";

namespace {

struct RenderArgs {
  std::string mesh, image;
  render::Options render;
  bool highlight = false;
  bool quiet = false;
  bool help = false;
};

RenderArgs parse_render_args(int argc, char **argv) {
  RenderArgs o;
  ArgWalker args(argc, argv, "render");
  while (args.next()) {
    if (args.positional()) {
      if (!o.mesh.empty()) args.unknown();
      o.mesh = args.arg();
    } else if (args.is("-h", "--help")) {
      o.help = true;
      return o;
    } else if (args.is("-o", "--output")) {
      o.image = args.value();
    } else if (args.is(nullptr, "--view")) {
      const std::string name = args.value();
      if (!render::view_from_name(name, o.render.view))
        throw CliError(kExitUsage,
                       "--view '" + name + "': expected one of " + render::view_names());
    } else if (args.is(nullptr, "--size")) {
      const std::string size = args.value();
      if (!render::parse_size(size, o.render.width, o.render.height))
        throw CliError(kExitUsage, "--size '" + size + "': expected WxH or N, each from 1 to " +
                                       std::to_string(render::kMaxSide));
    } else if (args.is(nullptr, "--wireframe")) {
      o.render.wireframe = true;
    } else if (args.is(nullptr, "--highlight-defects")) {
      o.highlight = true;
    } else if (args.is("-q", "--quiet")) {
      o.quiet = true;
    } else {
      args.unknown();
    }
  }
  if (o.mesh.empty()) throw CliError(kExitUsage, "missing MESH (see moa render --help)");
  if (o.image.empty()) throw CliError(kExitUsage, "missing -o IMAGE.png");
  return o;
}

render::Highlights highlights_of(const io::MeshData &mesh, bool test_intersections) {
  MeshDefects d = find_mesh_defects(mesh.xyz.data(), mesh.xyz.size() / 3, mesh.triangles.data(),
                                    mesh.triangles.size() / 3, test_intersections);
  render::Highlights h;
  h.boundary_edges = std::move(d.boundary_edges);
  h.defective_faces = std::move(d.defective_faces);
  return h;
}

render::Image draw(const io::MeshData &mesh, const render::Options &options,
                   const render::Highlights *highlights) {
  try {
    return render::render_mesh(mesh.xyz.data(), mesh.xyz.size() / 3, mesh.triangles.data(),
                               mesh.triangles.size() / 3, options, highlights);
  } catch (const render::RenderError &e) {
    throw CliError(kExitInternal, std::string("cannot render: ") + e.what());
  }
}

void write(const std::string &path, const render::Image &image) {
  try {
    render::write_png(path, image);
  } catch (const render::RenderError &e) {
    throw CliError(kExitOutput, about_file(path, e.what()));
  }
}

}  // namespace

// A picture's name must end in .png: checked before anything long runs.
void check_png_path(const std::string &path) {
  if (!render::has_png_extension(path))
    throw CliError(kExitOutput, path + ": pictures are written as PNG (use a .png name)");
  check_writable(path);
}

double render_result(const std::string &image_path, const io::MeshData &mesh) {
  const auto start = Clock::now();
  // The library's meshes are manifold and free of crossings: only the borders can show.
  const render::Highlights highlights = highlights_of(mesh, false);
  write(image_path, draw(mesh, render::Options(), &highlights));
  return ms_since(start);
}

int run_render(int argc, char **argv) {
  const RenderArgs o = parse_render_args(argc, argv);
  if (o.help) {
    std::fputs(kRenderHelp, stdout);
    return kExitOk;
  }
  check_png_path(o.image);
  io::MeshData mesh;
  try {
    mesh = io::read_mesh(o.mesh);
  } catch (const io::IoError &e) {
    throw CliError(kExitInput, about_file(o.mesh, e.what()));
  }

  auto start = Clock::now();
  render::Highlights highlights;
  if (o.highlight) highlights = highlights_of(mesh, true);
  const double analysis_ms = ms_since(start);
  start = Clock::now();
  const render::Image image = draw(mesh, o.render, o.highlight ? &highlights : nullptr);
  const double render_ms = ms_since(start);
  write(o.image, image);

  if (!o.quiet) {
    std::printf("%s: %zu triangles -> %s (%dx%d, %s view) in %.1f ms", o.mesh.c_str(),
                mesh.triangles.size() / 3, o.image.c_str(), image.width, image.height,
                render::view_name(o.render.view), render_ms);
    if (o.highlight)
      std::printf("; %zu boundary edges (red), %zu defective faces (purple), found in %.1f ms",
                  highlights.boundary_edges.size(), highlights.defective_faces.size(), analysis_ms);
    std::printf("\n");
  }
  return kExitOk;
}

}  // namespace moa::cli
