// What the tracer learns of a surface at a hit point, beyond the distance:
// the record every shape kind hands to shading, so the tracer needs no
// kind-specific code.
#pragma once

#include "core/math/math.h"

#include <optional>

namespace prism {

struct SurfacePoint {
  Vec3 outward; // unit geometric normal, outward: decides entering or leaving, offsets rays
  Vec3 shading; // unit shading normal, outward (a smooth triangle's interpolated one)
  // Where rays leaving the outward side start, when not at the hit point itself
  // (a smooth triangle lifts them onto the curved surface its normals describe).
  std::optional<Vec3> outwardStart;
};

} // namespace prism
