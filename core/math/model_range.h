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
#include <limits>
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

// How unevenly the map of an ellipsoid or a sheared cone may stretch space:
// its condition number (largest over smallest singular value), bounded above by
// stretchRatioBound. Round-off in the shape's frame, and with it the offset by
// which rays leave its surface (frameSkew in core/shapes/roundoff.h), grows
// with how sheared the map is; and near 1e16 the map is singular to double
// precision, so it could not even be written back and read again.
inline constexpr double kMaxStretchRatio = 1e10;
inline constexpr const char* kMaxStretchRatioText = "1e10";

// |m| |m^-1| in the Frobenius norm, computed without under- or overflowing
// the squares: at least the condition number of m and at most 3 times it.
// Infinite (or NaN) when m is singular to double precision.
double stretchRatioBound(const Mat3& m);

// The message a reader gives for `what` (e.g. "sphere") stretched too unevenly.
inline std::string tooUnevenMessage(const std::string& what) {
  return what + ": the current transform stretches it too unevenly: one direction more than " +
         std::string(kMaxStretchRatioText) + " times another";
}

} // namespace prism
