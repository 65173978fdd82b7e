// The frames of the kinds built around an axis (cones, tori): two unit
// vectors completing a unit axis, placing the frame in the world, and whether
// a placed frame still has round cross-sections.
#pragma once

#include "core/math/math.h"

#include <cmath>

namespace prism {

// Unit `u` and `v` perpendicular to unit `w` and to each other (Frisvad's
// construction, made branch-safe as in Duff et al. 2017).
inline void perpendicularPair(const Vec3& w, Vec3& u, Vec3& v) {
  const double sign = std::copysign(1.0, w.z);
  const double a = -1.0 / (sign + w.z);
  const double b = w.x * w.y * a;
  u = Vec3(1.0 + sign * w.x * w.x * a, sign * b, -sign * w.x);
  v = Vec3(b, sign + w.y * w.y * a, -w.y);
}

// The unit frame around `axis` (any length, not zero, its length finite):
// columns u, v and the unit axis w.
inline Mat3 frameAround(const Vec3& axis) {
  const Vec3 w = glm::normalize(axis / maxAbsComponent(axis));
  Vec3 u, v;
  perpendicularPair(w, u, v);
  return Mat3(u, v, w);
}

// Places a kind that lives in its own frame (objectToWorld and its offset,
// their inverse, normalToWorld): object point x goes to
// linear (frame x + origin) + offset.
template <class Shape>
void placeFrame(Shape& shape, const Mat3& frame, const Vec3& origin, const Mat3& linear,
                const Vec3& offset) {
  shape.objectToWorld = linear * frame;
  shape.objectToWorldOffset = linear * origin + offset;
  shape.worldToObject = glm::inverse(shape.objectToWorld);
  shape.worldToObjectOffset = -(shape.worldToObject * shape.objectToWorldOffset);
  shape.normalToWorld = glm::transpose(shape.worldToObject); // carries gradients
}

// True when a frame (columns: its x, y and z axes in the world) has the
// circles around its z axis still circles in the world: x and y orthogonal,
// of equal length, and perpendicular to z.
inline bool hasRoundSections(const Mat3& m) {
  const Vec3& x = m[0];
  const Vec3& y = m[1];
  const Vec3& z = m[2];
  const double lx = glm::length(x), ly = glm::length(y), lz = glm::length(z);
  constexpr double kTolerance = 1e-12;
  return std::abs(lx - ly) <= kTolerance * lx && std::abs(glm::dot(x, y)) <= kTolerance * lx * ly &&
         std::abs(glm::dot(x, z)) <= kTolerance * lx * lz &&
         std::abs(glm::dot(y, z)) <= kTolerance * ly * lz;
}

} // namespace prism
