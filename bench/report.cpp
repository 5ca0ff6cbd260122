// `moa_bench report`: turns the inputs list written by `moa_bench sample` and the result files of
// run_bench.sh's runs into
//   RESULTS/results.tsv  one line per input and method (what bench/plot.py draws),
//   RESULTS/latest.md    the full report, with the detail tables,
//   BENCHMARKS           the top-level summary (BENCHMARKS.md): key figures, all results, plots,
//                        pictures.
// Plots and pictures are linked when their PNG exists in RESULTS (run_bench.sh draws them
// between two calls).
//
// Result files in WORK/results, per input NAME: NAME.METHOD.txt for each method of kMethods
// (the runner's keys, then `moa_bench analyze`'s q_* and d_* keys), NAME.moa1.txt (libmoa with
// one thread, large inputs only). WORK/run.tsv and WORK/peers.tsv describe the run.
#include <sched.h>
#include <sys/utsname.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "bench_modes.hpp"
#include "moa/moa.h"
#include "report_cells.hpp"

namespace moa::bench {
namespace {

namespace fs = std::filesystem;

struct Method {
  const char *key;    // result file suffix and results.tsv name
  const char *label;  // in the tables
  const char *peer;   // runner in peers.tsv ("" for libmoa)
};

const Method kMethods[] = {
    {"moa", "libmoa", ""},
    {"cgal", "CGAL AF", "cgal_afront"},
    {"o3d_bpa", "Open3D BPA", "open3d_recon"},
    {"o3d_poisson", "Open3D Poisson", "open3d_recon"},
    {"pcl_gp3", "PCL GP3", "pcl_gp3"},
};

constexpr double kTargetRatio = 5;            // times faster than CGAL's advancing front
constexpr double kTargetBytesPerPoint = 400;  // libmoa's peak memory at 1M points
constexpr double kBusy = 0.15;                // other processes' cores that make a time suspect

// The inputs whose rows make the key-figures table.
const char *const kKeyInputs[] = {"bunny00-vertices", "bunny00-uniform-100k", "bunny00-uniform-1m"};

struct Row {
  Record input;
  std::map<std::string, Record> runs;  // by method key; absent: the method was not run
  Record moa1;
};

struct Report {
  Record run, peers_built, peers_detail;
  std::vector<Row> rows;
  std::vector<const Method *> methods;  // those with at least one result
};

bool has_reference(const Record &input) { return text(input, "reference", "-") != "-"; }

std::string first_line_of(const std::string &path, const std::string &key) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, key.size(), key) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) {
        std::string v = line.substr(colon + 1);
        v.erase(0, v.find_first_not_of(" \t"));
        return v;
      }
    }
  return "unknown";
}

std::string machine() {
  cpu_set_t set;
  CPU_ZERO(&set);
  const int cores = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 0;
  utsname u{};
  uname(&u);
  std::string mem = first_line_of("/proc/meminfo", "MemTotal");
  const double kib = std::strtod(mem.c_str(), nullptr);
  if (kib > 0) mem = fmt("%.1f GB", kib * 1024 / 1e9);
  return first_line_of("/proc/cpuinfo", "model name") + ", " + std::to_string(cores) +
         " cores (nproc), " + mem + " RAM, " + u.sysname + " " + u.release + " " + u.machine +
         ", gcc " __VERSION__;
}

// Tab-separated file with a "#"-prefixed header line -> records.
std::vector<Record> read_table(const fs::path &path) {
  std::vector<Record> out;
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": missing");
  std::vector<std::string> columns;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, '\t')) cells.push_back(cell);
    if (cells.empty()) continue;
    if (cells[0][0] == '#') {
      cells[0].erase(0, 1);
      columns = cells;
      continue;
    }
    Record r;
    for (size_t c = 0; c < cells.size() && c < columns.size(); ++c) r[columns[c]] = cells[c];
    out.push_back(r);
  }
  return out;
}

Report load(const fs::path &work) {
  Report rep;
  rep.run = read_result((work / "run.tsv").string());
  if (fs::exists(work / "peers.tsv"))
    for (const Record &p : read_table(work / "peers.tsv")) {
      rep.peers_built[text(p, "peer")] = text(p, "built");
      rep.peers_detail[text(p, "peer")] = text(p, "detail");
    }
  for (const Record &input : read_table(work / "inputs.tsv")) {
    Row row;
    row.input = input;
    const std::string base = (work / "results" / text(input, "name")).string();
    for (const Method &m : kMethods) {
      const std::string path = base + "." + m.key + ".txt";
      if (fs::exists(path)) row.runs[m.key] = read_result(path);
    }
    row.moa1 = read_result(base + ".moa1.txt");
    rep.rows.push_back(row);
  }
  for (const Method &m : kMethods)
    if (std::any_of(rep.rows.begin(), rep.rows.end(), [&](const Row &r) { return r.runs.count(m.key); }))
      rep.methods.push_back(&m);
  return rep;
}

const Record *find_run(const Row &row, const char *method) {
  const auto it = row.runs.find(method);
  return it == row.runs.end() ? nullptr : &it->second;
}

bool needs_normals(const Method &m) { return m.peer[0] != '\0' && std::string(m.key) != "cgal"; }

double total_ms(const Record &r) {
  const double n = num(r, "normals_ms");
  return num(r, "recon_ms") + (std::isfinite(n) ? n : 0);
}

// ---- results.tsv -----------------------------------------------------------------------------

void write_tsv(const Report &rep, const fs::path &path) {
  std::ofstream out(path);
  out << "#input\tpoints\tkind\tsource\tmethod\tstatus\trecon_s\tnormals_s\ttotal_s\tpeak_mb\t"
         "bytes_per_point\ttriangles\tclosed\tgenus\tcomponents\tboundary_edges\t"
         "non_manifold_edges\tnon_manifold_vertices\tinconsistent_edges\tself_intersections\t"
         "below10\tbelow20\tbelow30\tmin_angle\tangle_histogram\thausdorff\tmean_distance\t"
         "points_on_mesh\tother_load\n";
  auto cell = [](double v) { return std::isfinite(v) ? fmt("%.6g", v) : std::string(); };
  for (const Row &row : rep.rows) {
    const Record &in = row.input;
    const double points = num(in, "points");
    const std::string head = text(in, "name") + '\t' + fmt("%.0f", points) + '\t' +
                             text(in, "kind") + '\t' + text(in, "source") + '\t';
    if (has_reference(in)) {  // the reference mesh, for the angle plot
      out << head << "reference\tok\t\t\t\t\t\t\t" << text(in, "ref_closed") << '\t'
          << text(in, "ref_genus") << '\t' << text(in, "ref_components") << '\t'
          << text(in, "ref_boundary_edges") << "\t\t\t\t" << text(in, "ref_self_intersections")
          << '\t' << text(in, "ref_below10") << '\t' << text(in, "ref_below20") << '\t'
          << text(in, "ref_below30") << '\t' << text(in, "ref_min_angle") << '\t'
          << text(in, "ref_angle_histogram") << "\t0\t0\t\t\n";
    }
    for (const Method *m : rep.methods) {
      const Record *r = find_run(row, m->key);
      if (!r) continue;
      out << head << m->key << '\t' << (ok(*r) ? (analysed(*r) ? "ok" : "not analysed") : failure(*r));
      if (!ok(*r)) {
        out << std::string(23, '\t') << '\n';
        continue;
      }
      const double peak = num(*r, "rss_peak");
      out << '\t' << cell(num(*r, "recon_ms") / 1000) << '\t' << cell(num(*r, "normals_ms") / 1000)
          << '\t' << cell(total_ms(*r) / 1000) << '\t' << cell(peak / 1e6) << '\t'
          << cell(peak / points) << '\t' << cell(num(*r, "triangles")) << '\t'
          << cell(num(*r, "q_closed")) << '\t'
          << (num(*r, "q_genus_defined") == 1 ? cell(num(*r, "q_genus")) : "") << '\t'
          << cell(num(*r, "q_components")) << '\t' << cell(num(*r, "q_boundary_edges")) << '\t'
          << cell(num(*r, "q_non_manifold_edges")) << '\t' << cell(num(*r, "q_non_manifold_vertices"))
          << '\t' << cell(num(*r, "q_inconsistent_edges")) << '\t'
          << cell(num(*r, "q_self_intersecting_pairs")) << '\t' << cell(num(*r, "q_below10")) << '\t'
          << cell(num(*r, "q_below20")) << '\t' << cell(num(*r, "q_below30")) << '\t'
          << cell(num(*r, "q_min_angle")) << '\t' << text(*r, "q_angle_histogram") << '\t'
          << cell(num(*r, "d_hausdorff")) << '\t' << cell(num(*r, "d_mean")) << '\t'
          << cell(num(*r, "q_input_points_on_mesh")) << '\t' << cell(num(*r, "other_load")) << '\n';
    }
  }
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

// ---- Markdown ---------------------------------------------------------------------------------

std::string genus_cell(const Record &r, const std::string &prefix) {
  if (num(r, prefix + "genus_defined") != 1) return "n/a";
  std::string g = grouped(num(r, prefix + "genus"));
  const double components = num(r, prefix + "components");
  if (components != 1 && std::isfinite(components)) g += " (" + grouped(components) + " comp.)";
  return g;
}

// Closed or not; bold when the surface it was sampled from is closed but the mesh is not.
std::string closed_cell(double closed, const Record &input) {
  if (!std::isfinite(closed)) return "—";
  if (closed == 1) return "yes";
  return num(input, "ref_closed") == 1 ? "**no**" : "no";
}

// A count that should be zero: bold when it is not.
std::string defects(double v) { return !std::isfinite(v) ? "—" : v == 0 ? "0" : "**" + grouped(v) + "**"; }

const char *const kMainHeader =
    "| input | method | time (s) | normals (s) | peak MB | B/point | triangles | closed | genus "
    "| boundary edges | non-manifold edges / vertices | inconsistent edges | self-intersecting pairs "
    "| min angle <10° / <20° / <30° (%) | Hausdorff / mean (% diag) |\n"
    "|---|---|--:|--:|--:|--:|--:|:-:|--:|--:|--:|--:|--:|--:|--:|\n";

const char *const kMainNote =
    "\nTimes in seconds; peak memory of the method's own process; angles: share of triangles "
    "whose smallest angle is below 10°, 20°, 30°; distances in % of the reference's "
    "bounding-box diagonal. Bold: a defect count above zero, or \"no\" closed where the "
    "reference is closed. Genus is summed over the components (n/a: some component is not a "
    "manifold orientable surface). \"—\": not applicable. ¹ Normals estimated once for both "
    "Open3D methods, in the ball-pivoting run; Poisson's peak memory leaves them out.\n\n";

void main_rows(std::ostream &md, const Report &rep, const Row &row) {
  if (row.runs.empty()) return;  // listed under "Inputs" as not run
  const Record &in = row.input;
  const std::string name = text(in, "name");
  const double points = num(in, "points");
  const std::string input_cell = name + " (" + grouped(points) + ")";
  if (has_reference(in))
    md << "| " << input_cell << " | *reference mesh* | | | | | | " << (num(in, "ref_closed") == 1 ? "yes" : "no")
       << " | " << genus_cell(in, "ref_") << " | " << grouped(num(in, "ref_boundary_edges"))
       << " | | | " << grouped(num(in, "ref_self_intersections")) << " | "
       // Angles compare only with a reconstruction from the same vertices.
       << (text(in, "kind") != "vertices"
               ? "—"
               : percent(num(in, "ref_below10")) + " / " + percent(num(in, "ref_below20")) + " / " +
                     percent(num(in, "ref_below30")))
       << " | |\n";
  for (const Method *m : rep.methods) {
    const Record *r = find_run(row, m->key);
    md << "| " << input_cell << " | " << m->label << " | ";
    if (!r) {
      md << "not run | | | | | | | | | | | | |\n";
      continue;
    }
    if (!ok(*r)) {
      md << "**" << failure(*r) << "** | | | | | | | | | | | | |\n";
      continue;
    }
    const double peak = num(*r, "rss_peak");
    std::string normals = "—";
    if (needs_normals(*m)) {
      const std::string how = text(*r, "normals");
      normals = how == "given" ? "given" : seconds(num(*r, "normals_ms")) + (how == "shared" ? " ¹" : "");
    }
    md << seconds(num(*r, "recon_ms")) << " | " << normals << " | " << megabytes(peak) << " | "
       << grouped(peak / points) << " | " << grouped(num(*r, "triangles")) << " | ";
    if (!analysed(*r)) {
      md << "not analysed: " << text(*r, "analysis", "no result") << " | | | | | | | |\n";
      continue;
    }
    md << closed_cell(num(*r, "q_closed"), in) << " | " << genus_cell(*r, "q_") << " | "
       << grouped(num(*r, "q_boundary_edges")) << " | " << defects(num(*r, "q_non_manifold_edges"))
       << " / " << defects(num(*r, "q_non_manifold_vertices")) << " | "
       << defects(num(*r, "q_inconsistent_edges")) << " | "
       << defects(num(*r, "q_self_intersecting_pairs")) << " | " << percent(num(*r, "q_below10"))
       << " / " << percent(num(*r, "q_below20")) << " / " << percent(num(*r, "q_below30")) << " | ";
    if (has(*r, "d_hausdorff"))
      md << relative(num(*r, "d_hausdorff")) << " / " << relative(num(*r, "d_mean"));
    else
      md << "no reference";
    md << " |\n";
  }
}

std::string libmoa_params(const Report &rep) {
  for (const Row &row : rep.rows)
    if (const Record *r = find_run(row, "moa"); r && ok(*r)) {
      std::string out;
      for (const auto &[key, value] : *r)
        if (key.compare(0, 6, "param_") == 0) out += (out.empty() ? "" : ", ") + key.substr(6) + "=" + value;
      return out;
    }
  return "defaults";
}

// The first successful record of a method, for its versions and parameters.
Record first_ok(const Report &rep, const char *method) {
  for (const Row &row : rep.rows)
    if (const Record *r = find_run(row, method); r && ok(*r)) return *r;
  return {};
}

void header(std::ostream &md, const Report &rep, const std::string &title) {
  const Record &run = rep.run;
  md << "# " << title << "\n\n";
  md << "- **Date**: " << text(run, "started", "unknown") << "; the whole run took "
     << grouped(num(run, "elapsed_s")) << " s (" << fmt("%.1f", num(run, "elapsed_s") / 60)
     << " min).\n";
  md << "- **Command**: `" << text(run, "command", "bench/run_bench.sh") << "` (from the project root).\n";
  md << "- **Machine**: " << machine() << ".\n";
  md << "- **Load**: load average (1 min) " << text(run, "load_start", "?") << " at the start, "
     << text(run, "load_end", "?") << " at the end. The machine is shared, so the times are "
        "noisy: every timed run records the cores other processes kept busy meanwhile (\"others' "
        "load\" in the run-details table of `bench/results/latest.md`).\n";
  md << "- **Code**: libmoa " << moa_version() << ", revision " << text(run, "revision", "unknown") << ".\n";
  md << "- **Peers**: ";
  bool first = true;
  for (const auto &[peer, built] : rep.peers_built) {
    md << (first ? "" : "; ") << "`" << peer << "` "
       << (built == "1" ? rep.peers_detail.at(peer) : "**skipped**: " + rep.peers_detail.at(peer));
    first = false;
  }
  if (rep.peers_built.empty()) md << "unknown (no peers.tsv)";
  md << ".\n\n";
}

void methods_section(std::ostream &md, const Report &rep) {
  const Record cgal = first_ok(rep, "cgal"), bpa = first_ok(rep, "o3d_bpa"),
               poisson = first_ok(rep, "o3d_poisson"), gp3 = first_ok(rep, "pcl_gp3");
  md << "## Methods and parameters\n\n"
        "Each method runs in its own process on the same points (read with libmoa's `moa_io`, so "
        "all see identical doubles), under a time limit of "
     << text(rep.run, "timeout", "?") << " s per run. Peer parameters are those their documentation "
        "recommends. The OpenMP peers (Open3D, PCL's normals) run with `OMP_WAIT_POLICY="
     << text(rep.run, "omp_wait_policy", "?")
     << "`: on a shared machine, spinning OpenMP threads compete with the other processes and "
        "made them several times slower (Poisson on 315 points: 11–16 s spinning, 3.6 s passive, "
        "at a load of 6 on 2 cores); libmoa uses TBB and CGAL runs sequentially.\n\n";
  md << "- **libmoa** (`moa_bench`): the C ABI with default parameters and `threads=0` (all "
        "cores): "
     << libmoa_params(rep) << ". Run twice per input in one process; the second run must return "
        "the same triangles (C6). No normals needed.\n";
  md << "- **CGAL advancing front** (`cgal_afront`, CGAL " << text(cgal, "cgal_version", "?")
     << "): `advancing_front_surface_reconstruction` with its defaults, radius_ratio_bound="
     << text(cgal, "param_radius_ratio_bound", "5") << ", beta=" << text(cgal, "param_beta", "0.52")
     << " rad, Exact_predicates_inexact_constructions_kernel; sequential. No normals needed.\n";
  md << "- **Open3D ball pivoting** (`open3d_recon --method bpa`, Open3D "
     << text(bpa, "open3d_version", "?")
     << "): `CreateFromPointCloudBallPivoting` with radii {"
     << text(bpa, "param_radii_x_spacing", "1.5,3,6")
     << "} × the average nearest-neighbour distance (`ComputeNearestNeighborDistance`, timed "
        "with the reconstruction), as the Open3D tutorial derives radii from the spacing.\n";
  md << "- **Open3D Poisson** (`open3d_recon --method poisson`): `CreateFromPointCloudPoisson`, "
        "depth "
     << text(poisson, "param_depth", "9")
     << " (the tutorial's), width 0, scale 1.1, no linear fit, all threads. The mesh is reported "
        "**untrimmed** (no density-quantile cut), as Poisson returns it. Its "
        "vertices are new points, so \"points on mesh\" does not apply.\n";
  md << "- **Open3D normals** (both Open3D methods, when the input has none): `EstimateNormals` "
        "with "
     << text(bpa.empty() ? poisson : bpa, "param_normal_k", "30")
     << " nearest neighbours (its default), then `OrientNormalsConsistentTangentPlane("
     << text(bpa.empty() ? poisson : bpa, "param_orient_k", "100")
     << ")` as in the tutorial; timed as \"normals\". They are estimated once per input, in "
        "the ball-pivoting run, and the Poisson run reads them back (marked ¹: the time is the "
        "ball-pivoting run's, and Poisson's peak memory leaves the normal estimation out; it is "
        "in the ball-pivoting row). Orienting them is the slow part: it takes minutes on large "
        "or sharp inputs.\n";
  md << "- **PCL greedy projection** (`pcl_gp3`, PCL " << text(gp3, "pcl_version", "?")
     << "): `GreedyProjectionTriangulation` with the tutorial's settings: mu "
     << text(gp3, "param_mu", "2.5") << ", maximum nearest neighbours "
     << text(gp3, "param_max_nn", "100")
     << ", maximum surface angle 45°, minimum angle 10°, maximum angle 120°, normal consistency "
        "off; search radius "
     << text(gp3, "param_radius_x_spacing", "7.5")
     << " × the average nearest-neighbour distance (measured with PCL's kd-tree, timed with the "
        "reconstruction), so that mu × the local spacing limits the edges rather than the "
        "radius. Normals (when the input has none): `NormalEstimationOMP`, "
     << text(gp3, "param_normal_k", "20")
     << " nearest neighbours, as in the tutorial (oriented towards the origin, PCL's default); "
        "timed as \"normals\". PCL computes in single precision; its triangles index the input "
        "points, which are written with their double coordinates.\n";
  md << "- **Given normals**: kitten and building carry normals; the methods that need normals "
        "use them (\"given\"), as the issue asks: normals are estimated only where the input has "
        "none.\n\n";
}

void measured_section(std::ostream &md) {
  md << "## What is measured\n\n"
        "- **time**: the reconstruction only, from the points in memory to the mesh, wall clock. "
        "libmoa: `moa_set_points` + the first `moa_run`; CGAL: the reconstruction call; Open3D BPA "
        "and PCL: the spacing measurement + the reconstruction call; Poisson: its call. Reading "
        "files is excluded. **normals**: estimation + orientation, for the methods that need "
        "them.\n"
        "- **peak memory**: `getrusage(RUSAGE_SELF).ru_maxrss` of the method's own process right "
        "after the reconstruction, nothing subtracted (program, libraries, the caller's copy of "
        "the points and normal estimation included, except for Poisson: see ¹), in MB and bytes per "
        "input point.\n"
        "- **the mesh checks**, by one checker for every method (`moa_bench analyze`, which is "
        "libmoa's `src/quality` analyser with exact predicates, plus `bench/distance.cpp`): "
        "closed (no boundary edge), genus (summed over components; n/a when a component is not "
        "a manifold orientable surface), boundary edges, non-manifold edges (more than two "
        "faces) and vertices (more than one fan), inconsistently oriented edges (two faces "
        "using the edge in the same direction), self-intersecting face pairs (exact test), the "
        "smallest angle of each triangle (share below 10°, 20°, 30°).\n"
        "- **distance to the reference** (inputs sampled from a mesh of `data/meshes`): both "
        "surfaces are sampled (all vertices plus at least 200,000 area-stratified points) and "
        "each sample's exact distance to the other surface is found with an Embree point-query "
        "tree. Hausdorff = the larger of the two one-sided maxima; mean = the average of the two "
        "one-sided area-weighted means; both in per cent of the reference's bounding-box "
        "diagonal. Noisy inputs are compared with the clean surface.\n\n";
}

void inputs_section(std::ostream &md, const Report &rep) {
  md << "## Inputs\n\nWritten by `moa_bench sample` (fixed seeds derived from each input's name; "
        "seeds and content hashes in `inputs.tsv` of the work directory), from `../shared/data`:\n\n"
        "- `*-vertices`: the vertices of a mesh of `data/meshes`, shuffled;\n"
        "- `*-uniform-N`: N points uniformly distributed over a mesh's surface by area;\n"
        "- `*-noise-N`: the same with Gaussian noise, σ = 0.02 % of the mesh's bounding-box "
        "diagonal on each coordinate;\n"
        "- `kitten` (`points/kitten.xyz`) and `building` (`points/building.ply`), with their own "
        "normals; no reference surface.\n\n";
  std::string skipped;
  for (const Row &row : rep.rows)
    if (row.runs.empty()) skipped += (skipped.empty() ? "" : ", ") + text(row.input, "name");
  if (!skipped.empty()) md << "Not run this time: " << skipped << ".\n\n";
}

// Everything that was skipped, failed or timed out, in one list.
void skipped_section(std::ostream &md, const Report &rep) {
  std::vector<std::string> lines;
  for (const auto &[peer, built] : rep.peers_built)
    if (built != "1") lines.push_back("`" + peer + "` not built: " + rep.peers_detail.at(peer) + ".");
  for (const Row &row : rep.rows)
    for (const Method *m : rep.methods) {
      const Record *r = find_run(row, m->key);
      if (r && !ok(*r))
        lines.push_back(std::string(m->label) + " on " + text(row.input, "name") + ": " + failure(*r) + ".");
      else if (r && !analysed(*r))
        lines.push_back(std::string(m->label) + " on " + text(row.input, "name") + ": mesh not analysed (" +
                        text(*r, "analysis", "no result") + ").");
    }
  md << "## Skipped, failed, timed out\n\n";
  if (lines.empty()) md << "Nothing: every method ran on every input of this run.\n";
  for (const std::string &l : lines) md << "- " << l << "\n";
  md << "\n";
}

void targets_section(std::ostream &md, const Report &rep) {
  size_t met = 0, compared = 0;
  double worst = INFINITY;
  std::string worst_input;
  for (const Row &row : rep.rows) {
    const Record *m = find_run(row, "moa"), *c = find_run(row, "cgal");
    if (!m || !c || !ok(*m) || !ok(*c)) continue;
    const double ratio = num(*c, "recon_ms") / num(*m, "recon_ms");
    ++compared;
    met += ratio >= kTargetRatio;
    if (ratio < worst) worst = ratio, worst_input = text(row.input, "name");
  }
  md << "## libmoa against its targets (`../shared/BENCHMARKS.md`)\n\n";
  if (compared)
    md << "- At least " << kTargetRatio << "× faster than CGAL's advancing front on every input: **"
       << (met == compared ? "met" : "not met") << "** (" << met << " of " << compared
       << " inputs; lowest ratio " << fmt("%.2f", worst) << "× on " << worst_input << ").\n";
  // One line for every input of a million points or more: met only when it holds on each.
  size_t large = 0, under = 0;
  std::string each;
  for (const Row &row : rep.rows) {
    const Record *m = find_run(row, "moa");
    if (!m || !ok(*m) || num(row.input, "points") < 1e6) continue;
    const double bpp = num(*m, "rss_peak") / num(row.input, "points");
    ++large;
    under += bpp < kTargetBytesPerPoint;
    each += (each.empty() ? "" : ", ") + text(row.input, "name") + " " + grouped(bpp);
  }
  if (large)
    md << "- Under " << kTargetBytesPerPoint << " bytes of peak memory per point at 1M points: **"
       << (under == large ? "met" : "not met") << "** (" << under << " of " << large
       << " inputs of a million points; " << each << " B/point).\n";
  size_t held = 0, c6 = 0, ran = 0;
  for (const Row &row : rep.rows)
    if (const Record *m = find_run(row, "moa"); m && analysed(*m)) {
      ++ran;
      held += num(*m, "q_contract") == 1;
      c6 += text(*m, "c6") == "identical";
    }
  md << "- Output contract C1–C5 held by libmoa on " << held << " of " << ran
     << " inputs; C6 (two runs identical) on " << c6 << " of " << ran << ".\n\n";
}

void plots_section(std::ostream &md, const fs::path &results, const std::string &prefix) {
  const std::pair<const char *, const char *> plots[] = {
      {"time_vs_points.png", "Time against the number of points (log–log), one line per method"},
      {"memory_vs_points.png", "Peak memory against the number of points (log–log)"},
      {"min_angle.png", "Distribution of the smallest angle of each triangle"},
  };
  md << "## Plots\n\n";
  bool any = false;
  for (const auto &[file, caption] : plots)
    if (fs::exists(results / file)) {
      md << "**" << caption << "**\n\n![" << caption << "](" << prefix << file << ")\n\n";
      any = true;
    }
  if (!any) md << "No plots this time (`bench/plot.py` needs python3-matplotlib).\n\n";
}

// The pictures run_bench.sh draws of every method's mesh for a few inputs (RESULTS/pictures/
// NAME.METHOD.png, `moa render --highlight-defects`): one row per input, one column per method.
void pictures_section(std::ostream &md, const Report &rep, const fs::path &results,
                      const std::string &prefix) {
  const fs::path dir = results / "pictures";
  std::ostringstream rows;
  for (const Row &row : rep.rows) {
    const std::string name = text(row.input, "name");
    std::string line = "| " + name + " |";
    bool any = false;
    for (const Method *m : rep.methods) {
      const std::string file = name + "." + m->key + ".png";
      if (fs::exists(dir / file)) {
        line += " ![" + name + ", " + m->label + "](" + prefix + "pictures/" + file + ") |";
        any = true;
      } else {
        line += " — |";
      }
    }
    if (any) rows << line << "\n";
  }
  if (rows.str().empty()) return;
  md << "## Pictures\n\n"
        "Every method's mesh of a few inputs, drawn by `moa render --highlight-defects` from the "
        "meshes of this run. Blue-grey: the side of a face its normal points to; sand: the other "
        "side (a face turned against its neighbours, a closed surface facing inward, or the "
        "inside seen through a hole); red: boundary edges; purple: faces on a non-manifold edge "
        "or vertex, or crossing another face (decided exactly). \"—\": no mesh.\n\n| input |";
  for (const Method *m : rep.methods) md << " " << m->label << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < rep.methods.size(); ++i) md << ":-:|";
  md << "\n" << rows.str() << "\n";
}

// Observations drawn from the numbers, so that nobody has to read them off the tables.
void observations(std::ostream &md, const Report &rep) {
  std::vector<std::string> notes;
  std::string faster, open;
  for (const Row &row : rep.rows) {
    const std::string name = text(row.input, "name");
    const Record *m = find_run(row, "moa");
    if (!m) continue;
    if (!ok(*m)) {
      notes.push_back(name + ": the libmoa run " + failure(*m) + ".");
      continue;
    }
    // The fastest method, normals included.
    const Method *fastest = nullptr;
    double best = INFINITY;
    for (const Method *method : rep.methods)
      if (const Record *r = find_run(row, method->key); r && ok(*r) && total_ms(*r) < best)
        best = total_ms(*r), fastest = method;
    if (fastest && std::string(fastest->key) != "moa")
      faster += (faster.empty() ? "" : ", ") + name + " (" + fastest->label + " " + seconds(best) +
                " s, libmoa " + seconds(total_ms(*m)) + " s)";
    if (analysed(*m) && has_reference(row.input) && num(row.input, "ref_closed") == 1 &&
        num(*m, "q_closed") != 1)
      open += (open.empty() ? "" : ", ") + name + " (" + grouped(num(*m, "q_boundary_edges")) + ")";
    if (analysed(*m) && num(*m, "q_contract") != 1)
      notes.push_back(name + ": libmoa's output contract C1–C5 fails.");
  }
  if (!faster.empty())
    notes.push_back("Inputs on which another method was faster than libmoa, normals included: " + faster + ".");
  if (!open.empty())
    notes.push_back("Inputs whose reference is closed but libmoa's mesh is open (boundary edges): " + open + ".");
  // How much the shared machine disturbed the timed runs.
  std::vector<double> loads;
  for (const Row &row : rep.rows)
    for (const Method *method : rep.methods)
      if (const Record *r = find_run(row, method->key); r && ok(*r) && std::isfinite(num(*r, "other_load")))
        loads.push_back(num(*r, "other_load"));
  if (!loads.empty()) {
    std::sort(loads.begin(), loads.end());
    const size_t busy = size_t(std::count_if(loads.begin(), loads.end(), [](double l) { return l > kBusy; }));
    notes.push_back(std::to_string(busy) + " of " + std::to_string(loads.size()) +
                    " timed runs shared the cores with other processes (more than " + fmt("%.2f", kBusy) +
                    " cores busy on average); their load: median " + fmt("%.2f", loads[loads.size() / 2]) +
                    ", maximum " + fmt("%.2f", loads.back()) + " cores. Times are inflated accordingly; "
                    "each run's load is in the run-details table of `bench/results/latest.md`.");
  }
  md << "## Observations (generated)\n\n";
  if (notes.empty()) md << "- Nothing to note.\n";
  for (const std::string &n : notes) md << "- " << n << "\n";
  md << "\n";
}

// ---- detail tables (latest.md only) -------------------------------------------------------------

void stages_section(std::ostream &md, const Report &rep) {
  md << "## libmoa per stage\n\nMilliseconds of the first run, from `moa_get_stats`; \"crossing "
        "checks\" is the part of the stages spent in the Embree and exact crossing tests.\n\n";
  md << "| input | points | neighbors | mesh | loops | finish | crossing checks | moa_run | second "
        "run | threads | triangles from loops | removed |\n";
  md << "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const Row &row : rep.rows) {
    const Record *m = find_run(row, "moa");
    if (!m || !ok(*m)) continue;
    md << "| " << text(row.input, "name");
    for (int s = 0; s < MOA_STAGE_COUNT; ++s)
      md << " | " << grouped(num(*m, std::string("stage_") + moa_stage_name(moa_stage(s))));
    md << " | " << grouped(num(*m, "intersection_ms")) << " | " << grouped(num(*m, "total_ms")) << " | "
       << grouped(num(*m, "repeat_ms")) << " | " << text(*m, "threads_used") << " | "
       << grouped(num(*m, "triangles_loops")) << " | " << grouped(num(*m, "triangles_removed")) << " |\n";
  }
  md << "\n";
}

void speedup_section(std::ostream &md, const Report &rep) {
  bool any = false;
  for (const Row &row : rep.rows) any = any || !row.moa1.empty();
  if (!any) return;
  md << "## libmoa's parallel speed-up\n\nThe same input with `threads=1` in its own process; "
        "\"same triangles\" compares its triangle list with the all-cores run.\n\n"
        "| input | 1 thread (s) | all cores (s) | threads | speed-up | same triangles | others' load |\n"
        "|---|--:|--:|--:|--:|---|--:|\n";
  for (const Row &row : rep.rows) {
    const Record *m = find_run(row, "moa");
    if (row.moa1.empty() || !m) continue;
    if (!ok(row.moa1) || !ok(*m)) {
      md << "| " << text(row.input, "name") << " | " << (ok(row.moa1) ? "" : failure(row.moa1)) << " | "
         << (ok(*m) ? "" : failure(*m)) << " | | | | |\n";
      continue;
    }
    md << "| " << text(row.input, "name") << " | " << seconds(num(row.moa1, "recon_ms")) << " | "
       << seconds(num(*m, "recon_ms")) << " | " << text(*m, "threads_used") << " | "
       << fmt("%.2f×", num(row.moa1, "recon_ms") / num(*m, "recon_ms")) << " | "
       << (text(row.moa1, "hash") == text(*m, "hash") ? "yes" : "**no**") << " | "
       << fmt("%.2f", std::max(num(row.moa1, "other_load"), num(*m, "other_load"))) << " |\n";
  }
  md << "\n";
}

void details_section(std::ostream &md, const Report &rep) {
  md << "## Run details\n\n\"peak after read\": the process's peak before the reconstruction "
        "(program, libraries and the points). \"others' load\": cores kept busy by other "
        "processes during the timed part, on average (from /proc/stat minus the run's own CPU "
        "time); above " << kBusy << " the time is inflated. \"points on mesh\": input points that "
        "are a vertex of some triangle. Distances are one-sided: mesh → reference (how far the "
        "surface strays) and reference → mesh (what it misses), max / mean in % of the diagonal.\n\n";
  md << "| input | method | read (s) | peak after read (MB) | others' load | points on mesh "
        "| components | C1–C5 | mesh → reference | reference → mesh | checker (s) |\n"
        "|---|---|--:|--:|--:|--:|--:|---|--:|--:|--:|\n";
  for (const Row &row : rep.rows)
    for (const Method *m : rep.methods) {
      const Record *r = find_run(row, m->key);
      if (!r || !analysed(*r)) continue;
      const double points = num(row.input, "points"), on = num(*r, "q_input_points_on_mesh");
      const std::string on_cell = std::string(m->key) == "o3d_poisson"
                                      ? "n/a"
                                      : grouped(on) + (on == points ? "" : fmt(" (%.2f %%)", 100 * on / points));
      md << "| " << text(row.input, "name") << " | " << m->label << " | " << seconds(num(*r, "read_ms"))
         << " | " << megabytes(num(*r, "rss_read")) << " | " << fmt("%.2f", num(*r, "other_load")) << " | "
         << on_cell << " | " << grouped(num(*r, "q_components")) << " | "
         << (num(*r, "q_contract") == 1 ? "held" : "fails") << " | ";
      if (has(*r, "d_hausdorff"))
        md << relative(num(*r, "d_max_to_ref")) << " / " << relative(num(*r, "d_mean_to_ref")) << " | "
           << relative(num(*r, "d_max_from_ref")) << " / " << relative(num(*r, "d_mean_from_ref"));
      else
        md << "— | —";
      md << " | " << seconds(num(*r, "q_analysis_ms") + (has(*r, "d_ms") ? num(*r, "d_ms") : 0)) << " |\n";
    }
  md << "\n";
}

// Every input's rows under the main table's header and note.
void all_results_section(std::ostream &md, const Report &rep) {
  md << "## All results\n\n" << kMainHeader;
  for (const Row &row : rep.rows) main_rows(md, rep, row);
  md << kMainNote;
}

// The sections both documents end with: what was seen, skipped, run and measured, and on what.
void closing_sections(std::ostream &md, const Report &rep) {
  observations(md, rep);
  skipped_section(md, rep);
  methods_section(md, rep);
  measured_section(md);
  inputs_section(md, rep);
}

void write_file(const fs::path &path, const std::string &content) {
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  std::ofstream out(path);
  out << content;
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
  std::printf("wrote %s\n", path.string().c_str());
}

}  // namespace

int report_main(int argc, char **argv) {
  fs::path work = "/tmp/moa-bench", results, benchmarks;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) throw UsageError("report: " + a + " needs a value");
    if (a == "--work") work = argv[++i];
    else if (a == "--results") results = argv[++i];
    else if (a == "--benchmarks") benchmarks = argv[++i];
    else throw UsageError("report: unknown option " + a);
  }
  if (results.empty()) throw UsageError("report: missing --results DIR");
  const Report rep = load(work);
  fs::create_directories(results);
  write_tsv(rep, results / "results.tsv");
  std::printf("wrote %s\n", (results / "results.tsv").string().c_str());

  // The detailed report, beside its plots.
  std::ostringstream full;
  header(full, rep, "libmoa benchmark: full results");
  full << "Summary and plots: `BENCHMARKS.md` at the project root. Numbers per line: "
          "`results.tsv` beside this file.\n\n";
  targets_section(full, rep);
  all_results_section(full, rep);
  details_section(full, rep);
  stages_section(full, rep);
  speedup_section(full, rep);
  closing_sections(full, rep);
  write_file(results / "latest.md", full.str());

  if (benchmarks.empty()) return 0;
  // The summary at the top level; links relative to it.
  const std::string to_results =
      fs::relative(fs::absolute(results), fs::absolute(benchmarks).parent_path()).generic_string() + "/";
  std::ostringstream md;
  header(md, rep, "Benchmarks: libmoa against CGAL, Open3D and PCL");
  md << "All methods on the same inputs in the same run, every mesh checked by the same checker. "
        "Reproduce with `bench/run_bench.sh` (see `bench/README.md`); the detail tables (libmoa "
        "per stage, parallel speed-up, one-sided distances, memory after reading, the load during "
        "each run) are in [`"
     << to_results << "latest.md`](" << to_results << "latest.md), every number in [`" << to_results
     << "results.tsv`](" << to_results << "results.tsv).\n\n";
  md << "## Key figures: bunny00\n\n" << kMainHeader;
  for (const char *key : kKeyInputs)
    for (const Row &row : rep.rows)
      if (text(row.input, "name") == key) main_rows(md, rep, row);
  md << kMainNote;
  targets_section(md, rep);
  plots_section(md, results, to_results);
  pictures_section(md, rep, results, to_results);
  all_results_section(md, rep);
  closing_sections(md, rep);
  write_file(benchmarks, md.str());
  return 0;
}

}  // namespace moa::bench
