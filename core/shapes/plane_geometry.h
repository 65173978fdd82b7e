// Points and predicates in a polygon's plane of projection, shared by the
// ear clipping and the sweep line of the triangulation (core/shapes/triangulate.h).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

namespace prism {

using Triangle2 = std::array<std::uint32_t, 3>; // three vertex indices

// A vertex in the plane of projection.
struct P2 {
  double u, v;
  bool operator==(const P2&) const = default;
};

// Twice the signed area of triangle o a b: positive when o -> a -> b turns
// left (counterclockwise), zero when they are collinear.
inline double cross2(const P2& o, const P2& a, const P2& b) {
  return (a.u - o.u) * (b.v - o.v) - (a.v - o.v) * (b.u - o.u);
}

inline double dot2(const P2& o, const P2& a, const P2& b) {
  return (a.u - o.u) * (b.u - o.u) + (a.v - o.v) * (b.v - o.v);
}

// The sweep's order: p comes before q when it is higher, or as high and
// further left. No two distinct points are level in this order, which is
// what spares the sweep every special case for horizontal edges.
inline bool above(const P2& p, const P2& q) { return p.v > q.v || (p.v == q.v && p.u < q.u); }

// Whether q, known to be collinear with segment s0 s1, lies on it.
inline bool withinSegment(const P2& s0, const P2& s1, const P2& q) {
  return std::min(s0.u, s1.u) <= q.u && q.u <= std::max(s0.u, s1.u) &&
         std::min(s0.v, s1.v) <= q.v && q.v <= std::max(s0.v, s1.v);
}

// Whether the closed segments a0 a1 and b0 b1 share a point.
inline bool segmentsMeet(const P2& a0, const P2& a1, const P2& b0, const P2& b1) {
  const double d1 = cross2(b0, b1, a0), d2 = cross2(b0, b1, a1);
  const double d3 = cross2(a0, a1, b0), d4 = cross2(a0, a1, b1);
  const bool aStraddles = (d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0);
  const bool bStraddles = (d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0);
  if (aStraddles && bStraddles) return true;
  return (d1 == 0.0 && withinSegment(b0, b1, a0)) || (d2 == 0.0 && withinSegment(b0, b1, a1)) ||
         (d3 == 0.0 && withinSegment(a0, a1, b0)) || (d4 == 0.0 && withinSegment(a0, a1, b1));
}

// Whether p lies inside or on triangle abc (counterclockwise).
inline bool inTriangle(const P2& p, const P2& a, const P2& b, const P2& c) {
  return cross2(a, b, p) >= 0.0 && cross2(b, c, p) >= 0.0 && cross2(c, a, p) >= 0.0;
}

} // namespace prism
