// Algorithm 1 of the paper (§3.5.1): the list of segments, shortest first; for each target
// segment the maximum opposite point on each open side that passes the topology judgment;
// every new triangle side enters the list.
#include <algorithm>
#include <queue>
#include <vector>

#include "core/growth_state.hpp"

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

using SegmentList = std::priority_queue<Segment, std::vector<Segment>, std::greater<Segment>>;

class Builder {
 public:
  explicit Builder(GrowthState &g) : g_(g) {}

  // Step 2: every point with its nearest neighbour. The seeds are listed a block at a time,
  // just before the list reaches their block (list_seeds_up_to): listing all of them at once
  // would hold a segment per point (24 MB at a million points) for no change in the order.
  void seed_list() {
    const uint32_t n = uint32_t(g_.points.size());
    const uint32_t blocks = ((n - 1) >> kBlockBits) + 1;
    std::vector<uint32_t> start(blocks + 1, 0);
    for (uint32_t i = 0; i < n; ++i) ++start[seed_block(i) + 1];
    for (uint32_t b = 0; b < blocks; ++b) start[b + 1] += start[b];
    seed_order_.resize(n);
    for (uint32_t i = 0; i < n; ++i) seed_order_[start[seed_block(i)]++] = i;
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
      const unsigned next_rank = unsigned(s.rank) + 1;
      if (!process(s.a, s.b) && s.seed != kNone && next_rank < std::min(kSeedRanks, g_.nb.k))
        push_seed(s.seed, next_rank);
    }
  }

 private:
  uint32_t seed_block(uint32_t i) const { return std::min(i, g_.nb.of(i)[0]) >> kBlockBits; }

  // Lists the seeds of every block up to the one the list will take its next segment from:
  // no unlisted seed then precedes that segment.
  void list_seeds_up_to() {
    while (next_seed_ < seed_order_.size() &&
           (list_.empty() || seed_block(seed_order_[next_seed_]) <= list_.top().block()))
      push_seed(seed_order_[next_seed_++], 0);
  }

  void push(uint32_t a, uint32_t b) {
    if (a > b) std::swap(a, b);
    list_.push({dist(g_.points.work[a], g_.points.work[b]), a, b});
  }

  void push_seed(uint32_t i, unsigned rank) {
    // A mutual nearest pair is listed twice, once for each point, so that each point moves on
    // to its own next neighbour if the pair finds no triangle.
    uint32_t j = g_.nb.of(i)[rank];
    Segment s{dist(g_.points.work[i], g_.points.work[j]), std::min(i, j), std::max(i, j), i,
              uint8_t(rank)};
    list_.push(s);
  }

  // Returns false when a bare segment found no triangle at all.
  bool process(uint32_t a, uint32_t b) {
    uint32_t fs[2];
    int n = g_.mesh.edge_faces(a, b, fs);
    if (n >= 2) return true;
    if (n == 0) {
      if (g_.mesh.fan_closed(a) || g_.mesh.fan_closed(b)) return true;
      if (!grow(a, b, kNone)) return false;
      n = g_.mesh.edge_faces(a, b, fs);
    }
    // Steps 5-6: the other side of the segment, opposite the triangle it already has.
    if (n == 1) grow(a, b, fs[0]);
    return true;
  }

  // Tries the candidates of one side of segment ab, best angle first; adds the first that
  // passes the judgment. `face` is the triangle already on ab, or kNone for a bare segment.
  bool grow(uint32_t a, uint32_t b, uint32_t face) {
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
      Verdict v = g_.judge.judge(t, sphere_.data(), sphere_.size());
      TopologyJudge::count(v, g_.stats);
      if (v != Verdict::Accept) continue;
      g_.add_face(t);
      ++g_.stats.triangles_mesh;
      for (int i = 0; i < 3; ++i) {
        uint32_t u = t[i], w = t[(i + 1) % 3], fs[2];
        if (g_.mesh.edge_faces(u, w, fs) == 1) push(u, w);
      }
      return true;
    }
    return false;
  }

  GrowthState &g_;
  SegmentList list_;
  std::vector<uint32_t> sphere_;
  std::vector<Candidate> ranked_;
  std::vector<uint32_t> seed_order_;  // points by the block of their seed segment
  std::size_t next_seed_ = 0;
};

}  // namespace

void build_mesh(GrowthState &g, const std::function<void(double)> &tick) {
  Builder builder(g);
  builder.seed_list();
  builder.run(tick, 0.0, 0.8);
  // A second pass: segments that found no partner early may find one now that their
  // surroundings are built.
  builder.requeue_open_edges();
  builder.run(tick, 0.8, 1.0);
  // Seams that cannot close because one side was turned inside out: turned back, they can.
  for (int round = 0; round < kRepairRounds && repair_inside_out_patches(g) > 0; ++round) {
    builder.requeue_open_edges();
    builder.run(tick, 1.0, 1.0);
  }
  tick(1.0);
}

}  // namespace moa
