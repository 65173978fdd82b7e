#include "core/accel/accel.h"

#include "core/accel/bvh.h"
#include "core/accel/group_bvh.h"
#include "core/shapes/geometry.h"

#include <stdexcept>

namespace prism {

const char* accelKindName(AccelKind kind) {
  switch (kind) {
  case AccelKind::Bvh: return "bvh";
  case AccelKind::Groups: return "groups";
  case AccelKind::None: return "none";
  }
  return "?";
}

const std::map<std::string, AccelKind>& accelKindsByName() {
  static const std::map<std::string, AccelKind> kinds{
      {"bvh", AccelKind::Bvh}, {"groups", AccelKind::Groups}, {"none", AccelKind::None}};
  return kinds;
}

std::uint64_t Accel::closestHits(std::span<const Ray> rays, std::span<Hit> hits) const {
  if (rays.size() > kMaxBundle || hits.size() < rays.size())
    throw std::length_error("closestHits: at most kMaxBundle rays, a hit for each");
  std::uint64_t found = 0;
  for (std::size_t i = 0; i < rays.size(); ++i)
    found |= std::uint64_t(closestHit(rays[i], Interval{}, nullptr, hits[i])) << i;
  return found;
}

bool intersectPrimitive(const Scene& scene, PrimitiveRef ref, const Ray& ray, Interval range,
                        double& t) {
  switch (ref.kind) {
  case PrimitiveKind::Sphere: return intersect(scene.spheres[ref.index], ray, range, t);
  case PrimitiveKind::Ellipsoid: return intersect(scene.ellipsoids[ref.index], ray, range, t);
  case PrimitiveKind::Polygon: {
    const Polygon& p = scene.polygons[ref.index];
    const PolygonEdgeIndex* edges =
        p.edgeIndex == Polygon::kNoEdgeIndex ? nullptr : &scene.polygonEdgeIndices[p.edgeIndex];
    return intersect(p, scene.polygonVertices.data(), edges, ray, range, t);
  }
  case PrimitiveKind::Cone: return intersect(scene.cones[ref.index], ray, range, t);
  case PrimitiveKind::Triangle:
    return intersect(scene.triangles[ref.index], scene.meshVertices.data(), ray, range, t);
  }
  return false;
}

Vec3 outwardNormal(const Scene& scene, PrimitiveRef ref, const Vec3& point) {
  switch (ref.kind) {
  case PrimitiveKind::Sphere: return normalAt(scene.spheres[ref.index], point);
  case PrimitiveKind::Ellipsoid: return normalAt(scene.ellipsoids[ref.index], point);
  case PrimitiveKind::Polygon: return scene.polygons[ref.index].normal;
  case PrimitiveKind::Cone: return normalAt(scene.cones[ref.index], point);
  case PrimitiveKind::Triangle:
    return geometricNormal(scene.triangles[ref.index], scene.meshVertices.data());
  }
  return Vec3(0.0, 0.0, 1.0);
}

Vec3 interpolatedNormal(const Scene& scene, PrimitiveRef ref, const Vec3& point) {
  if (ref.kind != PrimitiveKind::Triangle) return outwardNormal(scene, ref, point);
  return interpolatedNormal(scene.triangles[ref.index], scene.meshVertices.data(),
                            scene.meshNormals.data(), point);
}

namespace {

// Every primitive tested against every ray: the reference the hierarchies are
// checked against, and the baseline that shows what a hierarchy buys.
class BruteForce final : public Accel {
public:
  explicit BruteForce(const Scene& scene) : scene_(scene), refs_(scene.allPrimitives()) {}

  bool closestHit(const Ray& ray, Interval range, const PrimitiveRef* skip,
                  Hit& hit) const override {
    bool found = false;
    for (const PrimitiveRef& ref : refs_) {
      if (skip != nullptr && ref == *skip) continue;
      double t;
      if (intersectPrimitive(scene_, ref, ray, range, t)) keepNearest({t, ref}, found, hit, range);
    }
    return found;
  }

  bool anyHit(const Ray& ray, Interval range, const PrimitiveRef* skip,
              PrimitiveRef* blocker = nullptr) const override {
    for (const PrimitiveRef& ref : refs_) {
      if (skip != nullptr && ref == *skip) continue;
      double t;
      if (intersectPrimitive(scene_, ref, ray, range, t)) {
        if (blocker != nullptr) *blocker = ref;
        return true;
      }
    }
    return false;
  }

  std::size_t memoryBytes() const override { return refs_.size() * sizeof(PrimitiveRef); }

private:
  const Scene& scene_;
  std::vector<PrimitiveRef> refs_;
};

} // namespace

std::unique_ptr<Accel> makeAccel(const Scene& scene, AccelKind kind) {
  switch (kind) {
  case AccelKind::Bvh: return std::make_unique<Bvh>(scene);
  case AccelKind::Groups: return std::make_unique<GroupBvh>(scene);
  case AccelKind::None: return std::make_unique<BruteForce>(scene);
  }
  return nullptr;
}

} // namespace prism
