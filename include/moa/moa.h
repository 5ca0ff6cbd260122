/*
 * libmoa - surface reconstruction from unorganized points by Maximum Opposite Angulation.
 *
 * The only public header. It is C99 and declares the functions in the order a program calls them:
 * create a context, give it points, set parameters, run, read the mesh, destroy the context.
 *
 * Threading rules
 *   - A context is used by one thread at a time. Distinct contexts are independent and may run
 *     concurrently on different threads; the library keeps no global mutable state apart from
 *     the thread-local error slot read by moa_last_error(NULL).
 *   - moa_run may use worker threads internally (see the "threads" parameter). The progress
 *     callback is always called on the thread that called moa_run.
 *
 * Errors
 *   Every function that can fail returns a moa_status. On failure, moa_last_error(ctx) returns a
 *   message naming what was wrong; a failed call never leaves the context unusable. No C++
 *   exception ever crosses this interface.
 *
 * Ownership
 *   Input arrays are copied; the caller may free them when the call returns. Output arrays belong
 *   to the context and stay valid until the next moa_set_points*, moa_run or moa_ctx_destroy on
 *   that context.
 */
#ifndef MOA_MOA_H
#define MOA_MOA_H

#include <stddef.h>
#include <stdint.h>

#include "moa/version.h"

#if defined(_WIN32)
#  if defined(MOA_BUILDING_LIBRARY)
#    define MOA_API __declspec(dllexport)
#  else
#    define MOA_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__) && __GNUC__ >= 4
#  define MOA_API __attribute__((visibility("default")))
#else
#  define MOA_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Opaque reconstruction context: holds the points, the parameters, the last mesh and the last
 * error message. */
typedef struct moa_ctx moa_ctx;

/* Status codes. Values are part of the ABI and are never renumbered. */
typedef enum moa_status {
  MOA_OK = 0,
  MOA_ERROR_INVALID_ARGUMENT = 1, /* a NULL pointer, an out-of-range value, a bad stride */
  MOA_ERROR_UNKNOWN_PARAM = 2,    /* a parameter name that libmoa does not know */
  MOA_ERROR_INVALID_INPUT = 3,    /* the points: too few, non-finite, all collinear, ... */
  MOA_ERROR_BAD_STATE = 4,        /* a call in the wrong order: moa_run before moa_set_points, ... */
  MOA_ERROR_OUT_OF_MEMORY = 5,    /* an allocation failed; the context stays usable */
  MOA_ERROR_CANCELLED = 6,        /* the progress callback asked to stop */
  MOA_ERROR_IO = 7,               /* reserved for file operations of tools built on libmoa */
  MOA_ERROR_INTERNAL = 8          /* a bug in libmoa: please report it with the input */
} moa_status;

/* A triangle mesh. Vertices are the caller's points, in the caller's order. */
typedef struct moa_mesh {
  size_t vertex_count;   const double   *vertices;  /* x y z per vertex */
  size_t triangle_count; const uint32_t *triangles; /* 3 vertex indices per triangle */
} moa_mesh;

/* Stages of moa_run, reported to the progress callback and in the statistics. */
typedef enum moa_stage {
  MOA_STAGE_POINTS = 0,     /* validation, duplicate merging, spatial sort */
  MOA_STAGE_NEIGHBORS = 1,  /* k nearest neighbours, spacing, noise, stray points */
  MOA_STAGE_MESH = 2,       /* Algorithm 1: the list, maximum opposite points, judgment */
  MOA_STAGE_LOOPS = 3,      /* Algorithm 2: the loop module fills holes */
  MOA_STAGE_FINISH = 4,     /* edge flips, orientation, contract enforcement, index mapping */
  MOA_STAGE_COUNT = 5
} moa_stage;

/* Progress callback: stage and fraction of that stage done (0..1), never decreasing within a
 * stage; a report may repeat the last fraction (long steps report again, so that they can be
 * cancelled). Return non-zero to cancel the run; moa_run then returns MOA_ERROR_CANCELLED and
 * the context stays usable. */
typedef int (*moa_progress_fn)(moa_stage stage, double fraction, void *user_data);

/* Statistics of the last successful moa_run. Fields may be appended in later versions; the
 * caller passes sizeof(moa_stats) so older programs keep working. */
typedef struct moa_stats {
  size_t input_points;        /* points given to moa_set_points */
  size_t unique_points;       /* after merging duplicates */
  size_t duplicate_points;    /* duplicates merged into their first occurrence: exact ones,
                                 and near ones (near_duplicate_points) */
  size_t used_points;         /* unique points that are vertices of the mesh */
  size_t unused_points;       /* unique points left out of the mesh (outliers) */
  size_t triangles_mesh;      /* triangles made by Algorithm 1 */
  size_t triangles_loops;     /* triangles added by the loop module */
  size_t triangles_removed;   /* triangles removed by the final contract enforcement */
  size_t triangles;           /* triangles in the result */
  size_t boundary_edges;      /* edges of the result with one triangle */
  size_t boundary_loops_before; /* boundary loops after Algorithm 1 */
  size_t boundary_loops_after;  /* boundary loops left open by the loop module */
  size_t candidates_tested;   /* candidate triangles submitted to the judgment */
  size_t rejected_degenerate; /* rejections: zero area or a needle */
  size_t rejected_manifold;   /* rejections: an edge would get a third face / a vertex two fans */
  size_t rejected_orientation;/* rejections: the surface would become non-orientable */
  size_t rejected_flatness;   /* rejections: the function T (points off the triangle's plane) */
  size_t rejected_edge_fold;  /* rejections: the edge-sharing angle alpha */
  size_t rejected_vertex_fold;/* rejections: the vertex-sharing angles alpha, beta, gamma */
  size_t rejected_intersection; /* rejections: the triangle would cross an existing one */
  size_t embree_rebuilds;     /* times an Embree scene was built (the parallel first pass of
                                 Algorithm 1 builds its parts' scenes on their own) */
  double intersection_ms;     /* time spent in crossing checks (Embree and exact tests),
                                 summed over the worker threads */
  double stage_ms[MOA_STAGE_COUNT]; /* wall time per stage */
  double total_ms;            /* wall time of moa_run */
  unsigned threads;           /* threads the run used (the parameter "threads", at most the
                                 cores TBB may run on) */
  size_t boundary_edges_before; /* boundary edges after Algorithm 1, before the loop module */
  size_t smoothing_passes;    /* passes of the noisy-cloud smoothing; 0: the cloud did not look
                                 noisy (or the parameter smoothing is 0) */
  size_t near_duplicate_points; /* of duplicate_points, those merged as near duplicates onto
                                 the point given first: copies of points given again nearly
                                 in place, or jittered by up to about a third of the
                                 nearest-neighbour distance, in the whole cloud or in a region
                                 of it (two scans overlapping); 0 in a cloud given once */
  size_t edges_flipped;       /* edges flipped to the other diagonal of their quad for a wider
                                 smallest angle (parameter edge_flips) */
} moa_stats;

/* Version of the library actually loaded, as "MAJOR.MINOR.PATCH". Never NULL. */
MOA_API const char *moa_version(void);
/* Version as MAJOR*10000 + MINOR*100 + PATCH, comparable with MOA_VERSION_NUMBER. */
MOA_API unsigned moa_version_number(void);

/* Human-readable name of a status code, e.g. "MOA_ERROR_INVALID_INPUT". Never NULL. */
MOA_API const char *moa_status_string(moa_status status);

/* Creates a context with default parameters.
 *   out_ctx: receives the new context; must not be NULL. Set to NULL on failure. */
MOA_API moa_status moa_ctx_create(moa_ctx **out_ctx);

/* Destroys a context and everything it owns. NULL is a no-op. */
MOA_API void moa_ctx_destroy(moa_ctx *ctx);

/* Message of the last failed call on ctx, or of the last failed call on this thread that had no
 * usable context when ctx is NULL. Empty string if none. The pointer stays valid until the next
 * call on the same context (or thread). Never NULL. */
MOA_API const char *moa_last_error(const moa_ctx *ctx);

/* Gives the context its points (copied). Replaces earlier points and discards the last mesh.
 *   xyz: point_count * 3 doubles, x y z per point; may be NULL only when point_count is 0.
 *   point_count: number of points. Values are checked by moa_run, not here, except that
 *   point_count must fit the 32-bit triangle indices (at most 2^32 - 2). */
MOA_API moa_status moa_set_points(moa_ctx *ctx, const double *xyz, size_t point_count);

/* Same as moa_set_points, from single-precision coordinates in an interleaved buffer such as a
 * game engine's vertex buffer.
 *   xyz: the first point's x; y and z follow it.
 *   stride_bytes: bytes from one point's x to the next point's x; 0 means 3 * sizeof(float).
 *   Must be 0 or at least 3 * sizeof(float). */
MOA_API moa_status moa_set_points_float(moa_ctx *ctx, const float *xyz, size_t point_count,
                                        size_t stride_bytes);

/* Sets a parameter by name. Parameters are sticky (they keep their value across runs and
 * across moa_set_points) and the order in which they are set does not matter.
 *   name: a name listed by moa_param_count/moa_param_info; unknown -> MOA_ERROR_UNKNOWN_PARAM.
 *   value: must lie in [min, max] and be a whole number for integral parameters;
 *   otherwise MOA_ERROR_INVALID_ARGUMENT and the parameter keeps its value. */
MOA_API moa_status moa_set_param(moa_ctx *ctx, const char *name, double value);

/* Reads a parameter's current value into *out_value. */
MOA_API moa_status moa_get_param(const moa_ctx *ctx, const char *name, double *out_value);

/* Description of one parameter, for tools and bindings that list them. */
typedef struct moa_param_info {
  const char *name;        /* static storage, valid for the life of the program */
  const char *description; /* static storage */
  double default_value;
  double min_value;
  double max_value;
  int is_integral;         /* non-zero: only whole numbers are accepted */
} moa_param_info;

/* Number of parameters. */
MOA_API size_t moa_param_count(void);
/* Fills *out_info with parameter number index (0 <= index < moa_param_count()). */
MOA_API moa_status moa_param_info_get(size_t index, moa_param_info *out_info);

/* Installs a progress callback (NULL removes it). user_data is passed back unchanged. */
MOA_API moa_status moa_set_progress_callback(moa_ctx *ctx, moa_progress_fn callback,
                                             void *user_data);

/* Reconstructs the mesh of the points with the current parameters. Blocks until done.
 * On failure the previous mesh is discarded and the context stays usable.
 * MOA_OK promises the output contract, not a closed mesh or every point used: borders wider
 * than the parameter hole_size stay open (moa_stats.boundary_edges), points no accepted
 * triangle reaches stay out (moa_stats.unused_points), and points that span no surface (on one
 * line but for rounding or a tiny offset) give a mesh of no triangles. */
MOA_API moa_status moa_run(moa_ctx *ctx);

/* Reads the mesh of the last successful moa_run. The arrays are owned by ctx and stay valid
 * until the next moa_set_points*, moa_run or moa_ctx_destroy. MOA_ERROR_BAD_STATE if there is
 * no mesh. */
MOA_API moa_status moa_get_mesh(const moa_ctx *ctx, moa_mesh *out_mesh);

/* Copy-out variants for bindings and garbage-collected languages.
 *   moa_copy_triangles: writes min(capacity, 3 * triangle_count) indices into out (may be NULL
 *   when capacity is 0) and the total number of indices (3 * triangle_count) into *out_total. */
MOA_API moa_status moa_copy_triangles(const moa_ctx *ctx, uint32_t *out, size_t capacity,
                                      size_t *out_total);

/* Copies the statistics of the last successful moa_run.
 *   out_stats: receives at most stats_size bytes; pass sizeof(moa_stats). */
MOA_API moa_status moa_get_stats(const moa_ctx *ctx, moa_stats *out_stats, size_t stats_size);

/* Name of a stage, e.g. "neighbors". Never NULL. */
MOA_API const char *moa_stage_name(moa_stage stage);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* MOA_MOA_H */
