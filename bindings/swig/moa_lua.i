// Lua part of moa.i. SWIG's module is the raw layer; bindings/lua/moa.lua, compiled into the
// module as a string, builds the table that require("moa") returns on top of it.

// A flat Lua table of numbers for a (pointer, length) pair. The buffer is a userdata so that an
// error raised halfway (a longjmp in Lua) cannot leak it.
%typemap(in, checkfn="lua_istable") (const double *xyz, size_t length) {
  $2 = (size_t)lua_rawlen(L, $input);
  $1 = (double *)lua_newuserdatauv(L, ($2 > 0 ? $2 : 1) * sizeof(double), 0);
  for (size_t i = 0; i < $2; ++i) {
    int isnum = 0;
    lua_rawgeti(L, $input, (lua_Integer)i + 1);
    const_cast<double *>($1)[i] = lua_tonumberx(L, -1, &isnum);
    lua_pop(L, 1);
    if (!isnum) {
      lua_pushfstring(L, "value %d of the points is not a number", (int)(i + 1));
      SWIG_fail;
    }
  }
}

// Lua numbers are doubles; the progress hook and the mesh go through the natives below.
%ignore moa_swig::NativeProgress;
%ignore moa_swig::NativeContext::set_points_float;
%ignore moa_swig::NativeContext::set_listener;
%ignore moa_swig::NativeContext::set_progress_function;
%ignore moa_swig::NativeContext::copy_vertices;
%ignore moa_swig::NativeContext::copy_triangles;

%native(mesh) int moa_lua_mesh(lua_State *L);
%native(run) int moa_lua_run(lua_State *L);

%{
#include "moa_lua_layer.h"

static moa_swig::NativeContext *moa_lua_context(lua_State *L) {
  void *ctx = nullptr;
  if (!SWIG_IsOK(SWIG_ConvertPtr(L, 1, &ctx, SWIGTYPE_p_moa_swig__NativeContext, 0)) || !ctx)
    luaL_argerror(L, 1, "NativeContext expected");
  return static_cast<moa_swig::NativeContext *>(ctx);
}

// mesh(ctx) -> vertices {{x, y, z}, ...}, triangles {{a, b, c}, ...} with 1-based indices.
static int moa_lua_mesh(lua_State *L) {
  const moa_swig::NativeContext *ctx = moa_lua_context(L);
  const size_t nv = ctx->vertex_count(), nt = ctx->triangle_count();
  const double *v = ctx->vertex_data();
  const uint32_t *t = ctx->triangle_data();
  lua_createtable(L, (int)nv, 0);
  for (size_t i = 0; i < nv; ++i) {
    lua_createtable(L, 3, 0);
    for (int k = 0; k < 3; ++k) {
      lua_pushnumber(L, v[3 * i + k]);
      lua_rawseti(L, -2, k + 1);
    }
    lua_rawseti(L, -2, (lua_Integer)i + 1);
  }
  lua_createtable(L, (int)nt, 0);
  for (size_t i = 0; i < nt; ++i) {
    lua_createtable(L, 3, 0);
    for (int k = 0; k < 3; ++k) {
      lua_pushinteger(L, (lua_Integer)t[3 * i + k] + 1);
      lua_rawseti(L, -2, k + 1);
    }
    lua_rawseti(L, -2, (lua_Integer)i + 1);
  }
  return 2;
}

// The progress function of one run: the Lua function sits at index 2 of the running thread's
// stack, so it is called on the thread that called run, as libmoa promises.
struct MoaLuaProgress {
  lua_State *L;
  bool failed;
};

static int moa_lua_progress(void *handle, int stage, double fraction) {
  MoaLuaProgress *p = static_cast<MoaLuaProgress *>(handle);
  if (p->failed) return 0;
  lua_State *L = p->L;
  lua_pushvalue(L, 2);
  lua_pushstring(L, moa_stage_name(static_cast<moa_stage>(stage)));
  lua_pushnumber(L, fraction);
  // An error must not longjmp through libmoa: keep it on the stack and cancel the run.
  if (lua_pcall(L, 2, 1, 0) != LUA_OK) {
    p->failed = true;
    return 0;
  }
  const bool go_on = !(lua_isboolean(L, -1) && !lua_toboolean(L, -1));
  lua_pop(L, 1);
  return go_on ? 1 : 0;
}

// run(ctx [, progress]) -> status. progress(stage_name, fraction) returns false to cancel; an
// error it raises is raised again here once libmoa has stopped.
static int moa_lua_run(lua_State *L) {
  moa_swig::NativeContext *ctx = moa_lua_context(L);
  if (lua_isnoneornil(L, 2)) {
    lua_pushinteger(L, ctx->run());
    return 1;
  }
  luaL_checktype(L, 2, LUA_TFUNCTION);
  lua_settop(L, 2);
  MoaLuaProgress progress = {L, false};
  ctx->set_progress_function(&moa_lua_progress, &progress);
  const int status = ctx->run();
  ctx->set_progress_function(nullptr, nullptr);
  if (progress.failed) return lua_error(L);
  lua_pushinteger(L, status);
  return 1;
}
%}

// Replace the module that require("moa") returns by the one moa.lua builds from it. The SWIG
// module is on top of the stack here and luaopen_moa returns the top value.
%init %{
  if (luaL_loadbufferx(L, moa_lua_layer, sizeof moa_lua_layer - 1, "=moa.lua", "t") != LUA_OK)
    lua_error(L);
  lua_pushvalue(L, -2);
  lua_call(L, 1, 1);
  lua_replace(L, -2);
%}
