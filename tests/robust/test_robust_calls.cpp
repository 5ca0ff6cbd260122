// Calls in awkward orders and places: cancellation at every progress report, a callback that
// calls back in, one context's run inside another's callback, repeated runs, every parameter
// at the ends of its range, and a host that limits TBB's threads. Complements tests/abi, which
// checks each call on its own.
#include <algorithm>
#include <cmath>
#include <thread>

#include <tbb/global_control.h>

#include "robust/robust.hpp"

using robust::Points;

namespace {

// A shape with open borders and holes, so that every stage (the loop module included) has
// work to do and reports several times.
Points holed_sphere() {
  const Points all = robust::sphere(6000);
  Points p;
  for (std::size_t i = 0; i < all.size(); i += 3) {
    const double x = all[i], y = all[i + 1], z = all[i + 2];
    if (z > 0.8 || (x > 0.5 && std::fabs(y) < 0.3)) continue;  // a cap and a window removed
    p.insert(p.end(), {x, y, z});
  }
  return p;
}

struct Reports {
  long count = 0;       // reports seen
  long cancel_at = -1;  // report number at which to cancel; -1 never
  int stage_at_cancel = -1;
  int return_value = 1;  // what the callback returns to cancel
};

int count_reports(moa_stage stage, double, void *user_data) {
  auto *r = static_cast<Reports *>(user_data);
  const long n = r->count++;
  if (n != r->cancel_at) return 0;
  r->stage_at_cancel = int(stage);
  return r->return_value;
}

std::vector<std::uint32_t> triangles_of(const moa_ctx *ctx) {
  moa_mesh mesh;
  assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_OK);
  return {mesh.triangles, mesh.triangles + 3 * mesh.triangle_count};
}

// Cancelling at any report, not only a stage's first, gives MOA_ERROR_CANCELLED, no mesh and
// no statistics, and the next run gives the undisturbed mesh. With one thread and with all.
void cancel_at_every_report(void **) {
  const Points p = holed_sphere();
  for (double threads : {1.0, 0.0}) {
    moa_ctx *ctx = robust::new_ctx();
    assert_int_equal(moa_set_param(ctx, "threads", threads), MOA_OK);
    Reports reports;
    assert_int_equal(moa_set_progress_callback(ctx, count_reports, &reports), MOA_OK);
    EXPECT_RUN_OK(ctx, p);
    const std::vector<std::uint32_t> reference = triangles_of(ctx);
    const long total = reports.count;
    assert_true(total >= 2 * MOA_STAGE_COUNT);
    // Every report up to 200, then evenly spaced ones, always the last.
    std::vector<long> at;
    for (long k = 0; k < total; k += total <= 200 ? 1 : total / 200) at.push_back(k);
    if (at.back() != total - 1) at.push_back(total - 1);
    int stages_seen = 0;
    for (long k : at) {
      reports = Reports{};
      reports.cancel_at = k;
      reports.return_value = k % 3 == 0 ? 1 : k % 3 == 1 ? -1 : 42;  // any non-zero cancels
      const moa_status s = moa_run(ctx);
      if (s != MOA_ERROR_CANCELLED)
        fail_msg("cancelling at report %ld of %ld: %s '%s'", k, total, moa_status_string(s),
                 moa_last_error(ctx));
      assert_int_equal(reports.count, k + 1);  // no report after the one that cancelled
      stages_seen |= 1 << reports.stage_at_cancel;
      moa_mesh mesh;
      moa_stats st;
      assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_ERROR_BAD_STATE);
      assert_int_equal(moa_get_stats(ctx, &st, sizeof st), MOA_ERROR_BAD_STATE);
      if (k % 16 == 0 || k == total - 1) {  // re-running each time would be slow
        reports = Reports{};
        assert_int_equal(moa_run(ctx), MOA_OK);
        assert_true(triangles_of(ctx) == reference);
      }
    }
    assert_int_equal(stages_seen, (1 << MOA_STAGE_COUNT) - 1);
    moa_ctx_destroy(ctx);
  }
}

struct Ordered {
  int stage = -1;
  double fraction = 0;
  long count = 0, cancel_at = -1;
  bool backwards = false;
};

int check_order(moa_stage stage, double fraction, void *user_data) {
  auto *o = static_cast<Ordered *>(user_data);
  if (int(stage) < o->stage || (int(stage) == o->stage && fraction < o->fraction))
    o->backwards = true;
  o->stage = int(stage);
  o->fraction = fraction;
  return o->count++ == o->cancel_at;
}

// A cloud given twice (the copy in single precision) runs its first stages twice, the second
// time without the copies (near_duplicates.hpp): the reports still never go back, a cancel at
// any of them, in either pass, leaves the context usable, and the mesh is that of the cloud
// given once.
void cancel_in_a_cloud_given_twice(void **) {
  const Points once = holed_sphere();
  Points twice = once;
  for (double v : once) twice.push_back(double(float(v)));
  moa_ctx *ctx = robust::new_ctx();
  EXPECT_RUN_OK(ctx, once);
  const std::vector<std::uint32_t> reference = triangles_of(ctx);
  Ordered order;
  assert_int_equal(moa_set_progress_callback(ctx, check_order, &order), MOA_OK);
  EXPECT_RUN_OK(ctx, twice);
  assert_false(order.backwards);
  assert_true(triangles_of(ctx) == reference);
  moa_stats st;
  assert_int_equal(moa_get_stats(ctx, &st, sizeof st), MOA_OK);
  assert_int_equal(st.near_duplicate_points, once.size() / 3);
  const long total = order.count;
  for (long k = 0; k < total; k += std::max(1L, total / 40)) {
    order = Ordered{};
    order.cancel_at = k;
    EXPECT_FAILURE(ctx, moa_run(ctx), MOA_ERROR_CANCELLED, "moa_run", "cancel");
    assert_false(order.backwards);
  }
  order = Ordered{};
  assert_int_equal(moa_run(ctx), MOA_OK);
  assert_true(triangles_of(ctx) == reference);
  moa_ctx_destroy(ctx);
}

// A callback that keeps cancelling: every run is cancelled, none leaves a mesh behind.
void cancel_again_and_again(void **) {
  moa_ctx *ctx = robust::new_ctx();
  const Points p = robust::sphere(200);
  assert_int_equal(moa_set_points(ctx, p.data(), 200), MOA_OK);
  Reports reports;
  reports.cancel_at = 0;
  assert_int_equal(moa_set_progress_callback(ctx, count_reports, &reports), MOA_OK);
  for (int i = 0; i < 5; ++i) {
    reports.count = 0;
    EXPECT_FAILURE(ctx, moa_run(ctx), MOA_ERROR_CANCELLED, "moa_run", "cancel");
  }
  assert_int_equal(moa_set_progress_callback(ctx, nullptr, nullptr), MOA_OK);
  EXPECT_USABLE(ctx);
  moa_ctx_destroy(ctx);
}

// What a callback may try on its own context: destroying it and reading a mesh are refused,
// swapping the callback is allowed and takes effect on the next run.
struct Meddler {
  moa_ctx *ctx;
  int calls = 0, second_calls = 0, wrong = 0;
};

int second_callback(moa_stage, double, void *user_data) {
  ++static_cast<Meddler *>(user_data)->second_calls;
  return 0;
}

int meddle(moa_stage, double, void *user_data) {
  auto *m = static_cast<Meddler *>(user_data);
  moa_mesh mesh;
  moa_stats st;
  std::size_t total = 0;
  double value = 0;
  ++m->calls;
  moa_ctx_destroy(m->ctx);  // ignored while running
  if (moa_get_mesh(m->ctx, &mesh) != MOA_ERROR_BAD_STATE) ++m->wrong;
  if (moa_get_stats(m->ctx, &st, sizeof st) != MOA_ERROR_BAD_STATE) ++m->wrong;
  if (moa_copy_triangles(m->ctx, nullptr, 0, &total) != MOA_ERROR_BAD_STATE) ++m->wrong;
  if (moa_get_param(m->ctx, "neighbors", &value) != MOA_OK || value != 20) ++m->wrong;
  if (moa_set_points_float(m->ctx, nullptr, 0, 0) != MOA_ERROR_BAD_STATE) ++m->wrong;
  if (moa_last_error(m->ctx)[0] == '\0') ++m->wrong;
  if (moa_set_progress_callback(m->ctx, second_callback, m) != MOA_OK) ++m->wrong;
  return 0;
}

void callback_meddles(void **) {
  moa_ctx *ctx = robust::new_ctx();
  const Points p = robust::sphere(300);
  Meddler m{ctx};
  assert_int_equal(moa_set_points(ctx, p.data(), 300), MOA_OK);
  assert_int_equal(moa_set_progress_callback(ctx, meddle, &m), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);  // the context survived its own destruction
  assert_true(m.calls >= MOA_STAGE_COUNT);  // the swap waits for the next run
  assert_int_equal(m.second_calls, 0);
  assert_int_equal(m.wrong, 0);
  EXPECT_CONTRACT(ctx, p);
  m.calls = 0;
  assert_int_equal(moa_run(ctx), MOA_OK);
  assert_int_equal(m.calls, 0);
  assert_true(m.second_calls > 0);
  moa_ctx_destroy(ctx);
}

// Another context may run to completion inside a callback: contexts are independent.
struct Nested {
  const Points *points;
  int runs = 0;
  moa_status status = MOA_OK;
};

int run_other(moa_stage stage, double, void *user_data) {
  auto *n = static_cast<Nested *>(user_data);
  if (stage != MOA_STAGE_MESH || n->runs > 0) return 0;
  ++n->runs;
  moa_ctx *other = nullptr;
  n->status = moa_ctx_create(&other);
  if (n->status == MOA_OK) n->status = moa_set_param(other, "threads", 1);
  if (n->status == MOA_OK) n->status = moa_set_points(other, n->points->data(), n->points->size() / 3);
  if (n->status == MOA_OK) n->status = moa_run(other);
  moa_ctx_destroy(other);
  return 0;
}

void nested_contexts(void **) {
  const Points outer = robust::sphere(300), inner = robust::transformed(robust::sphere(250), 3, 1);
  moa_ctx *ctx = robust::new_ctx();
  Nested nested{&inner};
  assert_int_equal(moa_set_progress_callback(ctx, run_other, &nested), MOA_OK);
  EXPECT_RUN_OK(ctx, outer);
  assert_int_equal(nested.runs, 1);
  assert_int_equal(nested.status, MOA_OK);
  moa_ctx_destroy(ctx);
}

// Running twice, and after a failure, gives the mesh of a fresh context.
void repeated_runs(void **) {
  const Points p = robust::sphere(300);
  moa_ctx *fresh = robust::new_ctx(), *used = robust::new_ctx();
  EXPECT_RUN_OK(fresh, p);
  const std::vector<std::uint32_t> reference = triangles_of(fresh);
  const double nan_point[9] = {0, 0, 0, 1, 0, 0, NAN, 1, 0};
  assert_int_equal(moa_set_points(used, nan_point, 3), MOA_OK);
  EXPECT_FAILURE(used, moa_run(used), MOA_ERROR_INVALID_INPUT, "point 2 ");
  for (int i = 0; i < 3; ++i) {
    if (i > 0) assert_int_equal(moa_run(used), MOA_OK);  // same points, run again
    else EXPECT_RUN_OK(used, p);
    assert_true(triangles_of(used) == reference);
  }
  // moa_get_stats with room for nothing copies nothing.
  moa_stats st;
  std::memset(&st, 0xAB, sizeof st);
  assert_int_equal(moa_get_stats(used, &st, 0), MOA_OK);
  assert_int_equal(reinterpret_cast<unsigned char *>(&st)[0], 0xAB);
  moa_ctx_destroy(fresh);
  moa_ctx_destroy(used);
}

// Every parameter at each end of its range, alone and all together: a success that keeps
// C1-C5 (possibly an empty mesh when the thresholds reject everything), never a crash.
void parameter_extremes(void **) {
  const Points p = robust::sphere(300);
  const std::size_t count = moa_param_count();
  for (int end = 0; end < 2; ++end) {
    moa_ctx *all = robust::new_ctx();
    for (std::size_t i = 0; i < count; ++i) {
      moa_param_info info;
      assert_int_equal(moa_param_info_get(i, &info), MOA_OK);
      const double value = end == 0 ? info.min_value : info.max_value;
      moa_ctx *one = robust::new_ctx();
      assert_int_equal(moa_set_param(one, info.name, value), MOA_OK);
      assert_int_equal(moa_set_param(all, info.name, value), MOA_OK);
      EXPECT_RUN_OK(one, p);
      moa_ctx_destroy(one);
    }
    EXPECT_RUN_OK(all, p);
    moa_ctx_destroy(all);
  }
  // More neighbours asked for than there are points.
  moa_ctx *ctx = robust::new_ctx();
  assert_int_equal(moa_set_param(ctx, "neighbors", 64), MOA_OK);
  EXPECT_RUN_OK(ctx, robust::sphere(12));
  EXPECT_RUN_OK(ctx, Points({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  moa_ctx_destroy(ctx);
}

unsigned threads_used(const moa_ctx *ctx) {
  moa_stats st;
  assert_int_equal(moa_get_stats(ctx, &st, sizeof st), MOA_OK);
  return st.threads;
}

// A host that limits TBB (a game engine holding a tbb::global_control) keeps its limit: a run
// uses that many threads, whatever "threads" asks (every core, two, or more than there are),
// and makes the same mesh as on one thread. Without a limit, no more than the cores.
void host_limits_threads(void **) {
  const Points p = holed_sphere();
  moa_ctx *ctx = robust::new_ctx();
  assert_int_equal(moa_set_param(ctx, "threads", 1), MOA_OK);
  EXPECT_RUN_OK(ctx, p);
  const std::vector<std::uint32_t> reference = triangles_of(ctx);
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    for (double threads : {0.0, 2.0, 1024.0}) {
      assert_int_equal(moa_set_param(ctx, "threads", threads), MOA_OK);
      assert_int_equal(moa_run(ctx), MOA_OK);
      assert_int_equal(threads_used(ctx), 1);
      assert_true(triangles_of(ctx) == reference);
    }
  }
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  assert_int_equal(moa_set_param(ctx, "threads", 1024), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  assert_in_range(threads_used(ctx), 1, cores);
  assert_true(triangles_of(ctx) == reference);
  moa_ctx_destroy(ctx);
}

}  // namespace

int main() {
  const CMUnitTest tests[] = {
      cmocka_unit_test(cancel_at_every_report),
      cmocka_unit_test(cancel_again_and_again),
      cmocka_unit_test(cancel_in_a_cloud_given_twice),
      cmocka_unit_test(callback_meddles),
      cmocka_unit_test(nested_contexts),
      cmocka_unit_test(repeated_runs),
      cmocka_unit_test(parameter_extremes),
      cmocka_unit_test(host_limits_threads),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
