#include "capi/errors.hpp"

#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <string>

namespace moa::capi {
namespace {

// The only global state of the library: one message per thread, for calls without a context.
thread_local std::string t_error;

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
  va_list args;
  va_start(args, format);
  va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string message(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(message.data(), message.size() + 1, format, args);
  va_end(args);
  throw Error(code, message);
}

moa_status fail(const moa_ctx *ctx, moa_status code, const char *function,
                const char *what) noexcept {
  const char *prefix = code == MOA_ERROR_INTERNAL ? "internal error (please report it): " : "";
  store(ctx != nullptr ? ctx->last_error : t_error, function, prefix, what);
  return code;
}

const char *thread_error() noexcept { return t_error.c_str(); }

}  // namespace moa::capi
