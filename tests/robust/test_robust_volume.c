/* Points with no surface at all: 40,000 uniform random points filling a cube. The mesh is
 * meaningless, but the run must end with MOA_OK, a valid mesh, and time and memory in proportion
 * to the cloud. The loop module once appended an island's vertex list to the loop around it
 * again for every triangle that touched the island (a 50,000-point cloud peaked at 3.1 GB), and
 * later still copied every long loop a loop merged (this test's process at 196 MB) while its
 * rounds rebuilt the tangle they had taken apart, adding and removing about five faces per point
 * (200,000 points: 526 s). Now it sees the tangle before filling and leaves it: no face added,
 * 45 MB. Measured on the process's peak resident size, so not built with the sanitizers, whose
 * shadow memory would dwarf it. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <cmocka.h>

#include "moa/moa.h"

/* Peak resident size allowed to the whole test process, libraries and input included. */
#define PEAK_LIMIT_MB 80

static void test_volume_cloud_runs_in_bounded_memory(void **state) {
  const size_t n = 40000;
  double *xyz = (double *)malloc(3 * n * sizeof(double));
  uint64_t seed = 0x9e3779b97f4a7c15u;
  moa_ctx *ctx = NULL;
  moa_mesh mesh;
  moa_stats stats;
  struct rusage usage;
  size_t i;
  (void)state;
  assert_non_null(xyz);
  for (i = 0; i < 3 * n; ++i) { /* a fixed 64-bit linear congruential sequence, top 53 bits */
    seed = seed * 6364136223846793005u + 1442695040888963407u;
    xyz[i] = (double)(seed >> 11) / 9007199254740992.0;
  }
  assert_int_equal(moa_ctx_create(&ctx), MOA_OK);
  assert_int_equal(moa_set_param(ctx, "threads", 2), MOA_OK); /* the same work on any machine */
  assert_int_equal(moa_set_points(ctx, xyz, n), MOA_OK);
  free(xyz);
  assert_int_equal(moa_run(ctx), MOA_OK);
  assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_OK);
  assert_int_equal(moa_get_stats(ctx, &stats, sizeof stats), MOA_OK);
  assert_int_equal(mesh.vertex_count, n);
  assert_int_equal(mesh.triangle_count, stats.triangles);
  for (i = 0; i < 3 * mesh.triangle_count; ++i) assert_true(mesh.triangles[i] < n);
  /* The loop module sees the tangle (most vertices carry faces in several fans) and leaves it. */
  print_message("loop module: %zu faces added\n", stats.triangles_loops);
  assert_true(stats.triangles_loops < n / 4);
  moa_ctx_destroy(ctx);

  assert_int_equal(getrusage(RUSAGE_SELF, &usage), 0);
  print_message("peak resident size %ld kB\n", usage.ru_maxrss);
  assert_true(usage.ru_maxrss < PEAK_LIMIT_MB * 1024L);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_volume_cloud_runs_in_bounded_memory),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
