// Entry points that create a context and fill it: points, parameters, progress callback.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "capi/errors.hpp"
#include "core/parameters.hpp"
#include "moa/moa.h"

namespace {

using moa::capi::raise;

// Triangle indices are uint32_t and UINT32_MAX stays free as a sentinel.
constexpr std::size_t kMaxPoints = std::size_t{0xFFFFFFFFu} - 1;

void check_point_count(std::size_t point_count) {
  if (point_count > kMaxPoints || point_count > std::numeric_limits<std::size_t>::max() / 3)
    raise(MOA_ERROR_INVALID_ARGUMENT,
          "point_count %zu is too large: triangle indices are 32-bit, so at most %zu points",
          point_count, kMaxPoints);
}

// The spec of a known parameter; throws MOA_ERROR_UNKNOWN_PARAM otherwise.
const moa::ParamSpec &require_param(const char *name) {
  moa::capi::require_non_null(name, "name");
  const moa::ParamSpec *spec = moa::find_param(name);
  if (spec == nullptr) raise(MOA_ERROR_UNKNOWN_PARAM, "unknown parameter '%s'", name);
  return *spec;
}

// Replaces the points with a fresh copy; the old points and mesh survive a failed copy.
void replace_points(moa_ctx &ctx, std::vector<double> &&xyz) {
  ctx.discard_mesh();
  ctx.points = std::move(xyz);
  ctx.has_points = true;
}

}  // namespace

extern "C" {

MOA_API moa_status moa_ctx_create(moa_ctx **out_ctx) {
  MOA_CAPI_TRY(nullptr)
  moa::capi::require_non_null(out_ctx, "out_ctx");
  *out_ctx = nullptr;
  *out_ctx = std::make_unique<moa_ctx>().release();
  return MOA_OK;
  MOA_CAPI_CATCH
}

MOA_API void moa_ctx_destroy(moa_ctx *ctx) {
  // Nothing to report through a void function: an unusable handle is left alone.
  if (moa::capi::usable(ctx) == nullptr || ctx->running) return;
  ctx->magic = moa_ctx::kDeadMagic;
  delete ctx;
}

MOA_API moa_status moa_set_points(moa_ctx *ctx, const double *xyz, size_t point_count) {
  MOA_CAPI_TRY(ctx)
  moa_ctx &c = moa::capi::require_ctx(ctx);
  moa::capi::require_idle(c);
  if (xyz == nullptr && point_count > 0)
    raise(MOA_ERROR_INVALID_ARGUMENT, "xyz is NULL but point_count is %zu", point_count);
  check_point_count(point_count);
  std::vector<double> copy(xyz, xyz + 3 * point_count);
  replace_points(c, std::move(copy));
  return MOA_OK;
  MOA_CAPI_CATCH
}

MOA_API moa_status moa_set_points_float(moa_ctx *ctx, const float *xyz, size_t point_count,
                                        size_t stride_bytes) {
  MOA_CAPI_TRY(ctx)
  moa_ctx &c = moa::capi::require_ctx(ctx);
  moa::capi::require_idle(c);
  if (xyz == nullptr && point_count > 0)
    raise(MOA_ERROR_INVALID_ARGUMENT, "xyz is NULL but point_count is %zu", point_count);
  constexpr std::size_t kPacked = 3 * sizeof(float);
  if (stride_bytes != 0 && stride_bytes < kPacked)
    raise(MOA_ERROR_INVALID_ARGUMENT,
          "stride_bytes %zu is smaller than one point (%zu bytes); pass 0 for packed points",
          stride_bytes, kPacked);
  check_point_count(point_count);
  const std::size_t stride = stride_bytes == 0 ? kPacked : stride_bytes;
  std::vector<double> copy(3 * point_count);
  const auto *base = reinterpret_cast<const unsigned char *>(xyz);
  for (std::size_t i = 0; i < point_count; ++i) {
    // memcpy: an interleaved buffer need not keep its floats aligned.
    float p[3];
    std::memcpy(p, base + i * stride, sizeof p);
    copy[3 * i] = p[0];
    copy[3 * i + 1] = p[1];
    copy[3 * i + 2] = p[2];
  }
  replace_points(c, std::move(copy));
  return MOA_OK;
  MOA_CAPI_CATCH
}

MOA_API moa_status moa_set_param(moa_ctx *ctx, const char *name, double value) {
  MOA_CAPI_TRY(ctx)
  moa_ctx &c = moa::capi::require_ctx(ctx);
  moa::capi::require_idle(c);
  const moa::ParamSpec &spec = require_param(name);
  // The negated comparison also rejects NaN.
  const bool in_range = value >= spec.min_value && value <= spec.max_value;
  if (!in_range || (spec.integral && std::floor(value) != value))
    raise(MOA_ERROR_INVALID_ARGUMENT, "'%s' must be %s in [%g, %g], got %g", spec.name,
          spec.integral ? "a whole number" : "a number", spec.min_value, spec.max_value, value);
  c.params.*spec.field = value;
  return MOA_OK;
  MOA_CAPI_CATCH
}

MOA_API moa_status moa_get_param(const moa_ctx *ctx, const char *name, double *out_value) {
  MOA_CAPI_TRY(ctx)
  const moa_ctx &c = moa::capi::require_ctx(ctx);
  const moa::ParamSpec &spec = require_param(name);
  moa::capi::require_non_null(out_value, "out_value");
  *out_value = c.params.*spec.field;
  return MOA_OK;
  MOA_CAPI_CATCH
}

MOA_API moa_status moa_set_progress_callback(moa_ctx *ctx, moa_progress_fn callback,
                                             void *user_data) {
  MOA_CAPI_TRY(ctx)
  moa_ctx &c = moa::capi::require_ctx(ctx);
  // moa_run copies the callback before it starts, so changing it from inside is harmless.
  c.progress = callback;
  c.progress_user_data = user_data;
  return MOA_OK;
  MOA_CAPI_CATCH
}

}  // extern "C"
