// The ray-quadric roots shared by spheres and ellipsoids.
#pragma once

#include "core/math/interval.h"
#include "core/math/math.h"

#include <cmath>
#include <utility>

namespace prism {

// Both roots t0 <= t1 of |f + t d|^2 = r^2, or false when the line misses. In
// the form that keeps precision when the origin is far from the sphere
// compared with its radius (the discriminant is computed from the distance of
// the centre to the ray's line, not as a difference of squares of large
// numbers). `d` need not be unit length.
inline bool quadricRoots(const Vec3& f, const Vec3& d, double r2, double& t0, double& t1) {
  const double a = glm::dot(d, d);
  const double b = glm::dot(f, d); // half of the usual b
  const Vec3 l = f - (b / a) * d;  // centre-to-line offset
  const double disc = a * (r2 - glm::dot(l, l));
  if (disc < 0.0) return false;
  const double q = -b - std::copysign(std::sqrt(disc), b);
  const double c = glm::dot(f, f) - r2;
  t0 = q != 0.0 ? c / q : 0.0;
  t1 = q / a;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

// The nearest root inside `range`. Inline, like quadricRoots: it is the
// whole of the sphere's and the ellipsoid's intersection tests, which the
// hierarchies call for every candidate.
inline bool nearestQuadricRoot(const Vec3& f, const Vec3& d, double r2, Interval range, double& t) {
  double t0, t1;
  if (!quadricRoots(f, d, r2, t0, t1)) return false;
  if (range.contains(t0)) {
    t = t0;
    return true;
  }
  if (range.contains(t1)) {
    t = t1;
    return true;
  }
  return false;
}

} // namespace prism
