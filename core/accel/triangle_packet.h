// Up to four mesh triangles tested against one ray at once, one triangle a
// lane (core/accel/lanes.h): the leaves of a mesh hold several triangles, and
// a hierarchy's walk tests them together instead of one after another.
//
// The arithmetic is that of intersect(const Triangle&, ...) in
// core/shapes/triangle.cpp, operation for operation and in the same order on
// each lane (the projection along the ray's largest axis, the three edge
// functions, the plane's normal by glm::cross and distance by glm::dot), so a
// lane's answer, hit or miss and t, is the scalar test's bit for bit; the
// tests check that (tests/accel_test.cpp). A change to one is a change to
// both. What it saves: the ray's projection axis is chosen once per ray
// instead of per triangle, and one branch decides four triangles.
#pragma once

#include "core/accel/lanes.h"
#include "core/math/interval.h"
#include "core/math/math.h"
#include "core/math/ray.h"

namespace prism {

// The vertices a, b, c of up to four triangles, one triangle a lane (a lane
// without one repeats another's, and its answer is ignored).
struct TriangleCorners {
  const Vec3* v[4][3];
};

template <class L> class TrianglePacketTest {
public:
  explicit TrianglePacketTest(const Ray& ray) {
    // The axis of d's largest component, chosen as the scalar test does.
    const Vec3 m = glm::abs(ray.dir);
    axis_ = m.x >= m.y ? (m.x >= m.z ? 0 : 2) : (m.y >= m.z ? 1 : 2);
    for (int a = 0; a < 3; ++a) {
      origin_[a] = L::splat(ray.origin[a]);
      dir_[a] = L::splat(ray.dir[a]);
    }
  }

  // Bit i set where triangle i is hit inside `range` (open at both ends), at
  // t[i]. Lanes of `lanesUsed` (bits) only.
  unsigned hits(const TriangleCorners& corners, unsigned lanesUsed, Interval range,
                double (&t)[4]) const {
    switch (axis_) {
    case 0: return hitsAlong<0>(corners, range, t) & lanesUsed;
    case 1: return hitsAlong<1>(corners, range, t) & lanesUsed;
    default: return hitsAlong<2>(corners, range, t) & lanesUsed;
    }
  }

private:
  template <int kz>
  unsigned hitsAlong(const TriangleCorners& c, Interval range, double (&t)[4]) const {
    constexpr int kx = (kz + 1) % 3, ky = (kz + 2) % 3;
    using lanes::lessEqual;
    L vertex[3][3]; // [corner][axis]
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a)
        vertex[k][a] = L::set((*c.v[0][k])[a], (*c.v[1][k])[a], (*c.v[2][k])[a], (*c.v[3][k])[a]);
    // The corners moved by -origin and projected along the ray (passesInside).
    L moved[3][3], px[3], py[3];
    for (int k = 0; k < 3; ++k) {
      for (int a = 0; a < 3; ++a)
        moved[k][a] = vertex[k][a] - origin_[a];
      px[k] = moved[k][kx] * dir_[kz] - moved[k][kz] * dir_[kx];
      py[k] = moved[k][ky] * dir_[kz] - moved[k][kz] * dir_[ky];
    }
    // edgeFunction(p, q) = p.x * q.y - p.y * q.x, of b -> c, c -> a, a -> b.
    const L ea = px[1] * py[2] - py[1] * px[2];
    const L eb = px[2] * py[0] - py[2] * px[0];
    const L ec = px[0] * py[1] - py[0] * px[1];
    const L zero = L::splat(0.0);
    const L front = lessEqual(zero, ea) & lessEqual(zero, eb) & lessEqual(zero, ec);
    const L back = lessEqual(ea, zero) & lessEqual(eb, zero) & lessEqual(ec, zero);
    const L inside = front | back;
    if (lanes::bits(inside) == 0) return 0;
    // n = glm::cross(b - a, c - a); denominator glm::dot(n, d); distance
    // glm::dot(n, a - origin) / denominator (glm's dot sums x, y, then z).
    L e1[3], e2[3];
    for (int a = 0; a < 3; ++a) {
      e1[a] = vertex[1][a] - vertex[0][a];
      e2[a] = vertex[2][a] - vertex[0][a];
    }
    const L n[3] = {e1[1] * e2[2] - e2[1] * e1[2], e1[2] * e2[0] - e2[2] * e1[0],
                    e1[0] * e2[1] - e2[0] * e1[1]};
    const L denominator = n[0] * dir_[0] + n[1] * dir_[1] + n[2] * dir_[2];
    const L distance = n[0] * moved[0][0] + n[1] * moved[0][1] + n[2] * moved[0][2];
    const L tp = distance / denominator;
    const L hit = inside & lanes::notEqual(denominator, zero) &
                  lanes::less(L::splat(range.min), tp) & lanes::less(tp, L::splat(range.max));
    lanes::store(t, tp);
    return lanes::bits(hit);
  }

  L origin_[3], dir_[3];
  int axis_;
};

} // namespace prism
