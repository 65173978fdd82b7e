// The one list of shape kinds. From it come the scene's storage (one vector
// per kind, Scene::shapes<Kind>()), the kinds' names and flatness, the count
// the BVH's packed references are checked against, and the one dispatch from
// a PrimitiveRef to its typed shape (Scene::visit).
//
// Each kind is a struct in a file of its own (sphere.h, ...) with
//   static constexpr const char* kName;  // as in messages and the ray tree
//   static constexpr bool kFlat;         // a ray leaving it cannot meet it again
// (and static constexpr const char* kPlural, for counts, if its plural is
// not its name and "s": "tori"), and these functions of (const Kind&, const
// ShapeArrays&, ...):
//   bool intersect(..., const Ray&, Interval, double& t)  // nearest t in range
//   Vec3 outwardNormal(..., const Vec3& point)            // unit, geometric
//   Aabb boundsOf(...)
//   Vec2 uvAt(..., const Vec3& point)                     // surface coordinates
//   double roundoffScale(...)                             // see roundoff.h
//   SurfacePoint surfaceAt(..., const Vec3& point)        // optional: the
//                                  default shades with the outward normal
// (a kind that needs none of the ShapeArrays may provide intersect, normalAt,
// uvAt and boundsOf without them instead: see SelfContainedShape). A kind
// that bounds a solid also lists every crossing of a ray (ClosedShape in
// crossings.h), which CSG needs. A kind whose record depends on more than
// the point (a CSG node: which operand was hit) also provides
//   SurfacePoint surfaceAlong(..., const Ray&, double t, SurfaceDetail)
// which Scene::surfaceAt(ref, ray, t) prefers (see csg.h).
// Adding a kind: its file, an entry at the end of ShapeKinds (the order is
// the tie-break between coincident surfaces: existing scenes keep their
// pictures), a reader handler and a writer overload (see docs/architecture.md).
#pragma once

#include "core/shapes/blob.h"
#include "core/shapes/box.h"
#include "core/shapes/capped_cone.h"
#include "core/shapes/cone.h"
#include "core/shapes/csg.h"
#include "core/shapes/disc.h"
#include "core/shapes/ellipsoid.h"
#include "core/shapes/polygon.h"
#include "core/shapes/primitives.h"
#include "core/shapes/quadric_surface.h"
#include "core/shapes/roundoff.h"
#include "core/shapes/shape_arrays.h"
#include "core/shapes/sphere.h"
#include "core/shapes/torus.h"
#include "core/shapes/triangle.h"

#include <array>
#include <concepts>
#include <cstddef>
#include <tuple>
#include <type_traits>

namespace prism {

// Kinds that need none of the scene's arrays (spheres, ellipsoids, cones,
// tori, boxes, discs, capped cones, quadrics)
// provide intersect(shape, ray, range, t), normalAt(shape, point),
// uvAt(shape, point) and boundsOf(shape); these give them the interface.
template <class K>
concept SelfContainedShape = requires(const K& shape, const Ray& ray, Interval range, double& t,
                                      const Vec3& point) {
  { intersect(shape, ray, range, t) } -> std::same_as<bool>;
  { normalAt(shape, point) } -> std::same_as<Vec3>;
  { uvAt(shape, point) } -> std::same_as<Vec2>;
  { boundsOf(shape) } -> std::same_as<Aabb>;
};
template <SelfContainedShape K>
bool intersect(const K& shape, const ShapeArrays&, const Ray& ray, Interval range, double& t) {
  return intersect(shape, ray, range, t);
}
template <SelfContainedShape K>
Vec3 outwardNormal(const K& shape, const ShapeArrays&, const Vec3& point) {
  return normalAt(shape, point);
}
template <SelfContainedShape K> Vec2 uvAt(const K& shape, const ShapeArrays&, const Vec3& point) {
  return uvAt(shape, point);
}
template <SelfContainedShape K> Aabb boundsOf(const K& shape, const ShapeArrays&) {
  return boundsOf(shape);
}

// What every kind provides (see above); a kind in the list that lacks any of
// it does not compile.
template <class K>
concept ShapeKind = requires(const K& shape, const ShapeArrays& arrays, const Ray& ray,
                             Interval range, double& t, const Vec3& point) {
  { K::kName } -> std::convertible_to<const char*>;
  { K::kFlat } -> std::convertible_to<bool>;
  { shape.material } -> std::convertible_to<std::uint32_t>;
  { shape.origin } -> std::convertible_to<Origin>;
  { intersect(shape, arrays, ray, range, t) } -> std::same_as<bool>;
  { outwardNormal(shape, arrays, point) } -> std::same_as<Vec3>;
  { uvAt(shape, arrays, point) } -> std::same_as<Vec2>;
  { boundsOf(shape, arrays) } -> std::same_as<Aabb>;
  { roundoffScale(shape, arrays) } -> std::same_as<double>;
};

template <ShapeKind... Kinds> struct ShapeList {
  static constexpr std::size_t size = sizeof...(Kinds);
  template <std::size_t I> using At = std::tuple_element_t<I, std::tuple<Kinds...>>;
  static constexpr std::array<const char*, size> names{Kinds::kName...};
  static constexpr std::array<bool, size> flat{Kinds::kFlat...};
};

using ShapeKinds = ShapeList<Sphere, Ellipsoid, Polygon, Cone, Triangle, Torus, Box, Disc,
                             CappedCone, Quadric, Csg, Blob>;
inline constexpr std::size_t kShapeKindCount = ShapeKinds::size;

namespace detail {
template <class Kind, class List> struct IndexOf;
template <class Kind, class... Kinds> struct IndexOf<Kind, ShapeList<Kinds...>> {
  static constexpr std::size_t value = [] {
    constexpr bool matches[] = {std::is_same_v<Kind, Kinds>...};
    for (std::size_t i = 0; i < sizeof...(Kinds); ++i)
      if (matches[i]) return i;
    return sizeof...(Kinds);
  }();
  static_assert(value < sizeof...(Kinds), "not a shape kind of ShapeKinds");
};
} // namespace detail

// The PrimitiveKind of a shape type: its place in ShapeKinds.
template <class Kind>
inline constexpr PrimitiveKind kindOf = PrimitiveKind(detail::IndexOf<Kind, ShapeKinds>::value);

inline const char* kindName(PrimitiveKind kind) { return ShapeKinds::names[std::size_t(kind)]; }
inline bool isFlat(PrimitiveKind kind) { return ShapeKinds::flat[std::size_t(kind)]; }

// The surface record of a kind without anything better: the outward normal
// is also the shading normal, rays start at the hit point, and there is one
// part. (The material and the coordinates are filled in by Scene::surfaceAt.)
template <class Kind>
SurfacePoint surfaceAt(const Kind& shape, const ShapeArrays& arrays, const Vec3& point) {
  SurfacePoint s;
  s.point = point;
  s.outward = outwardNormal(shape, arrays, point);
  s.shading = s.outward;
  s.roundoffScale = roundoffScale(shape, arrays);
  return s;
}

// One vector per kind.
template <class List> struct ShapeStorage;
template <class... Kinds> struct ShapeStorage<ShapeList<Kinds...>> {
  std::tuple<std::vector<Kinds>...> vectors;
};

} // namespace prism
