// Constructive solid geometry: the union, intersection or difference of
// closed solids (spheres, ellipsoids, tori, boxes, capped cones and
// cylinders, blobs, closed triangle meshes) and of other CSG nodes, nested to
// any depth.
//
// Storage. A node names a run of operands in ShapeArrays::csgOperands; an
// operand is a closed shape of its own (with its own material and origin)
// or the index of a nested node in ShapeArrays::csgNodes. Only a root node is
// a primitive of the scene (Scene::shapes<Csg>()): the operands live in the
// CSG arrays, not in the kinds' vectors, so no hierarchy ever sees them on
// their own.
//
// Intersection. Every leaf's crossings along the whole line of the ray are
// gathered (appendCrossings, crossings.h) and walked in increasing t, each
// leaf's inside-state following its own crossings, and the node's boolean
// function of those states evaluated after each distinct t: where it
// changes, the combined solid is entered or left. All crossings at exactly
// the same t are applied together before the node is evaluated again, so
// coincident faces (a box's face flush with another's, two spheres touching)
// add a surface only where the combined solid changes, whatever the order of
// the operands. The face reported is that of the first leaf (in the order
// written) of the group whose own change moves the node the same way.
//
// Normals. A point of the combined surface on a leaf's surface has the
// combined solid's inside on the leaf's inside side exactly when the leaf
// appears an even number of times as a subtracted operand of a difference
// (A - (B - C) = A and not B, or C): odd, and the leaf's outward normal is
// turned inside out. The tracer's entering/leaving test (the sign of
// outward . direction) then agrees with the walk.
#pragma once

#include "core/math/aabb.h"
#include "core/math/interval.h"
#include "core/math/ray.h"
#include "core/shapes/blob.h"
#include "core/shapes/box.h"
#include "core/shapes/capped_cone.h"
#include "core/shapes/crossings.h"
#include "core/shapes/ellipsoid.h"
#include "core/shapes/primitives.h"
#include "core/shapes/shape_arrays.h"
#include "core/shapes/solid_mesh.h"
#include "core/shapes/sphere.h"
#include "core/shapes/surface_point.h"
#include "core/shapes/torus.h"

#include <cstdint>
#include <span>
#include <variant>
#include <vector>

namespace prism {

enum class CsgOp : std::uint8_t { Union, Intersection, Difference };

// "union", "intersection", "difference": as written after `csg`.
const char* csgOpName(CsgOp op);

struct Csg {
  static constexpr const char* kName = "csg";
  static constexpr bool kFlat = false; // a ray leaving it can meet it again

  CsgOp op = CsgOp::Union;
  std::uint32_t firstOperand = 0; // into ShapeArrays::csgOperands
  std::uint32_t operandCount = 0; // at least two
  Aabb bounds;                    // what the node can cover (csgBounds)
  double roundoff = 0.0;          // the largest of its leaves' roundoffScale
  std::uint32_t material = 0;     // the `surface` at `csg` (each leaf has its own)
  Origin origin;
};

// A nested node: the index of a Csg in ShapeArrays::csgNodes.
struct CsgNodeIndex {
  std::uint32_t index = 0;
};

struct CsgOperand {
  std::variant<Sphere, Ellipsoid, Torus, Box, CappedCone, Blob, SolidMesh, CsgNodeIndex> shape;
};

// The operands of `node`.
std::span<const CsgOperand> operandsOf(const Csg& node, const ShapeArrays& arrays);

// The box of what `node` can cover: a union by the union of its operands'
// boxes, an intersection by the intersection of theirs, a difference by its
// first operand's; and its leaves' largest roundoffScale. For a node whose
// operands (and nested nodes) are already in `arrays`.
void finishCsg(Csg& node, const ShapeArrays& arrays);

bool intersect(const Csg& node, const ShapeArrays& arrays, const Ray& ray, Interval range,
               double& t);
void appendCrossings(const Csg& node, const ShapeArrays& arrays, const Ray& ray, Interval range,
                     std::vector<Crossing>& out);
inline Aabb boundsOf(const Csg& node, const ShapeArrays&) { return node.bounds; }
inline double roundoffScale(const Csg& node, const ShapeArrays&) { return node.roundoff; }

// The surface record where `ray` meets the node at `t` (a t intersect
// returned): the crossing there is found again by the same walk, so the leaf,
// its part, its material and the normal's turn are exact. The tracer's way in.
SurfacePoint surfaceAlong(const Csg& node, const ShapeArrays& arrays, const Ray& ray, double t,
                          SurfaceDetail detail);

// The leaf (never a nested node) whose surface `ray` meets the node on at
// `t`: the one surfaceAlong takes the record of. For the --pixel ray tree,
// which names it; null if the ray meets no leaf.
const CsgOperand* operandAlong(const Csg& node, const ShapeArrays& arrays, const Ray& ray,
                               double t);

// From a point alone (no ray): the leaf whose surface passes nearest the
// point, found by a short probe along each leaf's normal there. Exact away
// from the leaves' intersection curves; for callers without the ray.
SurfacePoint surfaceAt(const Csg& node, const ShapeArrays& arrays, const Vec3& point);
Vec3 outwardNormal(const Csg& node, const ShapeArrays& arrays, const Vec3& point);
Vec2 uvAt(const Csg& node, const ShapeArrays& arrays, const Vec3& point);

} // namespace prism
