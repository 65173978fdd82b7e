// Mesh triangles, flat or smoothly shaded: the primitive of imported meshes
// (OBJ faces, NFF `pp` patches) and of the .sc `triangle` and `ptriangle`.
// Vertices (and vertex normals) live in shared arrays of the scene, so a mesh
// of a million triangles costs a few dozen bytes per triangle.
#pragma once

#include "core/shapes/primitives.h"
#include "core/shapes/shape_arrays.h"
#include "core/shapes/surface_point.h"

#include <array>
#include <optional>
#include <string>

namespace prism {

// Marks a triangle without vertex normals: it is shaded flat.
inline constexpr std::uint32_t kNoNormal = 0xFFFFFFFFu;

// Vertices are Scene::meshVertices[vertex[i]], counterclockwise seen from the
// front (the outward side by the right-hand rule). A smooth triangle's vertex
// normals, unit and pointing to the outward side, are
// Scene::meshNormals[normal[i]]; a flat one has normal[0] == kNoNormal.
struct Triangle {
  static constexpr const char* kName = "triangle";
  static constexpr bool kFlat = true; // a ray leaving it cannot meet it again

  std::array<std::uint32_t, 3> vertex{0, 0, 0};
  std::array<std::uint32_t, 3> normal{kNoNormal, kNoNormal, kNoNormal};
  std::uint32_t material = 0;
  Origin origin;

  bool smooth() const { return normal[0] != kNoNormal; }
};

// Why a, b, c cannot be a triangle (not finite, zero area), or nothing. The
// area test is relative to the triangle's size, like polygonProblem's.
std::optional<std::string> triangleProblem(const Vec3& a, const Vec3& b, const Vec3& c);

// Both sides are hit. Watertight along shared edges: each edge's test is
// computed so that two triangles sharing it get exactly opposite values, so a
// ray can never slip between two triangles of a mesh.
bool intersect(const Triangle& tri, const Vec3* vertices, const Ray& ray, Interval range,
               double& t);

// The unit geometric normal, by the right-hand rule: the one the tracer's
// entering/leaving test and ray offsets use.
Vec3 geometricNormal(const Triangle& tri, const Vec3* vertices);

// The shading normal at `point` on the triangle: the vertex normals weighted
// by the point's barycentric coordinates, normalised (Phong interpolation);
// the geometric normal for a flat triangle or where the weighted sum vanishes.
Vec3 interpolatedNormal(const Triangle& tri, const Vec3* vertices, const Vec3* normals,
                        const Vec3& point);

// Where rays leaving a smooth triangle should start: the point lifted from
// the flat face onto the curved surface its vertex normals describe (the
// barycentric blend of the point's projections onto the three vertex tangent
// planes; Hanika, "Hacking the Shadow Terminator", Ray Tracing Gems II). A
// shadow ray from the flat face toward a light near the horizon would
// otherwise hit the neighbouring faces and blot the terminator with facet
// shaped shadows. `point` itself for a flat triangle, or when the lifted
// point lies below the face.
Vec3 liftedPoint(const Triangle& tri, const Vec3* vertices, const Vec3* normals, const Vec3& point);

Aabb boundsOf(const Triangle& tri, const Vec3* vertices);

// The shape interface (see shape_kinds.h).
inline bool intersect(const Triangle& tri, const ShapeArrays& arrays, const Ray& ray,
                      Interval range, double& t) {
  return intersect(tri, arrays.meshVertices.data(), ray, range, t);
}
inline Vec3 outwardNormal(const Triangle& tri, const ShapeArrays& arrays, const Vec3&) {
  return geometricNormal(tri, arrays.meshVertices.data());
}
inline Aabb boundsOf(const Triangle& tri, const ShapeArrays& arrays) {
  return boundsOf(tri, arrays.meshVertices.data());
}
// The geometric normal; for a smooth triangle also the interpolated normal and
// the lifted start of rays leaving its outward side.
SurfacePoint surfaceAt(const Triangle& tri, const ShapeArrays& arrays, const Vec3& point);
// The barycentric weights of the second and third vertices: the point is
// a + u (b - a) + v (c - a). (Coordinates an OBJ file gives with `vt` will
// replace them where a texture needs them.)
Vec2 uvAt(const Triangle& tri, const ShapeArrays& arrays, const Vec3& point);

} // namespace prism
