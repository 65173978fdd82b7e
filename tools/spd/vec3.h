// The little vector algebra the benchmark generators need: a point or direction
// in world space, its operators, and an orthonormal frame around an axis. Plain
// doubles, so spd_gen links nothing of the renderer (whose Vec3 is GLM's).
#pragma once

#include <cmath>

namespace prism::spd {

struct V3 {
  double x = 0, y = 0, z = 0;
};

inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator-(V3 a) { return {-a.x, -a.y, -a.z}; }
inline V3 operator*(double s, V3 v) { return {s * v.x, s * v.y, s * v.z}; }
inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 cross(V3 a, V3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(V3 v) { return std::sqrt(dot(v, v)); }
inline V3 normalize(V3 v) { return (1.0 / length(v)) * v; }
inline V3 lerp(V3 a, V3 b, double t) { return a + t * (b - a); }

inline constexpr double kPi = 3.14159265358979323846;
inline double radians(double degrees) { return degrees * kPi / 180.0; }

// Two unit vectors that make a right-handed orthonormal frame (u, v, axis) with
// the unit vector `axis`; the helper vector avoids the axis it is nearly
// parallel to, so the frame never degenerates.
struct Frame {
  V3 u, v, w;
};
inline Frame frameAround(V3 axis) {
  const V3 helper = std::fabs(axis.x) < 0.9 ? V3{1, 0, 0} : V3{0, 1, 0};
  const V3 u = normalize(cross(helper, axis));
  return {u, cross(axis, u), axis};
}
// The direction at polar angle `theta` from the frame's axis and azimuth `phi`
// around it (radians).
inline V3 direction(const Frame& f, double theta, double phi) {
  const double s = std::sin(theta);
  return s * std::cos(phi) * f.u + s * std::sin(phi) * f.v + std::cos(theta) * f.w;
}

} // namespace prism::spd
