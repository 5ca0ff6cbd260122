// Small vector algebra on double triples, shared by every stage of the core.
#pragma once

#include <algorithm>
#include <cmath>

namespace moa {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm2(Vec3 a) { return dot(a, a); }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalized(Vec3 a) {
  double n = norm(a);
  return n > 0 ? a * (1.0 / n) : Vec3{};
}
inline double dist(Vec3 a, Vec3 b) { return norm(a - b); }
inline Vec3 midpoint(Vec3 a, Vec3 b) { return (a + b) * 0.5; }
inline Vec3 centroid(Vec3 a, Vec3 b, Vec3 c) { return (a + b + c) * (1.0 / 3.0); }

// Whether the closed boxes alo..ahi and blo..bhi meet.
inline bool boxes_meet(const Vec3 &alo, const Vec3 &ahi, const Vec3 &blo, const Vec3 &bhi) {
  return ahi.x >= blo.x && alo.x <= bhi.x && ahi.y >= blo.y && alo.y <= bhi.y && ahi.z >= blo.z &&
         alo.z <= bhi.z;
}

// Angle between two vectors in radians, well conditioned near 0 and pi.
inline double angle_between(Vec3 a, Vec3 b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

// Angle at vertex c of triangle (a, b, c), i.e. the angle under which c sees segment ab.
inline double angle_at(Vec3 c, Vec3 a, Vec3 b) { return angle_between(a - c, b - c); }

// The smallest angle of triangle abc (radians): the one facing its shortest side, so one angle
// is computed instead of three.
inline double smallest_angle(Vec3 a, Vec3 b, Vec3 c) {
  const double ab = norm2(a - b), bc = norm2(b - c), ca = norm2(c - a);
  if (ab <= bc && ab <= ca) return angle_at(c, a, b);
  if (bc <= ca) return angle_at(a, b, c);
  return angle_at(b, c, a);
}

constexpr double kPi = 3.14159265358979323846;
inline double degrees_to_radians(double d) { return d * kPi / 180.0; }

}  // namespace moa
