// Vector types and the few scalar helpers the renderer shares. Geometry and
// radiance are computed in double precision: scenes must render from 1e-4 to 1e4
// units (docs/rendering-model.md) and double keeps round-off far below any modelled detail.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

using Vec2 = glm::dvec2; // surface coordinates (u, v)
using Vec3 = glm::dvec3;
using Color = glm::dvec3; // linear RGB radiance; never clamped before exposure

using Mat3 = glm::dmat3;
using Mat4 = glm::dmat4;

// Radiance is never limited, but a double can overflow: a light of intensity
// 1e308 at distance 0.1, or a chain of mirrors with ksr > 1. Infinity is fine
// in a sum of non-negative terms; only infinity times zero (a material with
// kdr = 0 under that light) would make a NaN. So every value that may have
// overflowed is pegged at the largest double before it is multiplied by a
// coefficient that may be zero. The film then stores the largest float (see
// toRgb). For every finite radiance this changes nothing.
inline Color saturated(const Color& c) {
  return glm::min(c, Color(std::numeric_limits<double>::max()));
}

inline double maxComponent(const Vec3& v) { return std::max({v.x, v.y, v.z}); }

inline double maxAbsComponent(const Vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// The axis (0, 1, 2) of v's largest component in size, the first of equal
// ones. The ray-frame tests of triangles and polygons project along the
// ray direction's: one rule for the scalar tests and the BVH's packets, so
// they answer alike.
inline int largestAbsAxis(const Vec3& v) {
  const Vec3 m = glm::abs(v);
  return m.x >= m.y ? (m.x >= m.z ? 0 : 2) : (m.y >= m.z ? 1 : 2);
}

inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// x^e for x >= 0. A whole exponent up to 1024 (the highlight exponent almost
// always is one) is done by repeated squaring, at most 20 products: shading
// raises the cosine for every light of every hit, and that is a fraction of
// the libm call's time. A squaring doubles the relative error it is given, so
// the result is within about e/2 ulps of x^e (1e-14 for e = 60): far below
// anything a picture shows. Any other exponent goes to std::pow. 0^0 is 1
// either way.
inline double powNonNegative(double x, double e) {
  if (!(e >= 0.0 && e <= 1024.0) || e != std::floor(e)) return std::pow(x, e);
  double result = 1.0;
  for (auto n = unsigned(e); n != 0; n >>= 1) {
    if ((n & 1u) != 0) result *= x;
    x *= x;
  }
  return result;
}

} // namespace prism
