#include "core/shapes/box.h"

#include "core/shapes/roundoff.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

std::optional<std::string> boxProblem(const Vec3& corner0, const Vec3& corner1) {
  if (!isFinite(corner0) || !isFinite(corner1)) return "not finite";
  for (int i = 0; i < 3; ++i) {
    if (corner0[i] == corner1[i]) {
      static constexpr const char* kAxes[] = {"X", "Y", "Z"};
      return std::string("degenerate box (both corners have the same ") + kAxes[i] + ")";
    }
  }
  return std::nullopt;
}

Box makeBox(const Vec3& corner0, const Vec3& corner1, const Mat3& linear, const Vec3& offset) {
  Box b;
  Vec3 a = corner0, c = corner1;
  // Without rotation or shear the box stays axis-aligned in the world: store
  // it there (a mirror or a scale only swaps or moves its corners).
  const bool diagonal = linear[0][1] == 0.0 && linear[0][2] == 0.0 && linear[1][0] == 0.0 &&
                        linear[1][2] == 0.0 && linear[2][0] == 0.0 && linear[2][1] == 0.0;
  if (diagonal) {
    a = linear * a + offset;
    c = linear * c + offset;
  } else {
    b.frame = makeAffineFrame(linear, offset);
  }
  b.lo = glm::min(a, c);
  b.hi = glm::max(a, c);
  const AffineFrame& f = b.frame;
  b.roundoff = frameRoundoffScale(f.objectToWorld, f.worldToObject, f.objectToWorldOffset,
                                  std::max(maxAbsComponent(b.lo), maxAbsComponent(b.hi)));
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y,
                 (corner & 4) ? b.hi.z : b.lo.z);
    b.bounds.extend(f.objectToWorld * p + f.objectToWorldOffset);
  }
  return b;
}

bool slabSpan(const Vec3& o, const Vec3& d, const Vec3& lo, const Vec3& hi, BoxSpan& span) {
  span = {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), 0, 0};
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      // Parallel to the slab: inside it for every t (a ray in a face's plane
      // counts as inside, so it meets the faces across its path) or never.
      if (!(o[i] >= lo[i] && o[i] <= hi[i])) return false;
      continue;
    }
    // Divisions, not a reciprocal: the plane's t is exactly rounded, so the
    // faces meeting at an edge agree on it. Never NaN: d[i] is not zero.
    const double toLo = (lo[i] - o[i]) / d[i];
    const double toHi = (hi[i] - o[i]) / d[i];
    const bool up = d[i] > 0.0;
    const double enter = up ? toLo : toHi, leave = up ? toHi : toLo;
    // Strict comparisons: at an edge the first axis keeps it, the same for
    // every ray, and the span stays closed, so no ray slips between faces.
    if (enter > span.t0) span = {enter, span.t1, std::uint32_t(2 * i + (up ? 0 : 1)), span.part1};
    if (leave < span.t1) span = {span.t0, leave, span.part0, std::uint32_t(2 * i + (up ? 1 : 0))};
  }
  return span.t0 <= span.t1;
}

bool boxSpan(const Box& b, const Ray& ray, BoxSpan& span) {
  return slabSpan(b.frame.pointToObject(ray.origin), b.frame.directionToObject(ray.dir), b.lo, b.hi,
                  span);
}

bool intersect(const Box& b, const Ray& ray, Interval range, double& t) {
  BoxSpan span;
  if (!boxSpan(b, ray, span)) return false;
  for (const double candidate : {span.t0, span.t1}) {
    if (range.contains(candidate)) {
      t = candidate;
      return true;
    }
  }
  return false;
}

std::uint32_t partAt(const Box& b, const Vec3& point) {
  const Vec3 p = b.frame.pointToObject(point);
  std::uint32_t part = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double length = glm::length(b.frame.objectToWorld[i]); // world size of a unit along i
    const double toLo = std::abs(p[i] - b.lo[i]) * length;
    const double toHi = std::abs(b.hi[i] - p[i]) * length;
    if (toLo < nearest) nearest = toLo, part = std::uint32_t(2 * i);
    if (toHi < nearest) nearest = toHi, part = std::uint32_t(2 * i + 1);
  }
  return part;
}

namespace {

Vec3 faceNormal(const Box& b, std::uint32_t part) {
  Vec3 g(0.0);
  g[int(part / 2)] = (part & 1) ? 1.0 : -1.0;
  return b.frame.normalToWorldUnit(g);
}

} // namespace

Vec3 normalAt(const Box& b, const Vec3& point) { return faceNormal(b, partAt(b, point)); }

SurfacePoint surfaceAt(const Box& b, const ShapeArrays&, const Vec3& point) {
  SurfacePoint s;
  s.point = point;
  s.part = partAt(b, point);
  s.outward = faceNormal(b, s.part);
  s.shading = s.outward;
  s.roundoffScale = b.roundoff;
  return s;
}

Vec2 uvAt(const Box& b, const Vec3& point) {
  const std::uint32_t part = partAt(b, point);
  const Vec3 p = b.frame.pointToObject(point);
  const int i = int(part / 2), j = (i + 1) % 3, k = (i + 2) % 3;
  const auto across = [&](int axis) {
    return std::clamp((p[axis] - b.lo[axis]) / (b.hi[axis] - b.lo[axis]), 0.0, 1.0);
  };
  const double u = across(j), v = across(k);
  return {(part & 1) ? u : 1.0 - u, v};
}

bool isWorldAligned(const Box& b) {
  return b.frame.objectToWorld == Mat3(1.0) && b.frame.objectToWorldOffset == Vec3(0.0);
}

} // namespace prism
