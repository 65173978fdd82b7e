// One ray set traced by both engines: their rates, timed alternately on one
// thread, and whether they found the same hits.
#pragma once

#include "bench/embree/agreement.h"
#include "bench/embree/timing.h"

#include <string>

namespace prism::bench {

enum class QueryKind { Closest, Any }; // closestHit / rtcIntersect1, anyHit / rtcOccluded1

struct SetResult {
  std::string name; // "eye", "secondary", "shadow"
  QueryKind kind = QueryKind::Closest;
  std::size_t rays = 0;
  RatePair rates;
  Agreement agreement;

  // Prism's median rate over Embree's: above 1, Prism is faster.
  double ratio() const {
    return rates.embree.median > 0.0 ? rates.prism.median / rates.embree.median : 0.0;
  }
};

SetResult compareSet(const std::string& name, QueryKind kind, const Scene& scene,
                     const Accel& accel, const EmbreeScene& embree,
                     const std::vector<Query>& queries, const TimingOptions& timing);

} // namespace prism::bench
