// Filtered exact predicates. The filter bounds follow the usual forward error analysis of the
// determinant (the rounding of the differences included) with a wide safety margin; whatever the
// filter cannot certify is recomputed exactly with GMP (every double is a dyadic rational).
#include "support/exact_predicates.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <gmpxx.h>

namespace moa::test {

namespace {

// Far above the true bounds ((7 + 56u)u and (3 + 16u)u with u = 2^-53): cheap insurance.
constexpr double k_orient3d_bound = 1e-14;
constexpr double k_orient2d_bound = 4e-15;
// The relative bounds need every product to be a normal double: the filter only trusts
// inputs whose non-zero differences lie in [1e-90, 1e90] (triple products stay in 1e+-270).
constexpr double k_small = 1e-90, k_large = 1e90;

bool filter_safe(const double *diffs, int n) {
  for (int i = 0; i < n; ++i) {
    const double m = std::fabs(diffs[i]);
    if (m != 0 && !(m >= k_small && m <= k_large)) return false;  // also rejects NaN
  }
  return true;
}

thread_local PredicateCounters t_counters;

// Exact evaluation. Scaling every input by one power of two makes them all integers without
// rounding (and keeps every sign), so GMP integers do the work without the gcds of rationals;
// mpq handles the rare inputs whose exponents are too far apart to scale within double range.
bool scale_to_integers(const double *in, int n, double *out) {
  int emin = INT_MAX;
  for (int i = 0; i < n; ++i) {
    if (in[i] == 0) continue;
    int e = 0;
    std::frexp(in[i], &e);
    emin = std::min(emin, e - 53);  // in[i] = integer * 2^(e - 53)
  }
  for (int i = 0; i < n; ++i) {
    out[i] = emin == INT_MAX ? 0.0 : std::ldexp(in[i], -emin);
    if (!std::isfinite(out[i])) return false;
  }
  return true;
}

// Reused GMP integers: no allocation per call once they have grown.
struct Scratch {
  mpz_t v[12], d[9], t1, t2, acc;
  Scratch() {
    for (auto &z : v) mpz_init(z);
    for (auto &z : d) mpz_init(z);
    mpz_init(t1), mpz_init(t2), mpz_init(acc);
  }
  ~Scratch() {
    for (auto &z : v) mpz_clear(z);
    for (auto &z : d) mpz_clear(z);
    mpz_clear(t1), mpz_clear(t2), mpz_clear(acc);
  }
};
thread_local Scratch t_scratch;

// acc += sign * x * (y1 * z1 - y2 * z2), all arguments in t_scratch.d.
void add_term(Scratch &s, int x, int y1, int z1, int y2, int z2) {
  mpz_mul(s.t1, s.d[y1], s.d[z1]);
  mpz_mul(s.t2, s.d[y2], s.d[z2]);
  mpz_sub(s.t1, s.t1, s.t2);
  mpz_addmul(s.acc, s.d[x], s.t1);
}

int orient3d_rational(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d) {
  const mpq_class adx = mpq_class(a.x) - d.x, ady = mpq_class(a.y) - d.y, adz = mpq_class(a.z) - d.z;
  const mpq_class bdx = mpq_class(b.x) - d.x, bdy = mpq_class(b.y) - d.y, bdz = mpq_class(b.z) - d.z;
  const mpq_class cdx = mpq_class(c.x) - d.x, cdy = mpq_class(c.y) - d.y, cdz = mpq_class(c.z) - d.z;
  const mpq_class det = adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) +
                        cdx * (ady * bdz - adz * bdy);
  return sgn(det);
}

int orient3d_exact(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d) {
  const double in[12] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  double scaled[12];
  if (!scale_to_integers(in, 12, scaled)) return orient3d_rational(a, b, c, d);
  Scratch &s = t_scratch;
  for (int i = 0; i < 12; ++i) mpz_set_d(s.v[i], scaled[i]);
  for (int i = 0; i < 9; ++i) mpz_sub(s.d[i], s.v[i], s.v[9 + i % 3]);  // rows a-d, b-d, c-d
  // d[0..2] = a-d, d[3..5] = b-d, d[6..8] = c-d (x, y, z); cofactor expansion along x.
  mpz_set_ui(s.acc, 0);
  add_term(s, 0, 4, 8, 5, 7);
  add_term(s, 3, 7, 2, 8, 1);
  add_term(s, 6, 1, 5, 2, 4);
  return mpz_sgn(s.acc);
}

int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) {
  const double in[6] = {ax, ay, bx, by, cx, cy};
  double scaled[6];
  if (!scale_to_integers(in, 6, scaled)) {
    const mpq_class acx = mpq_class(ax) - cx, acy = mpq_class(ay) - cy;
    const mpq_class bcx = mpq_class(bx) - cx, bcy = mpq_class(by) - cy;
    return sgn(mpq_class(acx * bcy - acy * bcx));
  }
  Scratch &s = t_scratch;
  for (int i = 0; i < 6; ++i) mpz_set_d(s.v[i], scaled[i]);
  mpz_sub(s.d[0], s.v[0], s.v[4]), mpz_sub(s.d[1], s.v[1], s.v[5]);
  mpz_sub(s.d[2], s.v[2], s.v[4]), mpz_sub(s.d[3], s.v[3], s.v[5]);
  mpz_mul(s.t1, s.d[0], s.d[3]);
  mpz_mul(s.t2, s.d[1], s.d[2]);
  return mpz_cmp(s.t1, s.t2) > 0 ? 1 : (mpz_cmp(s.t1, s.t2) < 0 ? -1 : 0);
}

}  // namespace

PredicateCounters &predicate_counters() { return t_counters; }

int orient3d(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d) {
  ++t_counters.orient3d_calls;
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  // A floating-point difference is zero only for equal inputs, so a zero column is exact: this
  // settles points on axis-aligned planes (grids, cube faces) without the slow path.
  if ((adx == 0 && bdx == 0 && cdx == 0) || (ady == 0 && bdy == 0 && cdy == 0) ||
      (adz == 0 && bdz == 0 && cdz == 0))
    return 0;
  const double diffs[9] = {adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz};
  const double m1 = bdy * cdz, m2 = bdz * cdy;
  const double m3 = cdy * adz, m4 = cdz * ady;
  const double m5 = ady * bdz, m6 = adz * bdy;
  const double det = adx * (m1 - m2) + bdx * (m3 - m4) + cdx * (m5 - m6);
  const double permanent = (std::fabs(m1) + std::fabs(m2)) * std::fabs(adx) +
                           (std::fabs(m3) + std::fabs(m4)) * std::fabs(bdx) +
                           (std::fabs(m5) + std::fabs(m6)) * std::fabs(cdx);
  if (filter_safe(diffs, 9)) {
    const double bound = k_orient3d_bound * permanent;
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  ++t_counters.orient3d_exact;
  return orient3d_exact(a, b, c, d);
}

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  ++t_counters.orient2d_calls;
  if ((ax == cx && bx == cx) || (ay == cy && by == cy)) return 0;  // exact, see orient3d
  const double diffs[4] = {ax - cx, by - cy, ay - cy, bx - cx};
  const double l = diffs[0] * diffs[1], r = diffs[2] * diffs[3];
  const double det = l - r;
  const double permanent = std::fabs(l) + std::fabs(r);
  if (filter_safe(diffs, 4)) {
    const double bound = k_orient2d_bound * permanent;
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  ++t_counters.orient2d_exact;
  return orient2d_exact(ax, ay, bx, by, cx, cy);
}

bool collinear3d(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  // The cross product (b-a) x (c-a) vanishes iff its three components do; each component is
  // a 2-D orientation in one coordinate plane.
  return orient2d(a.x, a.y, b.x, b.y, c.x, c.y) == 0 && orient2d(a.y, a.z, b.y, b.z, c.y, c.z) == 0 &&
         orient2d(a.z, a.x, b.z, b.x, c.z, c.x) == 0;
}

}  // namespace moa::test
