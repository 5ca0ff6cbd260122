#include "core/partition.hpp"

#include <algorithm>
#include <limits>

namespace moa {
namespace {

double coordinate(const Vec3 &p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
double &coordinate(Vec3 &p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

class Cutter {
 public:
  Cutter(const std::vector<Vec3> &points, std::size_t max_points, Partition &out)
      : points_(points), max_(max_points), out_(out) {}

  void cut(uint32_t *begin, uint32_t *end, Partition::Box box) {
    const std::size_t n = std::size_t(end - begin);
    // Parts are numbered in 16 bits; past that many, the last parts stay larger.
    if (n > max_ && out_.boxes.size() + 2 <= std::numeric_limits<uint16_t>::max()) {
      // Longest side of the points' own bounds first; the others when every point ties there.
      Vec3 lo = points_[*begin], hi = lo;
      for (const uint32_t *i = begin; i != end; ++i) {
        const Vec3 &p = points_[*i];
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
      }
      int axes[3] = {0, 1, 2};
      std::sort(axes, axes + 3, [&](int a, int b) {
        const double da = coordinate(hi, a) - coordinate(lo, a);
        const double db = coordinate(hi, b) - coordinate(lo, b);
        return da != db ? da > db : a < b;
      });
      for (int axis : axes) {
        // The median coordinate; points below it go left, the rest (ties too) right.
        uint32_t *mid = begin + n / 2;
        std::nth_element(begin, mid, end, [&](uint32_t a, uint32_t b) {
          return coordinate(points_[a], axis) < coordinate(points_[b], axis);
        });
        const double at = coordinate(points_[*mid], axis);
        uint32_t *split = std::partition(
            begin, end, [&](uint32_t i) { return coordinate(points_[i], axis) < at; });
        if (split == begin) continue;  // the lower half ties at the median: no cut here
        Partition::Box left = box, right = box;
        coordinate(left.hi, axis) = at;
        coordinate(right.lo, axis) = at;
        cut(begin, split, left);
        cut(split, end, right);
        return;
      }
    }
    const uint16_t id = uint16_t(out_.boxes.size());
    out_.boxes.push_back(box);
    for (const uint32_t *i = begin; i != end; ++i) out_.part_of[*i] = id;
  }

 private:
  const std::vector<Vec3> &points_;
  std::size_t max_;
  Partition &out_;
};

}  // namespace

bool Partition::holds(uint32_t part, const Vec3 &lo, const Vec3 &hi, double margin) const {
  const Box &b = boxes[part];
  return lo.x - margin >= b.lo.x && lo.y - margin >= b.lo.y && lo.z - margin >= b.lo.z &&
         hi.x + margin < b.hi.x && hi.y + margin < b.hi.y && hi.z + margin < b.hi.z;
}

Partition partition_points(const std::vector<Vec3> &points, std::size_t max_points) {
  Partition out;
  out.part_of.assign(points.size(), 0);
  std::vector<uint32_t> order(points.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  const double inf = std::numeric_limits<double>::infinity();
  Cutter(points, std::max<std::size_t>(max_points, 1), out)
      .cut(order.data(), order.data() + order.size(), {{-inf, -inf, -inf}, {inf, inf, inf}});
  return out;
}

}  // namespace moa
