/* moa_run through the C ABI: the mesh, its copies, the statistics, float input, progress and
 * cancellation, and failures that leave the context usable. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <pthread.h>
#include <cmocka.h>

#include "abi/abi_fixtures.h"

static int setup_sphere(void **state) {
  *state = abi_sphere_ctx();
  return 0;
}

static int teardown_ctx(void **state) {
  moa_ctx_destroy((moa_ctx *)*state);
  return 0;
}

static void test_run_sphere(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  double *xyz = abi_sphere(ABI_SPHERE_POINTS);
  moa_mesh mesh;
  assert_int_equal(moa_run(ctx), MOA_OK);
  mesh = abi_check_mesh(ctx, ABI_SPHERE_POINTS);
  /* The vertices are the caller's points, in the caller's order. */
  assert_memory_equal(mesh.vertices, xyz, 3 * ABI_SPHERE_POINTS * sizeof(double));
  free(xyz);
}

/* Same points and parameters, same faces in the same order. */
static void test_run_twice_same_mesh(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  size_t n1 = 0, n2 = 0;
  uint32_t *first, *second;
  assert_int_equal(moa_run(ctx), MOA_OK);
  first = abi_copy_mesh(ctx, &n1);
  assert_int_equal(moa_set_param(ctx, "threads", 1), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  second = abi_copy_mesh(ctx, &n2);
  assert_int_equal(n1, n2);
  assert_memory_equal(first, second, 3 * n1 * sizeof(uint32_t));
  free(first);
  free(second);
}

static void test_copy_triangles(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  moa_mesh mesh;
  size_t total = 0, i;
  uint32_t *buffer;
  assert_int_equal(moa_run(ctx), MOA_OK);
  mesh = abi_check_mesh(ctx, ABI_SPHERE_POINTS);
  /* Size query. */
  assert_int_equal(moa_copy_triangles(ctx, NULL, 0, &total), MOA_OK);
  assert_int_equal(total, 3 * mesh.triangle_count);
  /* Short buffer: a prefix, and nothing written past capacity. */
  buffer = (uint32_t *)malloc((total + 1) * sizeof(uint32_t));
  assert_non_null(buffer);
  for (i = 0; i <= total; ++i) buffer[i] = 0xDEADBEEFu;
  total = 0;
  assert_int_equal(moa_copy_triangles(ctx, buffer, 5, &total), MOA_OK);
  assert_int_equal(total, 3 * mesh.triangle_count);
  assert_memory_equal(buffer, mesh.triangles, 5 * sizeof(uint32_t));
  assert_int_equal(buffer[5], 0xDEADBEEFu);
  /* Larger buffer than needed: everything, and nothing past it. */
  assert_int_equal(moa_copy_triangles(ctx, buffer, total + 1, &total), MOA_OK);
  assert_memory_equal(buffer, mesh.triangles, total * sizeof(uint32_t));
  assert_int_equal(buffer[total], 0xDEADBEEFu);
  free(buffer);
}

static void test_stats(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  moa_stats stats;
  moa_mesh mesh;
  int i;
  assert_int_equal(moa_run(ctx), MOA_OK);
  mesh = abi_check_mesh(ctx, ABI_SPHERE_POINTS);
  memset(&stats, 0, sizeof stats);
  assert_int_equal(moa_get_stats(ctx, &stats, sizeof stats), MOA_OK);
  assert_int_equal(stats.triangles, mesh.triangle_count);
  assert_int_equal(stats.input_points, ABI_SPHERE_POINTS);
  assert_int_equal(stats.unique_points + stats.duplicate_points, stats.input_points);
  assert_int_equal(stats.used_points + stats.unused_points, stats.unique_points);
  assert_true(stats.used_points >= 3);
  assert_true(stats.total_ms > 0);
  for (i = 0; i < MOA_STAGE_COUNT; ++i) assert_true(stats.stage_ms[i] >= 0);
}

/* The edge flips through the parameter: on a random flat patch some edges are flipped by
 * default, none with edge_flips 0, and the triangle count is the same either way (a flip
 * trades one diagonal of a quad for the other). */
static void test_edge_flips_param(void **state) {
  moa_ctx *ctx = NULL;
  moa_stats with, without;
  double *xyz = (double *)malloc(3 * 2000 * sizeof(double)), value = -1;
  uint64_t seed = 12345;
  size_t i;
  (void)state;
  assert_non_null(xyz);
  for (i = 0; i < 3 * 2000; ++i) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    xyz[i] = i % 3 == 2 ? 0.0 : (double)(seed >> 11) / 9007199254740992.0;
  }
  assert_int_equal(moa_ctx_create(&ctx), MOA_OK);
  assert_int_equal(moa_set_points(ctx, xyz, 2000), MOA_OK);
  assert_int_equal(moa_get_param(ctx, "edge_flips", &value), MOA_OK);
  assert_true(value == 1.0);
  assert_int_equal(moa_run(ctx), MOA_OK);
  assert_int_equal(moa_get_stats(ctx, &with, sizeof with), MOA_OK);
  assert_int_equal(moa_set_param(ctx, "edge_flips", 0), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  assert_int_equal(moa_get_stats(ctx, &without, sizeof without), MOA_OK);
  assert_true(with.edges_flipped > 0);
  assert_int_equal(without.edges_flipped, 0);
  assert_int_equal(with.triangles, without.triangles);
  assert_int_equal(moa_set_param(ctx, "edge_flips", 2), MOA_ERROR_INVALID_ARGUMENT);
  moa_ctx_destroy(ctx);
  free(xyz);
}

/* An older caller's shorter struct and a newer caller's longer one: only the overlap is written. */
static void test_stats_size(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  moa_stats full;
  unsigned char buffer[sizeof(moa_stats) + 32];
  const size_t old_size = offsetof(moa_stats, triangles_mesh);
  size_t i;
  assert_int_equal(moa_run(ctx), MOA_OK);
  assert_int_equal(moa_get_stats(ctx, &full, sizeof full), MOA_OK);

  memset(buffer, 0xAB, sizeof buffer);
  assert_int_equal(moa_get_stats(ctx, (moa_stats *)(void *)buffer, old_size), MOA_OK);
  assert_memory_equal(buffer, &full, old_size);
  for (i = old_size; i < sizeof buffer; ++i) assert_int_equal(buffer[i], 0xAB);

  memset(buffer, 0xAB, sizeof buffer);
  assert_int_equal(moa_get_stats(ctx, (moa_stats *)(void *)buffer, sizeof buffer), MOA_OK);
  assert_memory_equal(buffer, &full, sizeof full);
  for (i = sizeof full; i < sizeof buffer; ++i) assert_int_equal(buffer[i], 0xAB);
}

/* Interleaved single-precision vertices (position, normal, uv) give the same mesh as the same
 * values passed as doubles. */
static void test_float_stride(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  enum { kFloats = 8 };
  const size_t n = ABI_SPHERE_POINTS;
  double *xyz = abi_sphere(n);
  float *interleaved = (float *)malloc(n * kFloats * sizeof(float));
  size_t i, n_double = 0, n_float = 0;
  uint32_t *from_double, *from_float;
  moa_mesh mesh;
  assert_non_null(interleaved);
  for (i = 0; i < n; ++i) {
    int k;
    for (k = 0; k < kFloats; ++k) interleaved[i * kFloats + k] = -99.0f; /* not a position */
    for (k = 0; k < 3; ++k) {
      interleaved[i * kFloats + k] = (float)xyz[3 * i + k];
      xyz[3 * i + k] = (double)(float)xyz[3 * i + k]; /* the values the floats hold */
    }
  }
  assert_int_equal(moa_set_points(ctx, xyz, n), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  from_double = abi_copy_mesh(ctx, &n_double);

  assert_int_equal(moa_set_points_float(ctx, interleaved, n, kFloats * sizeof(float)), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  mesh = abi_check_mesh(ctx, n);
  assert_memory_equal(mesh.vertices, xyz, 3 * n * sizeof(double));
  from_float = abi_copy_mesh(ctx, &n_float);
  assert_int_equal(n_double, n_float);
  assert_memory_equal(from_double, from_float, 3 * n_double * sizeof(uint32_t));

  /* Packed floats, stride 0, agree too. */
  for (i = 0; i < n; ++i)
    memmove(interleaved + 3 * i, interleaved + i * kFloats, 3 * sizeof(float));
  assert_int_equal(moa_set_points_float(ctx, interleaved, n, 0), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  free(from_float);
  from_float = abi_copy_mesh(ctx, &n_float);
  assert_int_equal(n_double, n_float);
  assert_memory_equal(from_double, from_float, 3 * n_double * sizeof(uint32_t));

  /* An odd stride leaves the floats unaligned; they must still be read as given. */
  {
    const size_t odd = 3 * sizeof(float) + 1;
    unsigned char *bytes = (unsigned char *)malloc(n * odd);
    assert_non_null(bytes);
    for (i = 0; i < n; ++i) {
      memcpy(bytes + i * odd, interleaved + 3 * i, 3 * sizeof(float));
      bytes[i * odd + 3 * sizeof(float)] = 0xFF;
    }
    assert_int_equal(moa_set_points_float(ctx, (const float *)(void *)bytes, n, odd), MOA_OK);
    free(bytes); /* copied: the caller may free it at once */
    assert_int_equal(moa_run(ctx), MOA_OK);
    mesh = abi_check_mesh(ctx, n);
    assert_memory_equal(mesh.vertices, xyz, 3 * n * sizeof(double));
    free(from_float);
    from_float = abi_copy_mesh(ctx, &n_float);
    assert_int_equal(n_double, n_float);
    assert_memory_equal(from_double, from_float, 3 * n_double * sizeof(uint32_t));
  }

  free(from_double);
  free(from_float);
  free(interleaved);
  free(xyz);
}

typedef struct ProgressLog {
  int calls[MOA_STAGE_COUNT];
  int last_stage;
  int out_of_order;
  int bad_fraction;
  int wrong_thread;
  pthread_t thread;
  int cancel_stage; /* -1: never cancel */
  int cancel_call;  /* cancel at this report of cancel_stage (1: the first) */
} ProgressLog;

static int log_progress(moa_stage stage, double fraction, void *user_data) {
  ProgressLog *log = (ProgressLog *)user_data;
  if ((int)stage < 0 || stage >= MOA_STAGE_COUNT) {
    log->out_of_order = 1;
    return 0;
  }
  log->calls[stage]++;
  if ((int)stage < log->last_stage) log->out_of_order = 1;
  log->last_stage = (int)stage;
  if (!(fraction >= 0.0 && fraction <= 1.0)) log->bad_fraction = 1;
  if (!pthread_equal(pthread_self(), log->thread)) log->wrong_thread = 1;
  return (int)stage == log->cancel_stage && log->calls[stage] >= log->cancel_call;
}

static void reset_log(ProgressLog *log, int cancel_stage) {
  memset(log, 0, sizeof *log);
  log->thread = pthread_self();
  log->cancel_stage = cancel_stage;
  log->cancel_call = 1;
}

static void test_progress_reports_every_stage(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  ProgressLog log;
  int s;
  reset_log(&log, -1);
  assert_int_equal(moa_set_progress_callback(ctx, log_progress, &log), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  for (s = 0; s < MOA_STAGE_COUNT; ++s) {
    if (log.calls[s] == 0) fail_msg("stage '%s' was never reported", moa_stage_name((moa_stage)s));
  }
  assert_false(log.out_of_order);
  assert_false(log.bad_fraction);
  assert_false(log.wrong_thread);
  /* Removing the callback stops the reports. */
  assert_int_equal(moa_set_progress_callback(ctx, NULL, NULL), MOA_OK);
  reset_log(&log, -1);
  assert_int_equal(moa_run(ctx), MOA_OK);
  for (s = 0; s < MOA_STAGE_COUNT; ++s) assert_int_equal(log.calls[s], 0);
}

/* Cancels the next run at report `call` of `stage`; then the context must be usable: the run
 * after gives `reference` (n_ref triangles) again, on the caller's points in their order. */
static void cancel_and_rerun(moa_ctx *ctx, moa_stage stage, int call, const uint32_t *reference,
                             size_t n_ref, const double *xyz, size_t count) {
  ProgressLog log;
  size_t n = 0;
  uint32_t *mesh;
  moa_mesh m;
  reset_log(&log, (int)stage);
  log.cancel_call = call;
  assert_int_equal(moa_set_progress_callback(ctx, log_progress, &log), MOA_OK);
  if (moa_run(ctx) != MOA_ERROR_CANCELLED)
    fail_msg("cancelling in stage '%s' did not give MOA_ERROR_CANCELLED: %s",
             moa_stage_name(stage), moa_last_error(ctx));
  assert_true(abi_message_has(moa_last_error(ctx), "moa_run", "cancel"));
  assert_int_equal(log.calls[stage], call); /* stopped at that report */
  assert_false(log.wrong_thread);
  assert_int_equal(moa_get_mesh(ctx, &m), MOA_ERROR_BAD_STATE); /* the old mesh is gone */

  reset_log(&log, -1);
  assert_int_equal(moa_run(ctx), MOA_OK);
  mesh = abi_copy_mesh(ctx, &n);
  assert_int_equal(n, n_ref);
  assert_memory_equal(mesh, reference, 3 * n * sizeof(uint32_t));
  m = abi_check_mesh(ctx, count);
  assert_memory_equal(m.vertices, xyz, 3 * count * sizeof(double));
  free(mesh);
  assert_int_equal(moa_set_progress_callback(ctx, NULL, NULL), MOA_OK); /* log goes now */
}

/* Cancelling in any stage gives MOA_ERROR_CANCELLED, no mesh, and a context whose next run
 * gives the same mesh as an undisturbed one, on the caller's points in the caller's order: the
 * run reorders them in place and must put them back when cancelled too. Every tenth point is
 * given twice, at the end, so that the duplicates move as well. */
static void test_cancel_each_stage(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  const size_t count = ABI_SPHERE_POINTS + ABI_SPHERE_POINTS / 10;
  double *xyz = (double *)malloc(3 * count * sizeof(double));
  size_t n_ref = 0, i;
  uint32_t *reference;
  int s;
  assert_non_null(xyz);
  abi_fibonacci_ellipsoid(xyz, ABI_SPHERE_POINTS, 2.0, 2.0, 2.0);
  for (i = 0; i < ABI_SPHERE_POINTS / 10; ++i)
    memcpy(xyz + 3 * (ABI_SPHERE_POINTS + i), xyz + 3 * (10 * i), 3 * sizeof(double));
  assert_int_equal(moa_set_points(ctx, xyz, count), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  reference = abi_copy_mesh(ctx, &n_ref);
  for (s = 0; s < MOA_STAGE_COUNT; ++s) /* at the first report of each stage */
    cancel_and_rerun(ctx, (moa_stage)s, 1, reference, n_ref, xyz, count);
  free(reference);
  free(xyz);
}

/* A cloud large enough for Algorithm 1's parallel first pass (its parts grow on worker
 * threads): the reports still come on the calling thread, in order, and a cancellation in the
 * middle of that pass stops the run and leaves the context usable. */
static void test_parallel_pass_progress_and_cancel(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  const size_t count = 9000; /* above 8192 points, two parts */
  double *xyz = abi_sphere(count);
  ProgressLog log;
  size_t n_ref = 0;
  uint32_t *reference;
  assert_int_equal(moa_set_param(ctx, "threads", 2), MOA_OK);
  assert_int_equal(moa_set_points(ctx, xyz, count), MOA_OK);
  reset_log(&log, -1);
  assert_int_equal(moa_set_progress_callback(ctx, log_progress, &log), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  assert_false(log.out_of_order);
  assert_false(log.bad_fraction);
  assert_false(log.wrong_thread);
  assert_true(log.calls[MOA_STAGE_MESH] > 2); /* reports from inside the parallel pass too */
  reference = abi_copy_mesh(ctx, &n_ref);
  /* The first report after the stage's start: inside the parallel pass. */
  cancel_and_rerun(ctx, MOA_STAGE_MESH, 2, reference, n_ref, xyz, count);
  free(reference);
  free(xyz);
}

/* On bad input the loop module can run for seconds (stray points through the volume: about
 * 25 s for 20,000 points with no surface at all); it reports progress from inside its passes,
 * so that a cancellation takes effect within a fraction of a second. A sphere of 800 points
 * with 320 stray points through its bounding cube, not smoothed (the stray points make it
 * look noisy in part, and the smoothed copy spares the loop module much of its work): the loop
 * module reports 75 times (with 160 stray points it reported 38 times before the stray
 * points in the volume were set aside too, 26 since), where
 * reports between its passes and steps alone come at most 25 times (the start, 6 rounds of 3
 * passes, 3 steps after them, the 3 passes of the round for sharp edges; 20 before the polls
 * came); and a cancellation halfway through its reports stops the run and leaves the context
 * usable. */
static void test_loop_module_progress_and_cancel(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  const size_t surface = 800, stray = 320, count = surface + stray;
  double *xyz = (double *)malloc(3 * count * sizeof(double));
  uint64_t seed = 12345;
  ProgressLog log;
  size_t n_ref = 0, i;
  uint32_t *reference;
  int loop_reports;
  assert_non_null(xyz);
  abi_fibonacci_ellipsoid(xyz, surface, 1.0, 1.0, 1.0);
  for (i = 3 * surface; i < 3 * count; ++i) { /* uniform in [-1.2, 1.2]^3, a fixed sequence */
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    xyz[i] = -1.2 + 2.4 * (double)(seed >> 11) / 9007199254740992.0;
  }
  assert_int_equal(moa_set_points(ctx, xyz, count), MOA_OK);
  assert_int_equal(moa_set_param(ctx, "smoothing", 0), MOA_OK);
  reset_log(&log, -1);
  assert_int_equal(moa_set_progress_callback(ctx, log_progress, &log), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  assert_false(log.out_of_order);
  assert_false(log.bad_fraction);
  loop_reports = log.calls[MOA_STAGE_LOOPS];
  print_message("the loop module reported progress %d times\n", loop_reports);
  if (loop_reports <= 30)
    fail_msg("the loop module reported progress %d times: only between its passes", loop_reports);
  reference = abi_copy_mesh(ctx, &n_ref);
  cancel_and_rerun(ctx, MOA_STAGE_LOOPS, loop_reports / 2, reference, n_ref, xyz, count);
  free(reference);
  free(xyz);
}

/* Bad points fail in moa_run with MOA_ERROR_INVALID_INPUT, discard the last mesh, and leave the
 * context ready for good points. */
static void test_invalid_input_keeps_ctx_usable(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  double two[6] = {0, 0, 0, 1, 0, 0};
  double line[12] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3};
  double *xyz = abi_sphere(ABI_SPHERE_POINTS);
  moa_mesh mesh;
  assert_int_equal(moa_run(ctx), MOA_OK);

  assert_int_equal(moa_set_points(ctx, two, 2), MOA_OK);
  assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_ERROR_BAD_STATE); /* new points, no mesh */
  assert_int_equal(moa_run(ctx), MOA_ERROR_INVALID_INPUT);
  assert_true(abi_message_has(moa_last_error(ctx), "moa_run", NULL));
  assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_ERROR_BAD_STATE);

  assert_int_equal(moa_set_points(ctx, NULL, 0), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_ERROR_INVALID_INPUT);
  assert_int_equal(moa_set_points(ctx, line, 4), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_ERROR_INVALID_INPUT);

  xyz[7] = NAN;
  assert_int_equal(moa_set_points(ctx, xyz, ABI_SPHERE_POINTS), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_ERROR_INVALID_INPUT);
  xyz[7] = INFINITY;
  assert_int_equal(moa_set_points(ctx, xyz, ABI_SPHERE_POINTS), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_ERROR_INVALID_INPUT);

  free(xyz);
  xyz = abi_sphere(ABI_SPHERE_POINTS);
  assert_int_equal(moa_set_points(ctx, xyz, ABI_SPHERE_POINTS), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  abi_check_mesh(ctx, ABI_SPHERE_POINTS);
  free(xyz);
}

/* A progress callback that calls back into its own context cannot disturb the run. */
static int reenter(moa_stage stage, double fraction, void *user_data) {
  moa_ctx *ctx = (moa_ctx *)user_data;
  double xyz[3] = {0, 0, 0};
  (void)stage;
  (void)fraction;
  if (moa_set_points(ctx, xyz, 1) != MOA_ERROR_BAD_STATE) return 1;
  if (moa_set_param(ctx, "neighbors", 9) != MOA_ERROR_BAD_STATE) return 1;
  if (moa_run(ctx) != MOA_ERROR_BAD_STATE) return 1;
  return 0;
}

static void test_reentrant_callback(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  assert_int_equal(moa_set_progress_callback(ctx, reenter, ctx), MOA_OK);
  assert_int_equal(moa_run(ctx), MOA_OK);
  abi_check_mesh(ctx, ABI_SPHERE_POINTS);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_run_sphere, setup_sphere, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_run_twice_same_mesh, setup_sphere, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_copy_triangles, setup_sphere, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_stats, setup_sphere, teardown_ctx),
      cmocka_unit_test(test_edge_flips_param),
      cmocka_unit_test_setup_teardown(test_stats_size, setup_sphere, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_float_stride, setup_sphere, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_progress_reports_every_stage, setup_sphere,
                                      teardown_ctx),
      cmocka_unit_test_setup_teardown(test_cancel_each_stage, setup_sphere, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_parallel_pass_progress_and_cancel, setup_sphere,
                                      teardown_ctx),
      cmocka_unit_test_setup_teardown(test_loop_module_progress_and_cancel, setup_sphere,
                                      teardown_ctx),
      cmocka_unit_test_setup_teardown(test_invalid_input_keeps_ctx_usable, setup_sphere,
                                      teardown_ctx),
      cmocka_unit_test_setup_teardown(test_reentrant_callback, setup_sphere, teardown_ctx),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
