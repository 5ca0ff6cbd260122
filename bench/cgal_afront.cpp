// cgal_afront: CGAL's advancing-front surface reconstruction on a point file, timed and measured
// the way moa_bench measures libmoa, so that both run on the same points in the same benchmark.
//
//   cgal_afront INPUT [--mesh OUT] [--result FILE] [--radius-ratio-bound R] [--beta B]
//
// The points are read with libmoa's own reader (moa_io) so both methods see identical doubles.
// Timed: the call to CGAL::advancing_front_surface_reconstruction only (its 3-D Delaunay
// triangulation, which sorts the points spatially itself, and the front), as in BENCHMARKS.md.
// The mesh is written with every input point as a vertex, in input order, so that
// `moa_bench analyze` can count the points used.
#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/version.h>

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "io/io.hpp"
#include "peer_runner.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using namespace moa::bench;

const char *const kUsage =
    "Usage: cgal_afront INPUT [--mesh OUT] [--result FILE] [--radius-ratio-bound R] "
    "[--beta B]\n"
    "CGAL's defaults: radius_ratio_bound 5, beta 0.52 rad (about 30 degrees).\n";

int run(int argc, char **argv) {
  double radius_ratio_bound = 5, beta = 0.52;  // CGAL's defaults
  RunnerArgs args("cgal_afront", kUsage);
  args.option("--radius-ratio-bound", radius_ratio_bound).option("--beta", beta);
  if (const int code = args.parse(argc, argv); code >= 0) return code;
  const std::string &input = args.input;

  ResultWriter r;
  r.put("method", "cgal_afront").put("input", input).put("cgal_version", CGAL_VERSION_STR);
  r.put("param_radius_ratio_bound", radius_ratio_bound).put("param_beta", beta);
  const uint64_t rss_start = peak_rss_bytes();
  auto t = Clock::now();
  std::vector<double> xyz = moa::io::read_points(input);
  std::vector<Point> points;
  points.reserve(xyz.size() / 3);
  for (size_t i = 0; i + 2 < xyz.size(); i += 3) points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  const double read_ms = ms_since(t);
  const uint64_t rss_read = peak_rss_bytes();
  r.put("points", points.size()).put("read_ms", read_ms);
  r.put("rss_start", rss_start).put("rss_read", rss_read);

  std::vector<std::array<std::size_t, 3>> facets;
  const OtherLoad load;
  t = Clock::now();
  CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(),
                                               std::back_inserter(facets), radius_ratio_bound, beta);
  const double recon_ms = ms_since(t);
  const uint64_t rss_peak = peak_rss_bytes();
  r.put("recon_ms", recon_ms).put("rss_peak", rss_peak).put("triangles", facets.size());
  r.put("other_load", load.cores());

  std::vector<uint32_t> tri;
  tri.reserve(3 * facets.size());
  for (const auto &f : facets)
    for (std::size_t v : f) tri.push_back(uint32_t(v));
  finish_run(r, moa::io::MeshData{std::move(xyz), std::move(tri)}, args);
  std::printf("%s: %zu points, %zu triangles, %.3f s (read %.3f s), peak %.1f MB (%.0f B/point)\n",
              input.c_str(), points.size(), facets.size(), recon_ms / 1000, read_ms / 1000,
              double(rss_peak) / 1e6, points.empty() ? 0.0 : double(rss_peak) / double(points.size()));
  return 0;
}

}  // namespace

int main(int argc, char **argv) { return runner_main("cgal_afront", run, argc, argv); }
