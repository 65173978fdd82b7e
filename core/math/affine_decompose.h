// Splits a linear map into rotation, scale, rotation (a singular value
// decomposition), which is how the scene writer expresses an ellipsoid or a
// sheared cone with the .sc language's rotate and scale commands.
#pragma once

#include "core/math/math.h"

namespace prism {

// a == u * diag(scale) * transpose(v) up to round-off, with u and v proper
// rotations (determinant +1); a mirroring map gets one negative scale.
struct RotationScaleRotation {
  Mat3 u{1.0};
  Vec3 scale{1.0};
  Mat3 v{1.0};
};

// `a` must be invertible.
RotationScaleRotation decompose(const Mat3& a);

// Axis and angle (degrees) of a rotation matrix, for `rotate`; the angle is 0
// (and the axis z) for the identity.
void axisAngle(const Mat3& rotation, Vec3& axis, double& degrees);

} // namespace prism
