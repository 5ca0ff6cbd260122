/* The out-of-memory guard: with the address space capped (RLIMIT_AS), libmoa must return
 * MOA_ERROR_OUT_OF_MEMORY, never abort, and leave the context usable once memory is back.
 * Each case runs in a child process so that the cap and a crash stay there; the parent never
 * calls libmoa, so the child starts without any of its threads. Not under AddressSanitizer,
 * whose shadow memory needs far more address space than any cap allows. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

#include "moa/moa.h"
#include "robust_clouds.h"

#if defined(__SANITIZE_ADDRESS__)
#define ROBUST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ROBUST_ASAN 1
#endif
#endif

/* In a child: report and leave with status 1. */
#define CHECK(cond, ...)                                       \
  do {                                                         \
    if (!(cond)) {                                             \
      fprintf(stderr, "%s:%d: ", __FILE__, __LINE__);          \
      fprintf(stderr, __VA_ARGS__);                            \
      fprintf(stderr, "\n");                                   \
      _exit(1);                                                \
    }                                                          \
  } while (0)

static size_t address_space_bytes(void) {
  long pages = 0;
  FILE *f = fopen("/proc/self/statm", "r");
  if (f != NULL) {
    if (fscanf(f, "%ld", &pages) != 1) pages = 0;
    fclose(f);
  }
  return (size_t)pages * (size_t)sysconf(_SC_PAGESIZE);
}

static struct rlimit g_saved;

static void cap_address_space(size_t extra_mb) {
  struct rlimit low;
  CHECK(getrlimit(RLIMIT_AS, &g_saved) == 0, "getrlimit");
  low = g_saved;
  low.rlim_cur = address_space_bytes() + extra_mb * 1024 * 1024;
  if (g_saved.rlim_max != RLIM_INFINITY && low.rlim_cur > g_saved.rlim_max)
    low.rlim_cur = g_saved.rlim_max;
  CHECK(setrlimit(RLIMIT_AS, &low) == 0, "setrlimit");
}

static void uncap_address_space(void) { CHECK(setrlimit(RLIMIT_AS, &g_saved) == 0, "setrlimit"); }

/* After a failure: a small sphere must reconstruct on the same context. */
static void check_usable(moa_ctx *ctx) {
  double xyz[3 * 120];
  moa_mesh mesh;
  fibonacci_sphere(xyz, 120);
  CHECK(moa_set_points(ctx, xyz, 120) == MOA_OK, "set_points: %s", moa_last_error(ctx));
  CHECK(moa_run(ctx) == MOA_OK, "run after OOM: %s", moa_last_error(ctx));
  CHECK(moa_get_mesh(ctx, &mesh) == MOA_OK && mesh.triangle_count > 0, "no mesh");
}

static int g_stage = -1;
static int note_stage(moa_stage stage, double fraction, void *user_data) {
  (void)fraction;
  (void)user_data;
  g_stage = (int)stage;
  return 0;
}

/* moa_run on 100,000 points under a cap that grows until the run succeeds, so that memory
 * runs out in one stage after another. */
static void child_run_under_caps(double threads) {
  const size_t n = 100000;
  double *xyz = (double *)malloc(3 * n * sizeof(double));
  moa_ctx *ctx = NULL;
  unsigned stages_failed = 0, failures = 0;
  size_t cap_mb;
  moa_status s = MOA_ERROR_OUT_OF_MEMORY;
  CHECK(xyz != NULL, "malloc");
  fibonacci_sphere(xyz, n);
  CHECK(moa_ctx_create(&ctx) == MOA_OK, "create");
  CHECK(moa_set_param(ctx, "threads", threads) == MOA_OK, "threads");
  CHECK(moa_set_progress_callback(ctx, note_stage, NULL) == MOA_OK, "callback");
  for (cap_mb = 1; s != MOA_OK; cap_mb = cap_mb * 3 / 2 + 1) {
    CHECK(cap_mb < 4096, "still out of memory with 4 GB more");
    CHECK(moa_set_points(ctx, xyz, n) == MOA_OK, "set_points: %s", moa_last_error(ctx));
    g_stage = -1;
    cap_address_space(cap_mb);
    s = moa_run(ctx);
    uncap_address_space();
    CHECK(s == MOA_OK || s == MOA_ERROR_OUT_OF_MEMORY, "cap +%zu MB: %s '%s'", cap_mb,
          moa_status_string(s), moa_last_error(ctx));
    if (s == MOA_ERROR_OUT_OF_MEMORY) {
      CHECK(strstr(moa_last_error(ctx), "moa_run") && strstr(moa_last_error(ctx), "memory"),
            "message '%s'", moa_last_error(ctx));
      ++failures;
      stages_failed |= 1u << (g_stage + 1);
      check_usable(ctx);
    }
  }
  fprintf(stderr, "threads %g: %u runs out of memory (stage mask %#x), then success at +%zu MB\n",
          threads, failures, stages_failed, cap_mb * 2 / 3);
  CHECK(failures > 0, "no cap made moa_run run out of memory: the guard was not exercised");
  CHECK((stages_failed & (stages_failed - 1)) != 0, "allocations failed in one stage only");
  moa_ctx_destroy(ctx);
  free(xyz);
  _exit(0);
}

/* moa_set_points* with more points than memory holds: refused, and the context keeps its
 * points and mesh. The input is untouched zero pages, so it costs no real memory. */
static void child_huge_point_count(void) {
  const size_t n = 50000000; /* 1.2 GB of doubles, against a cap of 64 MB more */
  double *big = (double *)calloc(3 * n, sizeof(double));
  double xyz[3 * 120];
  moa_ctx *ctx = NULL;
  moa_mesh before, after;
  moa_status s;
  CHECK(big != NULL, "calloc");
  fibonacci_sphere(xyz, 120);
  CHECK(moa_ctx_create(&ctx) == MOA_OK, "create");
  CHECK(moa_set_points(ctx, xyz, 120) == MOA_OK && moa_run(ctx) == MOA_OK, "first run");
  CHECK(moa_get_mesh(ctx, &before) == MOA_OK, "mesh");
  cap_address_space(64);
  s = moa_set_points(ctx, big, n);
  CHECK(s == MOA_ERROR_OUT_OF_MEMORY, "set_points: %s '%s'", moa_status_string(s),
        moa_last_error(ctx));
  CHECK(strstr(moa_last_error(ctx), "moa_set_points") != NULL, "'%s'", moa_last_error(ctx));
  s = moa_set_points_float(ctx, (const float *)(void *)big, 2 * n, 0);
  CHECK(s == MOA_ERROR_OUT_OF_MEMORY, "set_points_float: %s", moa_status_string(s));
  uncap_address_space();
  CHECK(moa_get_mesh(ctx, &after) == MOA_OK, "a failed moa_set_points lost the mesh");
  CHECK(after.triangle_count == before.triangle_count && after.vertex_count == 120, "changed");
  CHECK(moa_run(ctx) == MOA_OK, "run on the kept points: %s", moa_last_error(ctx));
  moa_ctx_destroy(ctx);
  free(big);
  _exit(0);
}

/* Every call with the heap exhausted, on a thread whose error slot has never been used:
 * OOM or success, never an abort; moa_last_error never NULL. */
static void child_exhausted_heap(void) {
  double xyz[3 * 120];
  moa_ctx *ctx = NULL, *other = NULL;
  moa_mesh mesh;
  void *hog = NULL;
  size_t size;
  moa_status s;
  fibonacci_sphere(xyz, 120);
  CHECK(moa_ctx_create(&ctx) == MOA_OK, "create");
  CHECK(moa_set_points(ctx, xyz, 120) == MOA_OK && moa_run(ctx) == MOA_OK, "warm-up run");
  cap_address_space(8);
  for (size = (size_t)1 << 20; size >= sizeof(void *); size /= 2)
    for (;;) {
      void **block = (void **)malloc(size);
      if (block == NULL) break;
      *block = hog;
      hog = block;
    }
  s = moa_ctx_create(&other);
  CHECK(s == MOA_OK || s == MOA_ERROR_OUT_OF_MEMORY, "create: %s", moa_status_string(s));
  CHECK(s == MOA_OK ? other != NULL : other == NULL, "out_ctx");
  CHECK(moa_ctx_create(NULL) == MOA_ERROR_INVALID_ARGUMENT, "create(NULL)");
  CHECK(moa_last_error(NULL) != NULL, "moa_last_error(NULL) is NULL");
  s = moa_set_points(ctx, xyz, 120);
  CHECK(s == MOA_OK || s == MOA_ERROR_OUT_OF_MEMORY, "set_points: %s", moa_status_string(s));
  s = moa_run(ctx);
  CHECK(s == MOA_OK || s == MOA_ERROR_OUT_OF_MEMORY, "run: %s", moa_status_string(s));
  s = moa_get_mesh(ctx, &mesh);
  CHECK(s == MOA_OK || s == MOA_ERROR_BAD_STATE, "get_mesh: %s", moa_status_string(s));
  CHECK(moa_last_error(ctx) != NULL, "moa_last_error(ctx) is NULL");
  while (hog != NULL) {
    void *next = *(void **)hog;
    free(hog);
    hog = next;
  }
  uncap_address_space();
  check_usable(ctx);
  moa_ctx_destroy(other);
  moa_ctx_destroy(ctx);
  _exit(0);
}

/* Runs child(arg) in a child process and fails unless it exits with 0 within its time. */
static void in_child(void (*child)(int), int arg) {
  int status = 0;
  pid_t pid;
#ifdef ROBUST_ASAN
  skip(); /* the cap cannot work: ASan's shadow memory alone exceeds it */
#endif
  fflush(NULL);
  pid = fork();
  assert_true(pid >= 0);
  if (pid == 0) {
    alarm(300); /* a hang becomes SIGALRM */
    child(arg);
    _exit(0);
  }
  assert_int_equal(waitpid(pid, &status, 0), pid);
  if (WIFSIGNALED(status))
    fail_msg("the child died of signal %d (%s)", WTERMSIG(status), strsignal(WTERMSIG(status)));
  if (WEXITSTATUS(status) != 0) fail_msg("the child failed (see above)");
}

static void run_one_thread(int arg) { (void)arg; child_run_under_caps(1); }
static void run_all_threads(int arg) { (void)arg; child_run_under_caps(0); }
static void huge_count(int arg) { (void)arg; child_huge_point_count(); }
static void exhausted(int arg) { (void)arg; child_exhausted_heap(); }

static void test_run_out_of_memory_one_thread(void **state) {
  (void)state;
  in_child(run_one_thread, 0);
}

static void test_run_out_of_memory_all_threads(void **state) {
  (void)state;
  in_child(run_all_threads, 0);
}

static void test_set_points_out_of_memory(void **state) {
  (void)state;
  in_child(huge_count, 0);
}

static void test_exhausted_heap(void **state) {
  (void)state;
  in_child(exhausted, 0);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_run_out_of_memory_one_thread),
      cmocka_unit_test(test_run_out_of_memory_all_threads),
      cmocka_unit_test(test_set_points_out_of_memory),
      cmocka_unit_test(test_exhausted_heap),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
