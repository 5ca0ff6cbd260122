// Helpers of the robustness tests: cmocka from C++, point sets, and checks that a context
// failed with the right status and message, or succeeded with a mesh that keeps C1-C5.
#pragma once

#include <csetjmp>  // cmocka needs these before its header
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>  // before cmocka.h, whose fail() macro breaks std::ios::fail
#include <initializer_list>
#include <string>
#include <vector>

#include "moa/moa.h"
#include "support/contract_checker.hpp"
#include "support/shapes.hpp"

extern "C" {  // cmocka 1.1 does not declare its functions extern "C" itself
#include <cmocka.h>
}

namespace robust {

// fail_msg with the caller's file and line.
[[noreturn]] inline void fail_at(const char *file, int line, const char *format, ...)
    __attribute__((format(printf, 3, 4)));
inline void fail_at(const char *file, int line, const char *format, ...) {
  va_list args;
  va_start(args, format);
  vprint_error(format, args);
  va_end(args);
  print_error("\n");
  _fail(file, line);
  std::abort();  // _fail longjmps out; this only tells the compiler
}

using Points = std::vector<double>;

// An evenly sampled unit sphere: a closed surface any parameter set reconstructs.
inline Points sphere(std::size_t n = 400) { return moa::test::fibonacci_sphere(n, 1.0); }

inline Points transformed(Points p, double scale, double offset) {
  for (double &v : p) v = v * scale + offset;
  return p;
}

// A fresh context; fails the test if none can be made.
inline moa_ctx *new_ctx() {
  moa_ctx *ctx = nullptr;
  assert_int_equal(moa_ctx_create(&ctx), MOA_OK);
  assert_non_null(ctx);
  return ctx;
}

// Fails the test unless `got` is `want` and the context's message holds every fragment.
inline void expect_failure(const moa_ctx *ctx, moa_status got, moa_status want,
                           std::initializer_list<const char *> fragments, const char *file,
                           int line) {
  const std::string message = moa_last_error(ctx);
  if (got != want)
    fail_at(file, line, "got %s, expected %s (message: '%s')", moa_status_string(got),
              moa_status_string(want), message.c_str());
  if (message.empty()) fail_at(file, line, "%s with an empty message", moa_status_string(got));
  for (const char *f : fragments)
    if (message.find(f) == std::string::npos)
      fail_at(file, line, "message '%s' lacks '%s'", message.c_str(), f);
}

// The mesh of the last run, checked against C1-C5 on the points that were given; returns the
// number of triangles.
inline std::size_t expect_contract(const moa_ctx *ctx, const Points &xyz, const char *file,
                                   int line) {
  moa_mesh mesh;
  std::memset(&mesh, 0, sizeof mesh);
  if (moa_get_mesh(ctx, &mesh) != MOA_OK) fail_at(file, line, "no mesh: %s", moa_last_error(ctx));
  if (mesh.vertex_count != xyz.size() / 3)
    fail_at(file, line, "%zu vertices for %zu points", mesh.vertex_count, xyz.size() / 3);
  const moa::test::ContractReport report =
      moa::test::check_contract(xyz.data(), xyz.size() / 3, mesh.triangles, mesh.triangle_count);
  if (!report.ok()) fail_at(file, line, "contract broken:\n%s", report.describe().c_str());
  return mesh.triangle_count;
}

// Runs xyz; fails unless the run gives MOA_OK and a mesh that keeps the contract.
inline std::size_t expect_run_ok(moa_ctx *ctx, const Points &xyz, const char *file, int line) {
  if (moa_set_points(ctx, xyz.data(), xyz.size() / 3) != MOA_OK)
    fail_at(file, line, "moa_set_points: %s", moa_last_error(ctx));
  const moa_status s = moa_run(ctx);
  if (s != MOA_OK) fail_at(file, line, "%s: %s", moa_status_string(s), moa_last_error(ctx));
  return expect_contract(ctx, xyz, file, line);
}

// A failed call leaves the context usable: good points reconstruct to a closed sphere.
inline void expect_usable(moa_ctx *ctx, const char *file, int line) {
  const Points good = sphere(200);
  expect_run_ok(ctx, good, file, line);
  moa_mesh mesh;
  moa_get_mesh(ctx, &mesh);
  const auto report =
      moa::test::check_contract(good.data(), good.size() / 3, mesh.triangles, mesh.triangle_count);
  if (!report.closed()) fail_at(file, line, "the sphere after a failure is not closed");
}

}  // namespace robust

#define EXPECT_FAILURE(ctx, call, status, ...) \
  robust::expect_failure((ctx), (call), (status), {__VA_ARGS__}, __FILE__, __LINE__)
#define EXPECT_CONTRACT(ctx, xyz) robust::expect_contract((ctx), (xyz), __FILE__, __LINE__)
#define EXPECT_RUN_OK(ctx, xyz) robust::expect_run_ok((ctx), (xyz), __FILE__, __LINE__)
#define EXPECT_USABLE(ctx) robust::expect_usable((ctx), __FILE__, __LINE__)
