// An Accel that passes every query on to another and counts them: how often
// the tracer or the sweep asks the hierarchy, independently of what they
// report themselves. Bundles of eye rays reach closestHit through Accel's own
// closestHits. Counters are atomic: renders run on several threads.
#pragma once

#include "core/accel/accel.h"

#include <atomic>

namespace prism::test {

class CountingAccel final : public Accel {
public:
  explicit CountingAccel(const Accel& inner) : inner_(inner) {}
  bool closestHit(const Ray& ray, Interval range, const PrimitiveRef* skip,
                  Hit& hit) const override {
    ++closestHits;
    return inner_.closestHit(ray, range, skip, hit);
  }
  bool anyHit(const Ray& ray, Interval range, const PrimitiveRef* skip,
              PrimitiveRef* blocker = nullptr) const override {
    ++anyHits;
    return inner_.anyHit(ray, range, skip, blocker);
  }
  std::size_t memoryBytes() const override { return inner_.memoryBytes(); }
  long long queries() const { return closestHits.load() + anyHits.load(); }

  mutable std::atomic<long long> closestHits{0};
  mutable std::atomic<long long> anyHits{0};

private:
  const Accel& inner_;
};

} // namespace prism::test
