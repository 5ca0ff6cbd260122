// Closed triangle/triangle and segment/triangle tests decided by exact orientation signs.
// Coplanar configurations are projected onto a coordinate plane in which the reference triangle
// keeps a non-zero area; that projection is a bijection on the common plane, so incidences are
// preserved exactly (the projected coordinates are the original doubles).
#include "support/triangle_intersection.hpp"

namespace moa::test {

namespace {

struct Pt2 {
  double x, y;
};

// Coordinate pair (i, j) whose projection keeps triangle abc non-degenerate.
struct Projection {
  int i = 0, j = 1;
  Pt2 operator()(const Vec3 &p) const { return {p[i], p[j]}; }
};

Projection projection_for(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  static const int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (const auto &pr : pairs) {
    if (orient2d(a[pr[0]], a[pr[1]], b[pr[0]], b[pr[1]], c[pr[0]], c[pr[1]]) != 0)
      return {pr[0], pr[1]};
  }
  return {};  // degenerate triangle: callers never pass one
}

int orient(const Pt2 &a, const Pt2 &b, const Pt2 &c) { return orient2d(a.x, a.y, b.x, b.y, c.x, c.y); }

// p lies in the closed box of segment ab (used once p is known to be collinear with ab).
bool within_box(const Pt2 &a, const Pt2 &b, const Pt2 &p) {
  const bool x_in = (a.x <= b.x) ? (a.x <= p.x && p.x <= b.x) : (b.x <= p.x && p.x <= a.x);
  const bool y_in = (a.y <= b.y) ? (a.y <= p.y && p.y <= b.y) : (b.y <= p.y && p.y <= a.y);
  return x_in && y_in;
}

bool segments_meet(const Pt2 &p, const Pt2 &q, const Pt2 &a, const Pt2 &b) {
  const int o1 = orient(p, q, a), o2 = orient(p, q, b);
  const int o3 = orient(a, b, p), o4 = orient(a, b, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && within_box(p, q, a)) return true;
  if (o2 == 0 && within_box(p, q, b)) return true;
  if (o3 == 0 && within_box(a, b, p)) return true;
  if (o4 == 0 && within_box(a, b, q)) return true;
  return false;
}

bool point_in_triangle(const Pt2 &p, const Pt2 &a, const Pt2 &b, const Pt2 &c) {
  const int s1 = orient(a, b, p), s2 = orient(b, c, p), s3 = orient(c, a, p);
  const bool has_pos = s1 > 0 || s2 > 0 || s3 > 0;
  const bool has_neg = s1 < 0 || s2 < 0 || s3 < 0;
  return !(has_pos && has_neg);
}

bool coplanar_segment_triangle(const Vec3 &p, const Vec3 &q, const Vec3 &a, const Vec3 &b,
                               const Vec3 &c) {
  const Projection pr = projection_for(a, b, c);
  const Pt2 p2 = pr(p), q2 = pr(q), a2 = pr(a), b2 = pr(b), c2 = pr(c);
  if (point_in_triangle(p2, a2, b2, c2) || point_in_triangle(q2, a2, b2, c2)) return true;
  return segments_meet(p2, q2, a2, b2) || segments_meet(p2, q2, b2, c2) ||
         segments_meet(p2, q2, c2, a2);
}

bool coplanar_triangles_meet(const Vec3 (&t)[3], const Vec3 (&u)[3]) {
  const Projection pr = projection_for(t[0], t[1], t[2]);
  Pt2 t2[3], u2[3];
  for (int k = 0; k < 3; ++k) {
    t2[k] = pr(t[k]);
    u2[k] = pr(u[k]);
  }
  for (int k = 0; k < 3; ++k) {
    if (point_in_triangle(t2[k], u2[0], u2[1], u2[2])) return true;
    if (point_in_triangle(u2[k], t2[0], t2[1], t2[2])) return true;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_meet(t2[i], t2[(i + 1) % 3], u2[j], u2[(j + 1) % 3])) return true;
  return false;
}

// Segment pq against triangle abc when the signs of p and q relative to the plane are known.
bool segment_meets_triangle_signed(const Vec3 &p, const Vec3 &q, int sp, int sq, const Vec3 &a,
                                   const Vec3 &b, const Vec3 &c) {
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) return coplanar_segment_triangle(p, q, a, b, c);
  // The segment reaches the plane and its line is not in it: the line pierces the closed
  // triangle iff the three edge volumes have no two strictly opposite signs.
  const int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
  const bool has_pos = s1 > 0 || s2 > 0 || s3 > 0;
  const bool has_neg = s1 < 0 || s2 < 0 || s3 < 0;
  return !(has_pos && has_neg);
}

}  // namespace

bool segment_meets_triangle(const Vec3 &p, const Vec3 &q, const Vec3 &a, const Vec3 &b,
                            const Vec3 &c) {
  return segment_meets_triangle_signed(p, q, orient3d(a, b, c, p), orient3d(a, b, c, q), a, b, c);
}

bool triangles_meet(const Vec3 (&t)[3], const Vec3 (&u)[3]) {
  int su[3], st[3];
  for (int k = 0; k < 3; ++k) su[k] = orient3d(t[0], t[1], t[2], u[k]);
  if ((su[0] > 0 && su[1] > 0 && su[2] > 0) || (su[0] < 0 && su[1] < 0 && su[2] < 0)) return false;
  if (su[0] == 0 && su[1] == 0 && su[2] == 0) return coplanar_triangles_meet(t, u);
  for (int k = 0; k < 3; ++k) st[k] = orient3d(u[0], u[1], u[2], t[k]);
  if ((st[0] > 0 && st[1] > 0 && st[2] > 0) || (st[0] < 0 && st[1] < 0 && st[2] < 0)) return false;
  // Not coplanar: the intersection, if any, is a segment on the planes' common line whose
  // end points lie on edges, so some edge of one triangle meets the other triangle.
  for (int k = 0; k < 3; ++k) {
    const int n = (k + 1) % 3;
    if (segment_meets_triangle_signed(t[k], t[n], st[k], st[n], u[0], u[1], u[2])) return true;
    if (segment_meets_triangle_signed(u[k], u[n], su[k], su[n], t[0], t[1], t[2])) return true;
  }
  return false;
}

bool shared_vertex_conflict(const Vec3 &v, const Vec3 &a, const Vec3 &b, const Vec3 &c,
                            const Vec3 &d) {
  // Both triangles lie in their wedges at v. If the wedges share a ray, that ray leaves each
  // triangle through its edge opposite v, and the nearer exit point lies in the other triangle;
  // so a conflict exists iff an opposite edge meets the other triangle (it never contains v).
  return segment_meets_triangle(a, b, v, c, d) || segment_meets_triangle(c, d, v, a, b);
}

bool shared_edge_conflict(const Vec3 &v, const Vec3 &w, const Vec3 &a, const Vec3 &b) {
  if (orient3d(v, w, a, b) != 0) return false;  // distinct planes meet only along vw
  const Projection pr = projection_for(v, w, a);
  const int sa = orient(pr(v), pr(w), pr(a)), sb = orient(pr(v), pr(w), pr(b));
  // Same side: the triangles overlap next to the edge. b on the line vw: the second triangle
  // is degenerate and reported by C1, not here.
  return sa * sb > 0;
}

}  // namespace moa::test
