// How large the numbers are that each kind's intersection test computes with:
// the scale of the round-off in the hit points it returns. The tracer moves
// the origins of new rays off a surface by a few units of round-off of this
// scale (frameAt in core/render/tracer.cpp); docs/rendering-model.md derives,
// kind by kind, why the round-off of a hit point along the normal stays below
//   u * (|point| + |ray origin| + roundoffScale(shape))      (u = 2^-53)
// times a small constant. Every |.| here is the largest absolute component.
#pragma once

#include "core/shapes/blob.h"
#include "core/shapes/box.h"
#include "core/shapes/capped_cone.h"
#include "core/shapes/cone.h"
#include "core/shapes/disc.h"
#include "core/shapes/ellipsoid.h"
#include "core/shapes/polygon.h"
#include "core/shapes/quadric_surface.h"
#include "core/shapes/shape_arrays.h"
#include "core/shapes/sphere.h"
#include "core/shapes/torus.h"
#include "core/shapes/triangle.h"

#include <algorithm>
#include <cmath>

namespace prism {

// How much a kind that intersects in its own frame (ellipsoids, cones, tori) can
// magnify round-off on the way back: max over axes i of |column i of the
// frame| * |row i of its inverse|. Rounding ray.origin into the frame errs in
// component i by about u |row i| |origin|, and that error returns to the world
// stretched by |column i|. 1 for a frame whose axes are orthogonal (any
// rotation and axis scale); large only for a strongly sheared one.
inline double frameSkew(const Mat3& toWorld, const Mat3& toObject) {
  double worst2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Vec3 row(toObject[0][i], toObject[1][i], toObject[2][i]);
    worst2 = std::max(worst2, glm::dot(toWorld[i], toWorld[i]) * glm::dot(row, row));
  }
  return std::sqrt(worst2);
}

// The scale of a kind that intersects in its own frame (x -> toWorld x +
// offset, inverse toObject): the origin is carried into the frame and the
// quadric solved there, with numbers of the frame's size (`size` in the
// frame's units: 1 for the unit sphere, the radii and the unit height for a
// cone), then the point lies on the world surface; frameSkew for the way back.
inline double frameRoundoffScale(const Mat3& toWorld, const Mat3& toObject, const Vec3& offset,
                                 double size) {
  const Mat3& m = toWorld;
  const double column2 =
      std::max({glm::dot(m[0], m[0]), glm::dot(m[1], m[1]), glm::dot(m[2], m[2])});
  return frameSkew(toWorld, toObject) * (maxAbsComponent(offset) + std::sqrt(column2) * size);
}

// The centre is subtracted from the ray's origin and the radius squared.
inline double roundoffScale(const Sphere& s, const ShapeArrays&) {
  return maxAbsComponent(s.center) + s.radius;
}

// Computed when the shape is made (frameRoundoffScale): a load here.
inline double roundoffScale(const Ellipsoid& e, const ShapeArrays&) { return e.roundoff; }
inline double roundoffScale(const Cone& c, const ShapeArrays&) { return c.roundoff; }
inline double roundoffScale(const Torus& t, const ShapeArrays&) { return t.roundoff; }
inline double roundoffScale(const Box& b, const ShapeArrays&) { return b.roundoff; }
inline double roundoffScale(const Disc& d, const ShapeArrays&) { return d.roundoff; }
inline double roundoffScale(const CappedCone& c, const ShapeArrays&) { return c.side.roundoff; }
// The clip box's largest coordinate as the size: the root is polished by a
// Newton step at the hit point (see docs/rendering-model.md#quadrics).
inline double roundoffScale(const Quadric& q, const ShapeArrays&) { return q.roundoff; }
// The frame's; the surface record adds the field's round-off (blob.h).
inline double roundoffScale(const Blob& b, const ShapeArrays&) { return b.roundoff; }

// t = (planeOffset - normal.origin) / (normal.dir): the plane's own offset
// from the world's origin is the only number besides the ray's.
inline double roundoffScale(const Polygon& p, const ShapeArrays&) {
  return std::abs(p.planeOffset);
}

// t = n.(a - origin) / (n.dir) with n from the edges: the vertices' size.
inline double roundoffScale(const Triangle& tri, const ShapeArrays& arrays) {
  const Vec3* v = arrays.meshVertices.data();
  return std::max({maxAbsComponent(v[tri.vertex[0]]), maxAbsComponent(v[tri.vertex[1]]),
                   maxAbsComponent(v[tri.vertex[2]])});
}

} // namespace prism
