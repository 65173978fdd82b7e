#include "core/shapes/triangle.h"

#include "core/shapes/roundoff.h"

#include <cmath>

namespace prism {

namespace {

// The vertices as the ray sees them: each moved by -origin and projected
// along the ray onto a plane containing it, in 2D. The two coordinates are the
// components of (v - o) x d on the axes other than d's largest, so the
// projection never degenerates, and each is one difference of two products:
// accurate to the rounding of v - o itself, however far the origin is. (The
// 3D edge function dot(d, (p - o) x (q - o)) cancels twice, and at an origin
// 10^13 away from a triangle of size 1 misjudged rays by whole units.)
struct Projected {
  double x, y;
};

// The ray's signed crossing of edge p -> q, from the projected vertices. The
// neighbour sharing this edge walks it q -> p and computes the same two
// products subtracted the other way round: exactly -value, so a ray can never
// slip between two triangles of a mesh.
double edgeFunction(Projected p, Projected q) { return p.x * q.y - p.y * q.x; }

// Whether the ray passes inside the triangle (on either side; a zero is on an
// edge and counts for both neighbours: the nearest-hit tie-break then picks
// one, the same whatever the traversal order). `kz` is the axis of d's
// largest component, a template argument so each projection is straight code.
template <int kz> bool passesInside(const Vec3& a, const Vec3& b, const Vec3& c, const Ray& ray) {
  constexpr int kx = (kz + 1) % 3, ky = (kz + 2) % 3;
  const Vec3& d = ray.dir;
  const auto project = [&](const Vec3& v) {
    const Vec3 p = v - ray.origin;
    return Projected{p[kx] * d[kz] - p[kz] * d[kx], p[ky] * d[kz] - p[kz] * d[ky]};
  };
  const Projected pa = project(a), pb = project(b), pc = project(c);
  const double ea = edgeFunction(pb, pc); // weight of a
  const double eb = edgeFunction(pc, pa);
  const double ec = edgeFunction(pa, pb);
  const bool front = ea >= 0.0 && eb >= 0.0 && ec >= 0.0;
  const bool back = ea <= 0.0 && eb <= 0.0 && ec <= 0.0;
  return front || back;
}

} // namespace

std::optional<std::string> triangleProblem(const Vec3& a, const Vec3& b, const Vec3& c) {
  if (!isFinite(a) || !isFinite(b) || !isFinite(c)) return "vertex is not finite";
  Aabb box;
  box.extend(a);
  box.extend(b);
  box.extend(c);
  const double size = glm::length(box.extent());
  const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
  // The same threshold as polygonProblem's, so `triangle` and `polygon 3`
  // accept the same shapes.
  if (!(size > 0.0) || !(area > 1e-12 * size * size)) return "degenerate triangle (zero area)";
  return std::nullopt;
}

// core/accel/packets.h does this arithmetic on four triangles at
// once and must answer bit for bit as this does: change both together.
bool intersect(const Triangle& tri, const Vec3* vertices, const Ray& ray, Interval range,
               double& t) {
  const Vec3& a = vertices[tri.vertex[0]];
  const Vec3& b = vertices[tri.vertex[1]];
  const Vec3& c = vertices[tri.vertex[2]];
  const int kz = largestAbsAxis(ray.dir);
  const bool inside = kz == 0   ? passesInside<0>(a, b, c, ray)
                      : kz == 1 ? passesInside<1>(a, b, c, ray)
                                : passesInside<2>(a, b, c, ray);
  if (!inside) return false;
  const Vec3 n = glm::cross(b - a, c - a);
  const double denom = glm::dot(n, ray.dir);
  if (denom == 0.0) return false; // in the plane, or all three zero: no area is hit
  const double tp = glm::dot(n, a - ray.origin) / denom;
  if (!range.contains(tp)) return false;
  t = tp;
  return true;
}

Vec3 geometricNormal(const Triangle& tri, const Vec3* vertices) {
  const Vec3& a = vertices[tri.vertex[0]];
  const Vec3& b = vertices[tri.vertex[1]];
  const Vec3& c = vertices[tri.vertex[2]];
  return glm::normalize(glm::cross(b - a, c - a));
}

namespace {

// Barycentric weights of `point` from the signed areas of the sub-triangles
// opposite each vertex. Round-off can put a hit point a hair outside an edge:
// negative weights are clamped, so what they blend stays a blend of the three.
bool barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n, const Vec3& point,
                 double (&w)[3]) {
  const double inv = 1.0 / glm::dot(n, n);
  w[0] = std::max(0.0, glm::dot(n, glm::cross(c - b, point - b)) * inv);
  w[1] = std::max(0.0, glm::dot(n, glm::cross(a - c, point - c)) * inv);
  w[2] = std::max(0.0, glm::dot(n, glm::cross(b - a, point - a)) * inv);
  const double sum = w[0] + w[1] + w[2];
  if (!(sum > 0.0) || !std::isfinite(sum)) return false;
  for (double& x : w)
    x /= sum;
  return true;
}

} // namespace

namespace {

// What the shading of a point on a triangle needs of it, computed once: the
// vertices, the unnormalised normal by the right-hand rule and, where they
// exist, the point's barycentric weights.
struct TrianglePoint {
  const Vec3* v[3];
  Vec3 n;
  double w[3];
  bool weighted;

  TrianglePoint(const Triangle& tri, const Vec3* vertices, const Vec3& point)
      : v{&vertices[tri.vertex[0]], &vertices[tri.vertex[1]], &vertices[tri.vertex[2]]},
        n(glm::cross(*v[1] - *v[0], *v[2] - *v[0])),
        weighted(barycentric(*v[0], *v[1], *v[2], n, point, w)) {}
};

// The vertex normals blended by the weights, normalised; `unit` (the
// geometric normal) where there are no weights or the blend vanishes.
Vec3 blendedNormal(const Triangle& tri, const TrianglePoint& p, const Vec3* normals,
                   const Vec3& unit) {
  if (!p.weighted) return unit;
  const Vec3 blend = p.w[0] * normals[tri.normal[0]] + p.w[1] * normals[tri.normal[1]] +
                     p.w[2] * normals[tri.normal[2]];
  const double length = glm::length(blend);
  return length > 1e-12 ? blend / length : unit;
}

// See liftedPoint.
Vec3 lift(const Triangle& tri, const TrianglePoint& p, const Vec3* normals, const Vec3& point) {
  if (!p.weighted) return point;
  Vec3 lifted(0.0);
  for (int i = 0; i < 3; ++i) {
    const Vec3& ni = normals[tri.normal[std::size_t(i)]];
    // The point raised onto vertex i's tangent plane when it lies below it;
    // never lowered (at a concave vertex the plane is below the face).
    const double below = std::min(0.0, glm::dot(point - *p.v[i], ni));
    lifted += p.w[i] * (point - below * ni);
  }
  // Outward is the side the vertex normals point to.
  const Vec3 outward =
      glm::dot(p.n, normals[tri.normal[0]] + normals[tri.normal[1]] + normals[tri.normal[2]]) >= 0.0
          ? p.n
          : -p.n;
  return isFinite(lifted) && glm::dot(lifted - point, outward) > 0.0 ? lifted : point;
}

} // namespace

Vec3 interpolatedNormal(const Triangle& tri, const Vec3* vertices, const Vec3* normals,
                        const Vec3& point) {
  if (!tri.smooth()) return geometricNormal(tri, vertices);
  const TrianglePoint p(tri, vertices, point);
  return blendedNormal(tri, p, normals, glm::normalize(p.n));
}

Vec3 liftedPoint(const Triangle& tri, const Vec3* vertices, const Vec3* normals,
                 const Vec3& point) {
  if (!tri.smooth()) return point;
  return lift(tri, TrianglePoint(tri, vertices, point), normals, point);
}

Aabb boundsOf(const Triangle& tri, const Vec3* vertices) {
  Aabb box;
  for (const std::uint32_t i : tri.vertex)
    box.extend(vertices[i]);
  return box;
}

SurfacePoint surfaceAt(const Triangle& tri, const ShapeArrays& arrays, const Vec3& point) {
  const Vec3* vertices = arrays.meshVertices.data();
  SurfacePoint s;
  s.point = point;
  s.outward = geometricNormal(tri, vertices);
  s.shading = s.outward;
  s.roundoffScale = roundoffScale(tri, arrays);
  if (!tri.smooth()) return s;
  // One set of weights for both (each of the two functions alone would
  // compute its own).
  const Vec3* normals = arrays.meshNormals.data();
  const TrianglePoint p(tri, vertices, point);
  s.shading = blendedNormal(tri, p, normals, s.outward);
  s.outwardStart = lift(tri, p, normals, point);
  return s;
}

Vec2 uvAt(const Triangle& tri, const ShapeArrays& arrays, const Vec3& point) {
  const Vec3& a = arrays.meshVertices[tri.vertex[0]];
  const Vec3& b = arrays.meshVertices[tri.vertex[1]];
  const Vec3& c = arrays.meshVertices[tri.vertex[2]];
  double w[3];
  if (!barycentric(a, b, c, glm::cross(b - a, c - a), point, w)) return Vec2(0.0);
  return {w[1], w[2]};
}

} // namespace prism
