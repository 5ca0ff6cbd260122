// pcl_gp3: PCL's greedy projection triangulation on a point file, timed and measured like
// moa_bench measures libmoa.
//
//   pcl_gp3 INPUT [--normals FILE] [--mesh OUT] [--result FILE] [--mu 2.5]
//           [--radius-factor 7.5] [--max-nn 100] [--normal-k 20]
//
// Parameters follow PCL's greedy projection tutorial (mu 2.5, 100 nearest neighbours at most,
// maximum surface angle 45 degrees, triangle angles between 10 and 120 degrees, no normal
// consistency; normals from NormalEstimation with 20 nearest neighbours, here its OpenMP
// variant on all cores). The tutorial's search radius (0.025) is in the units of its own
// cloud; here it is 7.5 x the average nearest-neighbour distance, so that mu x the local
// spacing (up to about 3 x the average on a random sample) decides the edge lengths and the
// radius rarely does. The spacing is measured with PCL's own kd-tree and timed as part of the
// reconstruction.
//
// PCL computes in single precision; its triangles index the input points, so the mesh is
// written with the input's double coordinates.
#include <pcl/common/io.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/pcl_config.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/surface/gp3.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/io.hpp"
#include "peer_runner.hpp"

namespace {

using namespace moa::bench;

const char *const kUsage =
    "Usage: pcl_gp3 INPUT [--normals FILE] [--mesh OUT] [--result FILE] [--mu 2.5]\n"
    "               [--radius-factor 7.5] [--max-nn 100] [--normal-k 20]\n"
    "  --normals        the input's own normals (nx ny nz per line); otherwise estimated\n"
    "  --radius-factor  search radius as a multiple of the average nearest-neighbour distance\n";

// Average distance from each point to its nearest other point, with PCL's kd-tree.
double average_spacing(const pcl::PointCloud<pcl::PointXYZ>::Ptr &cloud) {
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  std::vector<int> index(2);
  std::vector<float> dist2(2);
  double sum = 0;
  size_t counted = 0;
  for (size_t i = 0; i < cloud->size(); ++i)
    if (tree.nearestKSearch((*cloud)[i], 2, index, dist2) == 2) {  // the first is the point itself
      sum += std::sqrt(double(dist2[1]));
      ++counted;
    }
  return counted ? sum / double(counted) : 0;
}

int run(int argc, char **argv) {
  std::string normals_path;
  double mu = 2.5, radius_factor = 7.5;
  int max_nn = 100, normal_k = 20;
  RunnerArgs args("pcl_gp3", kUsage);
  args.option("--normals", normals_path).option("--mu", mu);
  args.option("--radius-factor", radius_factor).option("--max-nn", max_nn);
  args.option("--normal-k", normal_k);
  if (const int code = args.parse(argc, argv); code >= 0) return code;
  const std::string &input = args.input;

  ResultWriter r;
  r.put("method", "pcl_gp3").put("input", input).put("pcl_version", PCL_VERSION_PRETTY);
  r.put("param_mu", mu).put("param_radius_x_spacing", radius_factor).put("param_max_nn", max_nn);
  r.put("param_max_surface_angle_deg", 45).put("param_min_angle_deg", 10).put("param_max_angle_deg", 120);
  const uint64_t rss_start = peak_rss_bytes();
  auto t = Clock::now();
  std::vector<double> xyz = moa::io::read_points(input);
  const size_t n = xyz.size() / 3;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  cloud->resize(n);
  for (size_t i = 0; i < n; ++i)
    (*cloud)[i] = pcl::PointXYZ(float(xyz[3 * i]), float(xyz[3 * i + 1]), float(xyz[3 * i + 2]));
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  const bool given_normals = !normals_path.empty();
  if (given_normals) {
    const std::vector<double> given = read_normals(normals_path, xyz);
    normals->resize(n);
    for (size_t i = 0; i < n; ++i)
      (*normals)[i] = pcl::Normal(float(given[3 * i]), float(given[3 * i + 1]), float(given[3 * i + 2]));
  }
  r.put("points", n).put("read_ms", ms_since(t));
  r.put("rss_start", rss_start).put("rss_read", peak_rss_bytes());

  const OtherLoad load;
  double normals_ms = 0;
  if (!given_normals) {
    t = Clock::now();
    pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation;  // all cores
    pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
    estimation.setInputCloud(cloud);
    estimation.setSearchMethod(tree);
    estimation.setKSearch(normal_k);
    estimation.compute(*normals);
    normals_ms = ms_since(t);
    r.put("param_normal_k", normal_k);
  }
  r.put("normals", given_normals ? "given" : "estimated").put("normals_ms", normals_ms);

  t = Clock::now();
  const double spacing = average_spacing(cloud);
  const double spacing_ms = ms_since(t);
  pcl::PointCloud<pcl::PointNormal>::Ptr with_normals(new pcl::PointCloud<pcl::PointNormal>);
  pcl::concatenateFields(*cloud, *normals, *with_normals);
  pcl::search::KdTree<pcl::PointNormal>::Ptr tree(new pcl::search::KdTree<pcl::PointNormal>);
  tree->setInputCloud(with_normals);
  pcl::GreedyProjectionTriangulation<pcl::PointNormal> gp3;
  gp3.setSearchRadius(radius_factor * spacing);
  gp3.setMu(mu);
  gp3.setMaximumNearestNeighbors(max_nn);
  gp3.setMaximumSurfaceAngle(M_PI / 4);
  gp3.setMinimumAngle(M_PI / 18);
  gp3.setMaximumAngle(2 * M_PI / 3);
  gp3.setNormalConsistency(false);
  gp3.setInputCloud(with_normals);
  gp3.setSearchMethod(tree);
  std::vector<pcl::Vertices> polygons;
  gp3.reconstruct(polygons);
  const double recon_ms = ms_since(t);
  const uint64_t rss_peak = peak_rss_bytes();
  r.put("spacing", spacing).put("spacing_ms", spacing_ms);
  r.put("recon_ms", recon_ms).put("rss_peak", rss_peak).put("other_load", load.cores());

  std::vector<uint32_t> tri;
  tri.reserve(3 * polygons.size());
  size_t skipped = 0;
  for (const pcl::Vertices &p : polygons) {
    if (p.vertices.size() != 3) { ++skipped; continue; }  // greedy projection makes triangles only
    for (auto v : p.vertices) tri.push_back(uint32_t(v));
  }
  r.put("triangles", tri.size() / 3).put("non_triangles", skipped);
  finish_run(r, moa::io::MeshData{std::move(xyz), std::move(tri)}, args);
  std::printf("%s: %zu points, %zu triangles, %.3f s + %.3f s normals, peak %.1f MB (%.0f B/point)\n",
              input.c_str(), n, polygons.size() - skipped, recon_ms / 1000, normals_ms / 1000,
              double(rss_peak) / 1e6, n ? double(rss_peak) / double(n) : 0.0);
  return 0;
}

}  // namespace

int main(int argc, char **argv) { return runner_main("pcl_gp3", run, argc, argv); }
