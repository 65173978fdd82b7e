#include "core/shapes/crossings.h"

#include "core/shapes/quadric.h"

namespace prism {

namespace {

// A span of the ray inside a solid, entering at t0 and leaving at t1; one
// that only touches the surface (t0 == t1) is left out.
void appendSpan(double t0, std::uint32_t part0, double t1, std::uint32_t part1, Interval range,
                std::vector<Crossing>& out) {
  if (!(t0 < t1)) return;
  if (range.contains(t0)) out.push_back({t0, true, part0});
  if (range.contains(t1)) out.push_back({t1, false, part1});
}

// The two roots of a quadric solid are where the ray enters and leaves it.
void appendQuadricCrossings(const Vec3& f, const Vec3& d, double r2, Interval range,
                            std::vector<Crossing>& out) {
  double t0, t1;
  if (quadricRoots(f, d, r2, t0, t1)) appendSpan(t0, 0, t1, 0, range, out);
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

void appendCrossings(const Box& b, const ShapeArrays&, const Ray& ray, Interval range,
                     std::vector<Crossing>& out) {
  BoxSpan span;
  if (boxSpan(b, ray, span)) appendSpan(span.t0, span.part0, span.t1, span.part1, range, out);
}

void appendCrossings(const CappedCone& c, const ShapeArrays&, const Ray& ray, Interval range,
                     std::vector<Crossing>& out) {
  ConeSpan spans[2];
  const int count = coneSpans(c, ray, spans);
  for (int i = 0; i < count; ++i)
    appendSpan(spans[i].t0, spans[i].part0, spans[i].t1, spans[i].part1, range, out);
}

void appendCrossings(const Blob& b, const ShapeArrays& arrays, const Ray& ray, Interval range,
                     std::vector<Crossing>& out) {
  visitBlobCrossings(b, componentsOf(b, arrays), ray, range, [&](double t, bool entering) {
    out.push_back({t, entering, 0});
    return true;
  });
}

} // namespace prism
