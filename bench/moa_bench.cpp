// moa_bench: times libmoa on one point file through the public C ABI, the way a program would
// use it, and checks what it returns.
//
//   moa_bench INPUT [--threads N] [--cores N] [--runs N] [--param NAME=VALUE]... [--mesh OUT]
//             [--result FILE]
//   moa_bench analyze MESH [--points INPUT] [--reference REF] [--result FILE]
//   moa_bench sample --out DIR [--meshes DIR]           (sample_inputs.cpp)
//   moa_bench report --work DIR --out FILE.md [...]     (report.cpp)
//   moa_bench scan MESH --out FILE [...]                (range_scan.cpp)
//
// One input per process, so the peak resident set read at the end of the first run is that
// run's own (plus reading the file, which is reported separately). The mesh is checked by the
// `analyze` mode in a separate process, the same way as every other method's mesh.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <tbb/global_control.h>

#include "bench_common.hpp"
#include "bench_modes.hpp"
#include "distance.hpp"
#include "io/io.hpp"
#include "moa/moa.h"
#include "quality/quality.hpp"

namespace moa::bench {
namespace {

const char *const kUsage =
    "Usage:\n"
    "  moa_bench INPUT [--threads N] [--cores N] [--runs N] [--param NAME=VALUE]...\n"
    "                  [--mesh OUT] [--result FILE]\n"
    "      run libmoa on the points of INPUT (default threads 0 = all cores, runs 2: the\n"
    "      second run must give the same triangles, C6); --mesh writes the mesh for analyze;\n"
    "      --cores N lets TBB run N threads, as on a machine with N cores (for the memory of\n"
    "      N threads on a smaller machine; the times are then those of oversubscribed cores)\n"
    "  moa_bench analyze MESH [--points INPUT] [--reference REF] [--result FILE]\n"
    "      analyse any method's mesh: moa_quality, input points on the mesh, distance to REF\n"
    "  moa_bench sample --out DIR [--meshes DIR]\n"
    "      write the benchmark inputs and DIR/inputs.tsv (deterministic)\n"
    "  moa_bench report --work DIR --out FILE.md [--command TEXT]\n"
    "      turn the results of run_bench.sh into a Markdown report\n"
    "  moa_bench scan MESH --out FILE [--views N] [--resolution N] [--elevation RAD] [--above]\n"
    "                 [--noise F] [--registration F] [--seed N]\n"
    "      a range scan of MESH: N cameras (3) round its +y axis at RAD (0.3) alternately\n"
    "      below and above it (--above: all above), each an N x N grid of rays (300); range\n"
    "      noise and a per-camera offset as shares of the diagonal (0); the points to FILE\n";

// The moa_quality report as q_* keys: the contract C1-C5, topology and angles.
void put_quality(ResultWriter &r, const MeshReport &q) {
  r.put("q_vertices", q.vertices).put("q_vertices_referenced", q.vertices_referenced);
  r.put("q_triangles", q.triangles).put("q_edges", q.edges);
  r.put("q_invalid_faces", q.invalid_faces).put("q_degenerate_faces", q.degenerate_faces);
  r.put("q_duplicate_faces", q.duplicate_faces);
  r.put("q_boundary_edges", q.boundary_edges).put("q_boundary_loops", q.boundary_loops);
  r.put("q_components", q.components).put("q_closed_components", q.closed_components);
  r.put("q_euler", q.euler_characteristic).put("q_genus", q.genus);
  r.put("q_genus_defined", q.genus_defined);
  r.put("q_non_manifold_edges", q.non_manifold_edges);
  r.put("q_non_manifold_vertices", q.non_manifold_vertices);
  r.put("q_inconsistent_edges", q.inconsistent_edges);
  r.put("q_inward_components", q.inward_components);
  r.put("q_self_intersecting_pairs", q.self_intersecting_pairs);
  r.put("q_min_angle", q.min_angle).put("q_mean_min_angle", q.mean_min_angle);
  r.put("q_below10", q.share_below_10).put("q_below20", q.share_below_20);
  r.put("q_below30", q.share_below_30);
  std::string histogram;  // 5-degree bins from 0 to 60, for the angle plot
  for (size_t count : q.min_angle_histogram) histogram += (histogram.empty() ? "" : " ") + std::to_string(count);
  r.put("q_angle_histogram", histogram);
  r.put("q_c1", q.faces_ok()).put("q_c2", q.edge_manifold()).put("q_c3", q.vertex_manifold());
  r.put("q_c4", q.oriented()).put("q_c5", q.intersection_free());
  r.put("q_contract", q.contract_ok()).put("q_closed", q.closed());
  if (q.has_input_points) r.put("q_input_points_on_mesh", q.input_points_on_mesh);
  r.put("q_analysis_ms", q.analysis_ms);
}

struct RunOptions {
  std::string input, mesh, result;
  double threads = 0;
  int cores = 0;  // 0: the machine's own
  int runs = 2;
  std::vector<std::pair<std::string, double>> params;
};

// Takes the value of an option, or throws naming the option.
const char *option_value(int argc, char **argv, int &i) {
  if (i + 1 >= argc) throw UsageError(std::string(argv[i]) + " needs a value");
  return argv[++i];
}

double number(const std::string &option, const char *text) {
  char *end = nullptr;
  const double v = std::strtod(text, &end);
  if (*text == '\0' || *end != '\0')
    throw UsageError(option + ": '" + text + "' is not a number");
  return v;
}

RunOptions parse_run(int argc, char **argv) {
  RunOptions o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--threads") {
      o.threads = number(a, option_value(argc, argv, i));
    } else if (a == "--cores") {
      const double cores = number(a, option_value(argc, argv, i));
      if (!(cores >= 1 && cores <= 4096)) throw UsageError("--cores must be from 1 to 4096");
      o.cores = int(cores);
    } else if (a == "--runs") {
      o.runs = int(number(a, option_value(argc, argv, i)));
      if (o.runs < 1) throw UsageError("--runs must be at least 1");
    } else if (a == "--param") {
      const std::string spec = option_value(argc, argv, i);
      const size_t eq = spec.find('=');
      if (eq == std::string::npos || eq == 0) throw UsageError("--param expects NAME=VALUE");
      o.params.emplace_back(spec.substr(0, eq), number(a, spec.c_str() + eq + 1));
    } else if (a == "--mesh") {
      o.mesh = option_value(argc, argv, i);
    } else if (a == "--result") {
      o.result = option_value(argc, argv, i);
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError("unknown option " + a);
    } else if (o.input.empty()) {
      o.input = a;
    } else {
      throw UsageError("more than one INPUT");
    }
  }
  if (o.input.empty()) throw UsageError("missing INPUT");
  return o;
}

struct CtxDeleter {
  void operator()(moa_ctx *ctx) const { moa_ctx_destroy(ctx); }
};

void check(moa_status status, const moa_ctx *ctx, const char *what) {
  if (status != MOA_OK)
    throw std::runtime_error(std::string(what) + ": " + moa_status_string(status) + ": " +
                             moa_last_error(ctx));
}

std::vector<uint32_t> copy_triangles(const moa_ctx *ctx) {
  moa_mesh mesh{};
  check(moa_get_mesh(ctx, &mesh), ctx, "moa_get_mesh");
  return std::vector<uint32_t>(mesh.triangles, mesh.triangles + 3 * mesh.triangle_count);
}

int run_main(int argc, char **argv) {
  const RunOptions o = parse_run(argc, argv);
  // libmoa runs no more threads than TBB may (reconstruct.cpp); a host's global_control sets that.
  std::optional<tbb::global_control> cores;
  if (o.cores > 0) cores.emplace(tbb::global_control::max_allowed_parallelism, o.cores);
  ResultWriter r;
  r.put("method", "libmoa").put("input", o.input).put("moa_version", moa_version());
  const uint64_t rss_start = peak_rss_bytes();

  auto t = Clock::now();
  std::vector<double> xyz = io::read_points(o.input);
  const double read_ms = ms_since(t);
  const uint64_t rss_read = peak_rss_bytes();
  const size_t n = xyz.size() / 3;
  r.put("points", n).put("read_ms", read_ms);
  r.put("rss_start", rss_start).put("rss_read", rss_read);

  moa_ctx *raw = nullptr;
  check(moa_ctx_create(&raw), nullptr, "moa_ctx_create");
  std::unique_ptr<moa_ctx, CtxDeleter> ctx(raw);
  check(moa_set_param(raw, "threads", o.threads), raw, "threads");
  for (const auto &[name, value] : o.params) check(moa_set_param(raw, name.c_str(), value), raw, name.c_str());
  for (size_t i = 0; i < moa_param_count(); ++i) {
    moa_param_info info{};
    double value = 0;
    if (moa_param_info_get(i, &info) == MOA_OK && moa_get_param(raw, info.name, &value) == MOA_OK)
      r.put(std::string("param_") + info.name, value);
  }

  // The library's own time: copying the points in plus the run. The caller keeps its array
  // alive meanwhile, as a program that goes on using its points would.
  const OtherLoad load;
  t = Clock::now();
  check(moa_set_points(raw, xyz.data(), n), raw, "moa_set_points");
  const double set_ms = ms_since(t);
  t = Clock::now();
  const moa_status status = moa_run(raw);
  const double run_ms = ms_since(t);
  const uint64_t rss_peak = peak_rss_bytes();
  r.put("set_points_ms", set_ms).put("run_ms", run_ms).put("recon_ms", set_ms + run_ms);
  r.put("rss_peak", rss_peak).put("other_load", load.cores());
  if (status != MOA_OK) {
    const std::string message = std::string(moa_status_string(status)) + ": " + moa_last_error(raw);
    r.put("status", "moa_run failed: " + message);
    r.append_to(o.result);
    std::fprintf(stderr, "moa_bench: %s: %s\n", o.input.c_str(), message.c_str());
    return 1;
  }

  moa_stats s{};
  check(moa_get_stats(raw, &s, sizeof s), raw, "moa_get_stats");
  const std::vector<uint32_t> tri = copy_triangles(raw);
  const uint64_t hash = fnv1a(tri.data(), tri.size());

  // C6: every further run on the same context must return the same triangles in the same order.
  bool identical = true;
  std::string more_ms;
  for (int k = 2; k <= o.runs; ++k) {
    t = Clock::now();
    check(moa_run(raw), raw, "moa_run (repeat)");
    more_ms += (more_ms.empty() ? "" : " ") + std::to_string(ms_since(t));
    if (copy_triangles(raw) != tri) identical = false;
  }
  r.put("runs", o.runs).put("c6", o.runs < 2 ? "untested" : identical ? "identical" : "different");
  if (!more_ms.empty()) r.put("repeat_ms", more_ms);
  r.put("rss_end", peak_rss_bytes());
  r.put("triangles", tri.size() / 3).put("hash", hex64(hash));

  r.put("threads_used", s.threads).put("total_ms", s.total_ms);
  for (int i = 0; i < MOA_STAGE_COUNT; ++i)
    r.put(std::string("stage_") + moa_stage_name(moa_stage(i)), s.stage_ms[i]);
  r.put("intersection_ms", s.intersection_ms).put("embree_rebuilds", s.embree_rebuilds);
  r.put("unique_points", s.unique_points).put("used_points", s.used_points);
  r.put("unused_points", s.unused_points);
  r.put("triangles_mesh", s.triangles_mesh).put("triangles_loops", s.triangles_loops);
  r.put("triangles_removed", s.triangles_removed);
  r.put("boundary_loops_before", s.boundary_loops_before);
  r.put("boundary_loops_after", s.boundary_loops_after);
  r.put("candidates_tested", s.candidates_tested);

  // The mesh is analysed by `moa_bench analyze`, in another process, like every method's.
  if (!o.mesh.empty()) io::write_mesh(o.mesh, io::MeshData{std::move(xyz), tri});
  r.put("status", "ok");
  r.append_to(o.result);

  std::printf("%s: %zu points, %zu triangles, %.3f s (read %.3f s), peak %.1f MB (%.0f B/point), "
              "C6 %s\n",
              o.input.c_str(), n, tri.size() / 3, (set_ms + run_ms) / 1000, read_ms / 1000,
              double(rss_peak) / 1e6, n ? double(rss_peak) / double(n) : 0.0,
              o.runs < 2 ? "untested" : identical ? "held" : "FAILED");
  return 0;
}

// The one checker for every method's mesh: moa_quality, the input points found on the mesh,
// and the distance to the reference surface when there is one.
int analyze_main(int argc, char **argv) {
  std::string mesh_path, result, points_path, reference_path;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--result") result = option_value(argc, argv, i);
    else if (a == "--points") points_path = option_value(argc, argv, i);
    else if (a == "--reference") reference_path = option_value(argc, argv, i);
    else if (!a.empty() && a[0] == '-') throw UsageError("unknown option " + a);
    else if (mesh_path.empty()) mesh_path = a;
    else throw UsageError("more than one MESH");
  }
  if (mesh_path.empty()) throw UsageError("missing MESH");
  const io::MeshData mesh = io::read_mesh(mesh_path);
  const size_t vertices = mesh.xyz.size() / 3, triangles = mesh.triangles.size() / 3;
  MeshReport q = analyze_mesh(mesh.xyz.data(), vertices, mesh.triangles.data(), triangles);
  if (!points_path.empty()) {
    const std::vector<double> points = io::read_points(points_path);
    add_point_coverage(q, points.data(), points.size() / 3, mesh.xyz.data(), vertices,
                       mesh.triangles.data(), triangles);
  }
  ResultWriter r;
  put_quality(r, q);
  if (!reference_path.empty() && triangles > 0) {
    const io::MeshData ref = io::read_mesh(reference_path);
    const auto t = Clock::now();
    const SurfaceDistance d = surface_distance(mesh.xyz, mesh.triangles, ref.xyz, ref.triangles);
    r.put("d_diagonal", d.diagonal);
    r.put("d_hausdorff", d.hausdorff() / d.diagonal).put("d_mean", d.mean() / d.diagonal);
    r.put("d_max_to_ref", d.max_to_reference / d.diagonal);
    r.put("d_mean_to_ref", d.mean_to_reference / d.diagonal);
    r.put("d_max_from_ref", d.max_from_reference / d.diagonal);
    r.put("d_mean_from_ref", d.mean_from_reference / d.diagonal);
    r.put("d_samples", d.samples_mesh + d.samples_reference).put("d_ms", ms_since(t));
  }
  r.put("analysis", "ok");
  r.append_to(result);
  print_report(std::cout, q);
  return 0;
}

}  // namespace
}  // namespace moa::bench

int main(int argc, char **argv) {
  using namespace moa::bench;
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "-h" || mode == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (mode == "sample") return sample_main(argc - 1, argv + 1);
    if (mode == "report") return report_main(argc - 1, argv + 1);
    if (mode == "analyze") return analyze_main(argc - 1, argv + 1);
    if (mode == "scan") return scan_main(argc - 1, argv + 1);
    return run_main(argc, argv);
  } catch (const UsageError &e) {
    std::fprintf(stderr, "moa_bench: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const std::exception &e) {
    std::fprintf(stderr, "moa_bench: %s\n", e.what());
    return 1;
  }
}
