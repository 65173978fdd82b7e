// The frame a solid is modelled in (boxes, discs, capped cones): an affine
// map from the shape's own coordinates, where it is a fixed simple shape (the
// cube [-1, 1]^3, the unit disc, a cone along z), to the world. Rays are
// carried into the frame by the inverse map and keep their parameter t there;
// gradients come back by the inverse transpose, so normals stay correct
// under any shear or non-uniform scale (as for Ellipsoid and Cone).
#pragma once

#include "core/math/math.h"
#include "core/shapes/axis_frame.h" // perpendicularPair

#include <cmath>

namespace prism {

// `n` (not zero) at unit length, scaled first: the gradient of a very flat
// shape carried to the world can be so long that its squared length
// overflows.
inline Vec3 unitLength(const Vec3& n) { return glm::normalize(n / maxAbsComponent(n)); }

struct AffineFrame {
  Mat3 objectToWorld{1.0};       // columns: the frame's axes in the world
  Vec3 objectToWorldOffset{0.0}; // the world position of the frame's origin
  Mat3 worldToObject{1.0};
  Vec3 worldToObjectOffset{0.0};
  Mat3 normalToWorld{1.0}; // transpose of worldToObject: carries gradients

  Vec3 pointToObject(const Vec3& p) const { return worldToObject * p + worldToObjectOffset; }
  Vec3 directionToObject(const Vec3& d) const { return worldToObject * d; }
  // The unit world normal of a surface whose gradient in the frame is `g`.
  Vec3 normalToWorldUnit(const Vec3& g) const { return unitLength(normalToWorld * g); }
};

// The frame of x -> linear x + offset; `linear` must be invertible.
inline AffineFrame makeAffineFrame(const Mat3& linear, const Vec3& offset) {
  AffineFrame f;
  f.objectToWorld = linear;
  f.objectToWorldOffset = offset;
  f.worldToObject = glm::inverse(linear);
  f.worldToObjectOffset = -(f.worldToObject * offset);
  f.normalToWorld = glm::transpose(f.worldToObject);
  return f;
}

// The unit direction of a finite non-zero vector whose length may underflow
// or overflow, or false when it has none.
inline bool unitDirection(const Vec3& a, Vec3& unit) {
  const double scale = maxAbsComponent(a);
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  unit = glm::normalize(a / scale);
  return isFinite(unit);
}

// The angle of (x, y) around the frame's z axis as a fraction of a turn: 0.5
// on +x, growing toward +y (the cone's u).
inline double turnFraction(double x, double y) {
  constexpr double kPi = 3.14159265358979323846;
  return 0.5 + std::atan2(y, x) / (2.0 * kPi);
}

} // namespace prism
