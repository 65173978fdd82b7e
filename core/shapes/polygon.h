// Planar polygons of any number of vertices, convex or concave: the .sc
// `polygon`, NFF `p`. Two-sided: which side a ray hits is the tracer's
// entering/leaving test.
#pragma once

#include "core/math/aabb.h"
#include "core/math/interval.h"
#include "core/math/ray.h"
#include "core/shapes/polygon_edges.h"
#include "core/shapes/primitives.h"
#include "core/shapes/shape_arrays.h"

#include <optional>
#include <span>
#include <string>

namespace prism {

// A planar simple polygon (convex or concave); vertices live in
// Scene::polygonVertices[firstVertex, firstVertex + vertexCount) in
// counterclockwise order seen from the front, which `normal` faces.
struct Polygon {
  static constexpr const char* kName = "polygon";
  static constexpr bool kFlat = true; // a ray leaving it cannot meet it again

  std::uint32_t firstVertex = 0;
  std::uint32_t vertexCount = 0;
  Vec3 normal{0.0, 0.0, 1.0}; // unit, outward by the right-hand rule
  double planeOffset = 0.0;   // dot(normal, x) for points x on the plane
  std::uint8_t dropAxis = 2;  // the axis dropped to test containment in 2D
  // Containment is decided in the ray's frame (watertight: polygon.cpp):
  // for planar polygons without an edge index. The others are tested in the
  // plane's projection.
  bool rayFrameTest = false;
  // Into Scene::polygonEdgeIndices for a polygon of many vertices (see
  // core/shapes/polygon_edges.h), or kNoEdgeIndex.
  std::uint32_t edgeIndex = kNoEdgeIndex;
  static constexpr std::uint32_t kNoEdgeIndex = ~std::uint32_t(0);
  std::uint32_t material = 0;
  Origin origin;
};

// Vertices may lie off the polygon's plane by this much of their largest
// coordinate and still count as planar: a few ulps, the round-off of the
// plane's own computation.
inline constexpr double kPlanarRoundoff = 0x1p-40;

// `edges` is the polygon's edge index, or null to test every edge (the answer
// is the same; the index makes it logarithmic in the number of vertices).
bool intersect(const Polygon& p, const Vec3* vertices, const PolygonEdgeIndex* edges,
               const Ray& ray, Interval range, double& t);
inline bool intersect(const Polygon& p, const Vec3* vertices, const Ray& ray, Interval range,
                      double& t) {
  return intersect(p, vertices, nullptr, ray, range, t);
}

// The axes a polygon keeps in its 2D projection, in the order that keeps
// its orientation.
struct ProjectedAxes {
  int u, v;
};
ProjectedAxes polygonAxes(const Polygon& p);

Aabb boundsOf(const Polygon& p, const Vec3* vertices);
// Why `vertices` cannot be a polygon (fewer than 3 vertices, zero area, not
// planar), or nothing if it can.
std::optional<std::string> polygonProblem(std::span<const Vec3> vertices);

// Plane, normal and projection axis of a polygon whose vertices passed
// polygonProblem; firstVertex and material are left for the caller.
Polygon makePolygon(std::span<const Vec3> vertices);

// The shape interface (see shape_kinds.h).
inline bool intersect(const Polygon& p, const ShapeArrays& arrays, const Ray& ray, Interval range,
                      double& t) {
  const PolygonEdgeIndex* edges =
      p.edgeIndex == Polygon::kNoEdgeIndex ? nullptr : &arrays.polygonEdgeIndices[p.edgeIndex];
  return intersect(p, arrays.polygonVertices.data(), edges, ray, range, t);
}
inline Vec3 outwardNormal(const Polygon& p, const ShapeArrays&, const Vec3&) { return p.normal; }
// Planar coordinates in scene units: from the first vertex, u along the first
// edge and v along normal x u (so (u, v) turn like the vertices).
Vec2 uvAt(const Polygon& p, const ShapeArrays& arrays, const Vec3& point);
inline Aabb boundsOf(const Polygon& p, const ShapeArrays& arrays) {
  return boundsOf(p, arrays.polygonVertices.data());
}

} // namespace prism
