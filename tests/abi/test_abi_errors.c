/* The C ABI's lifecycle, its error paths, and its names for codes and versions. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "abi/abi_fixtures.h"

/* The thread slot must name the function and what was wrong. */
#define assert_thread_error(fn, what) \
  assert_true(abi_message_has(moa_last_error(NULL), fn, what))
#define assert_ctx_error(ctx, fn, what) \
  assert_true(abi_message_has(moa_last_error(ctx), fn, what))

static int setup_ctx(void **state) {
  moa_ctx *ctx = NULL;
  if (moa_ctx_create(&ctx) != MOA_OK) return -1;
  *state = ctx;
  return 0;
}

static int teardown_ctx(void **state) {
  moa_ctx_destroy((moa_ctx *)*state);
  return 0;
}

static void test_lifecycle(void **state) {
  moa_ctx *ctx = (moa_ctx *)0x1;
  (void)state;
  assert_int_equal(moa_ctx_create(&ctx), MOA_OK);
  assert_non_null(ctx);
  assert_non_null(moa_last_error(ctx));
  assert_string_equal(moa_last_error(ctx), "");
  moa_ctx_destroy(ctx);
  moa_ctx_destroy(NULL); /* a no-op */
  assert_non_null(moa_last_error(NULL));
}

static void test_create_null(void **state) {
  (void)state;
  assert_int_equal(moa_ctx_create(NULL), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_ctx_create", "out_ctx");
}

static void test_null_ctx(void **state) {
  double xyz[3] = {0, 0, 0}, value = 0;
  float xyzf[3] = {0, 0, 0};
  moa_mesh mesh;
  moa_stats stats;
  uint32_t tri[3];
  size_t total = 0;
  (void)state;
  assert_int_equal(moa_set_points(NULL, xyz, 1), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_set_points", "ctx");
  assert_int_equal(moa_set_points_float(NULL, xyzf, 1, 0), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_set_points_float", "ctx");
  assert_int_equal(moa_set_param(NULL, "neighbors", 20), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_set_param", "ctx");
  assert_int_equal(moa_get_param(NULL, "neighbors", &value), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_get_param", "ctx");
  assert_int_equal(moa_set_progress_callback(NULL, NULL, NULL), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_set_progress_callback", "ctx");
  assert_int_equal(moa_run(NULL), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_run", "ctx");
  assert_int_equal(moa_get_mesh(NULL, &mesh), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_get_mesh", "ctx");
  assert_int_equal(moa_copy_triangles(NULL, tri, 3, &total), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_copy_triangles", "ctx");
  assert_int_equal(moa_get_stats(NULL, &stats, sizeof stats), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_get_stats", "ctx");
}

/* A pointer to memory that is not a context: rejected, and the message goes to the thread. */
static void test_garbage_ctx(void **state) {
  uint64_t junk[64];
  moa_ctx *bad = (moa_ctx *)(void *)junk;
  double xyz[3] = {0, 0, 0};
  moa_mesh mesh;
  (void)state;
  memset(junk, 0xA5, sizeof junk);
  assert_int_equal(moa_set_points(bad, xyz, 1), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_set_points", "not a live context");
  assert_true(abi_message_has(moa_last_error(bad), "moa_set_points", NULL));
  assert_int_equal(moa_run(bad), MOA_ERROR_INVALID_ARGUMENT);
  assert_int_equal(moa_get_mesh(bad, &mesh), MOA_ERROR_INVALID_ARGUMENT);
  moa_ctx_destroy(bad); /* ignored, must not crash */
  /* Misaligned: must be rejected without reading through it. */
  assert_int_equal(moa_run((moa_ctx *)(void *)((char *)junk + 1)), MOA_ERROR_INVALID_ARGUMENT);
}

/* Using a destroyed handle is the caller's bug; libmoa recognises it on a best-effort basis.
 * AddressSanitizer rightly reports the read of freed memory, so the check is skipped there. */
static void test_destroyed_ctx(void **state) {
#if defined(__SANITIZE_ADDRESS__)
  (void)state;
  skip();
#else
  moa_ctx *ctx = NULL;
  (void)state;
  assert_int_equal(moa_ctx_create(&ctx), MOA_OK);
  moa_ctx_destroy(ctx);
  assert_int_equal(moa_run(ctx), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_run", "ctx");
#endif
}

static void test_null_outputs(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  moa_param_info info;
  size_t total = 0;
  assert_int_equal(moa_get_param(ctx, "neighbors", NULL), MOA_ERROR_INVALID_ARGUMENT);
  assert_ctx_error(ctx, "moa_get_param", "out_value");
  assert_int_equal(moa_get_mesh(ctx, NULL), MOA_ERROR_INVALID_ARGUMENT);
  assert_ctx_error(ctx, "moa_get_mesh", "out_mesh");
  assert_int_equal(moa_copy_triangles(ctx, NULL, 0, NULL), MOA_ERROR_INVALID_ARGUMENT);
  assert_ctx_error(ctx, "moa_copy_triangles", "out_total");
  assert_int_equal(moa_copy_triangles(ctx, NULL, 3, &total), MOA_ERROR_INVALID_ARGUMENT);
  assert_ctx_error(ctx, "moa_copy_triangles", "out");
  assert_int_equal(moa_get_stats(ctx, NULL, sizeof(moa_stats)), MOA_ERROR_INVALID_ARGUMENT);
  assert_ctx_error(ctx, "moa_get_stats", "out_stats");
  assert_int_equal(moa_param_info_get(0, NULL), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_param_info_get", "out_info");
  assert_int_equal(moa_param_info_get(moa_param_count(), &info), MOA_ERROR_INVALID_ARGUMENT);
  assert_thread_error("moa_param_info_get", "out of range");
}

static void test_bad_points(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  double xyz[3] = {0, 0, 0};
  float xyzf[4] = {0, 0, 0, 0};
  assert_int_equal(moa_set_points(ctx, NULL, 4), MOA_ERROR_INVALID_ARGUMENT);
  assert_ctx_error(ctx, "moa_set_points", "xyz");
  assert_int_equal(moa_set_points_float(ctx, NULL, 4, 0), MOA_ERROR_INVALID_ARGUMENT);
  assert_ctx_error(ctx, "moa_set_points_float", "xyz");
  /* The count is checked before the array is read, so a tiny array is enough here. */
  if (sizeof(size_t) > 4) {
    const size_t too_many = (size_t)UINT32_MAX;
    assert_int_equal(moa_set_points(ctx, xyz, too_many), MOA_ERROR_INVALID_ARGUMENT);
    assert_ctx_error(ctx, "moa_set_points", "point_count");
    assert_int_equal(moa_set_points_float(ctx, xyzf, too_many, 0), MOA_ERROR_INVALID_ARGUMENT);
    assert_ctx_error(ctx, "moa_set_points_float", "point_count");
  }
  assert_int_equal(moa_set_points_float(ctx, xyzf, 1, 4), MOA_ERROR_INVALID_ARGUMENT);
  assert_ctx_error(ctx, "moa_set_points_float", "stride_bytes");
  assert_int_equal(moa_set_points_float(ctx, xyzf, 1, 11), MOA_ERROR_INVALID_ARGUMENT);
  assert_int_equal(moa_set_points_float(ctx, xyzf, 1, 12), MOA_OK);
  assert_int_equal(moa_set_points_float(ctx, xyzf, 1, 16), MOA_OK);
  assert_int_equal(moa_set_points(ctx, NULL, 0), MOA_OK); /* empty is allowed here */
  assert_int_equal(moa_set_points(ctx, xyz, 1), MOA_OK);
}

/* Wrong order: run before points, read before run. */
static void test_bad_state(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  moa_mesh mesh;
  moa_stats stats;
  size_t total = 0;
  assert_int_equal(moa_run(ctx), MOA_ERROR_BAD_STATE);
  assert_ctx_error(ctx, "moa_run", "moa_set_points");
  assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_ERROR_BAD_STATE);
  assert_ctx_error(ctx, "moa_get_mesh", "no mesh");
  assert_int_equal(moa_copy_triangles(ctx, NULL, 0, &total), MOA_ERROR_BAD_STATE);
  assert_ctx_error(ctx, "moa_copy_triangles", "no mesh");
  assert_int_equal(moa_get_stats(ctx, &stats, sizeof stats), MOA_ERROR_BAD_STATE);
  assert_ctx_error(ctx, "moa_get_stats", "no mesh");
}

/* Errors on a context do not touch the thread slot, and the reverse. */
static void test_error_slots(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  assert_int_equal(moa_run(NULL), MOA_ERROR_INVALID_ARGUMENT);
  assert_int_equal(moa_run(ctx), MOA_ERROR_BAD_STATE);
  assert_thread_error("moa_run", "ctx is NULL");
  assert_ctx_error(ctx, "moa_run", "no points");
  /* A later success leaves the message of the last failure in place. */
  assert_int_equal(moa_set_param(ctx, "neighbors", 20), MOA_OK);
  assert_ctx_error(ctx, "moa_run", "no points");
}

static void test_status_strings(void **state) {
  (void)state;
  assert_string_equal(moa_status_string(MOA_OK), "MOA_OK");
  assert_string_equal(moa_status_string(MOA_ERROR_INVALID_ARGUMENT), "MOA_ERROR_INVALID_ARGUMENT");
  assert_string_equal(moa_status_string(MOA_ERROR_UNKNOWN_PARAM), "MOA_ERROR_UNKNOWN_PARAM");
  assert_string_equal(moa_status_string(MOA_ERROR_INVALID_INPUT), "MOA_ERROR_INVALID_INPUT");
  assert_string_equal(moa_status_string(MOA_ERROR_BAD_STATE), "MOA_ERROR_BAD_STATE");
  assert_string_equal(moa_status_string(MOA_ERROR_OUT_OF_MEMORY), "MOA_ERROR_OUT_OF_MEMORY");
  assert_string_equal(moa_status_string(MOA_ERROR_CANCELLED), "MOA_ERROR_CANCELLED");
  assert_string_equal(moa_status_string(MOA_ERROR_IO), "MOA_ERROR_IO");
  assert_string_equal(moa_status_string(MOA_ERROR_INTERNAL), "MOA_ERROR_INTERNAL");
  assert_non_null(moa_status_string((moa_status)99));
  assert_non_null(moa_status_string((moa_status)-1));
}

static void test_stage_names(void **state) {
  (void)state;
  assert_string_equal(moa_stage_name(MOA_STAGE_POINTS), "points");
  assert_string_equal(moa_stage_name(MOA_STAGE_NEIGHBORS), "neighbors");
  assert_string_equal(moa_stage_name(MOA_STAGE_MESH), "mesh");
  assert_string_equal(moa_stage_name(MOA_STAGE_LOOPS), "loops");
  assert_string_equal(moa_stage_name(MOA_STAGE_FINISH), "finish");
  assert_non_null(moa_stage_name(MOA_STAGE_COUNT));
  assert_non_null(moa_stage_name((moa_stage)-7));
}

static void test_version(void **state) {
  char expected[32];
  (void)state;
  assert_string_equal(moa_version(), MOA_VERSION_STRING);
  assert_int_equal(moa_version_number(), MOA_VERSION_NUMBER);
  snprintf(expected, sizeof expected, "%d.%d.%d", MOA_VERSION_MAJOR, MOA_VERSION_MINOR,
           MOA_VERSION_PATCH);
  assert_string_equal(moa_version(), expected);
  assert_int_equal(moa_version_number(),
                   MOA_VERSION_MAJOR * 10000 + MOA_VERSION_MINOR * 100 + MOA_VERSION_PATCH);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_lifecycle),
      cmocka_unit_test(test_create_null),
      cmocka_unit_test(test_null_ctx),
      cmocka_unit_test(test_garbage_ctx),
      cmocka_unit_test(test_destroyed_ctx),
      cmocka_unit_test_setup_teardown(test_null_outputs, setup_ctx, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_bad_points, setup_ctx, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_bad_state, setup_ctx, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_error_slots, setup_ctx, teardown_ctx),
      cmocka_unit_test(test_status_strings),
      cmocka_unit_test(test_stage_names),
      cmocka_unit_test(test_version),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
