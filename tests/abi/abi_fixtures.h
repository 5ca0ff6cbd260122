/* Shared helpers of the ABI tests: generated point sets and mesh checks. Include after cmocka.h. */
#ifndef MOA_TESTS_ABI_FIXTURES_H
#define MOA_TESTS_ABI_FIXTURES_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "moa/moa.h"

#define ABI_SPHERE_POINTS 500

/* Fibonacci points on an ellipsoid with semi-axes rx, ry, rz: an evenly sampled closed surface. */
static inline void abi_fibonacci_ellipsoid(double *xyz, size_t n, double rx, double ry,
                                           double rz) {
  const double golden_angle = 3.14159265358979323846 * (3.0 - sqrt(5.0));
  size_t i;
  for (i = 0; i < n; ++i) {
    const double y = 1.0 - 2.0 * ((double)i + 0.5) / (double)n;
    const double r = sqrt(1.0 - y * y);
    const double theta = golden_angle * (double)i;
    xyz[3 * i] = rx * r * cos(theta);
    xyz[3 * i + 1] = ry * y;
    xyz[3 * i + 2] = rz * r * sin(theta);
  }
}

/* A new array of n Fibonacci points on a sphere of radius 2; free() it. */
static inline double *abi_sphere(size_t n) {
  double *xyz = (double *)malloc(3 * n * sizeof(double));
  assert_non_null(xyz);
  abi_fibonacci_ellipsoid(xyz, n, 2.0, 2.0, 2.0);
  return xyz;
}

/* A context holding the ABI_SPHERE_POINTS sphere. */
static inline moa_ctx *abi_sphere_ctx(void) {
  moa_ctx *ctx = NULL;
  double *xyz = abi_sphere(ABI_SPHERE_POINTS);
  assert_int_equal(moa_ctx_create(&ctx), MOA_OK);
  assert_int_equal(moa_set_points(ctx, xyz, ABI_SPHERE_POINTS), MOA_OK);
  free(xyz);
  return ctx;
}

/* Asserts that ctx holds a mesh of point_count vertices with triangles whose three indices are
 * distinct and in range; returns the mesh. */
static inline moa_mesh abi_check_mesh(const moa_ctx *ctx, size_t point_count) {
  moa_mesh mesh;
  size_t t;
  memset(&mesh, 0, sizeof mesh);
  assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_OK);
  assert_int_equal(mesh.vertex_count, point_count);
  assert_non_null(mesh.vertices);
  assert_true(mesh.triangle_count > 0);
  assert_non_null(mesh.triangles);
  for (t = 0; t < mesh.triangle_count; ++t) {
    const uint32_t *tri = mesh.triangles + 3 * t;
    assert_true(tri[0] < point_count && tri[1] < point_count && tri[2] < point_count);
    assert_true(tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0]);
  }
  return mesh;
}

/* A malloc'ed copy of ctx's triangle indices (3 * *out_count of them). */
static inline uint32_t *abi_copy_mesh(const moa_ctx *ctx, size_t *out_count) {
  size_t total = 0;
  uint32_t *copy;
  assert_int_equal(moa_copy_triangles(ctx, NULL, 0, &total), MOA_OK);
  copy = (uint32_t *)malloc((total > 0 ? total : 1) * sizeof(uint32_t));
  assert_non_null(copy);
  assert_int_equal(moa_copy_triangles(ctx, copy, total, &total), MOA_OK);
  *out_count = total / 3;
  return copy;
}

/* Non-zero when the message is non-empty and contains every given fragment. */
static inline int abi_message_has(const char *message, const char *a, const char *b) {
  return message != NULL && message[0] != '\0' && strstr(message, a) != NULL &&
         (b == NULL || strstr(message, b) != NULL);
}

#endif /* MOA_TESTS_ABI_FIXTURES_H */
