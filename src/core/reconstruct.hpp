// The core's entry point: points in, triangles out. Plain C++; the C ABI in src/capi wraps it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/parameters.hpp"
#include "moa/moa.h"

namespace moa {

// The core's error type; the C ABI turns its code into the returned moa_status.
class Error : public std::runtime_error {
 public:
  Error(moa_status code, const std::string &message) : std::runtime_error(message), code_(code) {}
  moa_status code() const { return code_; }

 private:
  moa_status code_;
};

// Thrown from inside the core when the progress callback asks to stop.
class Cancelled : public Error {
 public:
  Cancelled() : Error(MOA_ERROR_CANCELLED, "the run was cancelled by the progress callback") {}
};

// Receives (stage, fraction done); returns true to cancel.
using ProgressFn = std::function<bool(moa_stage, double)>;

struct Result {
  std::vector<uint32_t> triangles;  // 3 indices per triangle into the caller's points
  moa_stats stats{};
};

// Runs the whole reconstruction. Throws moa::Error (including Cancelled) or std::bad_alloc.
Result reconstruct(const double *xyz, std::size_t point_count, const Params &params,
                   const ProgressFn &progress);

}  // namespace moa
