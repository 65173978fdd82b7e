#include "core/shapes/polygon.h"

#include <algorithm>
#include <cmath>

namespace prism {

namespace {

// The two axes a polygon keeps when its dropAxis is dropped, in the order
// that keeps the projection's orientation (u, v) = (y, z), (z, x), (x, y).
constexpr int kProjectedAxes[3][2] = {{1, 2}, {2, 0}, {0, 1}};

// Newell's method: a normal whose length is twice the polygon's area and whose
// direction follows the right-hand rule, for convex and concave polygons alike.
Vec3 newellNormal(std::span<const Vec3> v) {
  Vec3 n(0.0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = v[i];
    const Vec3& b = v[(i + 1) % v.size()];
    n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

// The polygon as the ray sees it, as the triangle test sees a triangle
// (core/shapes/triangle.cpp): each vertex moved by -origin and projected along
// the ray onto a plane containing it, in 2D, the ray itself at (0, 0). Every
// polygon sharing an edge projects its two vertices to the very same numbers,
// whatever the angle between the polygons: so a ray can never pass between
// two faces of a closed solid, nor be counted by both.
struct Projected {
  double x, y;
};

// Whether (0, 0) is inside the projected polygon by the crossing number of
// the half-line toward +x, for the point moved to (-eps, +delta) with delta
// infinitely smaller than eps: a vertex at y = 0 counts as below the
// half-line, and an edge crossing it exactly at x = 0 counts as crossing.
// Each edge's crossing is decided by the sign of e = a.x b.y - a.y b.x (the
// crossing lies at x = e / (b.y - a.y)); the polygon on the other side of the
// edge walks it b -> a and computes exactly -e (the same two products,
// subtracted the other way round), so the two always decide alike: the
// polygons around a point, edge or vertex it lies on, contain it exactly
// once. No division; every edge evaluated and counted without a branch, since
// which edges straddle is as good as random from one ray to the next.
template <int kz>
[[gnu::always_inline]] inline bool passesInside(const Vec3* vertices, std::uint32_t count,
                                                const Ray& ray) {
  constexpr int kx = (kz + 1) % 3, ky = (kz + 2) % 3;
  const Vec3& d = ray.dir;
  const auto project = [&](const Vec3& vertex) {
    const Vec3 p = vertex - ray.origin;
    return Projected{p[kx] * d[kz] - p[kz] * d[kx], p[ky] * d[kz] - p[kz] * d[ky]};
  };
  Projected a = project(vertices[count - 1]);
  bool inside = false;
  for (std::uint32_t i = 0; i < count; ++i) {
    const Projected b = project(vertices[i]);
    const bool straddles = (a.y > 0.0) != (b.y > 0.0);
    const double e = a.x * b.y - a.y * b.x;
    inside ^= straddles & ((e == 0.0) | ((e > 0.0) == (b.y > a.y)));
    a = b;
  }
  return inside;
}

} // namespace

ProjectedAxes polygonAxes(const Polygon& p) {
  return {kProjectedAxes[p.dropAxis][0], kProjectedAxes[p.dropAxis][1]};
}

// core/accel/packets.h does this arithmetic (the plane, then passesInside)
// on four polygons of up to four vertices at once and must answer bit for
// bit as this does: change both together.
bool intersect(const Polygon& p, const Vec3* vertices, const PolygonEdgeIndex* edges,
               const Ray& ray, Interval range, double& t) {
  const double denom = glm::dot(p.normal, ray.dir);
  if (denom == 0.0) return false; // parallel, or lying in the plane: no area is hit
  const double tp = (p.planeOffset - glm::dot(p.normal, ray.origin)) / denom;
  if (!range.contains(tp)) return false;
  const Vec3* v = vertices + p.firstVertex;
  bool inside = false;
  if (p.rayFrameTest) {
    const int kz = largestAbsAxis(ray.dir);
    inside = kz == 0   ? passesInside<0>(v, p.vertexCount, ray)
             : kz == 1 ? passesInside<1>(v, p.vertexCount, ray)
                       : passesInside<2>(v, p.vertexCount, ray);
  } else {
    // A polygon of many vertices, or one whose vertices lie off its plane:
    // the crossing-number test in the plane's own projection, of the point
    // where the ray meets the plane (for a polygon that is not planar the
    // ray-frame test could accept a grazing ray whose point on the plane lies
    // far outside the vertices' box, where a hierarchy would cull it). The
    // edge index, when given, finds the few edges a horizontal line can
    // cross (core/shapes/polygon_edges.h). Half-open rules (a vertex counts
    // as above when v > p.v, a crossing counts when p.u < x) give a point on
    // an edge shared with a *coplanar* polygon to exactly one of them; across
    // an edge with a polygon at an angle the two planes' projections are not
    // the same numbers, and a ray through the edge itself may pass between
    // them (docs/limits.md).
    const int uAxis = kProjectedAxes[p.dropAxis][0], vAxis = kProjectedAxes[p.dropAxis][1];
    const Vec3 point = ray.at(tp);
    const double qu = point[uAxis], qv = point[vAxis];
    if (edges != nullptr) {
      inside = edges->contains(v, p.vertexCount, uAxis, vAxis, qu, qv);
    } else {
      // Every edge's x is computed and then counted or not, without a
      // branch: mispredicted branches cost more than the divisions (x is
      // used only where the edge crosses, so a 0/0 elsewhere does no harm).
      double au = v[p.vertexCount - 1][uAxis], av = v[p.vertexCount - 1][vAxis];
      for (std::uint32_t i = 0; i < p.vertexCount; ++i) {
        const double bu = v[i][uAxis], bv = v[i][vAxis];
        inside ^= ((av > qv) != (bv > qv)) & (qu < edgeCrossingU(au, av, bu, bv, qv));
        au = bu;
        av = bv;
      }
    }
  }
  if (inside) t = tp;
  return inside;
}

Vec2 uvAt(const Polygon& p, const ShapeArrays& arrays, const Vec3& point) {
  const Vec3& first = arrays.polygonVertices[p.firstVertex];
  // The first edge of non-zero length (a file may repeat a vertex).
  Vec3 edge(0.0);
  for (std::uint32_t i = 1; i < p.vertexCount && edge == Vec3(0.0); ++i)
    edge = arrays.polygonVertices[p.firstVertex + i] - first;
  // In the plane exactly (the vertices are planar only to a tolerance).
  const Vec3 u = glm::normalize(edge - glm::dot(edge, p.normal) * p.normal);
  const Vec3 v = glm::cross(p.normal, u);
  return {glm::dot(point - first, u), glm::dot(point - first, v)};
}

Aabb boundsOf(const Polygon& p, const Vec3* vertices) {
  // A polygon is hit on its plane, where the hit's projection (the dropped
  // axis left out) lies inside the vertices' projection. Its vertices may be
  // a little off that plane (the readers accept 1e-3 of the polygon's size),
  // so the box holds each vertex and also the point of the plane over it
  // along the dropped axis: hits lie between those, and a hierarchy never
  // culls a polygon its own test would hit.
  const int w = p.dropAxis;
  Aabb box;
  for (std::uint32_t i = 0; i < p.vertexCount; ++i) {
    Vec3 v = vertices[p.firstVertex + i];
    box.extend(v);
    v[w] += (p.planeOffset - glm::dot(p.normal, v)) / p.normal[w];
    box.extend(v);
  }
  return box;
}

std::optional<std::string> polygonProblem(std::span<const Vec3> vertices) {
  if (vertices.size() < 3) return "a polygon needs at least 3 vertices";
  Aabb box;
  for (const Vec3& v : vertices) {
    if (!isFinite(v)) return "vertex is not finite";
    box.extend(v);
  }
  const double size = glm::length(box.extent());
  const Vec3 n = newellNormal(vertices);
  const double area = 0.5 * glm::length(n);
  // Relative thresholds: the same polygon at any scale gets the same verdict.
  if (!(size > 0.0) || area <= 1e-12 * size * size) return "degenerate polygon (zero area)";
  const Vec3 unit = n / glm::length(n);
  Vec3 mean(0.0);
  for (const Vec3& v : vertices)
    mean += v;
  mean /= double(vertices.size());
  // Hand-written and generated files round coordinates; 1e-3 of the polygon's
  // size tolerates that and still catches a mistyped coordinate.
  for (const Vec3& v : vertices) {
    if (std::abs(glm::dot(unit, v - mean)) > 1e-3 * size) return "polygon is not planar";
  }
  return std::nullopt;
}

Polygon makePolygon(std::span<const Vec3> vertices) {
  Polygon p;
  p.vertexCount = std::uint32_t(vertices.size());
  p.normal = glm::normalize(newellNormal(vertices));
  Vec3 mean(0.0);
  for (const Vec3& v : vertices)
    mean += v;
  mean /= double(vertices.size());
  p.planeOffset = glm::dot(p.normal, mean);
  const Vec3 a = glm::abs(p.normal);
  p.dropAxis = std::uint8_t(a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2));
  // Planar to within the round-off of the plane's own computation: the
  // vertices' distances from it are then a few ulps of their coordinates.
  double magnitude = 0.0, offPlane = 0.0;
  for (const Vec3& v : vertices) {
    magnitude = std::max(magnitude, maxAbsComponent(v));
    offPlane = std::max(offPlane, std::abs(glm::dot(p.normal, v) - p.planeOffset));
  }
  p.rayFrameTest =
      p.vertexCount < kIndexedPolygonVertices && offPlane <= kPlanarRoundoff * magnitude;
  return p;
}

} // namespace prism
