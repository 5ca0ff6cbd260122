// The object behind the opaque moa_ctx handle. Only src/capi sees its layout.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/parameters.hpp"
#include "moa/moa.h"

struct moa_ctx {
  // A live context carries kLiveMagic; moa_ctx_destroy overwrites it so that a stale handle is
  // (usually) recognised instead of being used.
  static constexpr std::uint64_t kLiveMagic = 0x6d6f615f63747821ull;  // "moa_ctx!"
  static constexpr std::uint64_t kDeadMagic = 0x6d6f615f64656164ull;  // "moa_dead"

  std::uint64_t magic = kLiveMagic;

  moa::Params params;

  // The caller's points as doubles, x y z per point, in the caller's order.
  std::vector<double> points;
  bool has_points = false;

  moa_progress_fn progress = nullptr;
  void *progress_user_data = nullptr;

  // Set while moa_run is inside the core, so that a progress callback calling back into the
  // same context cannot pull the points or the parameters from under it.
  bool running = false;

  // The last successful run.
  bool has_mesh = false;
  std::vector<std::uint32_t> triangles;
  moa_stats stats{};

  // Message of the last failed call; written by const entry points too.
  mutable std::string last_error;

  void discard_mesh() noexcept {
    has_mesh = false;
    triangles.clear();
    triangles.shrink_to_fit();
    stats = moa_stats{};
  }
};
