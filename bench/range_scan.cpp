// `moa_bench scan`: a range scan of a mesh, as a scanner or depth camera would deliver it. Each
// camera stands on a circle round the mesh's vertical (+y) axis and casts a square grid of rays
// at it; the first hit of each ray is a point. A face the camera meets at a grazing angle comes
// out in rows far apart, the sampling the lined regions of neighbors.cpp are for. Range noise
// moves a point along its ray; a registration offset moves every point of one camera alike, as
// when separate scans are aligned a little off. Embree casts the rays.
//
//   moa_bench scan MESH --out FILE [--views N] [--resolution N] [--elevation RAD] [--above]
//                  [--noise F] [--registration F] [--seed N]
#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_modes.hpp"
#include "io/io.hpp"

namespace moa::bench {
namespace {

struct ScanOptions {
  std::string mesh, out;
  int views = 3;
  int resolution = 300;
  double elevation = 0.3;   // radians above or below the horizontal plane through the centre
  bool above = false;       // every camera above (else they alternate, the first one below)
  double noise = 0;         // range noise, standard deviation as a share of the diagonal
  double registration = 0;  // per-camera offset, up to this share of the diagonal per axis
  uint64_t seed = 1;
};

// Uniform and normal numbers from std::mt19937_64, computed here so that every standard
// library gives the same scan.
class ScanRng {
 public:
  explicit ScanRng(uint64_t seed) : engine_(seed) {}
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  double normal() {
    const double radius = std::sqrt(-2 * std::log(1 - uniform()));
    return radius * std::cos(6.283185307179586 * uniform());
  }

 private:
  std::mt19937_64 engine_;
};

double number(const std::string &option, const char *text) {
  char *end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(value))
    throw UsageError(option + ": '" + text + "' is not a number");
  return value;
}

int whole(const std::string &option, const char *text, int least, int most) {
  const double value = number(option, text);
  if (!(value >= least && value <= most) || value != std::floor(value))
    throw UsageError(option + " must be a whole number from " + std::to_string(least) + " to " +
                     std::to_string(most));
  return int(value);
}

ScanOptions parse(int argc, char **argv) {
  ScanOptions o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> const char * {
      if (i + 1 >= argc) throw UsageError(a + " needs a value");
      return argv[++i];
    };
    if (a == "--out")
      o.out = value();
    else if (a == "--views")
      o.views = whole(a, value(), 1, 64);
    else if (a == "--resolution")
      o.resolution = whole(a, value(), 2, 4096);
    else if (a == "--elevation")
      o.elevation = number(a, value());
    else if (a == "--above")
      o.above = true;
    else if (a == "--noise")
      o.noise = number(a, value());
    else if (a == "--registration")
      o.registration = number(a, value());
    else if (a == "--seed")
      o.seed = uint64_t(whole(a, value(), 0, 1 << 30));
    else if (!a.empty() && a[0] == '-')
      throw UsageError("unknown option " + a);
    else if (o.mesh.empty())
      o.mesh = a;
    else
      throw UsageError("more than one MESH");
  }
  if (o.mesh.empty()) throw UsageError("missing MESH");
  if (o.out.empty()) throw UsageError("missing --out FILE");
  if (!(std::fabs(o.elevation) < 1.5)) throw UsageError("--elevation must lie within +-1.5 rad");
  if (o.noise < 0 || o.registration < 0)
    throw UsageError("--noise and --registration must not be negative");
  return o;
}

using Device = std::unique_ptr<RTCDeviceTy, void (*)(RTCDevice)>;
using Scene = std::unique_ptr<RTCSceneTy, void (*)(RTCScene)>;

}  // namespace

int scan_main(int argc, char **argv) {
  const ScanOptions o = parse(argc, argv);
  const io::MeshData mesh = io::read_mesh(o.mesh);
  const std::size_t vertices = mesh.xyz.size() / 3, faces = mesh.triangles.size() / 3;
  if (faces == 0) throw std::runtime_error(o.mesh + ": no triangles to scan");

  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (std::size_t i = 0; i < mesh.xyz.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], mesh.xyz[i]);
    hi[i % 3] = std::max(hi[i % 3], mesh.xyz[i]);
  }
  double centre[3], diagonal = 0;
  for (int a = 0; a < 3; ++a) {
    centre[a] = 0.5 * (lo[a] + hi[a]);
    diagonal += (hi[a] - lo[a]) * (hi[a] - lo[a]);
  }
  diagonal = std::sqrt(diagonal);
  if (!(diagonal > 0) || !std::isfinite(diagonal))
    throw std::runtime_error(o.mesh + ": the mesh has no extent to scan");

  // Embree in single precision, centred on the mesh (the hits are computed back in double).
  std::vector<float> xyz(3 * vertices + 1);  // Embree reads 16 bytes at the last vertex
  for (std::size_t i = 0; i < mesh.xyz.size(); ++i) xyz[i] = float(mesh.xyz[i] - centre[i % 3]);
  Device device(rtcNewDevice("verbose=0"), rtcReleaseDevice);
  if (!device) throw std::runtime_error("Embree: no device");
  Scene scene(rtcNewScene(device.get()), rtcReleaseScene);
  RTCGeometry geometry = rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, xyz.data(), 0,
                             3 * sizeof(float), vertices);
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                             mesh.triangles.data(), 0, 3 * sizeof(uint32_t), faces);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene.get(), geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene.get());
  if (rtcGetDeviceError(device.get()) != RTC_ERROR_NONE) throw std::runtime_error("Embree failed");

  ScanRng rng(o.seed);
  const double distance = 1.5 * diagonal;  // from the centre to each camera
  const double fan = 0.4;                  // tangent of half the field of view
  std::vector<double> points;
  for (int v = 0; v < o.views; ++v) {
    const double azimuth = 6.283185307179586 * v / o.views + 0.3;
    const double el = o.above || v % 2 ? o.elevation : -o.elevation;
    // back: from the centre to the camera; right = forward x up, up' = right x forward.
    const double back[3] = {std::cos(el) * std::cos(azimuth), std::sin(el),
                            std::cos(el) * std::sin(azimuth)};
    const double rn = std::hypot(back[0], back[2]);
    const double right[3] = {back[2] / rn, 0, -back[0] / rn};
    const double up[3] = {right[2] * back[1], right[0] * back[2] - right[2] * back[0],
                          -right[0] * back[1]};
    double offset[3];
    for (double &x : offset) x = o.registration * diagonal * (2 * rng.uniform() - 1);
    for (int i = 0; i < o.resolution; ++i)
      for (int j = 0; j < o.resolution; ++j) {
        const double x = (2 * (i + 0.5) / o.resolution - 1) * fan;
        const double y = (2 * (j + 0.5) / o.resolution - 1) * fan;
        double d[3];
        for (int a = 0; a < 3; ++a) d[a] = -back[a] + x * right[a] + y * up[a];
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit ray{};
        ray.ray.org_x = float(distance * back[0]);
        ray.ray.org_y = float(distance * back[1]);
        ray.ray.org_z = float(distance * back[2]);
        ray.ray.dir_x = float(d[0]);
        ray.ray.dir_y = float(d[1]);
        ray.ray.dir_z = float(d[2]);
        ray.ray.tfar = HUGE_VALF;
        ray.ray.mask = ~0u;
        ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene.get(), &context, &ray);
        if (ray.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double t = double(ray.ray.tfar) + o.noise * diagonal * rng.normal() / length;
        for (int a = 0; a < 3; ++a)
          points.push_back(centre[a] + distance * back[a] + t * d[a] + offset[a]);
      }
  }
  if (points.empty()) throw std::runtime_error(o.mesh + ": no ray met the mesh");
  io::write_points(o.out, points);
  std::printf("%s: %zu points from %d views\n", o.out.c_str(), points.size() / 3, o.views);
  return 0;
}

}  // namespace moa::bench
