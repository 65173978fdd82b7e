// Ray-primitive intersection, outward normals and bounds. Each intersect
// function returns the smallest t inside `range`, if any. Polygons are
// two-sided here; which side was hit is the tracer's entering/leaving test.
#pragma once

#include "core/shapes/polygon_edges.h"
#include "core/shapes/primitives.h"

#include <optional>
#include <span>
#include <string>

namespace prism {

bool intersect(const Sphere& s, const Ray& ray, Interval range, double& t);
bool intersect(const Ellipsoid& e, const Ray& ray, Interval range, double& t);
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

// Unit outward normals at a point on the surface.
Vec3 normalAt(const Sphere& s, const Vec3& point);
Vec3 normalAt(const Ellipsoid& e, const Vec3& point);

Aabb boundsOf(const Sphere& s);
Aabb boundsOf(const Polygon& p, const Vec3* vertices);

// The ellipsoid that is the unit sphere under `objectToWorld` (linear part
// `linear`, then `offset`); `linear` must be invertible.
Ellipsoid makeEllipsoid(const Mat3& linear, const Vec3& offset);

// Why `vertices` cannot be a polygon (fewer than 3 vertices, zero area, not
// planar), or nothing if it can.
std::optional<std::string> polygonProblem(std::span<const Vec3> vertices);

// Plane, normal and projection axis of a polygon whose vertices passed
// polygonProblem; firstVertex and material are left for the caller.
Polygon makePolygon(std::span<const Vec3> vertices);

} // namespace prism
