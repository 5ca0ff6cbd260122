// `moa reconstruct`: points in, mesh out, through the public C ABI only (the tool is the first
// user of libmoa's interface).
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli.hpp"
#include "io/io.hpp"
#include "moa/moa.h"
#include "quality/json_writer.hpp"

namespace moa::cli {

const char *const kReconstructHelp =
    "Usage: moa reconstruct INPUT -o OUTPUT [options]\n"
    "\n"
    "Reconstructs a triangle mesh from the points of INPUT (.xyz .txt .pts .csv .ply .off\n"
    ".obj) and writes it to OUTPUT (.ply .off .obj .stl). The mesh's vertices are all the\n"
    "input points, in input order.\n"
    "\n"
    "Options:\n"
    "  -o, --output FILE        the mesh to write (required)\n"
    "  -p, --param NAME=VALUE   set a parameter; repeatable (see moa params)\n"
    "      --stats FILE.json    write the run's statistics and timings as one JSON object\n"
    "      --render IMAGE.png   also draw the mesh into a PNG picture (iso view, 1024x1024,\n"
    "                           boundary edges in red; see moa render for more views)\n"
    "      --ascii              write ASCII PLY instead of binary\n"
    "  -q, --quiet              no progress bar and no summary\n"
    "  -h, --help               this text\n"
    "\n"
    "A progress bar is drawn on stderr when it is a terminal. Ctrl-C cancels the run.\n";

namespace {

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_interrupt(int) { g_interrupted = 1; }

struct ReconstructArgs {
  std::string input, output, stats, render;
  std::vector<std::pair<std::string, std::string>> params;  // as given: name, value text
  bool ascii = false;
  bool quiet = false;
  bool help = false;
};

struct CtxDeleter {
  void operator()(moa_ctx *ctx) const { moa_ctx_destroy(ctx); }
};
using CtxPtr = std::unique_ptr<moa_ctx, CtxDeleter>;

// The library's message without the "moa_function: " prefix it carries.
std::string library_error(const moa_ctx *ctx) {
  std::string m = moa_last_error(ctx);
  const size_t colon = m.find(": ");
  if (m.compare(0, 4, "moa_") == 0 && colon != std::string::npos) m.erase(0, colon + 2);
  return m;
}

bool find_param(const std::string &name, moa_param_info &info) {
  for (size_t i = 0; i < moa_param_count(); ++i)
    if (moa_param_info_get(i, &info) == MOA_OK && name == info.name) return true;
  return false;
}

ReconstructArgs parse_reconstruct_args(int argc, char **argv) {
  ReconstructArgs o;
  ArgWalker args(argc, argv, "reconstruct");
  while (args.next()) {
    if (args.positional()) {
      if (!o.input.empty()) args.unknown();
      o.input = args.arg();
    } else if (args.is("-h", "--help")) {
      o.help = true;
      return o;
    } else if (args.is("-o", "--output")) {
      o.output = args.value();
    } else if (args.is("-p", "--param")) {
      const std::string spec = args.value();
      const size_t eq = spec.find('=');
      if (eq == std::string::npos || eq == 0)
        throw CliError(kExitUsage, "--param '" + spec + "': expected NAME=VALUE");
      o.params.emplace_back(spec.substr(0, eq), spec.substr(eq + 1));
    } else if (args.is(nullptr, "--stats")) {
      o.stats = args.value();
    } else if (args.is(nullptr, "--render")) {
      o.render = args.value();
    } else if (args.is(nullptr, "--ascii")) {
      o.ascii = true;
    } else if (args.is("-q", "--quiet")) {
      o.quiet = true;
    } else {
      args.unknown();
    }
  }
  if (o.input.empty()) throw CliError(kExitUsage, "missing INPUT (see moa reconstruct --help)");
  if (o.output.empty()) throw CliError(kExitUsage, "missing -o OUTPUT");
  return o;
}

void set_params(moa_ctx *ctx, const ReconstructArgs &o) {
  for (const auto &[name, text] : o.params) {
    moa_param_info info;
    if (!find_param(name, info))
      throw CliError(kExitUsage, "unknown parameter '" + name + "' (see moa params)");
    char *end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0')
      throw CliError(kExitUsage, "parameter '" + name + "': '" + text + "' is not a number");
    if (moa_set_param(ctx, name.c_str(), value) != MOA_OK) {
      char range[96];
      std::snprintf(range, sizeof range, "%s in [%g, %g]",
                    info.is_integral ? "a whole number" : "a number", info.min_value, info.max_value);
      throw CliError(kExitUsage, "parameter '" + name + "' must be " + range + ", got '" + text + "'");
    }
  }
}

// Progress on stderr when it is a terminal; also where Ctrl-C turns into a cancel.
struct Progress {
  bool draw = false;
  int stage = -1;
  int percent = -1;
};

extern "C" int on_progress(moa_stage stage, double fraction, void *user) {
  Progress &p = *static_cast<Progress *>(user);
  if (g_interrupted) return 1;
  if (!p.draw) return 0;
  const int percent = fraction <= 0 ? 0 : fraction >= 1 ? 100 : int(fraction * 100);
  if (int(stage) == p.stage && percent == p.percent) return 0;
  p.stage = int(stage);
  p.percent = percent;
  constexpr int kWidth = 30;
  char bar[kWidth + 1];
  const int filled = percent * kWidth / 100;
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kWidth] = '\0';
  std::fprintf(stderr, "\r%d/%d %-10s [%s] %3d%%", int(stage) + 1, int(MOA_STAGE_COUNT),
               moa_stage_name(stage), bar, percent);
  std::fflush(stderr);
  return 0;
}

void write_stats(const ReconstructArgs &o, const moa_ctx *ctx, const moa_stats &s, size_t points,
                 double read_ms, double run_ms, double write_ms) {
  JsonWriter j;
  j.begin_object();
  j.value("moa_version", moa_version());
  j.value("input", o.input).value("output", o.output);
  j.value("points", points).value("triangles", s.triangles);
  j.value("reconstruct_ms", run_ms).value("read_ms", read_ms).value("write_ms", write_ms);
  j.begin_object("stage_ms");
  for (int i = 0; i < MOA_STAGE_COUNT; ++i) j.value(moa_stage_name(moa_stage(i)), s.stage_ms[i]);
  j.end_object();
  j.value("total_ms", s.total_ms).value("intersection_ms", s.intersection_ms);
  j.value("threads", s.threads);
  j.value("input_points", s.input_points).value("unique_points", s.unique_points);
  j.value("duplicate_points", s.duplicate_points)
      .value("near_duplicate_points", s.near_duplicate_points)
      .value("used_points", s.used_points);
  j.value("unused_points", s.unused_points);
  j.value("triangles_mesh", s.triangles_mesh).value("triangles_loops", s.triangles_loops);
  j.value("triangles_removed", s.triangles_removed).value("edges_flipped", s.edges_flipped);
  j.value("boundary_edges", s.boundary_edges);
  j.value("boundary_edges_before", s.boundary_edges_before);
  j.value("smoothing_passes", s.smoothing_passes);
  j.value("boundary_loops_before", s.boundary_loops_before);
  j.value("boundary_loops_after", s.boundary_loops_after);
  j.value("candidates_tested", s.candidates_tested);
  j.value("rejected_degenerate", s.rejected_degenerate);
  j.value("rejected_manifold", s.rejected_manifold);
  j.value("rejected_orientation", s.rejected_orientation);
  j.value("rejected_flatness", s.rejected_flatness);
  j.value("rejected_edge_fold", s.rejected_edge_fold);
  j.value("rejected_vertex_fold", s.rejected_vertex_fold);
  j.value("rejected_intersection", s.rejected_intersection);
  j.value("embree_rebuilds", s.embree_rebuilds);
  j.begin_object("params");
  for (size_t i = 0; i < moa_param_count(); ++i) {
    moa_param_info info;
    double value;
    if (moa_param_info_get(i, &info) == MOA_OK && moa_get_param(ctx, info.name, &value) == MOA_OK)
      j.value(info.name, value);
  }
  j.end_object();
  j.end_object();

  std::FILE *f = std::fopen(o.stats.c_str(), "w");
  if (!f) throw CliError(kExitOutput, o.stats + ": cannot write: " + std::strerror(errno));
  const std::string &text = j.str();
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok)
    throw CliError(kExitOutput, o.stats + ": cannot write: " + std::strerror(errno));
}

// "1 triangle", "2 triangles".
std::string counted(size_t n, const char *one, const char *many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

void print_summary(const ReconstructArgs &o, const moa_stats &s, size_t points, double run_ms) {
  std::printf("%s: %s -> %s, %s (%s), %zu of %zu points used; reconstruction %.1f ms (",
              o.input.c_str(), counted(points, "point", "points").c_str(),
              counted(s.triangles, "triangle", "triangles").c_str(),
              counted(s.boundary_edges, "boundary edge", "boundary edges").c_str(),
              counted(s.boundary_loops_after, "open loop", "open loops").c_str(), s.used_points,
              s.unique_points, run_ms);
  for (int i = 0; i < MOA_STAGE_COUNT; ++i)
    std::printf("%s%s %.1f", i ? ", " : "", moa_stage_name(moa_stage(i)), s.stage_ms[i]);
  std::printf(" ms) on %u thread%s; wrote %s.\n", s.threads, s.threads == 1 ? "" : "s",
              o.output.c_str());
}

}  // namespace

int run_reconstruct(int argc, char **argv) {
  const ReconstructArgs o = parse_reconstruct_args(argc, argv);
  if (o.help) {
    std::fputs(kReconstructHelp, stdout);
    return kExitOk;
  }

  // Settle everything the command line decides before the long parts.
  try {
    if (io::format_from_path(o.output) == io::Format::Xyz)
      throw CliError(kExitOutput, o.output + ": an XYZ file holds points, not a mesh (use .ply "
                                             ".off .obj or .stl)");
  } catch (const io::IoError &e) {
    throw CliError(kExitOutput, about_file(o.output, e.what()));
  }
  check_writable(o.output);
  if (!o.stats.empty()) check_writable(o.stats);
  if (!o.render.empty()) check_png_path(o.render);
  moa_ctx *raw = nullptr;
  if (moa_ctx_create(&raw) != MOA_OK)
    throw CliError(kExitInternal, "cannot create a context: " + library_error(nullptr));
  CtxPtr ctx(raw);
  set_params(ctx.get(), o);

  auto start = Clock::now();
  std::vector<double> points;
  try {
    points = io::read_points(o.input);
  } catch (const io::IoError &e) {
    throw CliError(kExitInput, about_file(o.input, e.what()));
  }
  const double read_ms = ms_since(start);
  const size_t count = points.size() / 3;
  if (moa_set_points(ctx.get(), points.data(), count) != MOA_OK)
    throw CliError(kExitInput, o.input + ": " + library_error(ctx.get()));

  Progress progress;
  progress.draw = !o.quiet && isatty(STDERR_FILENO);
  moa_set_progress_callback(ctx.get(), on_progress, &progress);
  void (*previous)(int) = std::signal(SIGINT, on_interrupt);
  start = Clock::now();
  const moa_status status = moa_run(ctx.get());
  const double run_ms = ms_since(start);
  std::signal(SIGINT, previous);
  if (progress.draw) std::fputs("\r\033[K", stderr);
  if (status != MOA_OK) {
    const std::string why = library_error(ctx.get());
    if (status == MOA_ERROR_INVALID_INPUT) throw CliError(kExitInput, o.input + ": " + why);
    if (status == MOA_ERROR_CANCELLED) throw CliError(kExitReconstruct, "interrupted");
    throw CliError(kExitReconstruct, o.input + ": reconstruction failed: " + why);
  }

  moa_mesh mesh;
  moa_stats stats;
  if (moa_get_mesh(ctx.get(), &mesh) != MOA_OK ||
      moa_get_stats(ctx.get(), &stats, sizeof stats) != MOA_OK)
    throw CliError(kExitReconstruct, "cannot read the result: " + library_error(ctx.get()));

  start = Clock::now();
  io::MeshData out;
  out.xyz.assign(mesh.vertices, mesh.vertices + 3 * mesh.vertex_count);
  out.triangles.assign(mesh.triangles, mesh.triangles + 3 * mesh.triangle_count);
  std::vector<double>().swap(points);
  try {
    io::write_mesh(o.output, out, o.ascii);
  } catch (const io::IoError &e) {
    throw CliError(kExitOutput, about_file(o.output, e.what()));
  }
  const double write_ms = ms_since(start);

  if (!o.stats.empty()) write_stats(o, ctx.get(), stats, count, read_ms, run_ms, write_ms);
  if (!o.quiet) print_summary(o, stats, count, run_ms);
  if (!o.render.empty()) {
    const double render_ms = render_result(o.render, out);
    if (!o.quiet) std::printf("rendered %s in %.1f ms.\n", o.render.c_str(), render_ms);
  }
  return kExitOk;
}

}  // namespace moa::cli
