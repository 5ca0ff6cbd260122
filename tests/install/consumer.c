/* A program built against an installed libmoa: reconstructs a generated sphere and exits
 * non-zero unless the mesh has triangles with valid indices. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <moa/moa.h>

#define POINTS 400

int main(void) {
  static double xyz[3 * POINTS];
  const double golden_angle = 3.14159265358979323846 * (3.0 - sqrt(5.0));
  moa_ctx *ctx = NULL;
  moa_mesh mesh;
  size_t i;
  if (strcmp(moa_version(), MOA_VERSION_STRING) != 0) {
    fprintf(stderr, "header %s but library %s\n", MOA_VERSION_STRING, moa_version());
    return 1;
  }
  for (i = 0; i < POINTS; ++i) {
    const double y = 1.0 - 2.0 * ((double)i + 0.5) / POINTS;
    const double r = sqrt(1.0 - y * y);
    xyz[3 * i] = r * cos(golden_angle * (double)i);
    xyz[3 * i + 1] = y;
    xyz[3 * i + 2] = r * sin(golden_angle * (double)i);
  }
  if (moa_ctx_create(&ctx) != MOA_OK || moa_set_points(ctx, xyz, POINTS) != MOA_OK ||
      moa_run(ctx) != MOA_OK || moa_get_mesh(ctx, &mesh) != MOA_OK) {
    fprintf(stderr, "libmoa failed: %s\n", moa_last_error(ctx != NULL ? ctx : NULL));
    moa_ctx_destroy(ctx);
    return 1;
  }
  if (mesh.triangle_count == 0 || mesh.vertex_count != POINTS) {
    fprintf(stderr, "bad mesh: %zu vertices, %zu triangles\n", mesh.vertex_count,
            mesh.triangle_count);
    moa_ctx_destroy(ctx);
    return 1;
  }
  for (i = 0; i < 3 * mesh.triangle_count; ++i) {
    if (mesh.triangles[i] >= POINTS) {
      fprintf(stderr, "index %u out of range\n", (unsigned)mesh.triangles[i]);
      moa_ctx_destroy(ctx);
      return 1;
    }
  }
  printf("libmoa %s: %zu triangles on %d points\n", moa_version(), mesh.triangle_count, POINTS);
  moa_ctx_destroy(ctx);
  return 0;
}
