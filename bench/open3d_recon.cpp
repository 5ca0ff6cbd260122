// open3d_recon: Open3D's ball pivoting or screened Poisson reconstruction on a point file, timed
// and measured like moa_bench measures libmoa.
//
//   open3d_recon INPUT --method bpa|poisson [--normals FILE [--normals-ms MS]] [--save-normals FILE]
//                [--mesh OUT] [--result FILE] [--radii 1.5,3,6] [--depth 9] [--normal-k 30]
//                [--orient-k 100]
//
// Parameters follow Open3D's surface-reconstruction tutorial:
//   - normals, when the input has none: EstimateNormals with its default search (30 nearest
//     neighbours), then OrientNormalsConsistentTangentPlane(100); timed apart as "normals";
//   - ball pivoting: radii = {1.5, 3, 6} x the average nearest-neighbour distance (from
//     ComputeNearestNeighborDistance, timed as part of the reconstruction);
//   - Poisson: depth 9, width 0, scale 1.1, no linear fit, all threads; the mesh is reported
//     untrimmed (no density-quantile cut), as Poisson returns it.
// Points are read with libmoa's moa_io so every method sees identical doubles.
//
// Both methods need the same normals, and orienting them is by far the slowest part on large or
// sharp inputs, so run_bench.sh estimates them once per input: the ball-pivoting run saves them
// (--save-normals) and the Poisson run reads them back with the time they took (--normals-ms).
#include <open3d/Open3DConfig.h>
#include <open3d/geometry/PointCloud.h>
#include <open3d/geometry/TriangleMesh.h>
#include <open3d/utility/Logging.h>

#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "io/io.hpp"
#include "peer_runner.hpp"

namespace {

using namespace moa::bench;

const char *const kUsage =
    "Usage: open3d_recon INPUT --method bpa|poisson [--normals FILE [--normals-ms MS]]\n"
    "                    [--save-normals FILE] [--mesh OUT] [--result FILE] [--radii 1.5,3,6]\n"
    "                    [--depth 9] [--normal-k 30] [--orient-k 100]\n"
    "  --normals       normals to use (nx ny nz per point); otherwise they are estimated\n"
    "  --normals-ms    those normals were estimated by another run in MS milliseconds\n"
    "  --save-normals  write the estimated normals (for a later --normals)\n"
    "  --radii    ball radii as multiples of the average nearest-neighbour distance\n";

std::vector<double> parse_list(const std::string &text) {
  std::vector<double> out;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) out.push_back(std::strtod(item.c_str(), nullptr));
  return out;
}

int run(int argc, char **argv) {
  std::string method, normals_path, save_normals;
  double shared_normals_ms = -1;  // >= 0: the normals come from another run that took this long
  std::vector<double> radius_factors = {1.5, 3, 6};
  int depth = 9, normal_k = 30, orient_k = 100;
  RunnerArgs args("open3d_recon", kUsage);
  args.option("--method", method).option("--normals", normals_path);
  args.option("--normals-ms", shared_normals_ms).option("--save-normals", save_normals);
  args.option("--radii", [&](const char *v) { radius_factors = parse_list(v); });
  args.option("--depth", depth).option("--normal-k", normal_k).option("--orient-k", orient_k);
  if (const int code = args.parse(argc, argv); code >= 0) return code;
  if (method != "bpa" && method != "poisson") return args.usage_error();
  const std::string &input = args.input;
  open3d::utility::SetVerbosityLevel(open3d::utility::VerbosityLevel::Error);

  ResultWriter r;
  r.put("method", method == "bpa" ? "open3d_bpa" : "open3d_poisson").put("input", input);
  r.put("open3d_version", OPEN3D_VERSION);
  const uint64_t rss_start = peak_rss_bytes();
  auto t = Clock::now();
  std::vector<double> xyz = moa::io::read_points(input);
  const size_t n = xyz.size() / 3;
  open3d::geometry::PointCloud cloud;
  cloud.points_.resize(n);
  for (size_t i = 0; i < n; ++i) cloud.points_[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  const bool given_normals = !normals_path.empty();
  if (given_normals) {
    const std::vector<double> normals = read_normals(normals_path, xyz);
    cloud.normals_.resize(n);
    for (size_t i = 0; i < n; ++i) cloud.normals_[i] = {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
  }
  r.put("points", n).put("read_ms", ms_since(t));
  r.put("rss_start", rss_start).put("rss_read", peak_rss_bytes());

  const OtherLoad load;
  double normals_ms = 0;
  if (!given_normals) {
    t = Clock::now();
    cloud.EstimateNormals(open3d::geometry::KDTreeSearchParamKNN(normal_k));
    cloud.OrientNormalsConsistentTangentPlane(size_t(orient_k));
    normals_ms = ms_since(t);
    r.put("param_normal_k", normal_k).put("param_orient_k", orient_k);
    if (!save_normals.empty()) {  // untimed, like reading the file
      std::vector<double> out;
      out.reserve(3 * n);
      for (const Eigen::Vector3d &v : cloud.normals_) out.insert(out.end(), {v.x(), v.y(), v.z()});
      moa::io::write_points(save_normals, out);
    }
    // Tells run_bench.sh that the normals are done and how long they took, even should the
    // reconstruction then time out.
    std::printf("normals estimated and oriented in %.3f ms\n", normals_ms);
    std::fflush(stdout);
  }
  const bool shared = given_normals && shared_normals_ms >= 0;
  if (shared) normals_ms = shared_normals_ms;
  r.put("normals", shared ? "shared" : given_normals ? "given" : "estimated").put("normals_ms", normals_ms);

  std::shared_ptr<open3d::geometry::TriangleMesh> mesh;
  t = Clock::now();
  if (method == "bpa") {
    const std::vector<double> nn = cloud.ComputeNearestNeighborDistance();
    const double spacing = nn.empty() ? 0 : std::accumulate(nn.begin(), nn.end(), 0.0) / double(nn.size());
    const double spacing_ms = ms_since(t);
    std::vector<double> radii;
    std::string shown;
    for (double f : radius_factors) {
      radii.push_back(f * spacing);
      char factor[32];
      std::snprintf(factor, sizeof factor, "%g", f);
      shown += (shown.empty() ? "" : ",") + std::string(factor);
    }
    mesh = open3d::geometry::TriangleMesh::CreateFromPointCloudBallPivoting(cloud, radii);
    r.put("spacing", spacing).put("spacing_ms", spacing_ms).put("param_radii_x_spacing", shown);
  } else {
    auto [poisson, densities] = open3d::geometry::TriangleMesh::CreateFromPointCloudPoisson(
        cloud, size_t(depth), 0.0f, 1.1f, false, -1);
    mesh = poisson;
    r.put("param_depth", depth).put("param_trimmed", 0);
  }
  const double recon_ms = ms_since(t);
  const uint64_t rss_peak = peak_rss_bytes();
  r.put("recon_ms", recon_ms).put("rss_peak", rss_peak).put("other_load", load.cores());
  r.put("triangles", mesh->triangles_.size());

  moa::io::MeshData out;
  out.xyz.reserve(3 * mesh->vertices_.size());
  for (const Eigen::Vector3d &v : mesh->vertices_) out.xyz.insert(out.xyz.end(), {v.x(), v.y(), v.z()});
  out.triangles.reserve(3 * mesh->triangles_.size());
  for (const Eigen::Vector3i &f : mesh->triangles_)
    out.triangles.insert(out.triangles.end(), {uint32_t(f[0]), uint32_t(f[1]), uint32_t(f[2])});
  finish_run(r, out, args);
  std::printf("%s: %zu points, %zu triangles, %.3f s + %.3f s normals, peak %.1f MB (%.0f B/point)\n",
              input.c_str(), n, mesh->triangles_.size(), recon_ms / 1000, normals_ms / 1000,
              double(rss_peak) / 1e6, n ? double(rss_peak) / double(n) : 0.0);
  return 0;
}

}  // namespace

int main(int argc, char **argv) { return runner_main("open3d_recon", run, argc, argv); }
