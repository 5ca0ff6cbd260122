// Contexts on threads: several contexts running at once on several threads, with progress
// callbacks, cancellation, worker threads inside runs, the per-thread error slot and a context
// handed from thread to thread. Each result must equal the same run done alone. The ordinary
// build runs it as a test; tests/robust/run_tsan.sh builds it with ThreadSanitizer, which
// turns any data race between the contexts (or inside one) into a failure.
#include <csetjmp>  // cmocka needs these before its header
#include <cstdarg>
#include <cstddef>
#include <cstdint>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include <tbb/global_control.h>

#include "moa/moa.h"

extern "C" {  // cmocka 1.1 does not declare its functions extern "C" itself
#include <cmocka.h>
}

namespace {

using Points = std::vector<double>;

Points ellipsoid(std::size_t n, double a, double b, double c, bool holed = false) {
  Points p;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = 1.0 - 2.0 * (double(i) + 0.5) / double(n), r = std::sqrt(1.0 - y * y);
    const double t = 2.39996322972865332 * double(i);
    const double x = r * std::cos(t), z = r * std::sin(t);
    if (holed && (y > 0.7 || (x > 0.6 && std::fabs(z) < 0.3))) continue;  // open borders
    p.insert(p.end(), {a * x, b * y, c * z});
  }
  return p;
}

// One context's work: its own points, parameters and (optionally) a report to cancel at.
struct Job {
  Points points;
  double neighbors = 20;
  double threads = 1;
  long cancel_at = -1;  // report number that cancels the first run; -1 never
  int runs = 2;

  // Results, written only by the thread that runs the job.
  std::vector<moa_status> statuses;
  std::vector<std::vector<std::uint32_t>> meshes;
  std::string error;
  long reports = 0;
  long foreign_reports = 0;  // reports on a thread other than the caller's
  std::thread::id runner;
};

int on_progress(moa_stage, double, void *user_data) {
  Job &job = *static_cast<Job *>(user_data);
  if (std::this_thread::get_id() != job.runner) ++job.foreign_reports;
  return job.reports++ == job.cancel_at ? 1 : 0;
}

// Runs a job on the calling thread; touches no cmocka state, so any thread may call it.
void run_job(Job &job) {
  job.runner = std::this_thread::get_id();
  moa_ctx *ctx = nullptr;
  if (moa_ctx_create(&ctx) != MOA_OK) {
    job.error = "moa_ctx_create failed";
    return;
  }
  moa_status s = moa_set_points(ctx, job.points.data(), job.points.size() / 3);
  if (s == MOA_OK) s = moa_set_param(ctx, "neighbors", job.neighbors);
  if (s == MOA_OK) s = moa_set_param(ctx, "threads", job.threads);
  if (s == MOA_OK) s = moa_set_progress_callback(ctx, on_progress, &job);
  if (s != MOA_OK) job.error = moa_last_error(ctx);
  for (int r = 0; r < job.runs && s == MOA_OK; ++r) {
    if (r == 1) job.cancel_at = -1;  // only the first run is cancelled
    const moa_status run = moa_run(ctx);
    job.statuses.push_back(run);
    moa_mesh mesh;
    if (run == MOA_OK && moa_get_mesh(ctx, &mesh) == MOA_OK)
      job.meshes.emplace_back(mesh.triangles, mesh.triangles + 3 * mesh.triangle_count);
    else
      job.meshes.emplace_back();
  }
  moa_ctx_destroy(ctx);
}

std::vector<std::uint32_t> reference_mesh(const Job &job) {
  Job alone = job;
  alone.cancel_at = -1;
  alone.runs = 1;
  alone.threads = 1;
  run_job(alone);
  assert_int_equal(alone.statuses.at(0), MOA_OK);
  return alone.meshes.at(0);
}

void run_concurrently(std::vector<Job> &jobs) {
  std::vector<std::thread> threads;
  for (Job &job : jobs) threads.emplace_back(run_job, std::ref(job));
  for (std::thread &t : threads) t.join();
}

// Four contexts on four threads, each run twice; then the same with the first run of each
// cancelled at a different report. Every mesh equals the one made alone.
void concurrent_contexts(void **) {
  std::vector<Job> jobs(4);
  jobs[0].points = ellipsoid(900, 1, 1, 1);
  jobs[1].points = ellipsoid(700, 2, 1, 0.5);
  jobs[1].neighbors = 12;
  jobs[2].points = ellipsoid(900, 1, 1, 1, true);  // the loop module has work
  jobs[3].points = ellipsoid(600, 1e6, 1e6, 1e6);
  jobs[3].neighbors = 30;
  std::vector<std::vector<std::uint32_t>> reference;
  for (const Job &job : jobs) reference.push_back(reference_mesh(job));

  for (int cancelling = 0; cancelling < 2; ++cancelling) {
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      jobs[j].statuses.clear();
      jobs[j].meshes.clear();
      jobs[j].reports = jobs[j].foreign_reports = 0;
      // Every run reports at least 7 times (0 and 1 for points and finish, 0 for the other
      // stages), so each of these cancels, each at another point of the run.
      static const long cancel_at[] = {1, 2, 4, 6};
      jobs[j].cancel_at = cancelling ? cancel_at[j] : -1;
      jobs[j].runs = 2;
    }
    run_concurrently(jobs);
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      const Job &job = jobs[j];
      if (!job.error.empty()) fail_msg("job %zu: %s", j, job.error.c_str());
      assert_int_equal(job.statuses.size(), 2);
      assert_int_equal(job.statuses[0], cancelling ? MOA_ERROR_CANCELLED : MOA_OK);
      assert_int_equal(job.statuses[1], MOA_OK);
      if (!cancelling) assert_true(job.meshes[0] == reference[j]);
      assert_true(job.meshes[1] == reference[j]);
      assert_true(job.reports > 0);
      assert_int_equal(job.foreign_reports, 0);
    }
  }
}

// Two contexts at once, each with worker threads of its own: the mesh does not depend on the
// thread count, and callbacks still come on the caller's thread.
void concurrent_contexts_with_workers(void **) {
  std::vector<Job> jobs(2);
  jobs[0].points = ellipsoid(1500, 1, 1, 1);
  jobs[1].points = ellipsoid(1200, 1, 2, 3, true);
  std::vector<std::vector<std::uint32_t>> reference;
  for (Job &job : jobs) {
    reference.push_back(reference_mesh(job));
    job.threads = 2;
  }
  jobs[1].cancel_at = 5;
  run_concurrently(jobs);
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    if (!jobs[j].error.empty()) fail_msg("job %zu: %s", j, jobs[j].error.c_str());
    assert_int_equal(jobs[j].statuses[0], j == 1 ? MOA_ERROR_CANCELLED : MOA_OK);
    assert_int_equal(jobs[j].statuses[1], MOA_OK);
    assert_true(jobs[j].meshes[1] == reference[j]);
    assert_int_equal(jobs[j].foreign_reports, 0);
  }
}

// Clouds large enough for Algorithm 1's parallel first pass, whose parts grow on the worker
// threads, two contexts at once: the same meshes as with one thread each.
void parallel_pass_with_workers(void **) {
  std::vector<Job> jobs(2);
  jobs[0].points = ellipsoid(9000, 1, 1, 1);
  jobs[1].points = ellipsoid(9000, 1, 2, 3);
  std::vector<std::vector<std::uint32_t>> reference;
  for (Job &job : jobs) {
    reference.push_back(reference_mesh(job));
    job.threads = 2;
    job.runs = 1;
  }
  run_concurrently(jobs);
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    if (!jobs[j].error.empty()) fail_msg("job %zu: %s", j, jobs[j].error.c_str());
    assert_int_equal(jobs[j].statuses[0], MOA_OK);
    assert_true(jobs[j].meshes[0] == reference[j]);
    assert_int_equal(jobs[j].foreign_reports, 0);
  }
}

// moa_last_error(NULL) is per thread: failures on other threads never show in a thread's slot.
void error_slot_per_thread(void **) {
  constexpr int kThreads = 6, kRounds = 200;
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([t, &wrong] {
      const std::string name = "no_such_parameter_" + std::to_string(t);
      for (int r = 0; r < kRounds; ++r) {
        if (moa_set_param(nullptr, name.c_str(), 1) != MOA_ERROR_INVALID_ARGUMENT) ++wrong;
        moa_ctx *ctx = nullptr;
        if (moa_ctx_create(&ctx) != MOA_OK) {
          ++wrong;
          continue;
        }
        if (moa_set_param(ctx, name.c_str(), 1) != MOA_ERROR_UNKNOWN_PARAM) ++wrong;
        if (std::strstr(moa_last_error(ctx), name.c_str()) == nullptr) ++wrong;
        if (moa_run(ctx) != MOA_ERROR_BAD_STATE) ++wrong;  // no points yet
        moa_ctx_destroy(ctx);
        if (moa_get_param(nullptr, "neighbors", nullptr) != MOA_ERROR_INVALID_ARGUMENT) ++wrong;
        if (moa_last_error(nullptr)[0] == '\0') ++wrong;
      }
    });
  for (std::thread &t : threads) t.join();
  assert_int_equal(wrong.load(), 0);
}

// A context used by one thread at a time, but not always the same one: made on this thread,
// run on a second, read on a third, destroyed here.
void context_handed_between_threads(void **) {
  const Points points = ellipsoid(500, 1, 1, 1);
  Job job;
  job.points = points;
  const std::vector<std::uint32_t> reference = reference_mesh(job);
  moa_ctx *ctx = nullptr;
  assert_int_equal(moa_ctx_create(&ctx), MOA_OK);
  assert_int_equal(moa_set_points(ctx, points.data(), points.size() / 3), MOA_OK);
  assert_int_equal(moa_set_param(ctx, "threads", 1), MOA_OK);
  moa_status run = MOA_ERROR_INTERNAL;
  std::thread([&] { run = moa_run(ctx); }).join();
  assert_int_equal(run, MOA_OK);
  std::vector<std::uint32_t> read;
  std::thread([&] {
    moa_mesh mesh;
    if (moa_get_mesh(ctx, &mesh) == MOA_OK)
      read.assign(mesh.triangles, mesh.triangles + 3 * mesh.triangle_count);
  }).join();
  assert_true(read == reference);
  moa_ctx_destroy(ctx);
}

}  // namespace

// "--only PATTERN" or "--skip PATTERN" picks tests by name: run_tsan.sh runs the tests with
// worker threads apart, under a suppression the others do not need.
int main(int argc, char **argv) {
  if (argc == 3 && std::strcmp(argv[1], "--only") == 0) cmocka_set_test_filter(argv[2]);
  if (argc == 3 && std::strcmp(argv[1], "--skip") == 0) cmocka_set_skip_filter(argv[2]);
  // A hold on TBB's workers, so that they can be waited for at the end.
  tbb::task_scheduler_handle workers{tbb::attach{}};
  const CMUnitTest tests[] = {
      cmocka_unit_test(concurrent_contexts),
      cmocka_unit_test(concurrent_contexts_with_workers),
      cmocka_unit_test(parallel_pass_with_workers),
      cmocka_unit_test(error_slot_per_thread),
      cmocka_unit_test(context_handed_between_threads),
  };
  const int failed = cmocka_run_group_tests(tests, nullptr, nullptr);
  // TBB leaves its workers running at exit, so ThreadSanitizer saw no order between a worker's
  // last writes and the static destructors that free the same memory (one CI run reported such
  // an exit-time free). Joined here, they end before those destructors run.
  if (!tbb::finalize(workers, std::nothrow))
    std::fputs("robust_threads: TBB's worker threads could not be joined\n", stderr);
  return failed;
}
