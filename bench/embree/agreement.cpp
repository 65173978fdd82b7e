#include "bench/embree/agreement.h"

#include <cmath>
#include <cstdio>

namespace prism::bench {

namespace {

constexpr std::size_t kExamples = 5;

std::string rayText(std::size_t i, const Query& q) {
  char text[200];
  std::snprintf(text, sizeof text, "ray %zu (%.9g %.9g %.9g) -> (%.9g %.9g %.9g)", i,
                q.ray.origin.x, q.ray.origin.y, q.ray.origin.z, q.ray.dir.x, q.ray.dir.y,
                q.ray.dir.z);
  return text;
}

std::string hitText(const Scene& scene, bool hit, const Hit& h) {
  if (!hit) return "miss";
  char t[40];
  std::snprintf(t, sizeof t, "t %.9g ", h.t);
  return t + scene.describe(h.primitive);
}

} // namespace

Agreement compareClosest(const Scene& scene, const Accel& accel, const EmbreeScene& embree,
                         const std::vector<Query>& queries, const std::vector<RTCRay>& rays) {
  std::vector<char> embreeHit(queries.size());
  std::vector<float> embreeT(queries.size());
  std::vector<PrimitiveRef> embreePrimitive(queries.size());
  {
    const EmbreeFloatMode mode;
    for (std::size_t i = 0; i < queries.size(); ++i)
      embreeHit[i] = embree.closestHit(rays[i], embreeT[i], &embreePrimitive[i]);
  }
  Agreement a;
  a.rays = queries.size();
  for (std::size_t i = 0; i < queries.size(); ++i) {
    Hit hit;
    const bool p = accel.closestHit(queries[i].ray, queries[i].range, nullptr, hit);
    const float t = embreeT[i];
    const bool e = embreeHit[i] != 0;
    a.prismHits += p;
    bool agree = p == e;
    if (p && !e) ++a.onlyPrismHits;
    if (e && !p) ++a.onlyEmbreeHits;
    const bool samePrimitive = p && e && hit.primitive == embreePrimitive[i];
    if (p && e && std::abs(hit.t - double(t)) > kAgreementTolerance * std::abs(hit.t)) {
      ++a.differentT;
      a.differentTSamePrimitive += samePrimitive;
      agree = false;
    } else if (p && e && !samePrimitive) {
      ++a.samePlaceOtherPrimitive;
    }
    if (!agree && !samePrimitive && a.examples.size() < kExamples) {
      const Hit theirs{double(t), embreePrimitive[i]};
      a.examples.push_back(rayText(i, queries[i]) + ": Prism " + hitText(scene, p, hit) +
                           ", Embree " + hitText(scene, e, theirs));
    }
  }
  return a;
}

Agreement compareAny(const Scene& scene, const Accel& accel, const EmbreeScene& embree,
                     const std::vector<Query>& queries, const std::vector<RTCRay>& rays) {
  std::vector<char> embreeHit(queries.size());
  {
    const EmbreeFloatMode mode;
    for (std::size_t i = 0; i < queries.size(); ++i)
      embreeHit[i] = embree.anyHit(rays[i]);
  }
  Agreement a;
  a.rays = queries.size();
  for (std::size_t i = 0; i < queries.size(); ++i) {
    PrimitiveRef blocker;
    const bool p = accel.anyHit(queries[i].ray, queries[i].range, nullptr, &blocker);
    const bool e = embreeHit[i] != 0;
    a.prismHits += p;
    if (p && !e) ++a.onlyPrismHits;
    if (e && !p) ++a.onlyEmbreeHits;
    if (p != e && a.examples.size() < kExamples) {
      char end[40];
      std::snprintf(end, sizeof end, " (ends at %.9g)", queries[i].range.max);
      a.examples.push_back(rayText(i, queries[i]) + end + ": Prism " +
                           (p ? "blocked by " + scene.describe(blocker) : "clear") + ", Embree " +
                           (e ? "blocked" : "clear"));
    }
  }
  return a;
}

} // namespace prism::bench
