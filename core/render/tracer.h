// The recursive tracer of docs/rendering-model.md: one ray in, the radiance flowing back along it
// out. A Tracer is used by one thread at a time (make one per tile: it is
// cheap): it remembers, per light and depth, the primitive that last blocked a
// shadow ray and tries it first on the next one, since neighbouring points
// are usually shadowed by the same thing. That changes how fast the answer
// comes, never the answer: a shadow ray is blocked if any primitive is hit
// before the light, whichever is found first. Everything else it writes is
// the caller's RayCounts (and the optional ray-tree record).
#pragma once

#include "core/accel/accel.h"
#include "core/render/bailout.h"
#include "core/render/ray_counts.h"
#include "core/render/ray_tree.h"

#include <optional>
#include <vector>

namespace prism {

// Origins of rays that leave a surface are moved off it along the normal by
// this many times u (the unit round-off of a double, 2^-53) times the size of
// the numbers the hit point was computed from: its own coordinates, the parent
// ray's origin and the primitive's (SurfacePoint::roundoffScale). The hit
// point's round-off along the normal stays below u times that size times a
// small constant, derived kind by kind in docs/rendering-model.md and measured
// by tests/extremes_test.cpp; this is that constant with a wide margin. So a
// scene keeps its picture wherever it sits: the offset is a fixed number of
// the coordinates' own ulps, not a fraction of their size.
inline constexpr double kRayOffsetRoundoff = 0x1p-44; // 512 u: 5.7e-14

class Tracer {
public:
  // Off sends every shadow ray to the Accel, for measuring the Accel alone.
  enum class BlockerCache { On, Off };

  // maxDepth >= 1; `scene` and `accel` must outlive the tracer.
  Tracer(const Scene& scene, const Accel& accel, int maxDepth,
         BlockerCache cache = BlockerCache::On);

  // Radiance arriving at the ray's origin from direction -ray.dir. `depth` is 1
  // for eye rays. `skip` is a flat primitive the ray leaves (never re-hit).
  Color trace(const Ray& ray, int depth, RayCounts& counts, RayTreeNode* record = nullptr,
              const PrimitiveRef* skip = nullptr);

  // trace(rays[i], 1, counts) for each of at most Accel::kMaxBundle eye rays,
  // into out[i]: the same colours and counts, with the nearest hits found for
  // the bundle at once (Accel::closestHits), which is faster when the rays
  // share their origin and point roughly the same way.
  void traceBundle(std::span<const Ray> rays, std::span<Color> out, RayCounts& counts);

  int maxDepth() const { return maxDepth_; }

  // The angle (radians) an eye ray's footprint spans from now on: the size
  // of the pixel, or of the subpixel, it samples at distance 1 from the eye
  // (Camera::pixelSpread). Image textures are filtered over the footprint of
  // this cone where it meets their surface, also after mirrors and
  // refractions (docs/rendering-model.md#image-textures); 0 (the default)
  // samples them at a point.
  void setEyeFootprint(double spread) {
    if (!cones_.empty()) cones_[1] = {0.0, spread};
  }

  // Skip mirror and refracted rays by `bound` (core/render/bailout.h) from now
  // on; an inactive bound (the default) traces exactly. `bound` must outlive
  // the tracer's use of it.
  void setBailout(const BailoutBound& bound);

private:
  // The surface as the incoming ray meets it (see tracer.cpp).
  struct Incidence;
  // The two local terms of the shading formula: C_mat kdr [I_a + sum diffuse]
  // and ksr sum specular.
  // A ray's footprint: a cone of `width` (world units) at the ray's origin
  // growing by `spread` per unit of length.
  struct RayCone {
    double width = 0.0;
    double spread = 0.0;
  };
  struct DirectLight {
    Color ambientDiffuse{0.0};
    Color highlight{0.0};
  };

  // The shading formula at a hit, in its named steps: the local terms from
  // the lights, then the mirror ray, then the refracted ray.
  Color shade(const Ray& ray, const Hit& hit, int depth, RayCounts& counts, RayTreeNode* record);
  // The rest of shade with the material `m` at the hit: the stored one, or
  // (shadeTextured) its blend at the point.
  Color shadeWith(const Ray& ray, const Hit& hit, const Vec3& point, const SurfacePoint& surface,
                  const Material& m, int depth, RayCounts& counts, RayTreeNode* record);
  Color shadeTextured(const Ray& ray, const Hit& hit, const Vec3& point,
                      const SurfacePoint& surface, const Material& stored, int depth,
                      RayCounts& counts, RayTreeNode* record);
  // Sets the cone of the new ray leaving a hit `t` along a ray at `depth`.
  void setChildCone(int depth, double t, double turn);
  // The image's colour at the hit, filtered over the current ray's footprint.
  Color imageColor(const Ray& ray, const Hit& hit, const Vec3& point, const SurfacePoint& surface,
                   const ImageMap& map, int depth, ImageLookup* lookup) const;
  DirectLight directLighting(const Ray& ray, const Incidence& at, const Material& m, int depth,
                             RayCounts& counts, RayTreeNode* record);
  // ksr I_r, or 0 at the depth limit or for a material that is no mirror.
  Color reflection(const Ray& ray, const Incidence& at, const Material& m, int depth,
                   RayCounts& counts, RayTreeNode* record);
  // kst I_t, or 0 at the depth limit, for an opaque material, and on total
  // internal reflection.
  Color transmission(const Ray& ray, const Incidence& at, const Material& m, int depth,
                     RayCounts& counts, RayTreeNode* record);
  // With a bailout, the new ray `ray` of `kind` from a hit on `m` at `depth`:
  // skipped when its bound, beyond[depth + 1], fits in its share of the
  // allowance, else traced with that share (see tracer.cpp).
  Color traceOrSkip(const Ray& ray, RayKind kind, const Material& m, int depth, RayCounts& counts,
                    RayTreeNode* record, const PrimitiveRef* skip);
  // The radiance `far` arriving at the origin of a segment of `length`
  // (infinite: a miss) through the fog or the solid the ray is in, with the
  // ray tree's record of it.
  Color alongSegment(const Color& far, double length, RayTreeNode* record) const;
  // Whether anything but `skip` lies on `ray` before `length` (the light).
  bool blocked(const Ray& ray, double length, const PrimitiveRef* skip, std::size_t light,
               int depth);

  const Scene& scene_;
  const Accel& accel_;
  int maxDepth_;
  // The last blocker per (depth - 1) * lights + light; empty with BlockerCache::Off.
  std::vector<std::optional<PrimitiveRef>> lastBlocker_;
  // The bailout: null traces exactly (and costs one test per new ray).
  const BailoutBound* bailout_ = nullptr;
  // The current ray's allowance per unit of its weight: the radiance its
  // skipped descendants may sum to, divided by the product of the
  // coefficients on its path. Set for each new ray and restored after it.
  double allowance_ = 0.0;
  // The scene has fog or an absorbing material: only then is a segment's
  // medium looked at (media.h).
  bool media_ = false;
  // The solid the current ray travels inside (its material absorbs), or null
  // for the air between solids. Set for each new ray and restored after it.
  const Material* inside_ = nullptr;
  // The scene has textured materials: only then is a hit's material asked.
  bool textured_ = false;
  // The scene has images: only then is a ray's footprint followed.
  bool images_ = false;
  // The footprint of the current ray at each depth (index: depth; eye rays
  // at 1 from setEyeFootprint), set for each new ray before it is traced:
  // a ray's own entry is never written while it is being shaded, so nothing
  // needs restoring. Empty for a scene without images.
  std::vector<RayCone> cones_;
};

} // namespace prism
