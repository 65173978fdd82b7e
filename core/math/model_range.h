// The magnitudes the renderer represents without overflow. Geometry is computed
// in double precision, whose range (about 1e308) is wide but not endless: a
// ray-sphere test squares distances, and a shading point's distance to a light
// is squared too. Every reader therefore keeps world-space coordinates (after
// transforms) of primitives, lights and the camera within +-kMaxCoordinate,
// where squares and sums of squares of differences stay below 1e62, far from
// overflow even after the hierarchy's and the camera's arithmetic. Radiance is
// not limited: it saturates instead (see Tracer and toRgb).
#pragma once

#include "core/math/aabb.h"

#include <cmath>
#include <string>

namespace prism {

inline constexpr double kMaxCoordinate = 1e30;
inline constexpr const char* kMaxCoordinateText = "1e30";

// False for NaN too.
inline bool withinModelRange(const Vec3& p) {
  return std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate &&
         std::abs(p.z) <= kMaxCoordinate;
}

// A box (a primitive's bounds) lies within range; NaN bounds do not.
inline bool withinModelRange(const Aabb& box) {
  return withinModelRange(box.lo) && withinModelRange(box.hi);
}

// The message a reader gives for `what` (e.g. "sphere") outside the range.
inline std::string outsideModelRangeMessage(const std::string& what) {
  return what + ": lies outside the supported range: world coordinates (after the current " +
         "transform) must be within +-" + kMaxCoordinateText;
}

} // namespace prism
