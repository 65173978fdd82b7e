// The one-ray queries of an Accel whose walk is one template, instantiated
// to stop at the first hit (any-hit: shadow rays) or to find the nearest
// (closest hit): the hierarchies (Bvh, GroupBvh) derive from this and provide
//   template <bool AnyHit>
//   bool traverse(const Ray&, Interval, const PrimitiveRef* skip, Hit* hit) const;
// which fills *hit (when given) with what it found.
#pragma once

#include "core/accel/accel.h"

namespace prism {

template <class Derived> class TraversalAccel : public Accel {
public:
  bool closestHit(const Ray& ray, Interval range, const PrimitiveRef* skip, Hit& hit) const final {
    return self().template traverse<false>(ray, range, skip, &hit);
  }
  bool anyHit(const Ray& ray, Interval range, const PrimitiveRef* skip,
              PrimitiveRef* blocker = nullptr) const final {
    Hit hit;
    const bool found =
        self().template traverse<true>(ray, range, skip, blocker != nullptr ? &hit : nullptr);
    if (found && blocker != nullptr) *blocker = hit.primitive;
    return found;
  }

private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

} // namespace prism
