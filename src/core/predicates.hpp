// Exact geometric predicates on the caller's double coordinates: a floating-point filter
// decides the easy cases, GMP rationals the rest. The contract's "no zero-area faces" and
// "no self-intersections" are decided here, so rounding can never let a crossing through.
#pragma once

#include "core/geometry.hpp"

namespace moa {

// Sign of the determinant |b-a, c-a, d-a|: >0 when d lies below the plane (a, b, c) seen
// counter-clockwise, <0 above, 0 when the four points are coplanar.
int orient3d(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d);

// Sign of the 2-D orientation of (a, b, c) after dropping coordinate `drop` (0 = x, 1 = y, 2 = z).
int orient2d(const Vec3 &a, const Vec3 &b, const Vec3 &c, int drop);

// True when the three points are exactly collinear (the triangle has zero area).
bool collinear(const Vec3 &a, const Vec3 &b, const Vec3 &c);

// Do closed segment pq and closed triangle abc share a point?
bool segment_meets_triangle(const Vec3 &p, const Vec3 &q, const Vec3 &a, const Vec3 &b,
                            const Vec3 &c);

// Do two triangles meet anywhere other than in the vertices and edges they share?
// Shared vertices are recognised by index: ia/ib are the vertex indices of t and f.
bool triangles_cross(const Vec3 t[3], const unsigned it[3], const Vec3 f[3], const unsigned jf[3]);

}  // namespace moa
