#include "core/shapes/quadric.h"

namespace prism {

bool nearestQuadricRoot(const Vec3& f, const Vec3& d, double r2, Interval range, double& t) {
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
