// The C++ layer under the SWIG bindings; see moa_swig.hpp.
#include "moa_swig.hpp"

#include <cstring>
#include <string>

namespace moa_swig {

bool NativeProgress::on_progress(int, double) { return true; }

NativeContext::~NativeContext() { close(); }

int NativeContext::open() {
  if (ctx_ != nullptr) return MOA_OK;
  const moa_status status = moa_ctx_create(&ctx_);
  // Without a context libmoa keeps the message in its thread slot; keep a copy here.
  if (status != MOA_OK) return fail(status, moa_last_error(nullptr));
  return check(status);
}

void NativeContext::close() {
  moa_ctx_destroy(ctx_);
  ctx_ = nullptr;
}

int NativeContext::fail(int status, const std::string &message) {
  own_error_ = true;
  error_ = message;
  return status;
}

int NativeContext::check(moa_status status) {
  if (status != MOA_OK) own_error_ = false;
  return status;
}

int NativeContext::require_open() {
  if (ctx_ != nullptr) return MOA_OK;
  return fail(MOA_ERROR_BAD_STATE, "the reconstructor is closed");
}

int NativeContext::set_points(const double *xyz, size_t length) {
  if (int s = require_open()) return s;
  if (length % 3 != 0)
    return fail(MOA_ERROR_INVALID_ARGUMENT,
                "xyz has " + std::to_string(length) + " values, not 3 per point");
  return check(moa_set_points(ctx_, xyz, length / 3));
}

int NativeContext::set_points_float(const float *xyz, size_t length) {
  if (int s = require_open()) return s;
  if (length % 3 != 0)
    return fail(MOA_ERROR_INVALID_ARGUMENT,
                "xyz has " + std::to_string(length) + " values, not 3 per point");
  return check(moa_set_points_float(ctx_, xyz, length / 3, 0));
}

int NativeContext::set_param(const char *name, double value) {
  if (int s = require_open()) return s;
  return check(moa_set_param(ctx_, name, value));
}

int NativeContext::get_param(const char *name, double *value) {
  *value = 0.0;
  if (int s = require_open()) return s;
  return check(moa_get_param(ctx_, name, value));
}

void NativeContext::set_listener(NativeProgress *listener) {
  listener_ = listener;
  function_ = nullptr;
  handle_ = nullptr;
}

void NativeContext::set_progress_function(NativeProgressFn function, void *handle) {
  listener_ = nullptr;
  function_ = function;
  handle_ = handle;
}

int NativeContext::trampoline(moa_stage stage, double fraction, void *self) {
  const NativeContext &c = *static_cast<const NativeContext *>(self);
  // An exception must not unwind into libmoa (a director may throw one when the target
  // language's handler failed): stopping the run is the only safe answer.
  try {
    if (c.listener_ != nullptr) return c.listener_->on_progress(int(stage), fraction) ? 0 : 1;
    if (c.function_ != nullptr) return c.function_(c.handle_, int(stage), fraction) != 0 ? 0 : 1;
  } catch (...) {
    return 1;
  }
  return 0;
}

int NativeContext::run() {
  if (int s = require_open()) return s;
  // Install the trampoline only when a hook exists, so a plain run pays nothing for it.
  const bool hooked = listener_ != nullptr || function_ != nullptr;
  moa_set_progress_callback(ctx_, hooked ? &NativeContext::trampoline : nullptr, this);
  return check(moa_run(ctx_));
}

moa_mesh NativeContext::mesh() const {
  moa_mesh m;
  std::memset(&m, 0, sizeof m);
  if (ctx_ == nullptr || moa_get_mesh(ctx_, &m) != MOA_OK) std::memset(&m, 0, sizeof m);
  return m;
}

size_t NativeContext::vertex_count() const { return mesh().vertex_count; }

size_t NativeContext::triangle_count() const { return mesh().triangle_count; }

int NativeContext::copy_vertices(double *out, size_t capacity) {
  if (int s = require_open()) return s;
  moa_mesh m;
  if (moa_status s = moa_get_mesh(ctx_, &m)) return check(s);
  const size_t n = capacity < 3 * m.vertex_count ? capacity : 3 * m.vertex_count;
  if (n > 0) std::memcpy(out, m.vertices, n * sizeof(double));
  return MOA_OK;
}

int NativeContext::copy_triangles(int *out, size_t capacity) {
  static_assert(sizeof(int) == sizeof(uint32_t), "indices are copied as 32-bit ints");
  if (int s = require_open()) return s;
  size_t total = 0;
  // The languages that call this index arrays with signed 32-bit ints, and their arrays hold
  // fewer than 2^31 values, so every index fits.
  return check(moa_copy_triangles(ctx_, reinterpret_cast<uint32_t *>(out), capacity, &total));
}

const char *NativeContext::last_error() const {
  if (own_error_) return error_.c_str();
  return moa_last_error(ctx_);
}

const char *NativeContext::status_name(int status) {
  return moa_status_string(static_cast<moa_status>(status));
}

const char *NativeContext::stage_name(int stage) {
  return moa_stage_name(static_cast<moa_stage>(stage));
}

const char *NativeContext::version() { return moa_version(); }

size_t NativeContext::param_count() { return moa_param_count(); }

NativeParam NativeContext::param_info(size_t index) {
  moa_param_info info;
  if (moa_param_info_get(index, &info) != MOA_OK) return NativeParam{"", "", 0.0, 0.0, 0.0, false};
  return NativeParam{info.name, info.description, info.default_value,
                     info.min_value, info.max_value, info.is_integral != 0};
}

}  // namespace moa_swig
