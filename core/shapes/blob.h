// Blobs (metaballs): the .sc `blob`, POV-Ray's blob of spherical
// components. Each component i (centre c_i, radius r_i, strength s_i, which
// may be negative) contributes the field
//   s_i (1 - |x - c_i|^2 / r_i^2)^2   where |x - c_i| < r_i, 0 elsewhere,
// and the solid is where the sum reaches the blob's threshold T > 0: field
// >= T is inside. One component alone is the ball of radius
// r sqrt(1 - sqrt(T / s)) (for s > T).
//
// A blob is one primitive; its components live in the scene's shared array
// (Scene::blobComponents[firstComponent, firstComponent + componentCount),
// as a polygon's vertices do), so the shape itself stays small whatever its
// number of components.
#pragma once

#include "core/math/aabb.h"
#include "core/math/interval.h"
#include "core/math/ray.h"
#include "core/shapes/affine_frame.h"
#include "core/shapes/primitives.h"
#include "core/shapes/shape_arrays.h"
#include "core/shapes/surface_point.h"

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace prism {

struct BlobComponent {
  Vec3 center{0.0};
  double radius = 1.0;
  double strength = 1.0;
};

// The components are in the blob's frame, carried into the world by
// frame's affine map (the current transform where the blob was written).
// A blob written under a similarity (rotations, uniform scales,
// translations, mirrors) is stored with the map applied to its components
// and the identity frame, so the common case costs no transform; a stretched
// one keeps its frame, into which rays are carried (keeping t), and its
// normals come back by the inverse transpose.
struct Blob {
  static constexpr const char* kName = "blob";
  static constexpr bool kFlat = false; // a ray leaving the inside meets it again

  AffineFrame frame;
  bool placed = false; // false: the frame is the identity
  std::uint32_t firstComponent = 0;
  std::uint32_t componentCount = 0;
  double threshold = 1.0;
  // roundoffScale (core/shapes/roundoff.h) of the frame, computed once.
  double roundoff = 0.0;
  // The union of the components of positive strength, where the field can
  // reach the threshold (the only ones that can make it positive).
  Aabb bounds;
  std::uint32_t material = 0;
  Origin origin;
};

// The most components one blob may have (a ray's cost grows with them: every
// component the ray's line meets splits its span).
inline constexpr std::uint64_t kMaxBlobComponents = 100000;

// Why these components and threshold cannot make a blob (a count of 0 or
// over kMaxBlobComponents, a number not finite, a radius not positive, a
// zero strength, a threshold not positive, no component of positive
// strength, positive strengths adding up to at most the threshold so that
// the field never reaches it), or nothing if they can.
std::optional<std::string> blobProblem(std::span<const BlobComponent> components, double threshold);

// The blob of `components` (in its own frame) carried by x -> linear x +
// offset. Requires blobProblem to find nothing and `linear` to be
// invertible. Returns the shape (its firstComponent left 0) and the
// components as stored (moved into the world under a similarity).
struct PlacedBlob {
  Blob blob;
  std::vector<BlobComponent> components;
};
PlacedBlob makeBlob(std::span<const BlobComponent> components, double threshold,
                    const Mat3& linear = Mat3(1.0), const Vec3& offset = Vec3(0.0));

// The components of `b` in `arrays`.
inline std::span<const BlobComponent> componentsOf(const Blob& b, const ShapeArrays& arrays) {
  return arrays.blobComponents.subspan(b.firstComponent, b.componentCount);
}

// The field minus the threshold at a point of the blob's frame (positive
// inside).
double fieldExcess(const Blob& b, std::span<const BlobComponent> components, const Vec3& p);

// Every crossing of the ray with the surface with t inside `range`, in
// increasing t, each with whether the ray enters the solid there, passed to
// visit(t, entering) until it returns false. A tangent touch within
// round-off may be reported as an entering and a leaving crossing at (almost)
// one t, or as none.
void visitBlobCrossings(const Blob& b, std::span<const BlobComponent> components, const Ray& ray,
                        Interval range, const std::function<bool(double, bool)>& visit);

// The shape interface (see shape_kinds.h).
bool intersect(const Blob& b, const ShapeArrays& arrays, const Ray& ray, Interval range, double& t);
// The unit outward normal: minus the field's gradient (the field falls
// outward), carried to the world by the inverse transpose.
Vec3 outwardNormal(const Blob& b, const ShapeArrays& arrays, const Vec3& point);
// Spherical coordinates about the centre of the component contributing most
// at the point, in the blob's frame (as a sphere's: u the longitude, v the
// latitude, 0 at the bottom and 1 at the top).
Vec2 uvAt(const Blob& b, const ShapeArrays& arrays, const Vec3& point);
inline Aabb boundsOf(const Blob& b, const ShapeArrays&) { return b.bounds; }
// The surface record, with a round-off scale that grows where the field's
// gradient is small (see docs/rendering-model.md, Blobs).
SurfacePoint surfaceAt(const Blob& b, const ShapeArrays& arrays, const Vec3& point);

} // namespace prism
