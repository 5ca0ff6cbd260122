// Entry points that run the reconstruction and read its results.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "capi/errors.hpp"
#include "core/reconstruct.hpp"
#include "moa/moa.h"

namespace {

using moa::capi::raise;

// Clears ctx.running however moa_run leaves.
class RunningFlag {
 public:
  explicit RunningFlag(moa_ctx &ctx) : ctx_(ctx) { ctx_.running = true; }
  ~RunningFlag() { ctx_.running = false; }
  RunningFlag(const RunningFlag &) = delete;
  RunningFlag &operator=(const RunningFlag &) = delete;

 private:
  moa_ctx &ctx_;
};

// The core promises valid indices; a broken promise must not reach the caller as a crash.
void check_result(const std::vector<std::uint32_t> &triangles, std::size_t point_count) {
  if (triangles.size() % 3 != 0)
    raise(MOA_ERROR_INTERNAL, "the core returned %zu indices, not a multiple of 3",
          triangles.size());
  for (std::uint32_t index : triangles)
    if (index >= point_count)
      raise(MOA_ERROR_INTERNAL, "the core returned vertex index %u for %zu points",
            static_cast<unsigned>(index), point_count);
}

const moa_ctx &require_mesh(const moa_ctx *ctx) {
  const moa_ctx &c = moa::capi::require_ctx(ctx);
  if (!c.has_mesh)
    raise(MOA_ERROR_BAD_STATE,
          "no mesh: moa_run has not succeeded since the points were last set");
  return c;
}

}  // namespace

extern "C" {

MOA_API moa_status moa_run(moa_ctx *ctx) {
  MOA_CAPI_TRY(ctx)
  moa_ctx &c = moa::capi::require_ctx(ctx);
  moa::capi::require_idle(c);
  if (!c.has_points)
    raise(MOA_ERROR_BAD_STATE, "no points: call moa_set_points or moa_set_points_float first");
  c.discard_mesh();

  const moa_progress_fn callback = c.progress;
  void *const user_data = c.progress_user_data;
  const moa::ProgressFn progress = [callback, user_data](moa_stage stage, double fraction) {
    return callback != nullptr && callback(stage, fraction, user_data) != 0;
  };

  const std::size_t point_count = c.points.size() / 3;
  const auto start = std::chrono::steady_clock::now();
  moa::Result result;
  {
    RunningFlag running(c);
    result = moa::reconstruct(c.points.data(), point_count, c.params, progress);
  }
  const std::chrono::duration<double, std::milli> elapsed =
      std::chrono::steady_clock::now() - start;
  check_result(result.triangles, point_count);

  c.triangles = std::move(result.triangles);
  c.stats = result.stats;
  if (c.stats.total_ms <= 0) c.stats.total_ms = elapsed.count();
  c.has_mesh = true;
  return MOA_OK;
  MOA_CAPI_CATCH
}

MOA_API moa_status moa_get_mesh(const moa_ctx *ctx, moa_mesh *out_mesh) {
  MOA_CAPI_TRY(ctx)
  moa::capi::require_ctx(ctx);
  moa::capi::require_non_null(out_mesh, "out_mesh");
  const moa_ctx &c = require_mesh(ctx);
  out_mesh->vertex_count = c.points.size() / 3;
  out_mesh->vertices = c.points.data();
  out_mesh->triangle_count = c.triangles.size() / 3;
  out_mesh->triangles = c.triangles.data();
  return MOA_OK;
  MOA_CAPI_CATCH
}

MOA_API moa_status moa_copy_triangles(const moa_ctx *ctx, uint32_t *out, size_t capacity,
                                      size_t *out_total) {
  MOA_CAPI_TRY(ctx)
  moa::capi::require_ctx(ctx);
  moa::capi::require_non_null(out_total, "out_total");
  if (out == nullptr && capacity > 0)
    raise(MOA_ERROR_INVALID_ARGUMENT, "out is NULL but capacity is %zu", capacity);
  const moa_ctx &c = require_mesh(ctx);
  const std::size_t n = std::min(capacity, c.triangles.size());
  if (n > 0) std::memcpy(out, c.triangles.data(), n * sizeof(std::uint32_t));
  *out_total = c.triangles.size();
  return MOA_OK;
  MOA_CAPI_CATCH
}

MOA_API moa_status moa_get_stats(const moa_ctx *ctx, moa_stats *out_stats, size_t stats_size) {
  MOA_CAPI_TRY(ctx)
  moa::capi::require_ctx(ctx);
  moa::capi::require_non_null(out_stats, "out_stats");
  const moa_ctx &c = require_mesh(ctx);
  // An older caller passes a smaller struct; a newer one a larger struct whose tail stays as is.
  std::memcpy(out_stats, &c.stats, std::min(stats_size, sizeof(moa_stats)));
  return MOA_OK;
  MOA_CAPI_CATCH
}

}  // extern "C"
