/* Points with no surface at all: 40,000 uniform random points filling a cube. The mesh is
 * meaningless, but the run must end with MOA_OK, a valid mesh, and time and memory in proportion
 * to the cloud. The loop module once appended an island's vertex list to the loop around it
 * again for every triangle that touched the island (a 50,000-point cloud peaked at 3.1 GB), and
 * later still copied every long loop a loop merged (this test's process at 196 MB) while its
 * rounds rebuilt the tangle they had taken apart, adding and removing about five faces per point
 * (200,000 points: 526 s). Now it sees the tangle before filling and leaves it: no face added,
 * 45 MB. Measured on the process's peak resident size, so not built with the sanitizers, whose
 * shadow memory would dwarf it.
 * And a surface beside such a volume (clutter next to a scanned object): the tangle is told
 * apart piece by piece, so the surface is still closed while the tangle is left alone (when the
 * test was of the whole mesh, the loop module added 108,395 faces on this cloud, in 31 s).
 * And a surface with such a volume attached (vegetation on a scanned wall): one piece with it,
 * most of whose vertices are not in a tangle, so it is the tangled region that is told apart
 * (when only whole pieces were, the loop module added 67,383 faces and removed 70,970 on this
 * cloud, in about 14 s; now 16 faces, in under 2 s). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <cmocka.h>

#include "moa/moa.h"
#include "robust_clouds.h"

/* Peak resident size allowed to the whole test process, libraries and input included. */
#define PEAK_LIMIT_MB 80

/* Fills xyz[0 .. count) with numbers in [0, 1): a fixed 64-bit linear congruential sequence,
 * its top 53 bits. */
static void fill_random(double *xyz, size_t count) {
  uint64_t seed = 0x9e3779b97f4a7c15u;
  size_t i;
  for (i = 0; i < count; ++i) {
    seed = seed * 6364136223846793005u + 1442695040888963407u;
    xyz[i] = (double)(seed >> 11) / 9007199254740992.0;
  }
}

static int compare_keys(const void *a, const void *b) {
  const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
  return x < y ? -1 : x > y;
}

static void test_volume_cloud_runs_in_bounded_memory(void **state) {
  const size_t n = 40000;
  double *xyz = (double *)malloc(3 * n * sizeof(double));
  moa_ctx *ctx = NULL;
  moa_mesh mesh;
  moa_stats stats;
  struct rusage usage;
  size_t i;
  (void)state;
  assert_non_null(xyz);
  fill_random(xyz, 3 * n);
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

/* Runs, on two threads, a unit sphere of ns points (a Fibonacci lattice) with nc random points
 * filling the box of the given side whose lowest corner is `corner`. Returns the context, whose
 * mesh and statistics are in *mesh and *stats. */
static moa_ctx *run_sphere_and_box(size_t ns, size_t nc, double side, const double corner[3],
                                   moa_mesh *mesh, moa_stats *stats) {
  const size_t n = ns + nc;
  double *xyz = (double *)malloc(3 * n * sizeof(double));
  moa_ctx *ctx = NULL;
  size_t i;
  int k;
  assert_non_null(xyz);
  fibonacci_sphere(xyz, ns);
  fill_random(xyz + 3 * ns, 3 * nc);
  for (i = ns; i < n; ++i)
    for (k = 0; k < 3; ++k) xyz[3 * i + k] = side * xyz[3 * i + k] + corner[k];
  assert_int_equal(moa_ctx_create(&ctx), MOA_OK);
  assert_int_equal(moa_set_param(ctx, "threads", 2), MOA_OK);
  assert_int_equal(moa_set_points(ctx, xyz, n), MOA_OK);
  free(xyz);
  assert_int_equal(moa_run(ctx), MOA_OK);
  assert_int_equal(moa_get_mesh(ctx, mesh), MOA_OK);
  assert_int_equal(moa_get_stats(ctx, stats, sizeof *stats), MOA_OK);
  return ctx;
}

/* Asserts that each edge (a key a << 32 | b, a < b) of the list, one entry per face side,
 * comes exactly twice. Sorts the list; returns the number of distinct edges. */
static size_t assert_each_edge_twice(uint64_t *edges, size_t count) {
  size_t i, distinct = 0;
  qsort(edges, count, sizeof *edges, compare_keys);
  for (i = 0; i < count; i += 2, ++distinct) {
    assert_true(i + 1 < count && edges[i] == edges[i + 1]);
    assert_true(i + 2 >= count || edges[i + 2] != edges[i]);
  }
  return distinct;
}

static uint64_t edge_key(uint64_t a, uint64_t b) { return a < b ? a << 32 | b : b << 32 | a; }

/* A unit sphere of 10,000 points (about 0.035 apart) and, a gap of ten spacings away, 20,000
 * random points filling a unit cube at about the same spacing. */
static void test_surface_beside_a_volume(void **state) {
  const size_t ns = 10000, nc = 20000, n = ns + nc;
  const double corner[3] = {1.35, -0.5, -0.5};
  uint64_t *edges = (uint64_t *)malloc(3 * 2 * ns * sizeof(uint64_t));
  unsigned char *on_mesh = (unsigned char *)calloc(ns, 1);
  moa_ctx *ctx;
  moa_mesh mesh;
  moa_stats stats;
  size_t i, sphere_faces = 0, edge_count = 0;
  (void)state;
  assert_non_null(edges);
  assert_non_null(on_mesh);
  ctx = run_sphere_and_box(ns, nc, 1.0, corner, &mesh, &stats);
  print_message("loop module: %zu faces added\n", stats.triangles_loops);
  assert_true(stats.triangles_loops < n / 4);
  /* The sphere: no face joins it to the cube, and its own faces close it, every point on it,
   * each edge between exactly two faces. */
  for (i = 0; i < mesh.triangle_count; ++i) {
    const uint32_t *t = mesh.triangles + 3 * i;
    const int on_sphere = (t[0] < ns) + (t[1] < ns) + (t[2] < ns);
    int k;
    assert_true(on_sphere == 0 || on_sphere == 3);
    if (on_sphere == 0) continue;
    ++sphere_faces;
    assert_true(sphere_faces <= 2 * ns - 4);
    for (k = 0; k < 3; ++k) {
      edges[edge_count++] = edge_key(t[k], t[(k + 1) % 3]);
      on_mesh[t[k]] = 1;
    }
  }
  for (i = 0; i < ns; ++i) assert_true(on_mesh[i]);
  assert_int_equal(sphere_faces, 2 * ns - 4); /* Euler: a closed sphere of ns vertices */
  assert_each_edge_twice(edges, edge_count);
  free(edges);
  free(on_mesh);
  moa_ctx_destroy(ctx);
}

/* The unit sphere of 10,000 points again, and 12,000 random points filling a box 0.8 wide
 * whose base cuts through the sphere's top at y = 0.9: clutter that touches the surface. */
static void test_surface_with_a_volume_attached(void **state) {
  const size_t ns = 10000, nc = 12000;
  const double corner[3] = {-0.4, 0.9, -0.4};
  const size_t edge_room = 6 * ns; /* at most 3 ns edges on ns vertices, each in two faces */
  uint64_t *edges = (uint64_t *)malloc(edge_room * sizeof(uint64_t));
  unsigned char *on_mesh = (unsigned char *)calloc(ns, 1);
  moa_ctx *ctx;
  moa_mesh mesh;
  moa_stats stats;
  size_t i, edge_count = 0;
  (void)state;
  assert_non_null(edges);
  assert_non_null(on_mesh);
  ctx = run_sphere_and_box(ns, nc, 0.8, corner, &mesh, &stats);
  print_message("loop module: %zu faces added, %zu removed\n", stats.triangles_loops,
                stats.triangles_removed);
  assert_true(stats.triangles_loops < nc / 4);
  /* The sphere away from the clutter (below y = 0.4, over 14 spacings from the box) is whole:
   * every point on the mesh, every edge between two of its points in exactly two faces. */
  for (i = 0; i < mesh.triangle_count; ++i) {
    const uint32_t *t = mesh.triangles + 3 * i;
    int k;
    for (k = 0; k < 3; ++k) {
      const uint32_t a = t[k], b = t[(k + 1) % 3];
      const int a_far = a < ns && mesh.vertices[3 * a + 1] < 0.4;
      if (a_far) on_mesh[a] = 1;
      if (a_far && b < ns && mesh.vertices[3 * b + 1] < 0.4) {
        assert_true(edge_count < edge_room);
        edges[edge_count++] = edge_key(a, b);
      }
    }
  }
  for (i = 0; i < ns; ++i) assert_true(on_mesh[i] || mesh.vertices[3 * i + 1] >= 0.4);
  /* 70 % of the sphere lies below y = 0.4: about 21,000 edges */
  assert_true(assert_each_edge_twice(edges, edge_count) > 3 * ns / 2);
  free(edges);
  free(on_mesh);
  moa_ctx_destroy(ctx);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_volume_cloud_runs_in_bounded_memory),
      cmocka_unit_test(test_surface_beside_a_volume),
      cmocka_unit_test(test_surface_with_a_volume_attached),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
