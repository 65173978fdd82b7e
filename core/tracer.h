// The recursive tracer of SPEC 1: one ray in, the radiance flowing back along it
// out. Pure and thread-safe: the only mutable state is the caller's RayCounts
// (and the optional ray-tree record).
#pragma once

#include "core/accel.h"
#include "core/ray_counts.h"
#include "core/ray_tree.h"

namespace prism {

// Origins of rays that leave a surface are moved off it along the normal by this
// fraction of the magnitude of the coordinates involved. Round-off in a hit point
// is proportional to those magnitudes, so the offset scales with the scene (SPEC
// 1.5): the same picture at 1e-4 and at 1e4 units, no shadow acne.
inline constexpr double kRayOffsetScale = 1e-9;

class Tracer {
public:
  // maxDepth >= 1; `scene` and `accel` must outlive the tracer.
  Tracer(const Scene& scene, const Accel& accel, int maxDepth);

  // Radiance arriving at the ray's origin from direction -ray.dir. `depth` is 1
  // for eye rays. `skip` is a flat primitive the ray leaves (never re-hit).
  Color trace(const Ray& ray, int depth, RayCounts& counts, RayTreeNode* record = nullptr,
              const PrimitiveRef* skip = nullptr) const;

  int maxDepth() const { return maxDepth_; }

private:
  Color shade(const Ray& ray, const Hit& hit, int depth, RayCounts& counts,
              RayTreeNode* record) const;

  const Scene& scene_;
  const Accel& accel_;
  int maxDepth_;
};

} // namespace prism
