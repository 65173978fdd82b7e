// Axis-aligned bounding boxes and the slab test used by every hierarchy.
#pragma once

#include "core/math/interval.h"
#include "core/math/ray.h"

#include <limits>

namespace prism {

struct Aabb {
  Vec3 lo{std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity()};

  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void extend(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void extend(const Aabb& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  Vec3 centroid() const { return 0.5 * (lo + hi); }
  Vec3 extent() const { return hi - lo; }

  // Half the surface area: proportional to the chance that a random ray hits
  // the box, which is what the hierarchies weigh boxes by. 0 for an empty
  // box; an unbounded one costs "a lot", not NaN.
  double halfArea() const {
    if (empty()) return 0.0;
    const Vec3 e = extent();
    const double a = e.x * e.y + e.y * e.z + e.z * e.x;
    return std::isnan(a) ? std::numeric_limits<double>::infinity() : a;
  }

  // Grows the box by a tiny amount relative to its position, so flat boxes
  // (of axis-aligned polygons) have thickness and the slab test never
  // evaluates 0 * inf for a ray lying in a face plane: 2^-46, 64 ulps of its
  // coordinates, as boxSlack (ray.h) for the ray's. No more: a ray leaving a
  // surface starts a few hundred ulps off it (kRayOffsetRoundoff), and a
  // thicker box around the neighbouring tiles of a floor would hold that
  // start and send every shadow ray into them.
  void pad() {
    if (empty()) return; // inf - inf would make an empty box NaN
    const double margin = 0x1p-46 * (maxAbsComponent(lo) + maxAbsComponent(hi)) + 1e-300;
    lo -= Vec3(margin);
    hi += Vec3(margin);
  }

  // Slab test against the parameter range, of the box widened by `slack`
  // (boxSlack(ray)); `invDir` is 1/ray.dir per component.
  bool hit(const Ray& ray, const Vec3& invDir, Interval range, double slack) const {
    for (int a = 0; a < 3; ++a) {
      double t0 = (lo[a] - slack - ray.origin[a]) * invDir[a];
      double t1 = (hi[a] + slack - ray.origin[a]) * invDir[a];
      if (t0 > t1) std::swap(t0, t1);
      range.min = t0 > range.min ? t0 : range.min;
      range.max = t1 < range.max ? t1 : range.max;
      if (range.min > range.max) return false;
    }
    return true;
  }
};

} // namespace prism
