// The C++ layer that SWIG wraps for every language binding. It owns one moa_ctx and gives it
// signatures that map onto target-language arrays: a pointer plus the array's length, status
// codes instead of exceptions (each language raises its own error type from them), and a
// progress hook that a target language either subclasses (SWIG directors) or feeds with a
// plain function pointer (ahead-of-time runtimes such as Unity's IL2CPP cannot host directors).
#ifndef MOA_BINDINGS_MOA_SWIG_HPP
#define MOA_BINDINGS_MOA_SWIG_HPP

#include <cstddef>
#include <cstdint>
#include <string>

#include "moa/moa.h"

namespace moa_swig {

// Progress hook for directors: target languages subclass it and override on_progress.
class NativeProgress {
 public:
  virtual ~NativeProgress() {}
  // stage is a moa_stage value, fraction the part of that stage done (0..1). Called on the
  // thread that called NativeContext::run. Return false to cancel the run.
  virtual bool on_progress(int stage, double fraction);
};

// The same hook as a plain function: return 0 to cancel the run. handle is passed back as given.
typedef int (*NativeProgressFn)(void *handle, int stage, double fraction);

// One entry of the parameter table; the strings have static storage.
struct NativeParam {
  const char *name;
  const char *description;
  double default_value;
  double min_value;
  double max_value;
  bool integral;
};

// A reconstruction context. Every int result is a moa_status; on failure last_error() says why.
class NativeContext {
 public:
  NativeContext() {}
  ~NativeContext();
  NativeContext(const NativeContext &) = delete;
  NativeContext &operator=(const NativeContext &) = delete;

  // Creates the underlying moa_ctx. Kept out of the constructor so its failure is a status.
  int open();
  // Releases the moa_ctx now rather than when the target language collects this object.
  void close();
  bool is_open() const { return ctx_ != nullptr; }

  // length is the number of values in xyz (3 per point); it must be a multiple of 3.
  int set_points(const double *xyz, size_t length);
  int set_points_float(const float *xyz, size_t length);
  int set_param(const char *name, double value);
  int get_param(const char *name, double *value);

  // Installs a hook (nullptr removes it). Only one kind is active: setting one clears the other.
  // The hook is not owned and must outlive the runs that use it.
  void set_listener(NativeProgress *listener);
  void set_progress_function(NativeProgressFn function, void *handle);

  int run();

  // Sizes of the last mesh (0 without one) and copies of its arrays: at most capacity values,
  // 3 per vertex or triangle.
  size_t vertex_count() const;
  size_t triangle_count() const;
  int copy_vertices(double *out, size_t capacity);
  int copy_triangles(int *out, size_t capacity);
  // The arrays themselves, valid until the next set_points*, run or close (nullptr without a
  // mesh), for bindings that convert them element by element.
  const double *vertex_data() const { return mesh().vertices; }
  const uint32_t *triangle_data() const { return mesh().triangles; }

  // Message of the last failed call on this object. Never NULL.
  const char *last_error() const;

  static const char *status_name(int status);
  static const char *stage_name(int stage);
  static const char *version();
  static size_t param_count();
  // Entry index of the parameter table; an entry with an empty name when out of range.
  static NativeParam param_info(size_t index);

 private:
  static int trampoline(moa_stage stage, double fraction, void *self);
  int fail(int status, const std::string &message);
  int check(moa_status status);
  int require_open();
  moa_mesh mesh() const;

  moa_ctx *ctx_ = nullptr;
  NativeProgress *listener_ = nullptr;
  NativeProgressFn function_ = nullptr;
  void *handle_ = nullptr;
  // Set when this layer, not libmoa, refused the last call.
  bool own_error_ = false;
  std::string error_;
};

}  // namespace moa_swig

#endif  // MOA_BINDINGS_MOA_SWIG_HPP
