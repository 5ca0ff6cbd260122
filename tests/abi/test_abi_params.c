/* Parameters through the C ABI: discovery, defaults, validation, stickiness. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>

#include "abi/abi_fixtures.h"

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

static moa_param_info info_at(size_t i) {
  moa_param_info info;
  memset(&info, 0, sizeof info);
  assert_int_equal(moa_param_info_get(i, &info), MOA_OK);
  return info;
}

/* Every listed parameter is readable, starts at its default, and is described sensibly. */
static void test_discovery_matches_defaults(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  size_t i, j, count = moa_param_count();
  assert_true(count > 0);
  for (i = 0; i < count; ++i) {
    const moa_param_info info = info_at(i);
    double value = -12345;
    assert_non_null(info.name);
    assert_non_null(info.description);
    assert_true(info.name[0] != '\0' && info.description[0] != '\0');
    assert_true(info.min_value <= info.default_value && info.default_value <= info.max_value);
    if (info.is_integral) assert_true(floor(info.default_value) == info.default_value);
    assert_int_equal(moa_get_param(ctx, info.name, &value), MOA_OK);
    assert_true(value == info.default_value);
    for (j = 0; j < i; ++j) assert_string_not_equal(info_at(j).name, info.name);
  }
}

/* The documented names exist. */
static void test_known_names(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  double value;
  assert_int_equal(moa_get_param(ctx, "neighbors", &value), MOA_OK);
  assert_int_equal(moa_get_param(ctx, "threads", &value), MOA_OK);
  assert_int_equal(moa_get_param(ctx, "hole_size", &value), MOA_OK);
}

static void test_unknown_name(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  double value = 7;
  assert_int_equal(moa_set_param(ctx, "foo", 1), MOA_ERROR_UNKNOWN_PARAM);
  assert_string_equal(moa_last_error(ctx), "moa_set_param: unknown parameter 'foo'");
  assert_int_equal(moa_get_param(ctx, "foo", &value), MOA_ERROR_UNKNOWN_PARAM);
  assert_string_equal(moa_last_error(ctx), "moa_get_param: unknown parameter 'foo'");
  assert_true(value == 7);
  assert_int_equal(moa_set_param(ctx, "", 1), MOA_ERROR_UNKNOWN_PARAM);
  assert_int_equal(moa_set_param(ctx, "Neighbors", 20), MOA_ERROR_UNKNOWN_PARAM);
  assert_int_equal(moa_set_param(ctx, NULL, 1), MOA_ERROR_INVALID_ARGUMENT);
  assert_true(abi_message_has(moa_last_error(ctx), "moa_set_param", "name"));
  assert_int_equal(moa_get_param(ctx, NULL, &value), MOA_ERROR_INVALID_ARGUMENT);
  assert_true(abi_message_has(moa_last_error(ctx), "moa_get_param", "name"));
}

/* A rejected value leaves the parameter as it was. */
static void expect_rejected(moa_ctx *ctx, const moa_param_info *info, double bad) {
  double before = 0, after = 0;
  assert_int_equal(moa_get_param(ctx, info->name, &before), MOA_OK);
  assert_int_equal(moa_set_param(ctx, info->name, bad), MOA_ERROR_INVALID_ARGUMENT);
  assert_true(abi_message_has(moa_last_error(ctx), "moa_set_param", info->name));
  assert_int_equal(moa_get_param(ctx, info->name, &after), MOA_OK);
  assert_true(after == before);
}

static void test_range_and_nan(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  size_t i;
  for (i = 0; i < moa_param_count(); ++i) {
    const moa_param_info info = info_at(i);
    double value = 0;
    expect_rejected(ctx, &info, info.min_value - 1);
    expect_rejected(ctx, &info, info.max_value + 1);
    expect_rejected(ctx, &info, NAN);
    expect_rejected(ctx, &info, -INFINITY);
    if (!isinf(info.max_value)) expect_rejected(ctx, &info, INFINITY);
    /* Both ends are allowed, and read back exactly. */
    assert_int_equal(moa_set_param(ctx, info.name, info.min_value), MOA_OK);
    assert_int_equal(moa_get_param(ctx, info.name, &value), MOA_OK);
    assert_true(value == info.min_value);
    assert_int_equal(moa_set_param(ctx, info.name, info.max_value), MOA_OK);
    assert_int_equal(moa_get_param(ctx, info.name, &value), MOA_OK);
    assert_true(value == info.max_value);
    assert_int_equal(moa_set_param(ctx, info.name, info.default_value), MOA_OK);
  }
}

static void test_integral(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state;
  size_t i;
  int integral_seen = 0, fractional_seen = 0;
  for (i = 0; i < moa_param_count(); ++i) {
    const moa_param_info info = info_at(i);
    const double mid = info.min_value + 0.5; /* non-integral, and inside every range here */
    if (mid > info.max_value) continue;
    if (info.is_integral) {
      integral_seen = 1;
      expect_rejected(ctx, &info, mid);
    } else {
      double value = 0;
      fractional_seen = 1;
      assert_int_equal(moa_set_param(ctx, info.name, mid), MOA_OK);
      assert_int_equal(moa_get_param(ctx, info.name, &value), MOA_OK);
      assert_true(value == mid);
      assert_int_equal(moa_set_param(ctx, info.name, info.default_value), MOA_OK);
    }
  }
  assert_true(integral_seen && fractional_seen);
  assert_int_equal(moa_set_param(ctx, "neighbors", 3.5), MOA_ERROR_INVALID_ARGUMENT);
  assert_string_equal(moa_last_error(ctx),
                      "moa_set_param: 'neighbors' must be a whole number in [8, 64], got 3.5");
}

/* Parameters survive new points and runs, and contexts do not share them. */
static void test_sticky_and_independent(void **state) {
  moa_ctx *ctx = (moa_ctx *)*state, *other = NULL;
  double xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, value = 0, other_value = 0;
  assert_int_equal(moa_set_param(ctx, "neighbors", 24), MOA_OK);
  assert_int_equal(moa_set_points(ctx, xyz, 3), MOA_OK);
  (void)moa_run(ctx); /* whatever the outcome, parameters stay */
  assert_int_equal(moa_set_points(ctx, xyz, 3), MOA_OK);
  assert_int_equal(moa_get_param(ctx, "neighbors", &value), MOA_OK);
  assert_true(value == 24);
  assert_int_equal(moa_ctx_create(&other), MOA_OK);
  assert_int_equal(moa_get_param(other, "neighbors", &other_value), MOA_OK);
  assert_true(other_value != 24);
  moa_ctx_destroy(other);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_discovery_matches_defaults, setup_ctx, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_known_names, setup_ctx, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_unknown_name, setup_ctx, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_range_and_nan, setup_ctx, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_integral, setup_ctx, teardown_ctx),
      cmocka_unit_test_setup_teardown(test_sticky_and_independent, setup_ctx, teardown_ctx),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
