// The runs and the property judgments behind the core tests. Messages always carry the
// checker's full description, so a failing test tells the algorithm's author what broke.
#include "core_harness.hpp"

#include <cctype>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <fstream>
#include <sstream>

// cmocka last: its macros (fail, ...) clash with names in the standard headers.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {  // this cmocka's header has no C++ guard of its own
#include <cmocka.h>
}

namespace moa::test {

namespace {

std::string header(const Case &c) {
  std::ostringstream s;
  s << c.name << " (" << c.points.size() / 3 << " points, " << c.run.triangles.size() / 3
    << " triangles, " << c.run.seconds << " s)";
  return s.str();
}

// Non-empty when the first run threw; every property fails then.
std::string run_error(const Case &c) {
  return c.run.error.empty() ? "" : header(c) + ": moa::reconstruct threw: " + c.run.error;
}

std::string first_difference(const Run &a, const Run &b) {
  std::ostringstream s;
  s << a.triangles.size() / 3 << " vs " << b.triangles.size() / 3 << " triangles";
  const std::size_t n = std::min(a.triangles.size(), b.triangles.size());
  for (std::size_t i = 0; i < n; ++i)
    if (a.triangles[i] != b.triangles[i]) {
      const std::size_t f = i / 3;
      s << ", first difference at triangle " << f << ": (" << a.triangles[3 * f] << ' '
        << a.triangles[3 * f + 1] << ' ' << a.triangles[3 * f + 2] << ") vs (" << b.triangles[3 * f]
        << ' ' << b.triangles[3 * f + 1] << ' ' << b.triangles[3 * f + 2] << ')';
      break;
    }
  return s.str();
}

// With MOA_TEST_DUMP=<dir>, writes the input points and the result as <dir>/<name>.off, so a
// failing mesh can be looked at; nothing is written otherwise.
void dump_if_asked(const Case &c) {
  const char *dir = std::getenv("MOA_TEST_DUMP");
  if (!dir || !*dir) return;
  std::string file = c.name;
  for (char &ch : file)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  std::ofstream out(std::string(dir) + "/" + file + ".off");
  out.precision(17);
  out << "OFF\n" << c.points.size() / 3 << ' ' << c.run.triangles.size() / 3 << " 0\n";
  for (std::size_t i = 0; i < c.points.size(); i += 3)
    out << c.points[i] << ' ' << c.points[i + 1] << ' ' << c.points[i + 2] << '\n';
  for (std::size_t i = 0; i < c.run.triangles.size(); i += 3)
    out << "3 " << c.run.triangles[i] << ' ' << c.run.triangles[i + 1] << ' ' << c.run.triangles[i + 2] << '\n';
}

}  // namespace

Run run_reconstruct(const Points &points, unsigned threads, Params params) {
  Run run;
  params.threads = threads;
  const auto start = std::chrono::steady_clock::now();
  try {
    Points copy = points;  // the run reorders it and puts it back
    Result result = reconstruct(copy.data(), copy.size() / 3, params,
                                [](moa_stage, double) { return false; });
    if (copy != points) throw std::runtime_error("the points were not restored to their order");
    run.triangles = std::move(result.triangles);
    run.stats = result.stats;
  } catch (const std::exception &e) {
    run.error = e.what();
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

Case make_case(const std::string &name, Points points, std::size_t duplicates,
               const Params &params) {
  Case c;
  c.name = name;
  c.points = std::move(points);
  c.duplicates = duplicates;
  c.params = params;
  c.run = run_reconstruct(c.points, 2, c.params);
  if (c.run.error.empty()) c.report = check_contract(c.points, c.run.triangles);
  print_message("%s\n", header(c).c_str());
  dump_if_asked(c);
  return c;
}

std::string contract_failure(const Case &c) {
  if (!c.run.error.empty()) return run_error(c);
  if (c.run.triangles.size() % 3 != 0) return header(c) + ": triangle list length is not a multiple of 3";
  if (c.report.ok() && c.report.faces > 0) return "";
  return header(c) + (c.report.faces == 0 ? ": no triangles (an empty mesh meets C1-C5 only vacuously)\n"
                                               : ": contract violated\n") +
         c.report.describe();
}

std::string stats_failure(const Case &c) {
  if (!c.run.error.empty()) return run_error(c);
  const moa_stats &s = c.run.stats;
  const std::size_t n = c.points.size() / 3;
  std::ostringstream bad;
  auto expect = [&](bool ok, const char *what, std::size_t got, std::size_t want) {
    if (!ok) bad << "  " << what << ": " << got << ", expected " << want << '\n';
  };
  expect(s.triangles == c.run.triangles.size() / 3, "stats.triangles", s.triangles, c.run.triangles.size() / 3);
  expect(s.input_points == n, "stats.input_points", s.input_points, n);
  expect(s.duplicate_points == c.duplicates, "stats.duplicate_points", s.duplicate_points, c.duplicates);
  expect(s.unique_points + s.duplicate_points == s.input_points, "unique + duplicate points",
         s.unique_points + s.duplicate_points, s.input_points);
  expect(s.used_points + s.unused_points == s.unique_points, "used + unused points",
         s.used_points + s.unused_points, s.unique_points);
  expect(s.used_points == c.report.vertices_used, "stats.used_points (vs distinct indices in the result)",
         s.used_points, c.report.vertices_used);
  expect(s.boundary_edges == c.report.boundary_edges, "stats.boundary_edges (vs the checker)",
         s.boundary_edges, c.report.boundary_edges);
  expect(s.threads >= 1 && s.threads <= 2, "stats.threads with params.threads = 2", s.threads, 2);
  const std::string text = bad.str();
  return text.empty() ? "" : header(c) + ": stats inconsistent with the result\n" + text;
}

// One more run, with 1 thread, against the first (2 threads): the serial and the parallel paths
// of every stage must agree. A 2-thread run that varied from run to run would differ from the
// serial one as well, so a second 2-thread run is not made (it cost a quarter of the closed
// surface and noisy cloud tests' time under the sanitizers); tests/robust runs contexts twice
// and compares the meshes.
std::string determinism_failure(const Case &c) {
  if (!c.run.error.empty()) return run_error(c);
  const Run single = run_reconstruct(c.points, 1, c.params);
  if (!single.error.empty()) return header(c) + ": run with 1 thread threw: " + single.error;
  if (single.triangles != c.run.triangles)
    return header(c) + ": 2 threads and 1 thread differ: " + first_difference(c.run, single);
  return "";
}

std::string closed_failure(const Case &c, long genus, double min_used) {
  if (!c.run.error.empty()) return run_error(c);
  const ContractReport &r = c.report;
  const std::size_t unique = c.points.size() / 3 - c.duplicates;
  std::ostringstream bad;
  if (!r.closed()) bad << "  not closed: " << r.boundary_edges << " boundary edges in " << r.boundary_loops << " loops\n";
  if (r.components != 1) bad << "  " << r.components << " components, expected 1\n";
  if (r.genus_sum != genus || r.closed_components != 1)
    bad << "  genus sum " << r.genus_sum << " over " << r.closed_components << " closed components, expected genus " << genus << '\n';
  if (r.vertices_used > unique || double(r.vertices_used) < min_used * double(unique))
    bad << "  " << r.vertices_used << " of " << unique << " unique points used\n";
  const std::string what = min_used < 1.0 ? "nearly every point" : "every point";
  const std::string text = bad.str();
  return text.empty() ? "" : header(c) + ": not a closed genus-" + std::to_string(genus) + " surface using " + what + "\n" + text + r.describe();
}

std::string disk_failure(const Case &c) {
  if (!c.run.error.empty()) return run_error(c);
  const ContractReport &r = c.report;
  std::ostringstream bad;
  if (!r.disk())
    bad << "  components " << r.components << ", boundary loops " << r.boundary_loops << ", euler "
        << r.euler_characteristic << " (a disk has 1, 1, 1)\n";
  if (r.vertices_used != c.points.size() / 3) bad << "  " << r.vertices_used << " of " << c.points.size() / 3 << " points used\n";
  const std::string text = bad.str();
  return text.empty() ? "" : header(c) + ": not a single disk using every point\n" + text + r.describe();
}

}  // namespace moa::test
