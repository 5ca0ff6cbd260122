/* Distinct contexts are independent: two contexts running at once on two threads give the same
 * meshes as the same runs one after the other. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <pthread.h>
#include <cmocka.h>

#include "abi/abi_fixtures.h"

/* One job: its own points and parameters, and what the run gave. */
typedef struct Job {
  size_t point_count;
  double radii[3];
  double neighbors;
  moa_status status;
  char error[256];
  uint32_t *triangles;
  size_t triangle_count;
} Job;

/* Runs a job in a context of its own; touches no cmocka state, so it may run on any thread. */
static void *run_job(void *arg) {
  Job *job = (Job *)arg;
  moa_ctx *ctx = NULL;
  double *xyz = (double *)malloc(3 * job->point_count * sizeof(double));
  moa_mesh mesh;
  job->triangles = NULL;
  job->triangle_count = 0;
  job->error[0] = '\0';
  job->status = MOA_ERROR_OUT_OF_MEMORY;
  if (xyz == NULL) return NULL;
  abi_fibonacci_ellipsoid(xyz, job->point_count, job->radii[0], job->radii[1], job->radii[2]);
  job->status = moa_ctx_create(&ctx);
  if (job->status == MOA_OK) job->status = moa_set_points(ctx, xyz, job->point_count);
  if (job->status == MOA_OK) job->status = moa_set_param(ctx, "neighbors", job->neighbors);
  if (job->status == MOA_OK) job->status = moa_run(ctx);
  if (job->status == MOA_OK) job->status = moa_get_mesh(ctx, &mesh);
  if (job->status == MOA_OK) {
    job->triangles = (uint32_t *)malloc(3 * mesh.triangle_count * sizeof(uint32_t) + 1);
    if (job->triangles == NULL) {
      job->status = MOA_ERROR_OUT_OF_MEMORY;
    } else {
      memcpy(job->triangles, mesh.triangles, 3 * mesh.triangle_count * sizeof(uint32_t));
      job->triangle_count = mesh.triangle_count;
    }
  }
  if (job->status != MOA_OK)
    snprintf(job->error, sizeof job->error, "%s", moa_last_error(ctx));
  moa_ctx_destroy(ctx);
  free(xyz);
  return NULL;
}

static void init_jobs(Job jobs[2]) {
  memset(jobs, 0, 2 * sizeof(Job));
  /* Different points and different parameters, so that any shared state would show. */
  jobs[0].point_count = ABI_SPHERE_POINTS;
  jobs[0].radii[0] = jobs[0].radii[1] = jobs[0].radii[2] = 2.0;
  jobs[0].neighbors = 16;
  jobs[1].point_count = 700;
  jobs[1].radii[0] = 3.0;
  jobs[1].radii[1] = 2.0;
  jobs[1].radii[2] = 1.5;
  jobs[1].neighbors = 24;
}

static void check_job(const Job *job) {
  size_t i;
  if (job->status != MOA_OK) fail_msg("%s: %s", moa_status_string(job->status), job->error);
  assert_true(job->triangle_count > 0);
  for (i = 0; i < 3 * job->triangle_count; ++i) assert_true(job->triangles[i] < job->point_count);
}

static void test_two_threads_match_sequential(void **state) {
  Job sequential[2], parallel[2];
  pthread_t threads[2];
  int round, i;
  (void)state;
  init_jobs(sequential);
  run_job(&sequential[0]);
  run_job(&sequential[1]);
  check_job(&sequential[0]);
  check_job(&sequential[1]);
  /* A few rounds make an overlap of the two runs likely. */
  for (round = 0; round < 3; ++round) {
    init_jobs(parallel);
    for (i = 0; i < 2; ++i)
      assert_int_equal(pthread_create(&threads[i], NULL, run_job, &parallel[i]), 0);
    for (i = 0; i < 2; ++i) assert_int_equal(pthread_join(threads[i], NULL), 0);
    for (i = 0; i < 2; ++i) {
      check_job(&parallel[i]);
      assert_int_equal(parallel[i].triangle_count, sequential[i].triangle_count);
      assert_memory_equal(parallel[i].triangles, sequential[i].triangles,
                          3 * sequential[i].triangle_count * sizeof(uint32_t));
      free(parallel[i].triangles);
    }
  }
  free(sequential[0].triangles);
  free(sequential[1].triangles);
}

/* Each thread has its own error slot. */
static void *fail_without_ctx(void *arg) {
  (void)arg;
  (void)moa_ctx_create(NULL);
  return NULL;
}

static void test_thread_local_error(void **state) {
  pthread_t thread;
  (void)state;
  assert_int_equal(moa_run(NULL), MOA_ERROR_INVALID_ARGUMENT);
  assert_int_equal(pthread_create(&thread, NULL, fail_without_ctx, NULL), 0);
  assert_int_equal(pthread_join(thread, NULL), 0);
  assert_true(abi_message_has(moa_last_error(NULL), "moa_run", NULL));
  assert_null(strstr(moa_last_error(NULL), "moa_ctx_create"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_two_threads_match_sequential),
      cmocka_unit_test(test_thread_local_error),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
