// The driver: the stages of the reconstruction in order, each timed and reporting progress.
#include "core/reconstruct.hpp"

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "core/finish.hpp"
#include "core/growth_state.hpp"
#include "core/isolated_points.hpp"
#include "core/near_duplicates.hpp"
#include "core/neighbors.hpp"
#include "core/point_set.hpp"
#include "core/smoothing.hpp"

namespace moa {

// Embree rebuilds, and the parts of Algorithm 1's parallel pass (on worker threads, each with
// a heap of its own), free tens of megabytes in pieces that glibc keeps resident. Handing them
// back before the next large allocation keeps the peaks apart: before the loop module's own
// rebuild, 15 MB less at a million points.
void return_free_memory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

// Passes of the noisy-cloud smoothing at most (smooth_if_noisy).
constexpr int kMaxSmoothingPasses = 3;
// Neighbourhood of a pass forced on a cloud that does not look noisy.
constexpr unsigned kForcedSmoothingK = 40;

// Replaces the judgment's geometry by a smoothed copy when the parameter and the cloud call for
// it (smoothing.hpp); the caller's points stay in raw_work. A pass leaves some roughness at the
// smallest scale when the noise exceeds the spacing, so the cloud is looked at again after each.
// Returns the tree over the final work coordinates, for the neighbour stage.
std::unique_ptr<KdIndex> smooth_if_noisy(PointSet &points, const Params &params,
                                         const std::function<void(double)> &tick,
                                         moa_stats &stats) {
  auto index = std::make_unique<KdIndex>(points.work);
  if (params.smoothing == 0) return index;
  for (int pass = 0; pass < kMaxSmoothingPasses; ++pass) {
    NoiseEstimate noise = estimate_noise(*index, pass > 0);
    const bool forced = pass == 0 && params.smoothing == 2;
    if (!noise.noisy && !forced) break;
    const unsigned k = noise.smoothing_k ? noise.smoothing_k : kForcedSmoothingK;
    std::vector<Vec3> smooth = smoothed_points(
        *index, k, noise.thin_walls, [&](double f) { tick((pass + f) / kMaxSmoothingPasses); });
    index.reset();
    if (points.raw_work.empty()) points.raw_work = std::move(points.work);
    points.work = std::move(smooth);
    index = std::make_unique<KdIndex>(points.work);
    ++stats.smoothing_passes;
  }
  return index;
}

// The stages once. Near duplicates (near_duplicates.hpp) show only in the neighbour lists: while
// `merged` is empty they are looked for there, and if the cloud has them they go into `merged`
// and the run stops (nothing returned), to be started again without them. The caller's points
// are back in their order by then.
std::optional<Result> run_stages_once(double *xyz, std::size_t count, const Params &params,
                                      const std::function<void(moa_stage, double)> &report,
                                      std::vector<uint32_t> &merged) {
  Result result;
  moa_stats &st = result.stats;

  auto t = Clock::now();
  report(MOA_STAGE_POINTS, 0.0);
  PointSet points = prepare_points(xyz, count, merged);
  InternalOrder ordered(points, xyz);
  st.input_points = count;
  st.unique_points = points.size();
  st.duplicate_points = points.duplicates;
  st.near_duplicate_points = merged.size();
  report(MOA_STAGE_POINTS, 1.0);
  st.stage_ms[MOA_STAGE_POINTS] = ms_since(t);

  std::vector<Tri> faces;
  {
    // The neighbourhoods and the growth structures (mesh bookkeeping, Embree scene) are freed
    // before the finish stage allocates its own: the peak memory is the larger of the two, not
    // their sum.
    t = Clock::now();
    report(MOA_STAGE_NEIGHBORS, 0.0);
    std::unique_ptr<KdIndex> index = smooth_if_noisy(
        points, params, [&](double f) { report(MOA_STAGE_NEIGHBORS, 0.5 * f); }, st);
    Neighborhood nb = compute_neighbors(*index, unsigned(params.neighbors), [&](double f) {
      report(MOA_STAGE_NEIGHBORS, 0.5 + 0.5 * f);
    });
    index.reset();
    if (merged.empty()) {
      merged = near_duplicates(points, nb);
      if (!merged.empty()) return std::nullopt;
    }
    mark_isolated_points(points, nb);
    st.stage_ms[MOA_STAGE_NEIGHBORS] = ms_since(t);

    // The search tree's memory goes back to the system before the mesh's per-vertex records
    // take fresh pages of their own (ZeroedArray), or both stay resident.
    return_free_memory();
    GrowthState g(points, nb, params, median_spacing(nb), st);

    t = Clock::now();
    report(MOA_STAGE_MESH, 0.0);
    build_mesh(g, [&](double f) { report(MOA_STAGE_MESH, f); });
    return_free_memory();
    st.stage_ms[MOA_STAGE_MESH] = ms_since(t);

    t = Clock::now();
    report(MOA_STAGE_LOOPS, 0.0);
    fill_loops(g, [&](double f) { report(MOA_STAGE_LOOPS, f); });
    st.stage_ms[MOA_STAGE_LOOPS] = ms_since(t);

    t = Clock::now();
    report(MOA_STAGE_FINISH, 0.0);
    // Nothing reads the neighbour lists any more: freed before the flips add faces to the
    // crossing index (at a million points 80 MB, and the flips' faces would have taken the
    // peak from 379 to 408 bytes per point).
    std::vector<uint32_t>().swap(nb.knn);
    st.edges_flipped = flip_edges(g, [&](double f) { report(MOA_STAGE_FINISH, 0.5 * f); });
    st.embree_rebuilds = g.crossings.rebuilds() + g.parts_rebuilds;
    st.intersection_ms = g.crossings.milliseconds() + g.parts_crossing_ms;
    g.crossings.release();  // before the faces are copied out, so the copy reuses its memory
    faces = oriented_faces(g.mesh);
  }

  finish_mesh(points, faces, st);
  result.triangles.resize(faces.size() * 3);
  std::vector<char> used(points.size(), 0);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      used[faces[f][k]] = 1;
      result.triangles[3 * f + k] = points.original[faces[f][k]];
    }
  st.triangles = faces.size();
  st.used_points = std::size_t(std::count(used.begin(), used.end(), 1));
  st.unused_points = points.size() - st.used_points;
  report(MOA_STAGE_FINISH, 1.0);
  st.stage_ms[MOA_STAGE_FINISH] = ms_since(t);
  return result;
}

Result run_stages(double *xyz, std::size_t count, const Params &params,
                  const ProgressFn &progress) {
  auto total = Clock::now();
  // Reports never go back, not even when the stages start again without near duplicates.
  moa_stage last_stage = MOA_STAGE_POINTS;
  double last_fraction = 0;
  auto report = [&](moa_stage stage, double fraction) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    if (stage < last_stage || (stage == last_stage && fraction < last_fraction)) {
      stage = last_stage;
      fraction = last_fraction;
    }
    last_stage = stage;
    last_fraction = fraction;
    if (progress && progress(stage, fraction)) throw Cancelled();
  };
  std::vector<uint32_t> merged;
  std::optional<Result> result = run_stages_once(xyz, count, params, report, merged);
  if (!result) result = run_stages_once(xyz, count, params, report, merged);
  result->stats.total_ms = ms_since(total);
  return std::move(*result);
}

}  // namespace

Result reconstruct(double *xyz, std::size_t count, const Params &params,
                   const ProgressFn &progress) {
  if (count > 0 && !xyz) throw Error(MOA_ERROR_INVALID_ARGUMENT, "points are NULL");
  // No more threads than TBB may run at once: the cores this process may use, or fewer when
  // the host application holds a tbb::global_control. More would not run (TBB keeps to that
  // limit) and TBB would print a warning on the caller's stderr.
  const int allowed = int(
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  int threads = int(params.threads);
  if (threads <= 0 || threads > allowed) threads = std::max(1, allowed);
  // An arena per run: two contexts with different thread counts can run at once.
  tbb::task_arena arena(threads);
  Result result;
  arena.execute([&] { result = run_stages(xyz, count, params, progress); });
  result.stats.threads = unsigned(threads);
  return result;
}

}  // namespace moa
