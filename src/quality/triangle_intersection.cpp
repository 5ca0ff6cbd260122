// Triangle-triangle intersection by exact predicates only: signs of orient3d and orient2d, and
// comparisons of input coordinates. The cases follow what two faces share by index.
//
// Why the tests below are complete:
// - No shared vertex: two closed triangles meet iff an edge of one meets the other (the ends of
//   the intersection segment lie on edges; a triangle inside the other has its edges inside).
// - One shared vertex v: T n U is convex and contains v; if it holds another point it holds a
//   segment from v, whose far end lies on an edge of T or U. That edge is either the edge
//   opposite v (tested as a segment) or an edge from v lying in the other face's plane, which
//   is inside the other face near v iff its direction lies in that face's angle at v.
// - One shared edge pq: off the common plane the faces meet only along the line pq, i.e. in the
//   edge; in the plane they overlap iff the third vertices lie on the same side of pq.
#include "quality/triangle_intersection.hpp"

#include "quality/exact_predicates.hpp"

namespace moa::quality {
namespace {

using P = const double *;

int sgn_mul(int a, int b) { return a * b; }

// Given that x lies on line pq (in the projection), is it between p and q?
bool between_2d(P p, P q, P x, int drop) {
  for (int k = 1; k <= 2; ++k) {
    int i = (drop + k) % 3;
    double lo = p[i] < q[i] ? p[i] : q[i], hi = p[i] < q[i] ? q[i] : p[i];
    if (x[i] < lo || x[i] > hi) return false;
  }
  return true;
}

// Closed segments pq and ab in the projection.
bool segments_meet_2d(P p, P q, P a, P b, int drop) {
  int d1 = orient2d(p, q, a, drop), d2 = orient2d(p, q, b, drop);
  if (d1 != 0 && d1 == d2) return false;
  int d3 = orient2d(a, b, p, drop), d4 = orient2d(a, b, q, drop);
  if (d3 != 0 && d3 == d4) return false;
  if (sgn_mul(d1, d2) < 0 && sgn_mul(d3, d4) < 0) return true;
  return (d1 == 0 && between_2d(p, q, a, drop)) || (d2 == 0 && between_2d(p, q, b, drop)) ||
         (d3 == 0 && between_2d(a, b, p, drop)) || (d4 == 0 && between_2d(a, b, q, drop));
}

// Closed triangle abc (non-degenerate in the projection) contains x.
bool point_in_triangle_2d(P x, P a, P b, P c, int drop) {
  int s = orient2d(a, b, c, drop);
  return sgn_mul(orient2d(a, b, x, drop), s) >= 0 && sgn_mul(orient2d(b, c, x, drop), s) >= 0 &&
         sgn_mul(orient2d(c, a, x, drop), s) >= 0;
}

bool segment_meets_triangle_2d(P p, P q, P a, P b, P c, int drop) {
  return point_in_triangle_2d(p, a, b, c, drop) || point_in_triangle_2d(q, a, b, c, drop) ||
         segments_meet_2d(p, q, a, b, drop) || segments_meet_2d(p, q, b, c, drop) ||
         segments_meet_2d(p, q, c, a, drop);
}

// Closed segment pq against closed triangle abc; op, oq = orient3d(a, b, c, p / q).
bool segment_meets_triangle(P p, P q, P a, P b, P c, int op, int oq) {
  if (op != 0 && op == oq) return false;
  if (op == 0 && oq == 0) return segment_meets_triangle_2d(p, q, a, b, c, projection_axis(a, b, c));
  // The segment crosses the plane at one point; the line through it passes through the closed
  // triangle iff the three line-edge orientations do not disagree in sign.
  int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c);
  if (s1 * s2 < 0) return false;
  int s3 = orient3d(p, q, c, a);
  return s1 * s3 >= 0 && s2 * s3 >= 0;
}

// x lies in the plane of triangle (v, b1, b2); is it inside the closed angle at v?
bool in_angle_at(P x, P v, P b1, P b2) {
  int drop = projection_axis(v, b1, b2);
  int s = orient2d(v, b1, b2, drop);
  return sgn_mul(orient2d(v, b1, x, drop), s) >= 0 && sgn_mul(orient2d(v, x, b2, drop), s) >= 0;
}

bool no_shared(const Face &t, const Face &u) {
  int su[3], st[3];
  for (int k = 0; k < 3; ++k) su[k] = orient3d(t.p[0], t.p[1], t.p[2], u.p[k]);
  if ((su[0] > 0 && su[1] > 0 && su[2] > 0) || (su[0] < 0 && su[1] < 0 && su[2] < 0)) return false;
  if (su[0] == 0 && su[1] == 0 && su[2] == 0) {
    int drop = projection_axis(t.p[0], t.p[1], t.p[2]);
    for (int k = 0; k < 3; ++k)
      if (segment_meets_triangle_2d(t.p[k], t.p[(k + 1) % 3], u.p[0], u.p[1], u.p[2], drop))
        return true;
    return point_in_triangle_2d(u.p[0], t.p[0], t.p[1], t.p[2], drop);
  }
  for (int k = 0; k < 3; ++k) st[k] = orient3d(u.p[0], u.p[1], u.p[2], t.p[k]);
  if ((st[0] > 0 && st[1] > 0 && st[2] > 0) || (st[0] < 0 && st[1] < 0 && st[2] < 0)) return false;
  for (int k = 0; k < 3; ++k) {
    int l = (k + 1) % 3;
    if (segment_meets_triangle(t.p[k], t.p[l], u.p[0], u.p[1], u.p[2], st[k], st[l])) return true;
    if (segment_meets_triangle(u.p[k], u.p[l], t.p[0], t.p[1], t.p[2], su[k], su[l])) return true;
  }
  return false;
}

// t = (v, a1, a2), u = (v, b1, b2) after rotation.
bool shared_vertex(P v, P a1, P a2, P b1, P b2) {
  int oa1 = orient3d(v, b1, b2, a1), oa2 = orient3d(v, b1, b2, a2);
  if (oa1 != 0 && oa1 == oa2) return false;  // T touches U's plane only at v
  int ob1 = orient3d(v, a1, a2, b1), ob2 = orient3d(v, a1, a2, b2);
  if (ob1 != 0 && ob1 == ob2) return false;
  if (segment_meets_triangle(a1, a2, v, b1, b2, oa1, oa2)) return true;
  if (segment_meets_triangle(b1, b2, v, a1, a2, ob1, ob2)) return true;
  return (oa1 == 0 && in_angle_at(a1, v, b1, b2)) || (oa2 == 0 && in_angle_at(a2, v, b1, b2)) ||
         (ob1 == 0 && in_angle_at(b1, v, a1, a2)) || (ob2 == 0 && in_angle_at(b2, v, a1, a2));
}

// t = (p, q, a), u = (p, q, b) after rotation.
bool shared_edge(P p, P q, P a, P b) {
  if (orient3d(p, q, a, b) != 0) return false;
  int drop = projection_axis(p, q, a);
  return orient2d(p, q, a, drop) == orient2d(p, q, b, drop);
}

}  // namespace

bool faces_intersect(const Face &t, const Face &u) {
  int ti[3], ui[3], shared = 0;  // positions of the shared vertices
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (t.v[i] == u.v[j]) { ti[shared] = i; ui[shared] = j; ++shared; }
  if (shared == 0) return no_shared(t, u);
  if (shared == 3) return true;  // the same face twice
  if (shared == 1) {
    int i = ti[0], j = ui[0];
    return shared_vertex(t.p[i], t.p[(i + 1) % 3], t.p[(i + 2) % 3], u.p[(j + 1) % 3],
                         u.p[(j + 2) % 3]);
  }
  int ta = 3 - ti[0] - ti[1], ua = 3 - ui[0] - ui[1];  // the unshared vertex of each
  return shared_edge(t.p[ti[0]], t.p[ti[1]], t.p[ta], u.p[ua]);
}

}  // namespace moa::quality
