// The scene's primitives, stored compactly by kind and in world space. A
// PrimitiveRef names one of them. Every primitive also records where in which
// file it was written, for the --pixel ray tree and for error messages.
#pragma once

#include "core/math/aabb.h"

#include <cstdint>

namespace prism {

// New kinds go at the end: the order is the tie-break between coincident
// surfaces, and existing scenes must keep their pictures.
enum class PrimitiveKind : std::uint8_t { Sphere, Ellipsoid, Polygon, Cone, Triangle };

struct PrimitiveRef {
  PrimitiveKind kind = PrimitiveKind::Sphere;
  std::uint32_t index = 0;

  bool operator==(const PrimitiveRef&) const = default;
  // Orders hits at exactly the same distance (coincident surfaces), so every
  // acceleration structure picks the same one whatever order it visits them in.
  bool operator<(const PrimitiveRef& o) const {
    return kind != o.kind ? kind < o.kind : index < o.index;
  }
};

// Where a primitive was written: index into Scene::files and 1-based line.
struct Origin {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
};

struct Sphere {
  Vec3 center{0.0};
  double radius = 1.0;
  std::uint32_t material = 0;
  Origin origin;
};

// A sphere under a non-uniform scale: the image of the unit sphere under an
// affine map. Stored as the inverse map, which takes rays into the unit sphere's
// space, and the matrix that carries object normals back to world space; the
// map itself is kept too, for writing the ellipsoid back as text (inverting the
// inverse overflows for very flat ellipsoids).
struct Ellipsoid {
  Mat3 worldToObject{1.0};
  Vec3 worldToObjectOffset{0.0};
  Mat3 normalToWorld{1.0}; // transpose of worldToObject
  Aabb bounds;
  Mat3 objectToWorld{1.0};
  Vec3 center{0.0}; // objectToWorld's offset
  std::uint32_t material = 0;
  Origin origin;
};

// A planar simple polygon (convex or concave); vertices live in
// Scene::polygonVertices[firstVertex, firstVertex + vertexCount) in
// counterclockwise order seen from the front, which `normal` faces.
struct Polygon {
  std::uint32_t firstVertex = 0;
  std::uint32_t vertexCount = 0;
  Vec3 normal{0.0, 0.0, 1.0}; // unit, outward by the right-hand rule
  double planeOffset = 0.0;   // dot(normal, x) for points x on the plane
  std::uint8_t dropAxis = 2;  // the axis dropped to test containment in 2D
  // Into Scene::polygonEdgeIndices for a polygon of many vertices (see
  // core/shapes/polygon_edges.h), or kNoEdgeIndex.
  std::uint32_t edgeIndex = kNoEdgeIndex;
  static constexpr std::uint32_t kNoEdgeIndex = ~std::uint32_t(0);
  std::uint32_t material = 0;
  Origin origin;
};

} // namespace prism
