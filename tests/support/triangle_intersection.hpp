// Exact intersection tests between closed triangles, for the C5 check. Every triangle passed
// here must be non-degenerate (the checker reports zero-area faces under C1 and skips them).
#pragma once

#include "support/exact_predicates.hpp"

namespace moa::test {

// Does the closed segment pq meet the closed triangle abc?
bool segment_meets_triangle(const Vec3 &p, const Vec3 &q, const Vec3 &a, const Vec3 &b,
                            const Vec3 &c);

// Do two closed triangles with no vertex in common meet at all?
bool triangles_meet(const Vec3 (&t)[3], const Vec3 (&u)[3]);

// Triangles (v, a, b) and (v, c, d) share only v: do they meet anywhere else?
bool shared_vertex_conflict(const Vec3 &v, const Vec3 &a, const Vec3 &b, const Vec3 &c,
                            const Vec3 &d);

// Triangles (v, w, a) and (v, w, b) share the edge vw: do they overlap beyond it (a coplanar
// fold-over, with a and b on the same side of vw)?
bool shared_edge_conflict(const Vec3 &v, const Vec3 &w, const Vec3 &a, const Vec3 &b);

}  // namespace moa::test
