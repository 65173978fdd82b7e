// The ray-quadric root shared by spheres and ellipsoids.
#pragma once

#include "core/math/interval.h"
#include "core/math/math.h"

namespace prism {

// Roots of |f + t d|^2 = r^2 in the form that keeps precision when the origin is
// far from the sphere compared with its radius (the discriminant is computed from
// the distance of the centre to the ray's line, not as a difference of squares
// of large numbers). `d` need not be unit length.
bool nearestQuadricRoot(const Vec3& f, const Vec3& d, double r2, Interval range, double& t);

} // namespace prism
