/* Proves that moa.h is plain C99: this file includes nothing else and is built with
 * -std=c99 -pedantic -Werror. It also runs, as a smoke test of the loaded library. */
#include "moa/moa.h"

static int on_progress(moa_stage stage, double fraction, void *user_data) {
  (void)stage;
  (void)fraction;
  (void)user_data;
  return 0;
}

int main(void) {
  moa_ctx *ctx = NULL;
  moa_mesh mesh = {0, NULL, 0, NULL};
  moa_param_info info;
  moa_status status;
  if (moa_version_number() != MOA_VERSION_NUMBER) return 1;
  if (moa_param_count() == 0 || moa_param_info_get(0, &info) != MOA_OK) return 2;
  if (moa_ctx_create(&ctx) != MOA_OK) return 3;
  if (moa_set_progress_callback(ctx, on_progress, NULL) != MOA_OK) return 4;
  status = moa_get_mesh(ctx, &mesh);
  moa_ctx_destroy(ctx);
  return status == MOA_ERROR_BAD_STATE && moa_status_string(status)[0] != '\0' ? 0 : 5;
}
