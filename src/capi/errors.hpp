// How the C ABI reports failures: every exported function wraps its body in
// MOA_CAPI_TRY(ctx) ... MOA_CAPI_CATCH so that no C++ exception crosses the interface and the
// message of a failure lands on the context, or in a thread-local slot when there is no usable
// context (the pattern of Embree's RTC_CATCH_BEGIN/RTC_CATCH_END).
#pragma once

#include <new>
#include <stdexcept>

#include "capi/context.hpp"
#include "core/reconstruct.hpp"
#include "moa/moa.h"

namespace moa::capi {

// ctx if it looks like a live context, else nullptr (best effort: a handle to freed memory is
// recognised only while its magic number has not been reused).
const moa_ctx *usable(const moa_ctx *ctx) noexcept;

// The live context behind ctx; throws Error(MOA_ERROR_INVALID_ARGUMENT) naming the problem.
moa_ctx &require_ctx(moa_ctx *ctx);
const moa_ctx &require_ctx(const moa_ctx *ctx);

// Throws Error(MOA_ERROR_INVALID_ARGUMENT, "<what> is NULL") when p is NULL.
void require_non_null(const void *p, const char *what);

// Throws Error(MOA_ERROR_BAD_STATE) when ctx is inside moa_run (a progress callback calling back).
void require_idle(const moa_ctx &ctx);

// Throws Error(code, message) with a printf-formatted message.
[[noreturn]] void raise(moa_status code, const char *format, ...)
    __attribute__((format(printf, 2, 3)));

// Records "<function>: <what>" on ctx (or in the thread slot when ctx is NULL); returns code.
moa_status fail(const moa_ctx *ctx, moa_status code, const char *function,
                const char *what) noexcept;

// Records a standard exception: INTERNAL, or OUT_OF_MEMORY when no thread could be started.
moa_status fail(const moa_ctx *ctx, const char *function, const std::exception &e) noexcept;

// The thread-local message read by moa_last_error(NULL).
const char *thread_error() noexcept;

}  // namespace moa::capi

// Opens the guarded body of an exported function. ctx may be NULL or garbage.
#define MOA_CAPI_TRY(ctx)                                                 \
  const moa_ctx *const moa_capi_error_ctx_ = ::moa::capi::usable(ctx); \
  try {

// Closes it: maps every exception to a status and records the message.
#define MOA_CAPI_CATCH                                                                         \
  }                                                                                            \
  catch (const ::moa::Error &e) {                                                              \
    return ::moa::capi::fail(moa_capi_error_ctx_, e.code(), __func__, e.what());               \
  }                                                                                            \
  catch (const std::bad_alloc &) {                                                             \
    return ::moa::capi::fail(moa_capi_error_ctx_, MOA_ERROR_OUT_OF_MEMORY, __func__,           \
                             "out of memory");                                                 \
  }                                                                                            \
  catch (const std::exception &e) {                                                            \
    return ::moa::capi::fail(moa_capi_error_ctx_, __func__, e);                                \
  }                                                                                            \
  catch (...) {                                                                                \
    return ::moa::capi::fail(moa_capi_error_ctx_, MOA_ERROR_INTERNAL, __func__,                \
                             "unknown exception");                                             \
  }
