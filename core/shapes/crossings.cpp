#include "core/shapes/crossings.h"

#include "core/shapes/quadric.h"

namespace prism {

namespace {

// The two roots of a quadric solid are where the ray enters and leaves it.
void appendQuadricCrossings(const Vec3& f, const Vec3& d, double r2, Interval range,
                            std::vector<Crossing>& out) {
  double t0, t1;
  if (!quadricRoots(f, d, r2, t0, t1) || !(t0 < t1)) return;
  if (range.contains(t0)) out.push_back({t0, true, 0});
  if (range.contains(t1)) out.push_back({t1, false, 0});
}

} // namespace

void appendCrossings(const Sphere& s, const ShapeArrays&, const Ray& ray, Interval range,
                     std::vector<Crossing>& out) {
  appendQuadricCrossings(ray.origin - s.center, ray.dir, s.radius * s.radius, range, out);
}

void appendCrossings(const Ellipsoid& e, const ShapeArrays&, const Ray& ray, Interval range,
                     std::vector<Crossing>& out) {
  appendQuadricCrossings(e.worldToObject * ray.origin + e.worldToObjectOffset,
                         e.worldToObject * ray.dir, 1.0, range, out);
}

void appendCrossings(const Torus& torus, const ShapeArrays&, const Ray& ray, Interval range,
                     std::vector<Crossing>& out) {
  const TorusCrossings crossings = torusCrossings(torus, ray, range);
  for (int i = 0; i < crossings.count; ++i)
    out.push_back({crossings.t[i], crossings.entering[i], 0});
}

} // namespace prism
