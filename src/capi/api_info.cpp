// Entry points that describe the library rather than a context: versions, names of codes,
// parameter discovery, and the last error.
#include <cstddef>

#include "capi/errors.hpp"
#include "core/parameters.hpp"
#include "moa/moa.h"

extern "C" {

MOA_API const char *moa_version(void) { return MOA_VERSION_STRING; }

MOA_API unsigned moa_version_number(void) { return MOA_VERSION_NUMBER; }

MOA_API const char *moa_status_string(moa_status status) {
  switch (status) {
    case MOA_OK: return "MOA_OK";
    case MOA_ERROR_INVALID_ARGUMENT: return "MOA_ERROR_INVALID_ARGUMENT";
    case MOA_ERROR_UNKNOWN_PARAM: return "MOA_ERROR_UNKNOWN_PARAM";
    case MOA_ERROR_INVALID_INPUT: return "MOA_ERROR_INVALID_INPUT";
    case MOA_ERROR_BAD_STATE: return "MOA_ERROR_BAD_STATE";
    case MOA_ERROR_OUT_OF_MEMORY: return "MOA_ERROR_OUT_OF_MEMORY";
    case MOA_ERROR_CANCELLED: return "MOA_ERROR_CANCELLED";
    case MOA_ERROR_IO: return "MOA_ERROR_IO";
    case MOA_ERROR_INTERNAL: return "MOA_ERROR_INTERNAL";
  }
  // A C caller may pass any integer.
  return "MOA_ERROR_UNKNOWN_STATUS";
}

MOA_API const char *moa_stage_name(moa_stage stage) {
  switch (stage) {
    case MOA_STAGE_POINTS: return "points";
    case MOA_STAGE_NEIGHBORS: return "neighbors";
    case MOA_STAGE_MESH: return "mesh";
    case MOA_STAGE_LOOPS: return "loops";
    case MOA_STAGE_FINISH: return "finish";
    case MOA_STAGE_COUNT: break;
  }
  return "unknown";
}

MOA_API const char *moa_last_error(const moa_ctx *ctx) {
  // A NULL or unusable handle had its failures recorded in the thread slot, so read that.
  const moa_ctx *live = moa::capi::usable(ctx);
  return live != nullptr ? live->last_error.c_str() : moa::capi::thread_error();
}

MOA_API size_t moa_param_count(void) {
  std::size_t count = 0;
  moa::param_table(count);
  return count;
}

MOA_API moa_status moa_param_info_get(size_t index, moa_param_info *out_info) {
  MOA_CAPI_TRY(nullptr)
  moa::capi::require_non_null(out_info, "out_info");
  std::size_t count = 0;
  const moa::ParamSpec *table = moa::param_table(count);
  if (index >= count)
    moa::capi::raise(MOA_ERROR_INVALID_ARGUMENT,
                     "index %zu is out of range (moa_param_count() = %zu)", index, count);
  const moa::ParamSpec &spec = table[index];
  out_info->name = spec.name;
  out_info->description = spec.description;
  out_info->default_value = spec.default_value;
  out_info->min_value = spec.min_value;
  out_info->max_value = spec.max_value;
  out_info->is_integral = spec.integral ? 1 : 0;
  return MOA_OK;
  MOA_CAPI_CATCH
}

}  // extern "C"
