// A closed triangle mesh as a solid: the .sc `mesh` ... `end` block inside a
// `csg` block, one operand of the node (csg.h). The reader has checked that
// every edge is shared by exactly two of its triangles, running it in
// opposite directions, and wound them all outward (mesh_closure.h), so the
// mesh bounds a solid and each triangle's right-hand normal points out of it.
//
// Not a primitive kind of its own: only CSG sees a mesh as a solid; outside
// csg a mesh block adds plain triangles. Its triangles live in
// ShapeArrays::meshTriangles in the order written (their vertices and
// normals in the scene's mesh arrays, as every triangle's), with a small tree
// over them (mesh_tree.h; its order of the triangles is the same span of
// ShapeArrays::meshTreeOrder).
#pragma once

#include "core/math/aabb.h"
#include "core/math/interval.h"
#include "core/math/ray.h"
#include "core/shapes/mesh_tree.h"
#include "core/shapes/primitives.h"
#include "core/shapes/shape_arrays.h"
#include "core/shapes/surface_point.h"
#include "core/shapes/triangle.h"

#include <cstdint>
#include <span>
#include <vector>

namespace prism {

struct Crossing;

struct SolidMesh {
  static constexpr const char* kName = "mesh";

  std::uint32_t firstTriangle = 0; // into ShapeArrays::meshTriangles
  std::uint32_t triangleCount = 0;
  std::uint32_t firstNode = 0; // its tree's root, into ShapeArrays::meshTreeNodes
  std::uint32_t nodeCount = 0;
  Aabb bounds;
  double roundoff = 0.0; // the vertices' largest coordinate (as a triangle's)
  std::uint32_t material = 0;
  Origin origin; // the `mesh` line
};

inline std::span<const Triangle> trianglesOf(const SolidMesh& m, const ShapeArrays& arrays) {
  return arrays.meshTriangles.subspan(m.firstTriangle, m.triangleCount);
}

// Every crossing of the line with the surface inside `range`, in increasing t;
// a crossing's part is the index of its triangle in the mesh. A closed mesh's
// crossings alternate, entering and leaving, so where a ray through an edge
// or a vertex is reported by several triangles at (almost) one t, they count
// as one crossing the way most of them go, or as none (a touch) when as many
// enter as leave.
void appendCrossings(const SolidMesh& m, const ShapeArrays& arrays, const Ray& ray, Interval range,
                     std::vector<Crossing>& out);

// The record at a point of triangle `part` (a crossing's): its normal, or the
// interpolated one of a smooth triangle; the part is the triangle's index,
// and the coordinates (when asked for) a triangle's.
SurfacePoint surfaceAt(const SolidMesh& m, const ShapeArrays& arrays, const Vec3& point,
                       std::uint32_t part, SurfaceDetail detail);

// From a point alone (for callers without the ray, which are rare): the
// index of the triangle nearest it, every triangle measured, and its normal.
std::uint32_t nearestTriangle(const SolidMesh& m, const ShapeArrays& arrays, const Vec3& point);
Vec3 outwardNormal(const SolidMesh& m, const ShapeArrays& arrays, const Vec3& point);

inline Aabb boundsOf(const SolidMesh& m, const ShapeArrays&) { return m.bounds; }
inline double roundoffScale(const SolidMesh& m, const ShapeArrays&) { return m.roundoff; }

} // namespace prism
