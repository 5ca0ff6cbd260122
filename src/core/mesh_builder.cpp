// Algorithm 1 of the paper (§3.5.1): the list of segments, shortest first; for each target
// segment the maximum opposite point on each open side that passes the topology judgment;
// every new triangle side enters the list.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <queue>
#include <thread>
#include <vector>

#include "core/growth_state.hpp"
#include "core/partition.hpp"
#include "core/reconstruct.hpp"

namespace moa {
namespace {

// Bare segments that fail are replaced by the same point's next neighbour, up to this rank:
// on a thin slab a point's nearest neighbour lies on the other sheet.
constexpr unsigned kSeedRanks = 6;

// The list is kept shortest first within spatial blocks of this many consecutive points in
// Morton order, the blocks in order: the paper's global order would jump across the whole
// cloud at every step, and at a million points cache misses, not geometry, would set the pace.
constexpr uint32_t kBlockBits = 13;

// 24 bytes: the list holds about one segment per point at its longest.
struct Segment {
  double length;
  uint32_t a, b;          // a < b; the segment's block is that of a
  uint32_t seed = kNone;  // for a seed segment: the point whose neighbour list it came from
  uint8_t rank = 0;       // and the neighbour's rank in that list
  uint32_t block() const { return a >> kBlockBits; }
  // A total order: segments listed twice (a mutual nearest pair, once from each point) come
  // out in a fixed order whatever the list's history, which lets seeds be listed lazily.
  bool operator>(const Segment &o) const {
    if (block() != o.block()) return block() > o.block();
    if (length != o.length) return length > o.length;
    if (a != o.a) return a > o.a;
    if (b != o.b) return b > o.b;
    if (seed != o.seed) return seed > o.seed;
    return rank > o.rank;
  }
};

// Rounds of repair_inside_out_patches, each followed by growth over the seams it reopened.
constexpr int kRepairRounds = 3;
// Contradicting pairs left after them that call for the rays of turn_regions_against_ray_parity.
constexpr std::size_t kMinParityPairs = 8;

using SegmentList = std::priority_queue<Segment, std::vector<Segment>, std::greater<Segment>>;

// A part of the cloud that a Builder keeps to (the parallel first pass): it makes only
// triangles whose corners and whole judgment neighbourhood lie inside the part.
struct Region {
  const Partition &partition;
  uint16_t part;
  bool has(uint32_t v) const { return partition.part_of[v] == part; }
};

// How far inside its part a triangle's neighbourhood must stay, in work units: well above the
// crossing index's own padding of its boxes.
constexpr double kPartMargin = 1e-4;

class Builder {
 public:
  explicit Builder(GrowthState &g, const Region *region = nullptr) : g_(g), region_(region) {}

  // Step 2: every point with its nearest neighbour. The seeds are listed a block at a time,
  // just before the list reaches their block (list_seeds_up_to): listing all of them at once
  // would hold a segment per point (24 MB at a million points) for no change in the order.
  void seed_list() {
    const uint32_t n = uint32_t(g_.points.size());
    const uint32_t blocks = ((n - 1) >> kBlockBits) + 1;
    std::vector<uint32_t> start(blocks + 1, 0);
    seed_order_.clear();
    // The points of the region (the whole cloud without one), stray points left out.
    auto seeds = [&](uint32_t i) { return (!region_ || region_->has(i)) && !g_.nb.alone(i); };
    for (uint32_t i = 0; i < n; ++i)
      if (seeds(i)) ++start[seed_block(i) + 1];
    for (uint32_t b = 0; b < blocks; ++b) start[b + 1] += start[b];
    seed_order_.resize(start[blocks]);
    for (uint32_t i = 0; i < n; ++i)
      if (seeds(i)) seed_order_[start[seed_block(i)]++] = i;
    next_seed_ = 0;
  }

  void requeue_open_edges() {
    g_.mesh.for_each_open_edge([&](uint32_t f, int i) {
      const Tri &t = g_.mesh.stored(f);
      push(t[i], t[(i + 1) % 3]);
    });
  }

  void run(const std::function<void(double)> &tick, double from, double to) {
    std::size_t steps = 0;
    const double expected = 2.0 * double(g_.points.size());
    for (;;) {
      list_seeds_up_to();
      if (list_.empty()) break;
      Segment s = list_.top();
      list_.pop();
      if ((++steps & 4095) == 0)
        tick(from + (to - from) * std::min(1.0, double(g_.mesh.face_count()) / expected));
      if (process(s.a, s.b) == Outcome::None && s.seed != kNone)
        push_seed(s.seed, unsigned(s.rank) + 1);
    }
  }

 private:
  uint32_t seed_block(uint32_t i) const { return std::min(i, g_.nb.of(i)[0]) >> kBlockBits; }

  // Lists the seeds of every block up to the one the list will take its next segment from:
  // no unlisted seed then precedes that segment. A point whose fan is closed by then is left
  // out: every segment at it is done (Algorithm 1 removes no face, so the fan stays closed).
  // In the pass over the whole cloud that is most points, which the parts have closed: a
  // million pops of the list saved at a million points.
  void list_seeds_up_to() {
    while (next_seed_ < seed_order_.size() &&
           (list_.empty() || seed_block(seed_order_[next_seed_]) <= list_.top().block())) {
      const uint32_t i = seed_order_[next_seed_++];
      if (!g_.mesh.fan_closed(i)) push_seed(i, 0);
    }
  }

  void push(uint32_t a, uint32_t b) {
    if (a > b) std::swap(a, b);
    list_.push({dist(g_.points.work[a], g_.points.work[b]), a, b});
  }

  // Lists point i with its neighbour of the given rank, or the next one that is not isolated;
  // nothing once the ranks tried for seeds run out.
  void push_seed(uint32_t i, unsigned rank) {
    // A mutual nearest pair is listed twice, once for each point, so that each point moves on
    // to its own next neighbour if the pair finds no triangle.
    const unsigned ranks = std::min(kSeedRanks, g_.nb.k);
    while (rank < ranks && g_.nb.alone(g_.nb.of(i)[rank])) ++rank;
    if (rank >= ranks) return;
    uint32_t j = g_.nb.of(i)[rank];
    Segment s{dist(g_.points.work[i], g_.points.work[j]), std::min(i, j), std::max(i, j), i,
              uint8_t(rank)};
    list_.push(s);
  }

  // What became of one side of a segment: a triangle was added, no candidate passed, or (in a
  // region) the choice was left to the pass over the whole cloud.
  enum class Outcome { Added, None, Deferred };

  // Returns None when a bare segment found no triangle at all.
  Outcome process(uint32_t a, uint32_t b) {
    uint32_t fs[2];
    int n = g_.mesh.edge_faces(a, b, fs);
    if (n >= 2) return Outcome::Added;
    if (n == 0) {
      if (g_.mesh.fan_closed(a) || g_.mesh.fan_closed(b)) return Outcome::Added;
      if (region_ && !(region_->has(a) && region_->has(b))) return Outcome::Deferred;
      const Outcome first = grow(a, b, kNone);
      if (first != Outcome::Added) return first;
      n = g_.mesh.edge_faces(a, b, fs);
    }
    // Steps 5-6: the other side of the segment, opposite the triangle it already has.
    if (n == 1) grow(a, b, fs[0]);
    return Outcome::Added;
  }

  // Whether the judgment of t in a region sees everything it would see in the whole cloud: a
  // corner outside the region, or a neighbourhood reaching out of it, leaves t to the pass over
  // the whole cloud.
  bool judged_alone(const Tri &t) const {
    if (!region_->has(t[2])) return false;
    Vec3 lo, hi;
    g_.crossings.bounds(t, lo, hi);
    return region_->partition.holds(region_->part, lo, hi, g_.judge.reach(t) + kPartMargin);
  }

  // Tries the candidates of one side of segment ab, best angle first; adds the first that
  // passes the judgment. `face` is the triangle already on ab, or kNone for a bare segment.
  Outcome grow(uint32_t a, uint32_t b, uint32_t face) {
    g_.search.sphere_points(a, b, sphere_);
    Vec3 side{};
    uint32_t opposite = kNone;
    Tri order{a, b, 0};
    if (face != kNone) {
      Tri f = g_.mesh.oriented(face);
      opposite = third_vertex(f, a, b);
      // The new triangle runs along ab against the existing one.
      for (int i = 0; i < 3; ++i)
        if (f[i] == a && f[(i + 1) % 3] == b) order = {b, a, 0};
      const Vec3 &A = g_.points.work[a], &B = g_.points.work[b];
      Vec3 ab = normalized(B - A);
      Vec3 away = A - g_.points.work[opposite];
      side = away - ab * dot(away, ab);
    }
    g_.search.rank(a, b, sphere_, side, opposite, ranked_);
    for (const Candidate &c : ranked_) {
      Tri t{order[0], order[1], c.vertex};
      if (region_ && !judged_alone(t)) return Outcome::Deferred;
      Verdict v = g_.judge.judge(t, sphere_.data(), sphere_.size());
      TopologyJudge::count(v, g_.stats);
      if (v != Verdict::Accept) continue;
      g_.add_face(t);
      ++g_.stats.triangles_mesh;
      for (int i = 0; i < 3; ++i) {
        uint32_t u = t[i], w = t[(i + 1) % 3], fs[2];
        if (g_.mesh.edge_faces(u, w, fs) == 1) push(u, w);
      }
      return Outcome::Added;
    }
    return Outcome::None;
  }

  GrowthState &g_;
  const Region *region_;
  SegmentList list_;
  std::vector<uint32_t> sphere_;
  std::vector<Candidate> ranked_;
  std::vector<uint32_t> seed_order_;  // points by the block of their seed segment
  std::size_t next_seed_ = 0;
};

// Parts of the parallel first pass: about kParts of them, each of kMinPartPoints to
// kMaxPartPoints points. Many parts balance the threads' loads; few parts leave less seam for
// the sequential pass over the whole cloud and cost less to set up (every part's state is
// indexed like the whole cloud: at a million points about 7 MB for each part running at once,
// as its per-vertex records take only the pages its points fall in and its crossing index
// reads the whole cloud's single-precision points).
// Fixed by the number of points alone: the mesh must not depend on the number of threads.
constexpr std::size_t kParts = 16;
constexpr std::size_t kMinPartPoints = 8192;
constexpr std::size_t kMaxPartPoints = 65536;

// The parallel first pass: each part of the cloud grows on its own (a GrowthState of its own,
// so no state is shared), keeping to triangles whose judgment sees nothing outside the part;
// then the faces join the whole cloud's mesh in part order, so the result does not depend on
// which thread grew which part. The progress callback is called on the calling thread only
// (moa.h); a cancellation stops the other parts at their next tick.
void grow_parts(GrowthState &g, const Partition &parts, const std::function<void(double)> &tick) {
  const std::size_t count = parts.size();
  std::vector<std::vector<Tri>> faces(count);
  std::vector<moa_stats> stats(count, moa_stats{});
  std::vector<std::size_t> rebuilds(count, 0);
  std::vector<double> crossing_ms(count, 0.0);
  std::atomic<std::size_t> made{0};
  // Read by every part's crossing index at once (only read).
  const std::shared_ptr<const EmbreePoints> embree_points = g.crossings.embree_points();
  // No exception leaves a part's task: the first one is kept and rethrown once every task has
  // ended. An exception escaping into TBB would cancel the other parts' tasks together with the
  // Embree builds nested in them, and Embree does not survive a build cancelled half way.
  std::atomic<bool> stop{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const std::thread::id caller = std::this_thread::get_id();
  const double expected = 2.0 * double(g.points.size());
  // TBB ends every task before parallel_for returns, but ThreadSanitizer cannot see that order
  // inside an uninstrumented libtbb, and the tasks read the caller's context (parameters,
  // points) that the caller may free right after the run. Each task's last act, a release on
  // this counter, read with acquire below, shows it the order.
  std::atomic<std::size_t> ended{0};
  struct EndOfTask {
    std::atomic<std::size_t> &ended;
    ~EndOfTask() { ended.fetch_add(1, std::memory_order_release); }
  };
  tbb::parallel_for(std::size_t(0), count, [&](std::size_t p) {
    const EndOfTask end_of_task{ended};
    if (stop.load()) return;
    try {
      GrowthState local(g.points, g.nb, g.params, g.spacing, stats[p], embree_points);
      const Region region{parts, uint16_t(p)};
      Builder builder(local, &region);
      auto part_tick = [&](double) {
        if (stop.load()) throw Cancelled();
        if (std::this_thread::get_id() == caller)
          tick(std::min(1.0, double(made.load() + local.mesh.face_count()) / expected));
      };
      builder.seed_list();
      builder.run(part_tick, 0.0, 1.0);
      std::vector<Tri> &out = faces[p];
      out.reserve(local.mesh.face_count());
      for (uint32_t f = 0; f < local.mesh.face_count(); ++f)
        if (local.mesh.alive(f)) out.push_back(local.mesh.oriented(f));
      made += out.size();
      rebuilds[p] = local.crossings.rebuilds();
      crossing_ms[p] = local.crossings.milliseconds();
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      stop.store(true);
    }
  });
  (void)ended.load(std::memory_order_acquire);  // the order, for ThreadSanitizer (above)
  if (failure) std::rethrow_exception(failure);
  // The parts' states were freed on the worker threads, into heaps that glibc keeps resident:
  // handed back before the whole mesh's faces take their place (at a million points the peak
  // of this stage 405 MB -> 360 on a noisy cloud, 371 -> 328 on a clean one).
  return_free_memory();
  // Within a part every face was oriented consistently with its neighbours, and faces of
  // different parts share no edge yet: added as they are, they keep their orientation classes.
  for (std::size_t p = 0; p < count; ++p) {
    for (const Tri &t : faces[p]) g.mesh.add(t);
    std::vector<Tri>().swap(faces[p]);
    const moa_stats &st = stats[p];
    g.stats.candidates_tested += st.candidates_tested;
    g.stats.rejected_degenerate += st.rejected_degenerate;
    g.stats.rejected_manifold += st.rejected_manifold;
    g.stats.rejected_orientation += st.rejected_orientation;
    g.stats.rejected_flatness += st.rejected_flatness;
    g.stats.rejected_edge_fold += st.rejected_edge_fold;
    g.stats.rejected_vertex_fold += st.rejected_vertex_fold;
    g.stats.rejected_intersection += st.rejected_intersection;
    g.stats.triangles_mesh += st.triangles_mesh;
    g.parts_rebuilds += rebuilds[p];
    g.parts_crossing_ms += crossing_ms[p];
  }
  // The part lists' memory too, before the mesh's Embree build, or the two add up.
  return_free_memory();
  g.crossings.add_all(g.mesh);
}

// Algorithm 1 over the whole cloud, after the parts when it has several.
void grow(GrowthState &g, const std::function<void(double)> &tick) {
  // Clouds larger than a part grow part by part in parallel first; the pass over the whole
  // cloud below then sews the parts together and finishes what they left.
  double from = 0.0;
  const std::size_t n = g.points.size();
  if (n > kMinPartPoints) {
    const std::size_t part_points = std::clamp(n / kParts, kMinPartPoints, kMaxPartPoints);
    const Partition parts = partition_points(g.points.placed(), part_points);
    grow_parts(g, parts, [&](double f) { tick(0.7 * f); });
    from = 0.7;
  }
  Builder builder(g);
  builder.seed_list();
  builder.run(tick, from, 0.8);
  // A second pass: segments that found no partner early may find one now that their
  // surroundings are built.
  builder.requeue_open_edges();
  builder.run(tick, 0.8, 1.0);
  // Seams that cannot close because one side was turned inside out: turned back, they can.
  // Returns the contradicting pairs the last round found.
  auto repair_rounds = [&] {
    std::size_t contradicting = 0;
    for (int round = 0; round < kRepairRounds && repair_inside_out_patches(g, &contradicting) > 0;
         ++round) {
      builder.requeue_open_edges();
      builder.run(tick, 1.0, 1.0);
    }
    return contradicting;
  };
  // Many seams still contradicting: a region tied to the rest too widely for a cut, which rays
  // can tell (parity_orientation.cpp).
  if (repair_rounds() >= kMinParityPairs && turn_regions_against_ray_parity(g) > 0) {
    builder.requeue_open_edges();
    builder.run(tick, 1.0, 1.0);
    repair_rounds();
  }
}

}  // namespace

void build_mesh(GrowthState &g, const std::function<void(double)> &tick) {
  grow(g, tick);
  // No triangle at all: where the planes fitted to the lists follow the surface nowhere, the
  // normal test refuses every candidate (a tube given by two rings far apart, each list holding
  // its own ring or the whole cloud: 0 of 48 points used). Judged by the other tests alone,
  // Algorithm 1 and the loop module build a mesh; none at all helps no one.
  if (g.mesh.face_count() == g.mesh.removed_count()) {
    g.judge.drop_normal_test();
    grow(g, [&](double) { tick(1.0); });  // progress stays where the first try ended
  }
  tick(1.0);
}

}  // namespace moa
