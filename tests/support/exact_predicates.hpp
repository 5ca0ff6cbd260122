// Exact geometric predicates for the contract checker: a floating-point filter decides the easy
// cases and GMP rationals decide the rest, so the checker never guesses on near-degenerate input.
// Independent of the library's own predicates on purpose: the checker judges the library.
#pragma once

#include <cstdint>

namespace moa::test {

struct Vec3 {
  double x, y, z;
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

// Point i of a flat x y z array.
inline Vec3 point(const double *xyz, std::uint32_t i) {
  return {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
}

// Sign of det[a-d; b-d; c-d]: +1, 0 or -1 (exact).
int orient3d(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d);

// Sign of det[a-c; b-c] for 2-D points (exact).
int orient2d(double ax, double ay, double bx, double by, double cx, double cy);

// Exact collinearity of three 3-D points: all three coordinate projections are degenerate.
bool collinear3d(const Vec3 &a, const Vec3 &b, const Vec3 &c);

// Counters of how often the exact fallback ran (for the performance self-test).
struct PredicateCounters {
  unsigned long long orient3d_calls = 0, orient3d_exact = 0;
  unsigned long long orient2d_calls = 0, orient2d_exact = 0;
};
PredicateCounters &predicate_counters();

}  // namespace moa::test
