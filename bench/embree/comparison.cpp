#include "bench/embree/comparison.h"

namespace prism::bench {

namespace {

// The two engines' passes over the same rays, each in its own format (built
// before timing), each query exactly as a renderer would make it.
RatePair time(QueryKind kind, const Accel& accel, const EmbreeScene& embree,
              const std::vector<Query>& queries, const std::vector<RTCRay>& rays,
              const TimingOptions& timing) {
  const Pass prism = [&] {
    std::size_t hits = 0;
    Hit hit;
    for (const Query& q : queries)
      hits += kind == QueryKind::Closest ? accel.closestHit(q.ray, q.range, nullptr, hit)
                                         : accel.anyHit(q.ray, q.range, nullptr);
    return hits;
  };
  const Pass theirs = [&] {
    const EmbreeFloatMode mode;
    std::size_t hits = 0;
    float t;
    for (const RTCRay& r : rays)
      hits += kind == QueryKind::Closest ? embree.closestHit(r, t) : embree.anyHit(r);
    return hits;
  };
  return compareRates(queries.size(), prism, theirs, timing);
}

} // namespace

SetResult compareSet(const std::string& name, QueryKind kind, const Scene& scene,
                     const Accel& accel, const EmbreeScene& embree,
                     const std::vector<Query>& queries, const TimingOptions& timing) {
  const std::vector<RTCRay> rays = toEmbreeRays(queries);
  SetResult r;
  r.name = name;
  r.kind = kind;
  r.rays = queries.size();
  r.agreement = kind == QueryKind::Closest ? compareClosest(scene, accel, embree, queries, rays)
                                           : compareAny(scene, accel, embree, queries, rays);
  r.rates = time(kind, accel, embree, queries, rays, timing);
  return r;
}

} // namespace prism::bench
