// `moa_bench sample`: writes the benchmark inputs, the same bytes on every run and machine.
//
//   - the vertices of each reference mesh, shuffled (a well-sampled cloud in no useful order);
//   - uniform random samples of a mesh's surface by area (clusters, gaps, unavoidable slivers);
//   - the same with Gaussian noise of 0.02 % of the mesh's bounding-box diagonal;
//   - the shared point files kitten.xyz and building.ply, with their normals beside them.
//
// Randomness is std::mt19937_64 with a fixed seed per input (its output sequence is fixed by
// the standard), turned into numbers here rather than by the standard distributions, whose
// algorithms differ between library implementations. Built with -ffp-contract=off so that no
// compiler fuses the sampling arithmetic differently.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "bench_modes.hpp"
#include "io/io.hpp"
#include "quality/quality.hpp"

#ifndef MOA_BENCH_DATA
#define MOA_BENCH_DATA "../shared/data"
#endif

namespace moa::bench {
namespace {

class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1): the top 53 bits as the mantissa.
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }

  // Uniform in [0, n), unbiased: reject the low 2^64 mod n values so the rest divides evenly.
  uint64_t below(uint64_t n) {
    const uint64_t reject = (0 - n) % n;
    for (;;) {
      const uint64_t x = engine_();
      if (x >= reject) return x % n;
    }
  }

 private:
  std::mt19937_64 engine_;
};

// The seed of an input comes from its name, so adding inputs does not change the others.
uint64_t seed_of(const std::string &name) { return fnv1a(name.data(), name.size()) ^ 0x6d6f61u; }

std::vector<double> shuffled_vertices(const io::MeshData &mesh, uint64_t seed) {
  std::vector<double> xyz = mesh.xyz;
  Rng rng(seed);
  const size_t n = xyz.size() / 3;
  for (size_t i = n; i > 1; --i) {  // Fisher-Yates
    const size_t j = size_t(rng.below(i));
    for (int a = 0; a < 3; ++a) std::swap(xyz[3 * (i - 1) + a], xyz[3 * j + a]);
  }
  return xyz;
}

// Points uniformly distributed over the surface: a triangle chosen with probability
// proportional to its area, then a uniform point in it (the square-root warp of barycentrics).
std::vector<double> surface_sample(const io::MeshData &mesh, size_t count, uint64_t seed) {
  const std::vector<double> &v = mesh.xyz;
  const std::vector<uint32_t> &t = mesh.triangles;
  const size_t faces = t.size() / 3;
  std::vector<double> cumulative(faces);
  double total = 0;
  for (size_t f = 0; f < faces; ++f) {
    const double *a = &v[3 * t[3 * f]], *b = &v[3 * t[3 * f + 1]], *c = &v[3 * t[3 * f + 2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                         u[0] * w[1] - u[1] * w[0]};
    total += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    cumulative[f] = total;
  }
  Rng rng(seed);
  std::vector<double> xyz(3 * count);
  for (size_t i = 0; i < count; ++i) {
    const double pick = rng.uniform() * total;
    size_t f = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
    if (f >= faces) f = faces - 1;  // pick rounded up to total
    const double r1 = std::sqrt(rng.uniform()), r2 = rng.uniform();
    const double wa = 1 - r1, wb = r1 * (1 - r2), wc = r1 * r2;
    const double *a = &v[3 * t[3 * f]], *b = &v[3 * t[3 * f + 1]], *c = &v[3 * t[3 * f + 2]];
    for (int k = 0; k < 3; ++k) xyz[3 * i + k] = wa * a[k] + wb * b[k] + wc * c[k];
  }
  return xyz;
}

// Gaussian noise on every coordinate: Box-Muller on our own uniforms (1 - u keeps the
// logarithm's argument in (0, 1]).
void add_noise(std::vector<double> &xyz, double sigma, uint64_t seed) {
  Rng rng(seed ^ 0x6e6f697365ull);
  const double two_pi = 6.283185307179586;
  for (double &x : xyz) {
    const double radius = std::sqrt(-2 * std::log(1 - rng.uniform()));
    x += sigma * radius * std::cos(two_pi * rng.uniform());
  }
}

double bbox_diagonal(const std::vector<double> &xyz) {
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (size_t i = 0; i < xyz.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], xyz[i]);
    hi[i % 3] = std::max(hi[i % 3], xyz[i]);
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

// The normals of a shared point file: columns 4-6 of an XYZ file, or the nx ny nz properties of
// an ASCII PLY file (the two layouts data/points uses). moa_io reads the positions only.
std::vector<double> read_normals(const std::string &path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<double> normals;
  std::string line;
  int columns[3] = {3, 4, 5};
  const bool ply = path.size() > 4 && path.compare(path.size() - 4, 4, ".ply") == 0;
  if (ply) {
    int property = 0;
    bool in_vertex = false;
    while (std::getline(in, line) && line.rfind("end_header", 0) != 0) {
      std::istringstream words(line);
      std::string word, type, name;
      words >> word;
      if (word == "format" && line.find("ascii") == std::string::npos)
        throw std::runtime_error(path + ": only ASCII PLY normals are read");
      if (word == "element") {
        words >> name;
        in_vertex = name == "vertex";
      } else if (word == "property" && in_vertex) {
        words >> type >> name;
        for (int k = 0; k < 3; ++k)
          if (name == std::string("n") + char('x' + k)) columns[k] = property;
        ++property;
      }
    }
  }
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::vector<double> cells;
    double v;
    while (words >> v) cells.push_back(v);
    if (cells.size() < 6) throw std::runtime_error(path + ": a point without normal: " + line);
    for (int k = 0; k < 3; ++k) normals.push_back(cells[size_t(columns[k])]);
  }
  return normals;
}

enum class Kind { Vertices, Uniform, Noisy, File };

struct Sample {
  const char *source;  // a mesh of data/meshes (without .off), or a file of data/points
  Kind kind;
  size_t count;  // points of Uniform and Noisy samples
  bool large;    // skipped by run_bench.sh --quick
};

// The inputs, in the order of the report. Inputs made from one mesh are adjacent.
const Sample kSamples[] = {
    {"bunny00", Kind::Vertices, 0, false},       {"bunny00", Kind::Uniform, 10000, false},
    {"bunny00", Kind::Uniform, 100000, false},   {"bunny00", Kind::Uniform, 1000000, true},
    {"bunny00", Kind::Noisy, 10000, false},      {"bunny00", Kind::Noisy, 100000, false},
    {"elephant", Kind::Vertices, 0, false},      {"elephant", Kind::Uniform, 10000, false},
    {"elephant", Kind::Uniform, 100000, false},  {"elephant", Kind::Uniform, 1000000, true},
    {"fandisk", Kind::Vertices, 0, false},       {"fandisk", Kind::Uniform, 10000, false},
    {"fandisk", Kind::Uniform, 100000, false},   {"fandisk", Kind::Uniform, 1000000, true},
    {"fandisk", Kind::Noisy, 100000, false},     {"knot2", Kind::Vertices, 0, false},
    {"knot2", Kind::Uniform, 10000, false},      {"knot2", Kind::Uniform, 100000, false},
    {"eight", Kind::Vertices, 0, false},         {"homer", Kind::Vertices, 0, false},
    {"homer", Kind::Uniform, 100000, false},     {"sphere966", Kind::Vertices, 0, false},
    {"mushroom", Kind::Vertices, 0, false},      {"cow", Kind::Vertices, 0, false},
    {"kitten.xyz", Kind::File, 0, false},        {"building.ply", Kind::File, 0, false},
};

std::string count_label(size_t count) {
  if (count % 1000000 == 0) return std::to_string(count / 1000000) + "m";
  if (count % 1000 == 0) return std::to_string(count / 1000) + "k";
  return std::to_string(count);
}

std::string name_of(const Sample &s) {
  switch (s.kind) {
    case Kind::Vertices: return std::string(s.source) + "-vertices";
    case Kind::Uniform: return std::string(s.source) + "-uniform-" + count_label(s.count);
    case Kind::Noisy: return std::string(s.source) + "-noise-" + count_label(s.count);
    case Kind::File: break;
  }
  const std::string file = s.source;
  return file.substr(0, file.find('.'));
}

const char *kind_name(Kind kind) {
  switch (kind) {
    case Kind::Vertices: return "vertices";
    case Kind::Uniform: return "uniform";
    case Kind::Noisy: return "noise";
    case Kind::File: break;
  }
  return "file";
}

}  // namespace

int sample_main(int argc, char **argv) {
  std::string out_dir = "/tmp/moa-bench", data_dir = MOA_BENCH_DATA;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--out" || a == "--data") && i + 1 < argc) (a == "--out" ? out_dir : data_dir) = argv[++i];
    else throw UsageError("sample: unknown or incomplete option " + a);
  }
  namespace fs = std::filesystem;
  fs::create_directories(fs::path(out_dir) / "inputs");

  const std::string manifest_path = (fs::path(out_dir) / "inputs.tsv").string();
  std::ofstream manifest(manifest_path);
  manifest << "#name\tfile\tpoints\tkind\tsource\tseed\tlarge\txyz_hash\tnormals\treference\t"
              "noise_sigma\tref_closed\tref_boundary_edges\tref_components\tref_genus\t"
              "ref_genus_defined\tref_contract\tref_self_intersections\tref_min_angle\t"
              "ref_below10\tref_below20\tref_below30\tref_angle_histogram\n";
  manifest.precision(6);

  std::string loaded;
  io::MeshData mesh;
  MeshReport ref;
  double diagonal = 0;
  for (const Sample &s : kSamples) {
    const std::string name = name_of(s);
    const uint64_t seed = seed_of(name);
    const auto t = Clock::now();
    std::vector<double> xyz, normals;
    std::string reference = "-";
    double sigma = 0;
    if (s.kind == Kind::File) {
      const std::string path = (fs::path(data_dir) / "points" / s.source).string();
      xyz = io::read_points(path);
      normals = read_normals(path);
      if (normals.size() != xyz.size()) throw std::runtime_error(path + ": normals and points differ in number");
    } else {
      reference = (fs::path(data_dir) / "meshes" / (std::string(s.source) + ".off")).string();
      if (loaded != s.source) {
        mesh = io::read_mesh(reference);
        ref = analyze_mesh(mesh.xyz.data(), mesh.xyz.size() / 3, mesh.triangles.data(),
                           mesh.triangles.size() / 3);
        diagonal = bbox_diagonal(mesh.xyz);
        loaded = s.source;
      }
      xyz = s.kind == Kind::Vertices ? shuffled_vertices(mesh, seed) : surface_sample(mesh, s.count, seed);
      if (s.kind == Kind::Noisy) {
        sigma = 0.0002 * diagonal;  // 0.02 % of the bounding-box diagonal, per coordinate
        add_noise(xyz, sigma, seed);
      }
    }
    const std::string file = (fs::path(out_dir) / "inputs" / (name + ".ply")).string();
    io::write_points(file, xyz);
    std::string normals_file = "-";
    if (!normals.empty()) {
      // Given normals go beside the points, for the methods that use them.
      normals_file = (fs::path(out_dir) / "inputs" / (name + ".normals.xyz")).string();
      io::write_points(normals_file, normals);
    }
    manifest << name << '\t' << file << '\t' << xyz.size() / 3 << '\t' << kind_name(s.kind) << '\t'
             << s.source << '\t' << hex64(seed) << '\t' << (s.large ? 1 : 0) << '\t'
             << hex64(fnv1a(xyz.data(), xyz.size())) << '\t' << normals_file << '\t' << reference
             << '\t' << sigma;
    if (reference == "-") {
      for (int k = 0; k < 12; ++k) manifest << "\t-";
    } else {
      std::string histogram;
      for (size_t c : ref.min_angle_histogram) histogram += (histogram.empty() ? "" : " ") + std::to_string(c);
      manifest << '\t' << (ref.closed() ? 1 : 0) << '\t' << ref.boundary_edges << '\t'
               << ref.components << '\t' << ref.genus << '\t' << (ref.genus_defined ? 1 : 0) << '\t'
               << (ref.contract_ok() ? 1 : 0) << '\t' << ref.self_intersecting_pairs << '\t'
               << ref.min_angle << '\t' << ref.share_below_10 << '\t' << ref.share_below_20 << '\t'
               << ref.share_below_30 << '\t' << histogram;
    }
    manifest << '\n';
    std::printf("%-26s %8zu points  %6.0f ms  %s\n", name.c_str(), xyz.size() / 3, ms_since(t),
                file.c_str());
  }
  if (!manifest) throw std::runtime_error(manifest_path + ": cannot write");
  return 0;
}

}  // namespace moa::bench
