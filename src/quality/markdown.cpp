// report_to_markdown: the numbers of print_report as tables, the histogram as a picture.
#include "quality/markdown.hpp"

#include <cstdio>
#include <sstream>

namespace moa {
namespace {

std::string fixed(const char *fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

const char *ok(bool b) { return b ? "ok" : "**FAIL**"; }

// Backslash-escapes what Markdown would read as markup in a file name.
std::string escaped(const std::string &text) {
  std::string out;
  for (char c : text) {
    if (c == '\\' || c == '`' || c == '*' || c == '_' || c == '[' || c == ']' || c == '|' ||
        c == '<' || c == '>' || c == '#')
      out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string report_to_markdown(const MeshReport &r, const std::string &mesh_name,
                               const std::string &histogram_image) {
  std::ostringstream md;
  md << "# moa check: " << escaped(mesh_name) << "\n\n";
  md << "The mesh " << (r.contract_ok() ? "satisfies" : "**violates**")
     << " the output contract (C1-C5).\n\n";

  md << "| | |\n|---|---|\n";
  md << "| vertices | " << r.vertices << " (" << r.vertices_referenced << " used by faces) |\n";
  md << "| triangles | " << r.triangles;
  if (r.invalid_faces) md << " (" << r.invalid_faces << " with an index out of range)";
  md << " |\n";
  md << "| edges | " << r.edges << " |\n";
  md << "| components | " << r.components << " (" << r.closed_components << " closed) |\n";
  md << "| closed | " << (r.closed() ? "yes" : "no") << ": " << r.boundary_edges
     << " boundary edges in " << r.boundary_loops << " loops |\n";
  md << "| Euler characteristic | " << r.euler_characteristic << " |\n";
  md << "| genus | " << r.genus;
  if (!r.genus_defined) md << " (some components are not orientable manifolds)";
  md << " |\n";
  md << "| non-manifold edges | " << r.non_manifold_edges << " |\n";
  md << "| non-manifold vertices | " << r.non_manifold_vertices << " |\n";
  md << "| inconsistently oriented edges | " << r.inconsistent_edges << " |\n";
  md << "| closed components facing inward | " << r.inward_components << " |\n";
  md << "| degenerate faces | " << r.degenerate_faces << " |\n";
  md << "| duplicate faces | " << r.duplicate_faces << " |\n";
  md << "| self-intersecting pairs | " << r.self_intersecting_pairs << " (" << r.candidate_pairs
     << " candidate pairs tested) |\n";
  md << "| smallest angle | " << fixed("%.2f", r.min_angle) << " deg |\n";
  md << "| mean smallest angle | " << fixed("%.2f", r.mean_min_angle) << " deg |\n";
  md << "| triangles below 10 / 20 / 30 deg | " << fixed("%.2f%%", 100 * r.share_below_10) << " / "
     << fixed("%.2f%%", 100 * r.share_below_20) << " / " << fixed("%.2f%%", 100 * r.share_below_30)
     << " |\n";
  if (r.has_input_points)
    md << "| input points on the mesh | " << r.input_points_on_mesh << " of " << r.input_points
       << " |\n";
  md << "| analysis time | " << fixed("%.1f", r.analysis_ms) << " ms |\n\n";

  md << "## Output contract\n\n";
  md << "| C1 faces | C2 edge manifold | C3 vertex manifold | C4 oriented | C5 no "
        "self-intersections |\n";
  md << "|---|---|---|---|---|\n";
  md << "| " << ok(r.faces_ok()) << " | " << ok(r.edge_manifold()) << " | "
     << ok(r.vertex_manifold()) << " | " << ok(r.oriented()) << " | " << ok(r.intersection_free())
     << " |\n\n";

  md << "## Smallest angle of each triangle\n\n";
  if (!histogram_image.empty())
    md << "![Share of the triangles per 5-degree bin of their smallest angle](<" << histogram_image
       << ">)\n\n";
  size_t total = 0;
  for (size_t n : r.min_angle_histogram) total += n;
  md << "| degrees | triangles | share |\n|---|---:|---:|\n";
  for (size_t b = 0; b < r.min_angle_histogram.size(); ++b) {
    const size_t n = r.min_angle_histogram[b];
    md << "| " << 5 * b << "-" << 5 * (b + 1) << " | " << n << " | "
       << fixed("%.2f%%", total ? 100.0 * double(n) / double(total) : 0.0) << " |\n";
  }
  return md.str();
}

}  // namespace moa
