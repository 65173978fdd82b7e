// Ray queries over a scene's primitives. An Accel answers two questions: the
// nearest hit along a ray (for eye and secondary rays) and whether anything at
// all is hit (for shadow rays, which may stop at the first blocker).
#pragma once

#include "core/scene/scene.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <string>

namespace prism {

struct Hit {
  double t = 0.0;
  PrimitiveRef primitive;
};

// The next double above x (std::nextafter(x, +inf), which is a call into the
// C library; this runs for every nearer hit found).
inline double nextUp(double x) {
  if (!(x < std::numeric_limits<double>::infinity())) return x; // +inf, NaN
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0.0 ? bits + 1 : bits - 1);
}

// Offers a candidate hit to the nearest one found so far (`found` says whether
// there is one) and narrows `range` so later candidates must be at least as near.
// Ties go to the smaller PrimitiveRef: the answer never depends on visiting order.
inline void keepNearest(const Hit& candidate, bool& found, Hit& nearest, Interval& range) {
  if (!found || candidate.t < nearest.t ||
      (candidate.t == nearest.t && candidate.primitive < nearest.primitive)) {
    nearest = candidate;
    found = true;
  }
  // Still accept hits at exactly nearest.t, for the tie-break above.
  range.max = nextUp(nearest.t);
}

// How rays find primitives. `Bvh` (the default) builds its own hierarchy with
// the surface area heuristic; `Groups` uses the push/pop groups as the
// hierarchy (with a median-split tree inside large groups); `None` tests every
// primitive. All three report exactly the same hits.
enum class AccelKind { Bvh, Groups, None };

const char* accelKindName(AccelKind kind);

// Every kind by its name ("bvh", "groups", "none"), for command lines.
const std::map<std::string, AccelKind>& accelKindsByName();

class Accel {
public:
  virtual ~Accel() = default;

  // Nearest hit with t inside `range`. `skip`, when given, is never reported: the
  // flat polygon a secondary ray leaves cannot be hit again, and skipping it makes
  // that guarantee exact rather than a matter of tolerance.
  virtual bool closestHit(const Ray& ray, Interval range, const PrimitiveRef* skip,
                          Hit& hit) const = 0;
  // Whether anything (but `skip`) is hit inside `range`; `blocker`, when given,
  // receives the primitive found (any one, not necessarily the nearest).
  virtual bool anyHit(const Ray& ray, Interval range, const PrimitiveRef* skip,
                      PrimitiveRef* blocker = nullptr) const = 0;

  // The nearest hits of a bundle of at most kMaxBundle rays that all start at
  // the same point (eye rays through neighbouring pixels), each over the whole
  // ray (Interval{}) with nothing skipped: bit i of the result says whether
  // rays[i] hits anything, hits[i] what. Exactly closestHit's answer for each
  // ray; an Accel may share the work of finding them.
  static constexpr std::size_t kMaxBundle = 64;
  virtual std::uint64_t closestHits(std::span<const Ray> rays, std::span<Hit> hits) const;

  // Bytes held by the structure itself (nodes, primitive references and the
  // copies of primitives' data it keeps for its own tests; not the scene's
  // primitives), for the benchmark's bytes per primitive.
  virtual std::size_t memoryBytes() const = 0;
};

std::unique_ptr<Accel> makeAccel(const Scene& scene, AccelKind kind);

// The nearest intersection of one primitive, shared by every Accel.
bool intersectPrimitive(const Scene& scene, PrimitiveRef ref, const Ray& ray, Interval range,
                        double& t);

// The unit outward normal of a primitive at a point on it: the geometric one,
// which decides entering or leaving (docs/rendering-model.md) and where rays start.
Vec3 outwardNormal(const Scene& scene, PrimitiveRef ref, const Vec3& point);

} // namespace prism
