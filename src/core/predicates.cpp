// Exact predicates: Shewchuk-style static error bounds decide most signs in double precision;
// when the bound cannot, the determinant is recomputed exactly on floating-point expansions,
// and with GMP rationals (doubles convert to rationals without loss) in the rare case where an
// expansion product would underflow or overflow.
#include "core/predicates.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace moa {
namespace {

constexpr double kEps = 1.1102230246251565e-16;  // 2^-53
constexpr double kOrient3dBound = (7.0 + 56.0 * kEps) * kEps;
constexpr double kOrient2dBound = (3.0 + 16.0 * kEps) * kEps;

int sign_of(const mpq_class &v) { return sgn(v); }

// An exact value as a sum of doubles that do not overlap bit-wise, smallest first, zeros
// left out: its sign is that of its largest part. Sums and products are error-free
// transformations (two-sum, and a fused multiply-add for a product's rounding error), so they
// are exact unless a product leaves the normal range: `exact` then turns false. Points on a
// slanted plane (a tetrahedron's faces) send most orientation tests here; GMP's rationals
// took five times the whole run's other work on them.
class Expansion {
 public:
  Expansion() = default;
  // a - b, exactly.
  static Expansion difference(double a, double b) {
    Expansion e;
    e.add(a);
    e.add(-b);
    return e;
  }

  // Adds x: a running two-sum through the parts, keeping the nonzero rounding errors.
  void add(double x) {
    if (n_ == kCapacity) {  // no room for the carry: give up rather than overrun
      exact = false;
      return;
    }
    int k = 0;
    double carry = x;
    for (int i = 0; i < n_; ++i) {
      const double sum = carry + parts_[i];
      const double from_part = sum - carry;
      const double error = (carry - (sum - from_part)) + (parts_[i] - from_part);
      if (error != 0) parts_[k++] = error;
      carry = sum;
    }
    if (carry != 0) parts_[k++] = carry;
    n_ = k;
    if (!std::isfinite(carry)) exact = false;
  }
  void add(const Expansion &o) {
    for (int i = 0; i < o.n_; ++i) add(o.parts_[i]);
    exact = exact && o.exact;
  }
  Expansion times(const Expansion &o) const {
    Expansion r;
    r.exact = exact && o.exact;
    for (int i = 0; i < n_; ++i)
      for (int j = 0; j < o.n_; ++j) {
        const double p = parts_[i] * o.parts_[j];
        // Below 2^-969 the rounding error of p may not be representable.
        if (!(std::fabs(p) >= 0x1p-969) || !std::isfinite(p)) r.exact = false;
        r.add(std::fma(parts_[i], o.parts_[j], -p));
        r.add(p);
      }
    return r;
  }
  Expansion negated() const {
    Expansion r = *this;
    for (int i = 0; i < n_; ++i) r.parts_[i] = -r.parts_[i];
    return r;
  }
  int sign() const { return n_ == 0 ? 0 : parts_[n_ - 1] > 0 ? 1 : -1; }

  bool exact = true;

 private:
  // Six terms of three factors, each factor two parts: the determinant needs no more than 192
  // parts, and zero elimination keeps it to a handful in practice.
  static constexpr int kCapacity = 200;
  double parts_[kCapacity];
  int n_ = 0;
};

// The sign of the 3x3 determinant |b-a, c-a, d-a| on expansions; 2 when they cannot be exact.
int orient3d_expansion(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d) {
  const Expansion bx = Expansion::difference(b.x, a.x), by = Expansion::difference(b.y, a.y),
                  bz = Expansion::difference(b.z, a.z), cx = Expansion::difference(c.x, a.x),
                  cy = Expansion::difference(c.y, a.y), cz = Expansion::difference(c.z, a.z),
                  dx = Expansion::difference(d.x, a.x), dy = Expansion::difference(d.y, a.y),
                  dz = Expansion::difference(d.z, a.z);
  auto minor = [](const Expansion &p, const Expansion &q, const Expansion &r, const Expansion &s) {
    Expansion m = p.times(q);  // p q - r s
    m.add(r.times(s).negated());
    return m;
  };
  Expansion det = bx.times(minor(cy, dz, cz, dy));
  det.add(by.times(minor(cz, dx, cx, dz)));
  det.add(bz.times(minor(cx, dy, cy, dx)));
  return det.exact ? det.sign() : 2;
}

int orient2d_expansion(double au, double av, double bu, double bv, double cu, double cv) {
  Expansion det = Expansion::difference(bu, au).times(Expansion::difference(cv, av));
  det.add(Expansion::difference(bv, av).times(Expansion::difference(cu, au)).negated());
  return det.exact ? det.sign() : 2;
}

int orient3d_exact(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d) {
  const int s = orient3d_expansion(a, b, c, d);
  if (s != 2) return s;
  mpq_class ax(a.x), ay(a.y), az(a.z);
  mpq_class bx = mpq_class(b.x) - ax, by = mpq_class(b.y) - ay, bz = mpq_class(b.z) - az;
  mpq_class cx = mpq_class(c.x) - ax, cy = mpq_class(c.y) - ay, cz = mpq_class(c.z) - az;
  mpq_class dx = mpq_class(d.x) - ax, dy = mpq_class(d.y) - ay, dz = mpq_class(d.z) - az;
  mpq_class det = bx * (cy * dz - cz * dy) + by * (cz * dx - cx * dz) + bz * (cx * dy - cy * dx);
  return sign_of(det);
}

// Whether each value is zero or between `low` and `high` in magnitude, so that the products of
// the filter below neither underflow nor overflow: its error bound assumes that, and so does
// reading a zero permanent as an exactly zero determinant (1e-300 cubed is zero in doubles).
bool in_filter_range(std::initializer_list<double> values, double low, double high) {
  for (double v : values)
    if (v != 0 && !(std::fabs(v) >= low && std::fabs(v) <= high)) return false;
  return true;
}

void project(const Vec3 &p, int drop, double &u, double &v) {
  if (drop == 0) {
    u = p.y;
    v = p.z;
  } else if (drop == 1) {
    u = p.z;
    v = p.x;
  } else {
    u = p.x;
    v = p.y;
  }
}

int orient2d_exact(double au, double av, double bu, double bv, double cu, double cv) {
  const int s = orient2d_expansion(au, av, bu, bv, cu, cv);
  if (s != 2) return s;
  mpq_class l = (mpq_class(bu) - mpq_class(au)) * (mpq_class(cv) - mpq_class(av));
  mpq_class r = (mpq_class(bv) - mpq_class(av)) * (mpq_class(cu) - mpq_class(au));
  return sign_of(l - r);
}

// Coordinate to drop so that the projection of triangle abc keeps a non-zero area.
int projection_axis(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  Vec3 n = cross(b - a, c - a);
  double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  int order[3];
  if (ax >= ay && ax >= az) {
    order[0] = 0;
    order[1] = ay >= az ? 1 : 2;
    order[2] = 3 - order[1];
  } else if (ay >= az) {
    order[0] = 1;
    order[1] = ax >= az ? 0 : 2;
    order[2] = 2 - order[1];
  } else {
    order[0] = 2;
    order[1] = ax >= ay ? 0 : 1;
    order[2] = 1 - order[1];
  }
  for (int k = 0; k < 3; ++k)
    if (orient2d(a, b, c, order[k]) != 0) return order[k];
  return order[0];
}

// Closed point-in-triangle test in the projection that drops `drop`.
bool point_in_triangle_2d(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c, int drop) {
  int s = orient2d(a, b, c, drop);
  int s1 = orient2d(a, b, p, drop), s2 = orient2d(b, c, p, drop), s3 = orient2d(c, a, p, drop);
  return (s1 == s || s1 == 0) && (s2 == s || s2 == 0) && (s3 == s || s3 == 0);
}

// For p collinear with segment ab (in the projection): does p lie between a and b?
bool between_2d(const Vec3 &a, const Vec3 &b, const Vec3 &p, int drop) {
  double au, av, bu, bv, pu, pv;
  project(a, drop, au, av);
  project(b, drop, bu, bv);
  project(p, drop, pu, pv);
  return std::min(au, bu) <= pu && pu <= std::max(au, bu) && std::min(av, bv) <= pv &&
         pv <= std::max(av, bv);
}

// Do closed segments pq and ab meet (all four points coplanar, tested in the projection)?
bool segments_meet_2d(const Vec3 &p, const Vec3 &q, const Vec3 &a, const Vec3 &b, int drop) {
  int d1 = orient2d(p, q, a, drop), d2 = orient2d(p, q, b, drop);
  int d3 = orient2d(a, b, p, drop), d4 = orient2d(a, b, q, drop);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  if (d1 == 0 && between_2d(p, q, a, drop)) return true;
  if (d2 == 0 && between_2d(p, q, b, drop)) return true;
  if (d3 == 0 && between_2d(a, b, p, drop)) return true;
  if (d4 == 0 && between_2d(a, b, q, drop)) return true;
  return false;
}

// Does the ray from v through x lie in the closed angular sector (v; c, d) of a coplanar
// triangle v c d? (x is known to be coplanar with it.)
bool ray_in_sector(const Vec3 &v, const Vec3 &c, const Vec3 &d, const Vec3 &x) {
  int drop = projection_axis(v, c, d);
  int s = orient2d(v, c, d, drop);
  int o1 = orient2d(v, c, x, drop), o2 = orient2d(v, x, d, drop);
  if (o1 == 0 && o2 == 0) return false;  // x coincides with v: not a direction
  return (o1 == s || o1 == 0) && (o2 == s || o2 == 0);
}

// The size that bounds the rounding of dot(x, a): the sum of |x_k a_k|.
double abs_dot(const Vec3 &x, const Vec3 &a) {
  return std::fabs(x.x * a.x) + std::fabs(x.y * a.y) + std::fabs(x.z * a.z);
}

// How far apart two projections must lie to be apart for certain, given `size`, the abs_dot of
// the projections compared summed (a sum, not a maximum, so that a NaN carries through): 2^-40
// of it, far above their rounding (each below 8 eps of it); infinity, which no difference
// exceeds, for a NaN or infinite size or one under 2^-860, too small for a bound relative to it.
double projection_margin(double size) {
  return size > 0x1p-860 && size < HUGE_VAL ? 0x1p-40 * size : HUGE_VAL;
}

// Whether an axis perpendicular to an edge of t or f, in that triangle's plane, keeps the two
// apart, decided in floating point with a margin far above the rounding. Any axis will do:
// when the two closed triangles' projections onto it (whatever vector the rounded cross
// products made it) are disjoint intervals, the triangles are disjoint (projection_margin
// makes "disjoint" certain). Neighbouring faces of a nearly flat patch straddle each other's
// planes, so the plane tests cannot tell them apart while these axes can: the long, thin faces
// between the lines of a CT contour stack sent millions of such pairs to the six segment tests.
bool apart_in_plane(const Vec3 t[3], const Vec3 f[3]) {
  const Vec3 o = t[0];
  const Vec3 tp[3] = {Vec3{0, 0, 0}, t[1] - o, t[2] - o};
  const Vec3 fp[3] = {f[0] - o, f[1] - o, f[2] - o};
  auto apart_along = [&](const Vec3 &a) {
    double tlo = 0, thi = 0, flo = 0, fhi = 0, size = 0;
    for (int k = 0; k < 3; ++k) {
      const double pt = dot(tp[k], a), pf = dot(fp[k], a);
      tlo = k ? std::min(tlo, pt) : pt;
      thi = k ? std::max(thi, pt) : pt;
      flo = k ? std::min(flo, pf) : pf;
      fhi = k ? std::max(fhi, pf) : pf;
      size += abs_dot(tp[k], a) + abs_dot(fp[k], a);
    }
    const double margin = projection_margin(size);
    return flo - thi > margin || tlo - fhi > margin;
  };
  for (const Vec3 *q : {tp, fp}) {
    const Vec3 n = cross(q[1] - q[0], q[2] - q[0]);
    for (int i = 0; i < 3; ++i)
      if (apart_along(cross(q[(i + 1) % 3] - q[i], n))) return true;
  }
  return false;
}

// Whether triangles v a b and v c d, sharing only v, meet in v alone because a plane through v
// has a and b strictly on one side and c and d strictly on the other: the plane whose normal
// points from the directions of a and b toward those of c and d. Floating point with a margin,
// as apart_in_plane, and for the same pairs: faces around a vertex of a flat patch, in each
// other's planes, which the plane tests cannot separate.
bool apart_at_vertex(const Vec3 &v, const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d) {
  const Vec3 x[4] = {a - v, b - v, c - v, d - v};
  Vec3 axis{0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    const double len = std::sqrt(norm2(x[k]));
    axis = axis + x[k] * (k < 2 ? -1 / len : 1 / len);
  }
  double size = 0, side[4];
  for (int k = 0; k < 4; ++k) {
    side[k] = dot(x[k], axis);
    size += abs_dot(x[k], axis);
  }
  const double margin = projection_margin(size);
  return side[0] < -margin && side[1] < -margin && side[2] > margin && side[3] > margin;
}

}  // namespace

int orient3d(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d) {
  double bx = b.x - a.x, by = b.y - a.y, bz = b.z - a.z;
  double cx = c.x - a.x, cy = c.y - a.y, cz = c.z - a.z;
  double dx = d.x - a.x, dy = d.y - a.y, dz = d.z - a.z;
  if (!in_filter_range({bx, by, bz, cx, cy, cz, dx, dy, dz}, 0x1p-340, 0x1p+340))
    return orient3d_exact(a, b, c, d);
  double m1 = cy * dz, m2 = cz * dy, m3 = cz * dx, m4 = cx * dz, m5 = cx * dy, m6 = cy * dx;
  double det = bx * (m1 - m2) + by * (m3 - m4) + bz * (m5 - m6);
  double permanent = std::fabs(bx) * (std::fabs(m1) + std::fabs(m2)) +
                     std::fabs(by) * (std::fabs(m3) + std::fabs(m4)) +
                     std::fabs(bz) * (std::fabs(m5) + std::fabs(m6));
  double bound = kOrient3dBound * permanent;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  if (permanent == 0) return 0;
  return orient3d_exact(a, b, c, d);
}

int orient2d(const Vec3 &a, const Vec3 &b, const Vec3 &c, int drop) {
  double au, av, bu, bv, cu, cv;
  project(a, drop, au, av);
  project(b, drop, bu, bv);
  project(c, drop, cu, cv);
  const double du = bu - au, dv = cv - av, ev = bv - av, eu = cu - au;
  if (!in_filter_range({du, dv, ev, eu}, 0x1p-500, 0x1p+500))
    return orient2d_exact(au, av, bu, bv, cu, cv);
  double l = du * dv, r = ev * eu;
  double det = l - r;
  double bound = kOrient2dBound * (std::fabs(l) + std::fabs(r));
  if (det > bound) return 1;
  if (det < -bound) return -1;
  if (l == 0 && r == 0) return 0;
  return orient2d_exact(au, av, bu, bv, cu, cv);
}

bool collinear(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  return orient2d(a, b, c, 0) == 0 && orient2d(a, b, c, 1) == 0 && orient2d(a, b, c, 2) == 0;
}

bool segment_meets_triangle(const Vec3 &p, const Vec3 &q, const Vec3 &a, const Vec3 &b,
                            const Vec3 &c) {
  int o1 = orient3d(a, b, c, p), o2 = orient3d(a, b, c, q);
  if (o1 == o2 && o1 != 0) return false;
  if (o1 == 0 && o2 == 0) {
    int drop = projection_axis(a, b, c);
    return point_in_triangle_2d(p, a, b, c, drop) || point_in_triangle_2d(q, a, b, c, drop) ||
           segments_meet_2d(p, q, a, b, drop) || segments_meet_2d(p, q, b, c, drop) ||
           segments_meet_2d(p, q, c, a, drop);
  }
  // The segment reaches the plane; where its line crosses it must lie in the closed triangle.
  int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

bool triangles_cross(const Vec3 t[3], const unsigned it[3], const Vec3 f[3], const unsigned jf[3]) {
  // Which corners are shared: st[i] = corner of f equal to corner i of t, or -1.
  int st[3] = {-1, -1, -1}, sf[3] = {-1, -1, -1}, shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (it[i] == jf[j]) {
        st[i] = j;
        sf[j] = i;
        ++shared;
      }
  if (shared == 3) return true;
  // Separated by a plane: all corners of one triangle that are not shared lie strictly on one
  // side of the other's plane. Then the two meet at most in what they share. Most pairs end
  // here, after two or three orientation tests.
  auto strictly_one_side = [](const Vec3 p[3], const Vec3 q[3], const int sq[3]) {
    int side = 0;
    for (int j = 0; j < 3; ++j) {
      if (sq[j] >= 0) continue;
      int o = orient3d(p[0], p[1], p[2], q[j]);
      if (o == 0 || (side != 0 && o != side)) return false;
      side = o;
    }
    return side != 0;
  };
  if (shared < 2 && (strictly_one_side(t, f, sf) || strictly_one_side(f, t, st))) return false;
  if (shared == 0) {
    if (apart_in_plane(t, f)) return false;
    for (int i = 0; i < 3; ++i) {
      if (segment_meets_triangle(t[i], t[(i + 1) % 3], f[0], f[1], f[2])) return true;
      if (segment_meets_triangle(f[i], f[(i + 1) % 3], t[0], t[1], t[2])) return true;
    }
    return false;
  }
  if (shared == 2) {
    int a = 0, b = 0;
    while (st[a] >= 0) ++a;
    while (sf[b] >= 0) ++b;
    const Vec3 &u = t[(a + 1) % 3], &v = t[(a + 2) % 3];
    if (orient3d(u, v, t[a], f[b]) != 0) return false;
    int drop = projection_axis(u, v, t[a]);
    return orient2d(u, v, t[a], drop) == orient2d(u, v, f[b], drop);  // folded onto each other
  }
  // One shared vertex v: t = (v, a, b), f = (v, c, d).
  int i = 0, j = 0;
  while (st[i] < 0) ++i;
  j = st[i];
  const Vec3 &v = t[i], &a = t[(i + 1) % 3], &b = t[(i + 2) % 3];
  const Vec3 &c = f[(j + 1) % 3], &d = f[(j + 2) % 3];
  if (apart_at_vertex(v, a, b, c, d)) return false;
  if (segment_meets_triangle(a, b, v, c, d) || segment_meets_triangle(c, d, v, a, b)) return true;
  // An edge leaving v that lies in the other triangle's plane and inside its corner at v.
  if (orient3d(v, c, d, a) == 0 && ray_in_sector(v, c, d, a)) return true;
  if (orient3d(v, c, d, b) == 0 && ray_in_sector(v, c, d, b)) return true;
  if (orient3d(v, a, b, c) == 0 && ray_in_sector(v, a, b, c)) return true;
  if (orient3d(v, a, b, d) == 0 && ray_in_sector(v, a, b, d)) return true;
  return false;
}

}  // namespace moa
