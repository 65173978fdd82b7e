#include "core/shapes/geometry.h"

#include <array>
#include <cmath>

namespace prism {

namespace {

// Roots of |f + t d|^2 = r^2 in the form that keeps precision when the origin is
// far from the sphere compared with its radius (the discriminant is computed from
// the distance of the centre to the ray's line, not as a difference of squares
// of large numbers). `d` need not be unit length.
bool nearestQuadricRoot(const Vec3& f, const Vec3& d, double r2, Interval range, double& t) {
  const double a = glm::dot(d, d);
  const double b = glm::dot(f, d); // half of the usual b
  const Vec3 l = f - (b / a) * d;  // centre-to-line offset
  const double disc = a * (r2 - glm::dot(l, l));
  if (disc < 0.0) return false;
  const double q = -b - std::copysign(std::sqrt(disc), b);
  const double c = glm::dot(f, f) - r2;
  double t0 = q != 0.0 ? c / q : 0.0;
  double t1 = q / a;
  if (t0 > t1) std::swap(t0, t1);
  if (range.contains(t0)) {
    t = t0;
    return true;
  }
  if (range.contains(t1)) {
    t = t1;
    return true;
  }
  return false;
}

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

} // namespace

bool intersect(const Sphere& s, const Ray& ray, Interval range, double& t) {
  return nearestQuadricRoot(ray.origin - s.center, ray.dir, s.radius * s.radius, range, t);
}

bool intersect(const Ellipsoid& e, const Ray& ray, Interval range, double& t) {
  // In the unit sphere's space the ray keeps its parameter: X(t) maps to X'(t).
  const Vec3 o = e.worldToObject * ray.origin + e.worldToObjectOffset;
  const Vec3 d = e.worldToObject * ray.dir;
  return nearestQuadricRoot(o, d, 1.0, range, t);
}

ProjectedAxes polygonAxes(const Polygon& p) {
  return {kProjectedAxes[p.dropAxis][0], kProjectedAxes[p.dropAxis][1]};
}

bool intersect(const Polygon& p, const Vec3* vertices, const PolygonEdgeIndex* edges,
               const Ray& ray, Interval range, double& t) {
  const double denom = glm::dot(p.normal, ray.dir);
  if (denom == 0.0) return false; // parallel, or lying in the plane: no area is hit
  const double tp = (p.planeOffset - glm::dot(p.normal, ray.origin)) / denom;
  if (!range.contains(tp)) return false;

  // Crossing-number test in the projection plane: a horizontal half-line from the
  // point toward +u, counting edge crossings. Half-open rules (a vertex counts as
  // above when v > p.v, a crossing counts when p.u < x) make a point on an edge
  // shared by two coplanar polygons belong to exactly one of them, and each edge
  // is evaluated from its lower endpoint so both polygons compute the same x.
  // Every edge's x is computed and then counted or not, without a branch: which
  // edges cross is as good as random from one ray to the next, and mispredicted
  // branches cost more than the divisions (x is used only where the edge
  // crosses, so a 0/0 elsewhere does no harm).
  const int uAxis = kProjectedAxes[p.dropAxis][0], vAxis = kProjectedAxes[p.dropAxis][1];
  const Vec3 point = ray.at(tp);
  const double qu = point[uAxis], qv = point[vAxis];
  const Vec3* v = vertices + p.firstVertex;
  bool inside = false;
  if (edges != nullptr) {
    inside = edges->contains(v, p.vertexCount, uAxis, vAxis, qu, qv);
  } else {
    double au = v[p.vertexCount - 1][uAxis], av = v[p.vertexCount - 1][vAxis];
    for (std::uint32_t i = 0; i < p.vertexCount; ++i) {
      const double bu = v[i][uAxis], bv = v[i][vAxis];
      inside ^= ((av > qv) != (bv > qv)) & (qu < edgeCrossingU(au, av, bu, bv, qv));
      au = bu;
      av = bv;
    }
  }
  if (inside) t = tp;
  return inside;
}

Vec3 normalAt(const Sphere& s, const Vec3& point) { return glm::normalize(point - s.center); }

Vec3 normalAt(const Ellipsoid& e, const Vec3& point) {
  const Vec3 objectNormal = e.worldToObject * point + e.worldToObjectOffset;
  return glm::normalize(e.normalToWorld * objectNormal);
}

Aabb boundsOf(const Sphere& s) {
  Aabb box;
  box.extend(s.center - Vec3(s.radius));
  box.extend(s.center + Vec3(s.radius));
  return box;
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

Ellipsoid makeEllipsoid(const Mat3& linear, const Vec3& offset) {
  Ellipsoid e;
  e.worldToObject = glm::inverse(linear);
  e.worldToObjectOffset = -(e.worldToObject * offset);
  e.normalToWorld = glm::transpose(e.worldToObject);
  e.objectToWorld = linear;
  e.center = offset;
  // The unit sphere's image extends sqrt(sum_j A_ij^2) along world axis i
  // (hypot: no underflow for a very flat ellipsoid).
  const Mat3& m = linear;
  const Vec3 half(std::hypot(m[0].x, m[1].x, m[2].x), std::hypot(m[0].y, m[1].y, m[2].y),
                  std::hypot(m[0].z, m[1].z, m[2].z));
  e.bounds.extend(offset - half);
  e.bounds.extend(offset + half);
  return e;
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
  return p;
}

} // namespace prism
