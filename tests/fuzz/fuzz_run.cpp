// libFuzzer target for moa_run: the bytes become a small point set and a few choices, and the
// run must either succeed with a mesh that keeps C1-C5 (tests/support's checker) or fail with
// exactly the status the input calls for. Any other outcome aborts, which the fuzzer reports.
//
// Layout (missing bytes read as 0):
//   byte 0  mode: bits 0-1 coordinate grid (0: int8, 1: 16 levels, 2: 4 levels, 3: int16);
//           bits 2-3 placement (0: unit 0.1, 1: georeferenced offsets with unit 0.01,
//           2: unit 1e-150, 3: unit 1e100); bit 4 one special coordinate (NaN, inf, 1e300,
//           subnormal); bit 5 cancel at a report; bit 6 run twice; bit 7 float entry point
//   byte 1  parameter to set (beyond the table: none); byte 2 its value, min..max; "threads"
//           instead reruns a success with 2-4 worker threads, which must give the same mesh
//   byte 3  special value and axis; byte 4 report at which to cancel; byte 5 special's point
//   then    x y z per point, 1 or 2 bytes each, at most kMaxPoints points
// Coarse grids make exact duplicates, collinear and coplanar subsets common.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "moa/moa.h"
#include "support/contract_checker.hpp"
#include "support/exact_predicates.hpp"

namespace {

constexpr std::size_t kMaxPoints = 300;  // degenerate sets of a few hundred take ~0.1 s already

[[noreturn]] void violated(const char *what, const std::string &detail = {}) {
  std::fprintf(stderr, "fuzz_run: %s%s%s\n", what, detail.empty() ? "" : ": ", detail.c_str());
  std::fflush(stderr);
  std::abort();
}

struct Bytes {
  const std::uint8_t *data;
  std::size_t size, pos = 0;
  std::uint8_t next() { return pos < size ? data[pos++] : 0; }
  std::size_t left() const { return size - std::min(pos, size); }
};

struct Case {
  std::vector<double> xyz;    // what the library sees (floats widened when the float path is used)
  std::vector<float> floats;  // 4 floats per point when the float path is used (stride 16)
  int param = -1;
  double value = 0;
  int cancel_at = -1;
  bool twice = false;
  int workers = 0;  // > 0: rerun a success with this many threads
};

double parameter_value(const moa_param_info &info, std::uint8_t byte) {
  const double t = byte / 255.0;
  double v = info.min_value + (info.max_value - info.min_value) * t;
  if (info.max_value - info.min_value > 1000)  // wide ranges: spread over the decades
    v = byte == 255 ? info.max_value : info.min_value + std::pow(10.0, 12.0 * t - 3.0);
  v = std::clamp(v, info.min_value, info.max_value);
  return info.is_integral ? std::round(v) : v;
}

Case decode(const std::uint8_t *data, std::size_t size) {
  Bytes in{data, size};
  const std::uint8_t mode = in.next(), pick = in.next(), value = in.next(), special = in.next(),
                     cancel = in.next(), special_point = in.next();
  Case c;
  const std::size_t params = moa_param_count();
  if (pick < params) {
    moa_param_info info;
    if (moa_param_info_get(pick, &info) != MOA_OK) violated("moa_param_info_get");
    if (std::strcmp(info.name, "threads") == 0) {
      c.workers = 2 + value % 3;
    } else {
      c.param = pick;
      c.value = parameter_value(info, value);
    }
  }
  if (mode & 0x20) c.cancel_at = cancel;
  c.twice = (mode & 0x40) != 0;

  const int grid = mode & 3, placement = (mode >> 2) & 3;
  const std::size_t width = grid == 3 ? 2 : 1;
  const std::size_t n = std::min(in.left() / (3 * width), kMaxPoints);
  static const double units[] = {0.1, 0.01, 1e-150, 1e100};
  static const double offsets[] = {512345.0, 4123456.0, 312.0};
  for (std::size_t i = 0; i < 3 * n; ++i) {
    int q;
    if (grid == 3) {
      const std::uint8_t lo = in.next(), hi = in.next();
      q = static_cast<std::int16_t>(static_cast<std::uint16_t>(lo | hi << 8));
    } else {
      const std::uint8_t b = in.next();
      q = grid == 0 ? static_cast<std::int8_t>(b) : grid == 1 ? (b & 15) - 8 : (b & 3) - 1;
    }
    c.xyz.push_back(q * units[placement] + (placement == 1 ? offsets[i % 3] : 0.0));
  }
  if ((mode & 0x10) && n > 0) {
    static const double values[] = {std::numeric_limits<double>::quiet_NaN(),
                                    std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(), 1e300, 5e-324};
    c.xyz[3 * (special_point % n) + (special / 5) % 3] = values[special % 5];
  }
  if (mode & 0x80) {  // interleaved floats, stride 16; the fourth float is noise
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) c.floats.push_back(static_cast<float>(c.xyz[3 * i + k]));
      c.floats.push_back(std::numeric_limits<float>::quiet_NaN());
    }
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) c.xyz[3 * i + k] = c.floats[4 * i + k];
  }
  return c;
}

// What moa_run must answer, found without the library: the status and a word of its message.
struct Expected {
  moa_status status = MOA_OK;
  const char *word = nullptr;
  std::vector<bool> duplicate;  // a point equal to an earlier one (0 and -0 equal)
  std::size_t duplicates = 0;
};

Expected expect(const std::vector<double> &xyz) {
  Expected e;
  const auto reject = [&e](const char *word) {
    e.status = MOA_ERROR_INVALID_INPUT;
    e.word = word;
    return e;
  };
  const std::size_t n = xyz.size() / 3;
  if (n < 3) return reject("at least 3 points");
  for (double v : xyz)
    if (!std::isfinite(v) || std::fabs(v) > 1e150) return reject("point");
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
  auto less = [&](std::uint32_t a, std::uint32_t b) {
    return std::lexicographical_compare(&xyz[3 * a], &xyz[3 * a + 3], &xyz[3 * b], &xyz[3 * b + 3]);
  };
  std::stable_sort(order.begin(), order.end(), less);  // equal points keep index order
  e.duplicate.assign(n, false);
  std::vector<moa::test::Vec3> distinct;
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t i = order[k];
    if (k > 0 && !less(order[k - 1], i)) {
      e.duplicate[i] = true;
      ++e.duplicates;
    } else {
      distinct.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
    }
  }
  if (distinct.size() < 3) return reject("distinct");
  double extent = 0;
  for (int axis = 0; axis < 3; ++axis) {
    double lo = distinct[0][axis], hi = lo;
    for (const auto &p : distinct) lo = std::min(lo, p[axis]), hi = std::max(hi, p[axis]);
    extent = std::max(extent, hi - lo);
  }
  if (!(extent > 1e-280)) return reject("rescale");
  bool collinear = true;
  for (std::size_t k = 2; k < distinct.size() && collinear; ++k)
    collinear = moa::test::collinear3d(distinct[0], distinct[1], distinct[k]);
  if (collinear) return reject("collinear");
  return e;
}

struct Progress {
  long reports = 0;
  long cancel_at = -1;
  int last_stage = 0;
};

int on_progress(moa_stage stage, double fraction, void *user_data) {
  auto *p = static_cast<Progress *>(user_data);
  if (stage < 0 || stage >= MOA_STAGE_COUNT) violated("a report of an unknown stage");
  if (!(fraction >= 0 && fraction <= 1)) violated("a report's fraction outside [0, 1]");
  if (int(stage) < p->last_stage) violated("a report of an earlier stage than the last one");
  p->last_stage = int(stage);
  return p->reports++ == p->cancel_at ? 1 : 0;
}

std::string message_of(const moa_ctx *ctx, moa_status s) {
  return std::string(moa_status_string(s)) + " '" + moa_last_error(ctx) + "'";
}

void set_points(moa_ctx *ctx, const Case &c) {
  const std::size_t n = c.xyz.size() / 3;
  const moa_status s = c.floats.empty()
                           ? moa_set_points(ctx, c.xyz.empty() ? nullptr : c.xyz.data(), n)
                           : moa_set_points_float(ctx, c.floats.data(), n, 4 * sizeof(float));
  if (s != MOA_OK) violated("moa_set_points", message_of(ctx, s));
}

std::vector<std::uint32_t> check_success(const moa_ctx *ctx, const Case &c, const Expected &e) {
  const std::size_t n = c.xyz.size() / 3;
  moa_mesh mesh;
  if (moa_get_mesh(ctx, &mesh) != MOA_OK) violated("no mesh after MOA_OK");
  if (mesh.vertex_count != n) violated("the mesh's vertex count is not the point count");
  if (n > 0 && std::memcmp(mesh.vertices, c.xyz.data(), 3 * n * sizeof(double)) != 0)
    violated("the mesh's vertices are not the caller's points");
  const moa::test::ContractReport report =
      moa::test::check_contract(c.xyz.data(), n, mesh.triangles, mesh.triangle_count);
  if (!report.ok()) violated("C1-C5 broken", report.describe());
  for (std::size_t k = 0; k < 3 * mesh.triangle_count; ++k)
    if (e.duplicate[mesh.triangles[k]]) violated("a merged duplicate is a vertex of the mesh");
  moa_stats st;
  if (moa_get_stats(ctx, &st, sizeof st) != MOA_OK) violated("no statistics after MOA_OK");
  // Near duplicates (merged only when a cloud is full of them) come on top of the exact ones.
  if (st.input_points != n || st.duplicate_points != e.duplicates + st.near_duplicate_points ||
      st.unique_points + st.duplicate_points != n ||
      st.used_points + st.unused_points != st.unique_points ||
      st.triangles != mesh.triangle_count || st.used_points != report.vertices_used)
    violated("statistics that do not add up");
  return {mesh.triangles, mesh.triangles + 3 * mesh.triangle_count};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const Case c = decode(data, size);
  const Expected e = expect(c.xyz);
  moa_ctx *ctx = nullptr;
  if (moa_ctx_create(&ctx) != MOA_OK) violated("moa_ctx_create");
  if (moa_set_param(ctx, "threads", 1) != MOA_OK) violated("threads");  // workers only on request
  if (c.param >= 0) {
    moa_param_info info;
    moa_param_info_get(static_cast<std::size_t>(c.param), &info);
    const moa_status s = moa_set_param(ctx, info.name, c.value);
    if (s != MOA_OK) violated("an in-range parameter refused", info.name + message_of(ctx, s));
  }
  Progress progress;
  progress.cancel_at = c.cancel_at;
  moa_set_progress_callback(ctx, on_progress, &progress);
  set_points(ctx, c);

  moa_status s = moa_run(ctx);
  if (s == MOA_ERROR_CANCELLED) {
    if (c.cancel_at < 0 || progress.reports != c.cancel_at + 1)
      violated("cancelled without being asked", message_of(ctx, s));
    moa_mesh mesh;
    if (moa_get_mesh(ctx, &mesh) != MOA_ERROR_BAD_STATE) violated("a mesh after a cancelled run");
    if (moa_last_error(ctx)[0] == '\0') violated("a cancelled run without a message");
    progress = Progress{};
    s = moa_run(ctx);  // the same context, no longer cancelled
  } else if (c.cancel_at >= 0 && progress.reports > c.cancel_at) {
    violated("a run went on after its callback cancelled", message_of(ctx, s));
  }

  static const bool verbose = std::getenv("MOA_FUZZ_VERBOSE") != nullptr;
  if (verbose)
    std::fprintf(stderr, "  %zu points: %s\n", c.xyz.size() / 3, message_of(ctx, s).c_str());
  if (s != e.status)
    violated("unexpected status",
             message_of(ctx, s) + ", expected " + moa_status_string(e.status));
  if (s != MOA_OK) {
    if (std::strstr(moa_last_error(ctx), e.word) == nullptr)
      violated("the message does not name the problem", message_of(ctx, s) + ", lacks " + e.word);
    moa_mesh mesh;
    if (moa_get_mesh(ctx, &mesh) != MOA_ERROR_BAD_STATE) violated("a mesh after a failed run");
  } else {
    const std::vector<std::uint32_t> first = check_success(ctx, c, e);
    if (c.twice) {
      progress = Progress{};
      s = moa_run(ctx);
      if (s != MOA_OK) violated("the second run failed", message_of(ctx, s));
      if (check_success(ctx, c, e) != first) violated("the second run gave another mesh");
    }
    if (c.workers > 0) {  // the mesh does not depend on the thread count
      if (moa_set_param(ctx, "threads", c.workers) != MOA_OK) violated("threads");
      progress = Progress{};
      s = moa_run(ctx);
      if (s != MOA_OK) violated("the run with worker threads failed", message_of(ctx, s));
      if (check_success(ctx, c, e) != first) violated("worker threads gave another mesh");
    }
  }
  moa_ctx_destroy(ctx);
  return 0;
}
