// Whether Prism and Embree find the same thing on the same rays: both miss,
// or both hit at the same t within a relative 1e-6 (Embree's t is a float).
// A small share of disagreements is expected: the engines' rules for a ray
// through a triangle's edge differ, and Embree intersects in single precision.
#pragma once

#include "bench/embree/embree_scene.h"
#include "core/accel/accel.h"

#include <string>
#include <vector>

namespace prism::bench {

inline constexpr double kAgreementTolerance = 1e-6;

struct Agreement {
  std::size_t rays = 0;
  std::size_t prismHits = 0;
  std::size_t onlyPrismHits = 0;  // Embree misses
  std::size_t onlyEmbreeHits = 0; // Prism misses
  std::size_t differentT = 0;     // both hit, beyond the tolerance
  // Of those, how many Embree found on the same primitive as Prism: single
  // precision round-off, not a different answer (closest hit only).
  std::size_t differentTSamePrimitive = 0;
  // Both hit within the tolerance, but different primitives: coincident
  // surfaces or a shared edge (closest hit only).
  std::size_t samePlaceOtherPrimitive = 0;
  std::vector<std::string> examples; // the first few disagreements, described

  std::size_t disagreements() const { return onlyPrismHits + onlyEmbreeHits + differentT; }
  double rate() const { return rays == 0 ? 1.0 : 1.0 - double(disagreements()) / double(rays); }
};

// closestHit against rtcIntersect1 (hit or miss, and t).
Agreement compareClosest(const Scene& scene, const Accel& accel, const EmbreeScene& embree,
                         const std::vector<Query>& queries, const std::vector<RTCRay>& rays);
// anyHit against rtcOccluded1 (blocked or not).
Agreement compareAny(const Scene& scene, const Accel& accel, const EmbreeScene& embree,
                     const std::vector<Query>& queries, const std::vector<RTCRay>& rays);

} // namespace prism::bench
