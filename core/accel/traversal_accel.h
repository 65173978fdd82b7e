// The one-ray queries of an Accel whose walk is one template, instantiated
// to stop at the first hit (any-hit: shadow rays) or to find the nearest
// (closest hit): the hierarchies (Bvh, GroupBvh) derive from this and provide
//   template <bool AnyHit>
//   bool traverse(const Ray&, Interval, const PrimitiveRef* skip, Hit* hit) const;
// which fills *hit (when given) with what it found.
#pragma once

#include "core/accel/accel.h"

namespace prism {

// One primitive met in a leaf during such a walk, `skip` passed over: an
// any-hit walk returns true at the first hit (putting it in *hit when
// asked); a closest-hit walk keeps the nearest in *hit, `found` and
// range.max (keepNearest) and goes on.
template <bool AnyHit>
inline bool testLeafPrimitive(const Scene& scene, PrimitiveRef prim, const Ray& ray,
                              Interval& range, const PrimitiveRef* skip, bool& found, Hit* hit) {
  if (skip != nullptr && prim == *skip) return false;
  double t;
  if (!intersectPrimitive(scene, prim, ray, range, t)) return false;
  if constexpr (AnyHit) {
    if (hit != nullptr) *hit = {t, prim}; // the blocker, when asked for
    return true;
  } else {
    keepNearest({t, prim}, found, *hit, range);
    return false;
  }
}

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
