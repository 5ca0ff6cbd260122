// The report as JSON (for scripts and the benchmarks) and as text (for `moa check`).
#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>

#include "quality/json_writer.hpp"
#include "quality/quality.hpp"

namespace moa {
namespace {

// Components listed in full in the JSON; the counts always cover all of them.
constexpr size_t kMaxComponentsListed = 1000;

std::string format(const char *fmt, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, a);
  return buf;
}

const char *yes_no(bool b) { return b ? "yes" : "no"; }

}  // namespace

std::string report_to_json(const MeshReport &r) {
  JsonWriter j;
  j.begin_object();
  j.value("vertices", r.vertices).value("vertices_referenced", r.vertices_referenced);
  j.value("triangles", r.triangles).value("edges", r.edges);
  j.value("invalid_faces", r.invalid_faces);
  j.value("closed", r.closed());
  j.value("boundary_edges", r.boundary_edges).value("boundary_loops", r.boundary_loops);
  j.value("components", r.components).value("closed_components", r.closed_components);
  j.value("euler_characteristic", r.euler_characteristic);
  j.value("genus", r.genus).value("genus_defined", r.genus_defined);
  j.value("degenerate_faces", r.degenerate_faces).value("duplicate_faces", r.duplicate_faces);
  j.value("non_manifold_edges", r.non_manifold_edges);
  j.value("non_manifold_vertices", r.non_manifold_vertices);
  j.value("inconsistent_edges", r.inconsistent_edges);
  j.value("inward_components", r.inward_components);
  j.value("self_intersecting_pairs", r.self_intersecting_pairs);
  j.value("candidate_pairs", r.candidate_pairs);
  j.begin_array("intersecting_pairs", true);
  for (const auto &[a, b] : r.intersecting_pairs) {
    j.begin_array(nullptr, true).item_value(a).item_value(b).end_array();
  }
  j.end_array();

  j.begin_object("min_angle");
  j.value("min", r.min_angle).value("mean", r.mean_min_angle);
  j.value("below_10", r.share_below_10).value("below_20", r.share_below_20);
  j.value("below_30", r.share_below_30);
  j.begin_array("histogram_5deg", true);
  for (size_t n : r.min_angle_histogram) j.item_value(n);
  j.end_array();
  j.end_object();

  if (r.has_input_points) {
    j.value("input_points", r.input_points).value("input_points_on_mesh", r.input_points_on_mesh);
  }

  j.begin_object("contract");
  j.value("C1_faces", r.faces_ok()).value("C2_edge_manifold", r.edge_manifold());
  j.value("C3_vertex_manifold", r.vertex_manifold()).value("C4_oriented", r.oriented());
  j.value("C5_no_self_intersections", r.intersection_free()).value("ok", r.contract_ok());
  j.end_object();

  j.begin_array("component_list");
  const size_t listed = std::min(r.component_list.size(), kMaxComponentsListed);
  for (size_t i = 0; i < listed; ++i) {
    const ComponentReport &c = r.component_list[i];
    j.begin_object();
    j.value("first_triangle", c.first_triangle).value("triangles", c.triangles);
    j.value("vertices", c.vertices).value("edges", c.edges);
    j.value("boundary_edges", c.boundary_edges).value("boundary_loops", c.boundary_loops);
    j.value("euler_characteristic", c.euler_characteristic).value("closed", c.closed);
    j.value("manifold", c.manifold).value("orientable", c.orientable).value("genus", c.genus);
    if (c.closed) j.value("signed_volume", c.signed_volume);
    j.end_object();
  }
  j.end_array();
  j.value("analysis_ms", r.analysis_ms).value("intersection_ms", r.intersection_ms);
  j.end_object();
  return j.str();
}

void print_report(std::ostream &out, const MeshReport &r) {
  out << "  vertices      " << r.vertices << " (" << r.vertices_referenced << " used by faces)\n";
  out << "  triangles     " << r.triangles << ", edges " << r.edges;
  if (r.invalid_faces) out << ", " << r.invalid_faces << " with an index out of range";
  out << "\n";
  out << "  components    " << r.components << " (" << r.closed_components << " closed)\n";
  out << "  closed        " << yes_no(r.closed()) << ": " << r.boundary_edges
      << " boundary edges in " << r.boundary_loops << " loops\n";
  out << "  topology      Euler characteristic " << r.euler_characteristic << ", genus ";
  if (r.genus_defined) out << r.genus; else out << r.genus << " (some components are not orientable manifolds)";
  if (r.component_list.size() > 1 && r.component_list.size() <= 20) {
    out << " =";
    for (const ComponentReport &c : r.component_list) out << ' ' << c.genus;
  }
  out << "\n";
  out << "  manifold      " << r.non_manifold_edges << " non-manifold edges, "
      << r.non_manifold_vertices << " non-manifold vertices\n";
  out << "  orientation   " << (r.inconsistent_edges ? "inconsistent" : "consistent") << " ("
      << r.inconsistent_edges << " edges), " << r.inward_components
      << " closed components facing inward\n";
  out << "  faces         " << r.degenerate_faces << " degenerate, " << r.duplicate_faces
      << " duplicate\n";
  out << "  intersections " << r.self_intersecting_pairs << " self-intersecting pairs ("
      << r.candidate_pairs << " candidate pairs tested)";
  for (size_t i = 0; i < r.intersecting_pairs.size() && i < 5; ++i)
    out << (i ? " " : ": ") << r.intersecting_pairs[i].first << '/' << r.intersecting_pairs[i].second;
  if (r.self_intersecting_pairs > 5) out << " ...";
  out << "\n";
  out << "  min angle     " << format("%.2f", r.min_angle) << " deg, mean "
      << format("%.2f", r.mean_min_angle) << " deg; below 10/20/30 deg: "
      << format("%.2f%%", 100 * r.share_below_10) << " / " << format("%.2f%%", 100 * r.share_below_20)
      << " / " << format("%.2f%%", 100 * r.share_below_30) << "\n";
  if (r.has_input_points)
    out << "  input points  " << r.input_points_on_mesh << " of " << r.input_points
        << " are mesh vertices\n";
  out << "  contract      C1 " << (r.faces_ok() ? "ok" : "FAIL") << ", C2 "
      << (r.edge_manifold() ? "ok" : "FAIL") << ", C3 " << (r.vertex_manifold() ? "ok" : "FAIL")
      << ", C4 " << (r.oriented() ? "ok" : "FAIL") << ", C5 "
      << (r.intersection_free() ? "ok" : "FAIL") << "\n";
  out << "  time          " << format("%.1f", r.analysis_ms) << " ms\n";
}

}  // namespace moa
