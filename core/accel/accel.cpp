#include "core/accel/accel.h"

#include "core/accel/bvh.h"
#include "core/accel/group_bvh.h"

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
  return scene.visit(
      ref, [&](const auto& shape) { return intersect(shape, scene.arrays(), ray, range, t); });
}

Vec3 outwardNormal(const Scene& scene, PrimitiveRef ref, const Vec3& point) {
  return scene.visit(
      ref, [&](const auto& shape) { return outwardNormal(shape, scene.arrays(), point); });
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
