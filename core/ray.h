// A ray X = origin + t * dir with a unit-length direction, so t is a distance.
#pragma once

#include "core/math.h"

namespace prism {

struct Ray {
  Vec3 origin{0.0};
  Vec3 dir{0.0, 0.0, -1.0};

  Vec3 at(double t) const { return origin + t * dir; }
};

// A ray with a NaN or infinite component hits nothing. Hierarchies check this
// first: in their box tests a NaN culls nothing, so such a ray would enter
// every box, unused child slots included, and never finish.
inline bool isFinite(const Ray& ray) { return isFinite(ray.origin) && isFinite(ray.dir); }

// What a traced ray is for; statistics and the --pixel ray tree are kept by kind.
enum class RayKind { Eye, Shadow, Reflected, Transmitted };

const char* rayKindName(RayKind kind);

} // namespace prism
