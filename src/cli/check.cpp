// `moa check`: reports what a mesh is (the output contract C1-C5, topology, angles). It reports
// and does not judge: the exit code is 0 whether or not the mesh is clean.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "io/io.hpp"
#include "quality/markdown.hpp"
#include "quality/quality.hpp"
#include "render/render.hpp"

namespace moa::cli {

const char *const kCheckHelp =
    "Usage: moa check MESH [--points INPUT] [--json] [--report REPORT.md]\n"
    "\n"
    "Analyses the triangle mesh MESH (.ply .off .obj .stl) and reports: vertex, triangle and\n"
    "edge counts; closed or not, boundary edges and loops; components, Euler characteristic\n"
    "and genus; non-manifold edges and vertices; orientation (inconsistent edges, closed\n"
    "components facing inward); self-intersecting face pairs (decided exactly); degenerate\n"
    "and duplicate faces; the distribution of each triangle's smallest angle.\n"
    "\n"
    "Options:\n"
    "      --points INPUT   also count the points of INPUT that are vertices of the mesh\n"
    "      --json           print one JSON object instead of text\n"
    "      --report REPORT.md\n"
    "                       also write the report as a Markdown page, with the histogram of\n"
    "                       the triangles' smallest angles beside it (REPORT_angles.png)\n"
    "  -h, --help           this text\n"
    "\n"
    "Exits with 0 whether or not the mesh is clean; non-zero only when a file cannot be read\n"
    "or written.\n";

namespace {

// The histogram picture beside a Markdown report: REPORT.md -> REPORT_angles.png.
std::string angles_image_path(const std::string &report_path) {
  std::string stem = report_path;
  const size_t slash = stem.find_last_of('/'), dot = stem.find_last_of('.');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) stem.erase(dot);
  return stem + "_angles.png";
}

// The Markdown report and, beside it, its histogram picture.
void write_report(const std::string &path, const std::string &mesh_path, const MeshReport &r) {
  const std::string image = angles_image_path(path);
  const render::Image chart = render::plot_histogram(
      std::vector<size_t>(r.min_angle_histogram.begin(), r.min_angle_histogram.end()), 0, 5);
  try {
    render::write_png(image, chart);
  } catch (const render::RenderError &e) {
    throw CliError(kExitOutput, about_file(image, e.what()));
  }
  const std::string text =
      report_to_markdown(r, mesh_path, image.substr(image.find_last_of('/') + 1));
  std::FILE *f = std::fopen(path.c_str(), "w");
  if (!f) throw CliError(kExitOutput, path + ": cannot write: " + std::strerror(errno));
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok)
    throw CliError(kExitOutput, path + ": cannot write: " + std::strerror(errno));
}

}  // namespace

int run_check(int argc, char **argv) {
  std::string mesh_path, points_path, report_path;
  bool json = false;
  ArgWalker args(argc, argv, "check");
  while (args.next()) {
    if (args.positional()) {
      if (!mesh_path.empty()) args.unknown();
      mesh_path = args.arg();
    } else if (args.is("-h", "--help")) {
      std::fputs(kCheckHelp, stdout);
      return kExitOk;
    } else if (args.is(nullptr, "--points")) {
      points_path = args.value();
    } else if (args.is(nullptr, "--json")) {
      json = true;
    } else if (args.is(nullptr, "--report")) {
      report_path = args.value();
    } else {
      args.unknown();
    }
  }
  if (mesh_path.empty()) throw CliError(kExitUsage, "missing MESH (see moa check --help)");
  if (!report_path.empty()) {
    check_writable(report_path);
    check_writable(angles_image_path(report_path));
  }

  io::MeshData mesh;
  try {
    mesh = io::read_mesh(mesh_path);
  } catch (const io::IoError &e) {
    throw CliError(kExitInput, about_file(mesh_path, e.what()));
  }
  std::vector<double> points;
  if (!points_path.empty()) {
    try {
      points = io::read_points(points_path);
    } catch (const io::IoError &e) {
      throw CliError(kExitInput, about_file(points_path, e.what()));
    }
  }

  const size_t vertex_count = mesh.xyz.size() / 3, triangle_count = mesh.triangles.size() / 3;
  MeshReport report =
      analyze_mesh(mesh.xyz.data(), vertex_count, mesh.triangles.data(), triangle_count);
  if (!points_path.empty())
    add_point_coverage(report, points.data(), points.size() / 3, mesh.xyz.data(), vertex_count,
                       mesh.triangles.data(), triangle_count);

  if (json) {
    std::cout << report_to_json(report);
  } else {
    std::cout << mesh_path << ": " << (report.contract_ok() ? "satisfies" : "violates")
              << " the output contract (C1-C5)\n";
    print_report(std::cout, report);
  }
  std::cout.flush();
  if (!report_path.empty()) write_report(report_path, mesh_path, report);
  return kExitOk;
}

}  // namespace moa::cli
