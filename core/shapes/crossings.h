// Where a ray crosses the surface of a closed shape (one that bounds a solid):
// every crossing, entering or leaving, not just the nearest. This is what
// constructive solid geometry combines (an intersection of two solids is
// inside where the ray is inside both), so a shape kind that bounds a solid
// provides it and can then be an operand of CSG.
#pragma once

#include "core/shapes/blob.h"
#include "core/shapes/box.h"
#include "core/shapes/capped_cone.h"
#include "core/shapes/ellipsoid.h"
#include "core/shapes/shape_arrays.h"
#include "core/shapes/sphere.h"
#include "core/shapes/torus.h"

#include <concepts>
#include <cstdint>
#include <vector>

namespace prism {

struct Crossing {
  double t = 0.0;
  bool entering = false;  // the ray goes from outside the solid to inside
  std::uint32_t part = 0; // which face of a compound shape (see SurfacePoint)
};

// A closed shape appends every crossing with t inside `range`, in increasing
// t. Crossings at a tangent point (the ray grazes the surface, entering and
// leaving at once) are left out: the ray is never inside.
template <class K>
concept ClosedShape = requires(const K& shape, const ShapeArrays& arrays, const Ray& ray,
                               Interval range, std::vector<Crossing>& out) {
  { appendCrossings(shape, arrays, ray, range, out) } -> std::same_as<void>;
};

void appendCrossings(const Sphere& s, const ShapeArrays&, const Ray& ray, Interval range,
                     std::vector<Crossing>& out);
void appendCrossings(const Ellipsoid& e, const ShapeArrays&, const Ray& ray, Interval range,
                     std::vector<Crossing>& out);
void appendCrossings(const Torus& torus, const ShapeArrays&, const Ray& ray, Interval range,
                     std::vector<Crossing>& out);
// A box's parts are its faces, a capped cone's its side and caps (box.h,
// capped_cone.h). A ray touching only an edge or a rim is never inside.
void appendCrossings(const Box& b, const ShapeArrays&, const Ray& ray, Interval range,
                     std::vector<Crossing>& out);
void appendCrossings(const CappedCone& c, const ShapeArrays&, const Ray& ray, Interval range,
                     std::vector<Crossing>& out);
// A tangent touch within round-off may show as an entering and a leaving
// crossing at almost one t (blob.h).
void appendCrossings(const Blob& b, const ShapeArrays& arrays, const Ray& ray, Interval range,
                     std::vector<Crossing>& out);

} // namespace prism
