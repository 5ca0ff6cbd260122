// Bad and awkward point sets through the C ABI: each gets a defined status and a message that
// names the problem, a success keeps C1-C5, and the context stays usable afterwards.
#include <cfloat>
#include <cmath>
#include <limits>

#include "robust/robust.hpp"

using robust::Points;

namespace {

// Runs xyz on a fresh context and expects `want` with a message holding every fragment; then
// the same context must still reconstruct good points.
void expect_rejected(const Points &xyz, moa_status want, std::initializer_list<const char *> what,
                     const char *file, int line) {
  moa_ctx *ctx = robust::new_ctx();
  assert_int_equal(moa_set_points(ctx, xyz.data(), xyz.size() / 3), MOA_OK);
  robust::expect_failure(ctx, moa_run(ctx), want, what, file, line);
  moa_mesh mesh;
  assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_ERROR_BAD_STATE);
  // The same bad points fail the same way twice: nothing is left half done.
  robust::expect_failure(ctx, moa_run(ctx), want, what, file, line);
  robust::expect_usable(ctx, file, line);
  moa_ctx_destroy(ctx);
}
#define EXPECT_REJECTED(xyz, status, ...) \
  expect_rejected((xyz), (status), {__VA_ARGS__}, __FILE__, __LINE__)

Points repeated(double x, double y, double z, std::size_t n) {
  Points p;
  for (std::size_t i = 0; i < n; ++i) p.insert(p.end(), {x, y, z});
  return p;
}

void too_few_points(void **) {
  EXPECT_REJECTED(Points{}, MOA_ERROR_INVALID_INPUT, "moa_run", "at least 3 points", "got 0");
  EXPECT_REJECTED(Points({1, 2, 3}), MOA_ERROR_INVALID_INPUT, "got 1");
  EXPECT_REJECTED(Points({1, 2, 3, 4, 5, 6}), MOA_ERROR_INVALID_INPUT, "got 2");
  // The float entry point leads to the same checks.
  moa_ctx *ctx = robust::new_ctx();
  const float two[6] = {0, 0, 0, 1, 1, 1};
  assert_int_equal(moa_set_points_float(ctx, two, 2, 0), MOA_OK);
  EXPECT_FAILURE(ctx, moa_run(ctx), MOA_ERROR_INVALID_INPUT, "got 2");
  assert_int_equal(moa_set_points_float(ctx, nullptr, 0, 0), MOA_OK);
  EXPECT_FAILURE(ctx, moa_run(ctx), MOA_ERROR_INVALID_INPUT, "got 0");
  EXPECT_USABLE(ctx);
  moa_ctx_destroy(ctx);
}

void identical_points(void **) {
  EXPECT_REJECTED(repeated(1, 2, 3, 3), MOA_ERROR_INVALID_INPUT, "only 1 distinct point after",
                  "duplicates");
  EXPECT_REJECTED(repeated(-7.5, 1e6, 0, 1000), MOA_ERROR_INVALID_INPUT, "only 1 distinct");
  Points two = repeated(0, 0, 0, 50);
  const Points other = repeated(0, 0, 1, 50);
  two.insert(two.end(), other.begin(), other.end());
  EXPECT_REJECTED(two, MOA_ERROR_INVALID_INPUT, "only 2 distinct");
  // 0 and -0 are the same point.
  EXPECT_REJECTED(Points({0, 0, 0, -0.0, 0, -0.0, 0, -0.0, 0}), MOA_ERROR_INVALID_INPUT,
                  "only 1 distinct");
}

void collinear_points(void **) {
  Points line, axis, dyadic;
  for (int i = 0; i < 100; ++i) {
    line.insert(line.end(), {double(i), 2.0 * i, -3.0 * i});
    axis.insert(axis.end(), {0, 0, double(i % 10)});  // with exact duplicates
    dyadic.insert(dyadic.end(), {1e6 + i * 0.125, 1e6 - i * 0.25, 4e6 + i * 0.5});
  }
  EXPECT_REJECTED(line, MOA_ERROR_INVALID_INPUT, "moa_run", "collinear");
  EXPECT_REJECTED(axis, MOA_ERROR_INVALID_INPUT, "collinear");
  EXPECT_REJECTED(dyadic, MOA_ERROR_INVALID_INPUT, "collinear");
  // Collinear up to rounding is not exactly collinear: a defined success, C1-C5 kept, and no
  // triangle, as the points span no surface (moa.h, moa_run). So too with one point moved
  // 1e-7 off a line 370 long.
  Points rounded, bent = line;
  for (int i = 0; i < 100; ++i) rounded.insert(rounded.end(), {i * 0.1, i * 0.2, i * 0.3});
  bent[3 * 50] += 1e-7;
  moa_ctx *ctx = robust::new_ctx();
  for (const Points *p : {&rounded, &bent}) {
    assert_int_equal(EXPECT_RUN_OK(ctx, *p), 0);
    moa_stats stats;
    assert_int_equal(moa_get_stats(ctx, &stats, sizeof stats), MOA_OK);
    assert_int_equal(stats.unused_points, 100);
  }
  moa_ctx_destroy(ctx);
}

void non_finite_coordinates(void **) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(),
                        -std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::signaling_NaN(),
                        std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  const Points good = robust::sphere(50);
  for (double value : bad)
    for (std::size_t at : {std::size_t{0}, std::size_t{7 * 3 + 1}, good.size() - 1}) {
      Points p = good;
      p[at] = value;
      const std::string point = "point " + std::to_string(at / 3) + " ";
      EXPECT_REJECTED(p, MOA_ERROR_INVALID_INPUT, "moa_run", point.c_str(), "non-finite");
    }
  // Single precision too: NaN and infinity survive the conversion and are caught.
  std::vector<float> f(good.begin(), good.end());
  moa_ctx *ctx = robust::new_ctx();
  f[3 * 9 + 2] = std::numeric_limits<float>::infinity();
  assert_int_equal(moa_set_points_float(ctx, f.data(), f.size() / 3, 0), MOA_OK);
  EXPECT_FAILURE(ctx, moa_run(ctx), MOA_ERROR_INVALID_INPUT, "point 9 ", "non-finite");
  f[3 * 9 + 2] = std::numeric_limits<float>::quiet_NaN();
  assert_int_equal(moa_set_points_float(ctx, f.data(), f.size() / 3, 0), MOA_OK);
  EXPECT_FAILURE(ctx, moa_run(ctx), MOA_ERROR_INVALID_INPUT, "point 9 ", "non-finite");
  EXPECT_USABLE(ctx);
  moa_ctx_destroy(ctx);
}

void huge_magnitudes(void **) {
  const Points unit = robust::sphere(300);
  // Beyond the documented range: rejected with a request to rescale.
  EXPECT_REJECTED(robust::transformed(unit, 1e300, 0), MOA_ERROR_INVALID_INPUT, "point 0 ",
                  "1e150", "rescale");
  EXPECT_REJECTED(robust::transformed(unit, DBL_MAX, 0), MOA_ERROR_INVALID_INPUT, "rescale");
  Points one_far = unit;
  one_far[3 * 42] = -1e300;
  EXPECT_REJECTED(one_far, MOA_ERROR_INVALID_INPUT, "point 42 ", "1e150");
  // Inside it, large clouds reconstruct like the unit sphere.
  moa_ctx *ctx = robust::new_ctx();
  for (double scale : {1e100, 1e149}) {
    const Points big = robust::transformed(unit, scale, 0);
    EXPECT_RUN_OK(ctx, big);
    moa_mesh mesh;
    assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_OK);
    assert_true(moa::test::check_contract(big.data(), 300, mesh.triangles, mesh.triangle_count)
                    .closed());
  }
  moa_ctx_destroy(ctx);
}

void tiny_magnitudes(void **) {
  const Points unit = robust::sphere(300);
  EXPECT_REJECTED(robust::transformed(unit, 1e-300, 0), MOA_ERROR_INVALID_INPUT, "rescale");
  EXPECT_REJECTED(robust::transformed(unit, 1e-320, 0), MOA_ERROR_INVALID_INPUT, "rescale");
  // Subnormal coordinates: distinct doubles, still too small to work with.
  Points sub;
  for (int i = 1; i <= 20; ++i)
    sub.insert(sub.end(), {i * 5e-324, double(i % 3) * 5e-324, double(i % 5) * 5e-324});
  EXPECT_REJECTED(sub, MOA_ERROR_INVALID_INPUT, "rescale");
  moa_ctx *ctx = robust::new_ctx();
  for (double scale : {1e-50, 1e-100, 1e-150}) EXPECT_RUN_OK(ctx, robust::transformed(unit, scale, 0));
  moa_ctx_destroy(ctx);
}

// Between 1e-280 (rejected as too small) and about 1e-160, products of coordinate differences
// underflow. A sphere there must reconstruct or be rejected as too small, never called collinear.
void tiny_magnitudes_not_collinear(void **) {
  const Points unit = robust::sphere(300);
  moa_ctx *ctx = robust::new_ctx();
  for (double scale : {1e-170, 1e-200, 1e-250, 1e-279}) {
    const Points p = robust::transformed(unit, scale, 0);
    assert_int_equal(moa_set_points(ctx, p.data(), 300), MOA_OK);
    const moa_status s = moa_run(ctx);
    if (s == MOA_OK) {
      EXPECT_CONTRACT(ctx, p);
      continue;
    }
    const std::string message = moa_last_error(ctx);
    if (s != MOA_ERROR_INVALID_INPUT || message.find("collinear") != std::string::npos ||
        message.find("rescale") == std::string::npos)
      fail_msg("a sphere of radius %g: %s '%s'", scale, moa_status_string(s), message.c_str());
  }
  moa_ctx_destroy(ctx);
}

// Georeferenced data: small shapes with offsets of 1e6 and more.
void far_from_origin(void **) {
  const Points unit = robust::sphere(400);
  moa_ctx *ctx = robust::new_ctx();
  for (double offset : {1e6, -3e7, 1e9}) {
    const Points p = robust::transformed(unit, 1.0, offset);
    EXPECT_RUN_OK(ctx, p);
    moa_mesh mesh;
    assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_OK);
    if (!moa::test::check_contract(p.data(), 400, mesh.triangles, mesh.triangle_count).closed())
      fail_msg("the unit sphere at offset %g is not closed", offset);
  }
  // A terrain patch in UTM-like coordinates, metres apart, a few hundred metres up.
  Points terrain;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j)
      terrain.insert(terrain.end(), {512345.0 + 2.0 * i + 0.3 * (j % 2), 4123456.0 + 2.0 * j,
                                     312.0 + 0.5 * std::sin(0.3 * i) * std::cos(0.2 * j)});
  assert_true(EXPECT_RUN_OK(ctx, terrain) > 0);
  moa_ctx_destroy(ctx);
}

// A small dense patch and one point millions of spacings away (a stray point in scanned,
// georeferenced data): the crossing index's cells are sized by the patch's spacing, so a
// triangle to the far point spans ~1e7 cells along each axis. Found by fuzz_run
// (tests/fuzz/regressions/run/cell-count-overflow): the cell count overflowed int64.
void dense_patch_and_far_point(void **) {
  const Points patch = {0,       0, 0,       0.125,   0, -0.0625, 0.03125, 0, -0.0625,
                        0.125,   0, -0.125,  0.0625,  0, -0.0625, 0.09375, 0, -0.09375,
                        0.09375, 0, -0.0625};
  moa_ctx *ctx = robust::new_ctx();
  for (double far : {4e6, 1e8}) {
    for (double threads : {1.0, 0.0}) {
      Points p = patch;
      p.insert(p.end(), {0.125, -far, 0});
      assert_int_equal(moa_set_param(ctx, "threads", threads), MOA_OK);
      EXPECT_RUN_OK(ctx, p);
      // Georeferenced: the same with UTM-like offsets.
      p = robust::transformed(patch, 1.0, 0);
      for (std::size_t i = 0; i < p.size(); i += 3) p[i] += 512345, p[i + 1] += 4123456;
      p.insert(p.end(), {512345.125, 4123456 - far, 0});
      EXPECT_RUN_OK(ctx, p);
    }
  }
  moa_ctx_destroy(ctx);
}

// Exact duplicates merge onto their first occurrence, are counted, and are never used.
void exact_duplicates(void **) {
  const std::size_t n = 300;
  const Points unit = robust::sphere(n);
  Points p = unit;
  p.insert(p.end(), unit.begin(), unit.end());
  p.insert(p.end(), unit.begin(), unit.end());
  moa_ctx *ctx = robust::new_ctx();
  EXPECT_RUN_OK(ctx, p);
  moa_stats st;
  assert_int_equal(moa_get_stats(ctx, &st, sizeof st), MOA_OK);
  assert_int_equal(st.input_points, 3 * n);
  assert_int_equal(st.duplicate_points, 2 * n);
  assert_int_equal(st.unique_points, n);
  moa_mesh mesh;
  assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_OK);
  for (std::size_t i = 0; i < 3 * mesh.triangle_count; ++i)
    if (mesh.triangles[i] >= n) fail_msg("a duplicate (index %u) is used", mesh.triangles[i]);

  // 0 and -0 are one point: a box with zeros, then the same box with every zero negated.
  const Points box = moa::test::cube_grid(4);
  Points signed_zeros = box;
  for (double v : box) signed_zeros.push_back(v == 0 ? -v : v);
  EXPECT_RUN_OK(ctx, signed_zeros);
  assert_int_equal(moa_get_stats(ctx, &st, sizeof st), MOA_OK);
  assert_int_equal(st.duplicate_points, box.size() / 3);
  moa_ctx_destroy(ctx);
}

// Points one ulp or a nanometre apart: a few such pairs are distinct points, every one a
// vertex; a cloud full of them (half its points given twice) is merged, each pair onto the
// point given first. No crash and C1-C5 kept either way.
void near_duplicates(void **) {
  const Points unit = robust::sphere(150);
  const std::size_t n = unit.size() / 3;
  moa_ctx *ctx = robust::new_ctx();
  for (double gap : {0.0, 1e-12, 1e-9}) {
    auto twin = [&](Points &p, std::size_t i) {
      p.insert(p.end(), {gap == 0 ? std::nextafter(unit[3 * i], 2.0) : unit[3 * i] + gap,
                         unit[3 * i + 1], unit[3 * i + 2]});
    };
    Points few = unit;
    for (std::size_t i = 0; i < 3; ++i) twin(few, 50 * i);
    assert_true(EXPECT_RUN_OK(ctx, few) > 0);
    moa_stats st;
    assert_int_equal(moa_get_stats(ctx, &st, sizeof st), MOA_OK);
    assert_int_equal(st.duplicate_points, 0);
    assert_int_equal(st.near_duplicate_points, 0);
    assert_int_equal(st.used_points, n + 3);  // every point a vertex

    Points many = unit;
    for (std::size_t i = 0; i < n; i += 2) twin(many, i);
    assert_true(EXPECT_RUN_OK(ctx, many) > 0);
    assert_int_equal(moa_get_stats(ctx, &st, sizeof st), MOA_OK);
    assert_int_equal(st.unique_points, n);
    assert_int_equal(st.duplicate_points, n / 2);
    assert_int_equal(st.near_duplicate_points, n / 2);
    moa_mesh mesh;
    assert_int_equal(moa_get_mesh(ctx, &mesh), MOA_OK);
    for (std::size_t i = 0; i < 3 * mesh.triangle_count; ++i)
      if (mesh.triangles[i] >= n) fail_msg("a second copy (index %u) is used", mesh.triangles[i]);
  }
  moa_ctx_destroy(ctx);
}

}  // namespace

int main() {
  const CMUnitTest tests[] = {
      cmocka_unit_test(too_few_points),
      cmocka_unit_test(identical_points),
      cmocka_unit_test(collinear_points),
      cmocka_unit_test(non_finite_coordinates),
      cmocka_unit_test(huge_magnitudes),
      cmocka_unit_test(tiny_magnitudes),
      cmocka_unit_test(tiny_magnitudes_not_collinear),
      cmocka_unit_test(far_from_origin),
      cmocka_unit_test(dense_patch_and_far_point),
      cmocka_unit_test(exact_duplicates),
      cmocka_unit_test(near_duplicates),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
