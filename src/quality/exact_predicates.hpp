// Exact orientation predicates for the mesh analyzer: a floating-point filter decides the easy
// signs, GMP integers the rest. Kept apart from the core's predicates so that the analyzer is
// an independent check of the core. Points are pointers to x y z.
#pragma once

namespace moa::quality {

// Sign of det[b-a, c-a, d-a]: > 0 when d lies on the side the normal (b-a) x (c-a) points to,
// 0 when the four points are coplanar.
int orient3d(const double *a, const double *b, const double *c, const double *d);

// Sign of the 2-D orientation of (a, b, c) in the projection that drops axis `drop` and keeps the
// other two in cyclic order (drop 0: y z, 1: z x, 2: x y).
int orient2d(const double *a, const double *b, const double *c, int drop);

// True when the three points are exactly collinear (or coincide).
bool collinear(const double *a, const double *b, const double *c);

// The axis to drop so that triangle abc keeps a non-zero area in the projection; -1 when the
// triangle is degenerate.
int projection_axis(const double *a, const double *b, const double *c);

}  // namespace moa::quality
