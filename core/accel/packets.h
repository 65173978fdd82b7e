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

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace prism {

// A packet's data are stored when a hierarchy is built, in its leaves'
// order, so that a test loads whole lanes instead of looking each vertex up
// through its primitive. Value j of lane i is data[j * stride + i], stride
// being the number of lanes used (1 to 4): the values of lanes past it are
// whatever follows in memory (the next values, or the next packet's), whose
// answers are ignored, so that a packet of fewer than four costs no more
// than its primitives. Whoever stores packets ends them with
// kPacketPadding doubles, for the last one's unused lanes.
inline constexpr std::size_t kPacketPadding = 3;

// Triangles: corner k's coordinate a is value 3 * k + a.
struct TriangleCorners {
  const double* data;
  std::uint32_t stride;
};

// The most vertices a polygon tested in a packet may have: every lane walks
// as many edges as the largest polygon of its packet has, and larger ones
// are rare outside the polygons with an edge index, which are never packed.
inline constexpr std::uint32_t kPacketPolygonVertices = 8;

// Polygons: the planes, dot(normal, x) = offset as Polygon stores them, the
// normal's coordinate a as value a and the offset as value 3; then vertex
// k's coordinate a as value 4 + 3 * k + a, for k below `vertices`, the most
// of any lane's polygon (one of fewer repeats its last vertex).
struct PolygonCorners {
  const double* data;
  std::uint32_t stride;
  std::uint32_t vertices;
};

// Append the data of a packet of `shapes` (1 to 4; the stride is their
// number) to `out`; the polygons' returns PolygonCorners::vertices.
void appendPacket(std::span<const Triangle* const> shapes, const ShapeArrays& arrays,
                  std::vector<double>& out);
std::uint32_t appendPacket(std::span<const Polygon* const> shapes, const ShapeArrays& arrays,
                           std::vector<double>& out);

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
  // Values first, first + 1 and first + 2 of the four lanes.
  template <class Corners> static void gather(const Corners& c, std::size_t first, L (&out)[3]) {
    for (std::size_t a = 0; a < 3; ++a)
      out[a] = L::load(c.data + (first + a) * c.stride);
  }
  // Corner k's coordinates.
  static void corner(const TriangleCorners& c, int k, L (&out)[3]) {
    gather(c, 3 * std::size_t(k), out);
  }
  static void corner(const PolygonCorners& c, std::uint32_t k, L (&out)[3]) {
    gather(c, 4 + 3 * std::size_t(k), out);
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
      corner(c, k, vertex[k]);
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
    gather(c, 0, normal);
    const L zero = L::splat(0.0);
    const L denominator = normal[0] * dir_[0] + normal[1] * dir_[1] + normal[2] * dir_[2];
    const L offset = L::load(c.data + 3 * c.stride);
    const L tp =
        (offset - (normal[0] * origin_[0] + normal[1] * origin_[1] + normal[2] * origin_[2])) /
        denominator;
    const L plane = lanes::notEqual(denominator, zero) & inRange(tp, range);
    if (lanes::bits(plane) == 0) return 0;
    // The crossing number of the half-line toward +x from (0, 0), edge by
    // edge from the last vertex round (polygon.cpp's passesInside).
    L vertex[3], moved[3], ax, ay, bx, by;
    corner(c, c.vertices - 1, vertex);
    project<kz>(vertex, moved, ax, ay);
    L inside = zero;
    for (std::uint32_t k = 0; k < c.vertices; ++k) {
      corner(c, k, vertex);
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
