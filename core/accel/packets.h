// Up to four flat primitives of one kind tested against one ray at once, one
// primitive a lane (core/accel/lanes.h): the leaves of a mesh hold several
// triangles, or several small polygons, and a hierarchy's walk tests them
// together instead of one after another.
//
// The arithmetic is that of the one-primitive tests, operation for operation
// and in the same order on each lane, so a lane's answer, hit or miss and t,
// is the scalar test's bit for bit; the tests check that
// (tests/packets_test.cpp). A change to one is a change to both:
//  - triangles: intersect(const Triangle&, ...) in core/shapes/triangle.cpp,
//    the projection along the ray's largest axis, the three edge functions,
//    the plane's normal by glm::cross and distance by glm::dot;
//  - polygons of up to kPacketPolygonVertices vertices tested in the ray's
//    frame (Polygon::rayFrameTest): intersect(const Polygon&, ...) in
//    core/shapes/polygon.cpp, the distance to the stored plane, then the
//    crossing number of the projected edges. A polygon of fewer vertices
//    than another in its packet repeats its last vertex: the extra edges
//    have both ends on one side of the half-line and never count.
// What it saves: the ray's projection axis is chosen once per ray instead
// of per primitive, and one branch decides four primitives.
#pragma once

#include "core/accel/lanes.h"
#include "core/math/interval.h"
#include "core/math/math.h"
#include "core/math/ray.h"
#include "core/shapes/polygon.h"
#include "core/shapes/triangle.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace prism {

// The vertices of up to four triangles, one triangle a lane (a lane without
// one repeats another's, and its answer is ignored).
struct TriangleCorners {
  const Vec3* v[4][3];

  // Lane `lane` is `tri`.
  void set(int lane, const Triangle& tri, const ShapeArrays& arrays) {
    for (int k = 0; k < 3; ++k)
      v[lane][k] = &arrays.meshVertices[tri.vertex[std::size_t(k)]];
  }
};

// The most vertices a polygon tested in a packet may have: every lane walks
// as many edges as the largest polygon of its packet has, and larger ones
// are rare outside the polygons with an edge index, which are never packed.
inline constexpr std::uint32_t kPacketPolygonVertices = 8;

// Up to four polygons, a lane each as above: the vertices, first[lane][0,
// last[lane]] (a polygon of fewer than `vertices` repeating its last), and
// the plane, dot(normal, x) = offset, as Polygon stores it.
struct PolygonCorners {
  const Vec3* first[4];
  std::uint32_t last[4];
  std::uint32_t vertices = 0; // the most of any lane's polygon
  const Vec3* normal[4];
  double offset[4];

  // Lane `lane` is `p`.
  void set(int lane, const Polygon& p, const ShapeArrays& arrays) {
    first[lane] = &arrays.polygonVertices[p.firstVertex];
    last[lane] = p.vertexCount - 1;
    this->vertices = std::max(this->vertices, p.vertexCount);
    normal[lane] = &p.normal;
    offset[lane] = p.planeOffset;
  }

  // Lane i's vertex k (its last one for k past it).
  const Vec3& vertex(int lane, std::uint32_t k) const {
    return first[lane][k < last[lane] ? k : last[lane]];
  }
};

template <class L> class PacketTest {
public:
  explicit PacketTest(const Ray& ray) {
    axis_ = largestAbsAxis(ray.dir); // as the scalar tests choose it
    for (int a = 0; a < 3; ++a) {
      origin_[a] = L::splat(ray.origin[a]);
      dir_[a] = L::splat(ray.dir[a]);
    }
  }

  // Bit i set where primitive i is hit inside `range` (open at both ends),
  // at t[i]. Lanes of `lanesUsed` (bits) only.
  template <class Corners>
  unsigned hits(const Corners& corners, unsigned lanesUsed, Interval range, double (&t)[4]) const {
    switch (axis_) {
    case 0: return along<0>(corners, range, t) & lanesUsed;
    case 1: return along<1>(corners, range, t) & lanesUsed;
    default: return along<2>(corners, range, t) & lanesUsed;
    }
  }

private:
  // Vertex k's coordinates of the four lanes.
  static void gather(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& v3, L (&out)[3]) {
    for (int a = 0; a < 3; ++a)
      out[a] = L::set(v0[a], v1[a], v2[a], v3[a]);
  }
  static void gather(const TriangleCorners& c, int k, L (&out)[3]) {
    gather(*c.v[0][k], *c.v[1][k], *c.v[2][k], *c.v[3][k], out);
  }
  static void gather(const PolygonCorners& c, std::uint32_t k, L (&out)[3]) {
    gather(c.vertex(0, k), c.vertex(1, k), c.vertex(2, k), c.vertex(3, k), out);
  }

  // A vertex moved by -origin and projected along the ray onto a plane
  // containing it (the scalar tests' `project`), in x and y.
  template <int kz> void project(const L (&vertex)[3], L (&moved)[3], L& x, L& y) const {
    constexpr int kx = (kz + 1) % 3, ky = (kz + 2) % 3;
    for (int a = 0; a < 3; ++a)
      moved[a] = vertex[a] - origin_[a];
    x = moved[kx] * dir_[kz] - moved[kz] * dir_[kx];
    y = moved[ky] * dir_[kz] - moved[kz] * dir_[ky];
  }

  // range.min < t < range.max.
  static L inRange(L t, Interval range) {
    return lanes::less(L::splat(range.min), t) & lanes::less(t, L::splat(range.max));
  }

  // The triangles' test, kz the ray's largest axis.
  template <int kz> unsigned along(const TriangleCorners& c, Interval range, double (&t)[4]) const {
    using lanes::lessEqual;
    L vertex[3][3], moved[3][3], px[3], py[3]; // [corner][axis], [corner]
    for (int k = 0; k < 3; ++k) {
      gather(c, k, vertex[k]);
      project<kz>(vertex[k], moved[k], px[k], py[k]);
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
    const L hit = inside & lanes::notEqual(denominator, zero) & inRange(tp, range);
    lanes::store(t, tp);
    return lanes::bits(hit);
  }

  // The polygons' test.
  template <int kz> unsigned along(const PolygonCorners& c, Interval range, double (&t)[4]) const {
    using lanes::less;
    // The plane first, as the scalar test: denominator glm::dot(normal, d),
    // t = (offset - glm::dot(normal, origin)) / denominator.
    L normal[3];
    for (int a = 0; a < 3; ++a)
      normal[a] =
          L::set((*c.normal[0])[a], (*c.normal[1])[a], (*c.normal[2])[a], (*c.normal[3])[a]);
    const L zero = L::splat(0.0);
    const L denominator = normal[0] * dir_[0] + normal[1] * dir_[1] + normal[2] * dir_[2];
    const L offset = L::set(c.offset[0], c.offset[1], c.offset[2], c.offset[3]);
    const L tp =
        (offset - (normal[0] * origin_[0] + normal[1] * origin_[1] + normal[2] * origin_[2])) /
        denominator;
    const L plane = lanes::notEqual(denominator, zero) & inRange(tp, range);
    if (lanes::bits(plane) == 0) return 0;
    // The crossing number of the half-line toward +x from (0, 0), edge by
    // edge from the last vertex round (polygon.cpp's passesInside).
    L vertex[3], moved[3], ax, ay, bx, by;
    gather(c, c.vertices - 1, vertex);
    project<kz>(vertex, moved, ax, ay);
    L inside = zero;
    for (std::uint32_t k = 0; k < c.vertices; ++k) {
      gather(c, k, vertex);
      project<kz>(vertex, moved, bx, by);
      const L straddles = less(zero, ay) ^ less(zero, by);
      const L e = ax * by - ay * bx;
      // straddles & (e == 0 | (e > 0) == (by > ay))
      const L disagree = less(zero, e) ^ less(ay, by);
      inside = inside ^ ((straddles & lanes::equal(e, zero)) | lanes::andNot(disagree, straddles));
      ax = bx;
      ay = by;
    }
    lanes::store(t, tp);
    return lanes::bits(plane & inside);
  }

  L origin_[3], dir_[3];
  int axis_;
};

} // namespace prism
