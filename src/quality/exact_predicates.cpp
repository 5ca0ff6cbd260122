// Three stages, each exact when it answers:
// 1. Shewchuk's static filter: the determinant in double with its "permanent" (the same sum of
//    absolute values) bounds the rounding error.
// 2. When the coordinate differences are exact doubles (nearby points: Sterbenz), the
//    determinant is expanded with error-free products (fma) into a few dozen doubles whose sum
//    has the sign; repeated error-free summation passes (Ogita-Rump-Oishi) decide it. This keeps
//    near-coplanar regions (flat parts, subdivided meshes) fast.
// 3. Otherwise every coordinate becomes, without loss, an integer times a common power of two,
//    and GMP integers evaluate the determinant (no gcd normalisation as with rationals).
#include "quality/exact_predicates.hpp"

#include <gmp.h>

#include <cmath>

namespace moa::quality {
namespace {

constexpr double kEps = 1.1102230246251565e-16;  // 2^-53
// Slightly above Shewchuk's (7 + 56 eps) eps and (3 + 16 eps) eps, for margin.
constexpr double kBound3 = 8.0 * kEps;
constexpr double kBound2 = 4.0 * kEps;
// Below this the products may have underflowed and the bound no longer holds.
constexpr double kTiny = 1e-280;

// Thread-local GMP scratch so the exact path allocates nothing after its first use.
struct Scratch {
  static constexpr int kCount = 24;
  mpz_t z[kCount];
  Scratch() { for (auto &v : z) mpz_init2(v, 256); }
  ~Scratch() { for (auto &v : z) mpz_clear(v); }
};

Scratch &scratch() {
  thread_local Scratch s;
  return s;
}

// Converts n doubles to integers sharing one scale: v[i] = out[i] * 2^e for a common e.
void to_common_integers(const double *v, int n, mpz_t *out) {
  int mant_exp[12];
  double mant[12];
  int emin = 0;
  bool any = false;
  for (int i = 0; i < n; ++i) {
    if (v[i] == 0) { mant[i] = 0; mant_exp[i] = 0; continue; }
    int e;
    double m = std::frexp(v[i], &e);     // v = m 2^e, 0.5 <= |m| < 1
    mant[i] = std::ldexp(m, 53);         // an integer below 2^53
    mant_exp[i] = e - 53;
    if (!any || mant_exp[i] < emin) emin = mant_exp[i];
    any = true;
  }
  for (int i = 0; i < n; ++i) {
    mpz_set_d(out[i], mant[i]);
    if (mant[i] != 0) mpz_mul_2exp(out[i], out[i], static_cast<unsigned>(mant_exp[i] - emin));
  }
}

int orient3d_exact(const double *a, const double *b, const double *c, const double *d) {
  Scratch &s = scratch();
  const double v[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
  mpz_t *z = s.z;
  to_common_integers(v, 12, z);
  // u = b - a, w = c - a, t = d - a in z[12..20]
  for (int k = 0; k < 3; ++k) {
    mpz_sub(z[12 + k], z[3 + k], z[k]);
    mpz_sub(z[15 + k], z[6 + k], z[k]);
    mpz_sub(z[18 + k], z[9 + k], z[k]);
  }
  mpz_t *u = z + 12, *w = z + 15, *t = z + 18;
  mpz_t &acc = z[21], &m1 = z[22];
  // acc = u0 (w1 t2 - w2 t1) + u1 (w2 t0 - w0 t2) + u2 (w0 t1 - w1 t0)
  mpz_set_ui(acc, 0);
  for (int k = 0; k < 3; ++k) {
    int i = (k + 1) % 3, j = (k + 2) % 3;
    mpz_mul(m1, w[i], t[j]);
    mpz_submul(m1, w[j], t[i]);
    mpz_addmul(acc, u[k], m1);
  }
  return mpz_sgn(acc);
}

// --- Stage 2: error-free transformations -------------------------------------------------

// a - b exactly representable? Then d holds it.
inline bool exact_difference(double a, double b, double &d) {
  d = a - b;
  const double bv = a - d, av = d + bv;
  return (a - av) + (bv - b) == 0;
}

// Nonzero magnitudes in this range keep every product and its error term clear of underflow.
inline bool in_safe_range(double x) {
  const double m = std::fabs(x);
  return m == 0 || (m > 0x1p-300 && m < 0x1p+300);
}

inline void two_sum(double a, double b, double &s, double &e) {
  s = a + b;
  const double bv = s - a;
  e = (a - (s - bv)) + (b - bv);
}

// Sign of the exact sum of x[0..n): 1, 0, -1, or 2 when undecided after a few passes.
int sign_of_sum(double *x, int n) {
  for (int pass = 0; pass < 8; ++pass) {
    int m = 0;  // keep the nonzero terms only
    for (int i = 0; i < n; ++i)
      if (x[i] != 0) x[m++] = x[i];
    n = m;
    if (n == 0) return 0;
    for (int i = 1; i < n; ++i) two_sum(x[i], x[i - 1], x[i], x[i - 1]);  // sum moves up
    double rest = 0;
    for (int i = 0; i + 1 < n; ++i) rest += std::fabs(x[i]);
    const double top = x[n - 1];
    if (std::fabs(top) > rest * (1 + 4 * n * kEps)) return top > 0 ? 1 : -1;
  }
  return 2;
}

// Stage 2 of orient3d on the differences u, v, w (exact doubles in the safe range).
int orient3d_expansion(const double u[3], const double v[3], const double w[3]) {
  double terms[24];
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    // u_k (v_i w_j - v_j w_i), each product split into value and error.
    const double p = v[i] * w[j], pe = std::fma(v[i], w[j], -p);
    const double q = v[j] * w[i], qe = std::fma(v[j], w[i], -q);
    const double minor[4] = {p, pe, -q, -qe};
    for (double t : minor) {
      const double h = u[k] * t;
      terms[n++] = h;
      terms[n++] = std::fma(u[k], t, -h);
    }
  }
  return sign_of_sum(terms, n);
}

void project(const double *p, int drop, double &x, double &y) {
  x = p[(drop + 1) % 3];
  y = p[(drop + 2) % 3];
}

int orient2d_exact(const double *v6) {
  Scratch &s = scratch();
  mpz_t *z = s.z;
  to_common_integers(v6, 6, z);
  // (b - a) x (c - a)
  mpz_sub(z[6], z[2], z[0]);
  mpz_sub(z[7], z[3], z[1]);
  mpz_sub(z[8], z[4], z[0]);
  mpz_sub(z[9], z[5], z[1]);
  mpz_mul(z[10], z[6], z[9]);
  mpz_submul(z[10], z[7], z[8]);
  return mpz_sgn(z[10]);
}

}  // namespace

int orient3d(const double *a, const double *b, const double *c, const double *d) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double p1 = vy * wz, p2 = vz * wy, p3 = vz * wx, p4 = vx * wz, p5 = vx * wy, p6 = vy * wx;
  const double det = ux * (p1 - p2) + uy * (p3 - p4) + uz * (p5 - p6);
  const double perm = std::fabs(ux) * (std::fabs(p1) + std::fabs(p2)) +
                      std::fabs(uy) * (std::fabs(p3) + std::fabs(p4)) +
                      std::fabs(uz) * (std::fabs(p5) + std::fabs(p6));
  if (perm > kTiny && std::isfinite(perm)) {
    const double bound = kBound3 * perm;
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  // Points on an axis-aligned plane: every term has a factor that is exactly zero (a difference
  // of doubles is zero only for equal doubles), so the determinant is exactly zero.
  if ((ux == 0 || ((vy == 0 || wz == 0) && (vz == 0 || wy == 0))) &&
      (uy == 0 || ((vz == 0 || wx == 0) && (vx == 0 || wz == 0))) &&
      (uz == 0 || ((vx == 0 || wy == 0) && (vy == 0 || wx == 0))))
    return 0;
  double u[3], v[3], w[3];
  bool exact = true;
  for (int k = 0; k < 3 && exact; ++k)
    exact = exact_difference(b[k], a[k], u[k]) && exact_difference(c[k], a[k], v[k]) &&
            exact_difference(d[k], a[k], w[k]) && in_safe_range(u[k]) && in_safe_range(v[k]) &&
            in_safe_range(w[k]);
  if (exact) {
    const int s = orient3d_expansion(u, v, w);
    if (s != 2) return s;
  }
  return orient3d_exact(a, b, c, d);
}

int orient2d(const double *a, const double *b, const double *c, int drop) {
  double v[6];
  project(a, drop, v[0], v[1]);
  project(b, drop, v[2], v[3]);
  project(c, drop, v[4], v[5]);
  const double l = (v[2] - v[0]) * (v[5] - v[1]);
  const double r = (v[3] - v[1]) * (v[4] - v[0]);
  const double det = l - r;
  const double sum = std::fabs(l) + std::fabs(r);
  if (sum > kTiny && std::isfinite(sum)) {
    const double bound = kBound2 * sum;
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  double d[4];
  if (exact_difference(v[2], v[0], d[0]) && exact_difference(v[5], v[1], d[1]) &&
      exact_difference(v[3], v[1], d[2]) && exact_difference(v[4], v[0], d[3]) &&
      in_safe_range(d[0]) && in_safe_range(d[1]) && in_safe_range(d[2]) && in_safe_range(d[3])) {
    const double p = d[0] * d[1], q = d[2] * d[3];
    double terms[4] = {p, std::fma(d[0], d[1], -p), -q, -std::fma(d[2], d[3], -q)};
    const int s = sign_of_sum(terms, 4);
    if (s != 2) return s;
  }
  return orient2d_exact(v);
}

int projection_axis(const double *a, const double *b, const double *c) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double n[3] = {std::fabs(uy * vz - uz * vy), std::fabs(uz * vx - ux * vz),
                       std::fabs(ux * vy - uy * vx)};
  // Try the dominant normal axis first: its projection is the best conditioned.
  int order[3] = {0, 1, 2};
  for (int i = 0; i < 2; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (n[order[j]] > n[order[i]]) { int t = order[i]; order[i] = order[j]; order[j] = t; }
  for (int axis : order)
    if (orient2d(a, b, c, axis) != 0) return axis;
  return -1;
}

bool collinear(const double *a, const double *b, const double *c) {
  return projection_axis(a, b, c) < 0;
}

}  // namespace moa::quality
