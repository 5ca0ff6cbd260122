#include "capi/errors.hpp"

#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace moa::capi {
namespace {

// The only global state of the library: one message per thread, for calls without a context.
// A plain array: a thread_local with a destructor makes glibc allocate on the thread's first
// use and abort when that fails, which is exactly when an out-of-memory error is reported.
thread_local char t_error[512];

void store(char *slot, std::size_t size, const char *function, const char *prefix,
           const char *what) noexcept {
  std::snprintf(slot, size, "%s: %s%s", function, prefix, what);  // truncates, never fails
}

void store(std::string &slot, const char *function, const char *prefix,
           const char *what) noexcept {
  try {
    slot.assign(function);
    slot.append(": ");
    slot.append(prefix);
    slot.append(what);
  } catch (...) {
    // Out of memory while reporting: an empty message is better than a stale one.
    slot.clear();
  }
}

}  // namespace

const moa_ctx *usable(const moa_ctx *ctx) noexcept {
  if (ctx == nullptr) return nullptr;
  // A misaligned pointer cannot be a context, and reading through it would be undefined.
  if (reinterpret_cast<std::uintptr_t>(ctx) % alignof(moa_ctx) != 0) return nullptr;
  return ctx->magic == moa_ctx::kLiveMagic ? ctx : nullptr;
}

const moa_ctx &require_ctx(const moa_ctx *ctx) {
  if (ctx == nullptr) raise(MOA_ERROR_INVALID_ARGUMENT, "ctx is NULL");
  if (usable(ctx) == nullptr)
    raise(MOA_ERROR_INVALID_ARGUMENT,
          "ctx is not a live context (destroyed, or not made by moa_ctx_create)");
  return *ctx;
}

moa_ctx &require_ctx(moa_ctx *ctx) {
  return const_cast<moa_ctx &>(require_ctx(static_cast<const moa_ctx *>(ctx)));
}

void require_non_null(const void *p, const char *what) {
  if (p == nullptr) raise(MOA_ERROR_INVALID_ARGUMENT, "%s is NULL", what);
}

void require_idle(const moa_ctx &ctx) {
  if (ctx.running)
    raise(MOA_ERROR_BAD_STATE, "the context is inside moa_run (called from its progress callback)");
}

void raise(moa_status code, const char *format, ...) {
  char message[1024];  // on the stack: argument errors are reported even with no heap left
  va_list args;
  va_start(args, format);
  std::vsnprintf(message, sizeof message, format, args);
  va_end(args);
  throw Error(code, message);
}

moa_status fail(const moa_ctx *ctx, moa_status code, const char *function,
                const char *what) noexcept {
  const char *prefix = code == MOA_ERROR_INTERNAL ? "internal error (please report it): " : "";
  if (ctx != nullptr)
    store(ctx->last_error, function, prefix, what);
  else
    store(t_error, sizeof t_error, function, prefix, what);
  return code;
}

moa_status fail(const moa_ctx *ctx, const char *function, const std::exception &e) noexcept {
  // TBB reports a worker thread it could not start as a runtime_error; under a memory cap
  // that is an out-of-memory condition, which the caller can act on.
  if (std::strstr(e.what(), "pthread_create") != nullptr)
    return fail(ctx, MOA_ERROR_OUT_OF_MEMORY, function,
                "out of memory (could not start a worker thread)");
  return fail(ctx, MOA_ERROR_INTERNAL, function, e.what());
}

const char *thread_error() noexcept { return t_error; }

}  // namespace moa::capi
