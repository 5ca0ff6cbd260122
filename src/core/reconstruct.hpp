// The core's entry point: points in, triangles out. Plain C++; the C ABI in src/capi wraps it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/parameters.hpp"
#include "moa/moa.h"

namespace moa {

// The core's error type; the C ABI turns its code into the returned moa_status.
// The message lives in the exception itself: reporting an error, even "out of memory" or a
// NULL argument with the heap exhausted, must not need the heap.
class Error : public std::exception {
 public:
  Error(moa_status code, const char *message) noexcept : code_(code) {
    std::snprintf(message_, sizeof message_, "%s", message);
  }
  Error(moa_status code, const std::string &message) noexcept : Error(code, message.c_str()) {}
  moa_status code() const noexcept { return code_; }
  const char *what() const noexcept override { return message_; }

 private:
  moa_status code_;
  char message_[1024];
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
// The points are reordered in place while it runs and are back in their order, bit for bit,
// when it returns or throws.
Result reconstruct(double *xyz, std::size_t point_count, const Params &params,
                   const ProgressFn &progress);

}  // namespace moa
