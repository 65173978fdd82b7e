#include "core/shapes/triangle.h"

#include <cmath>

namespace prism {

namespace {

// The ray's signed crossing of edge p -> q: dot(d, (p - o) x (q - o)). The
// cross product of swapped operands is the exact negation (each component is
// a difference of two products, computed in the opposite order), so the
// neighbour sharing this edge, which walks it q -> p, sees exactly -value.
double edgeFunction(const Vec3& p, const Vec3& q, const Ray& ray) {
  return glm::dot(ray.dir, glm::cross(p - ray.origin, q - ray.origin));
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

bool intersect(const Triangle& tri, const Vec3* vertices, const Ray& ray, Interval range,
               double& t) {
  const Vec3& a = vertices[tri.vertex[0]];
  const Vec3& b = vertices[tri.vertex[1]];
  const Vec3& c = vertices[tri.vertex[2]];
  const double ea = edgeFunction(b, c, ray); // weight of a
  const double eb = edgeFunction(c, a, ray);
  const double ec = edgeFunction(a, b, ray);
  // Inside when all three agree in sign (either sign: two-sided). A zero is
  // on an edge and counts for both neighbours; the nearest-hit tie-break then
  // picks one of them, the same one whatever the traversal order.
  const bool front = ea >= 0.0 && eb >= 0.0 && ec >= 0.0;
  const bool back = ea <= 0.0 && eb <= 0.0 && ec <= 0.0;
  if (!front && !back) return false;
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

Vec3 interpolatedNormal(const Triangle& tri, const Vec3* vertices, const Vec3* normals,
                        const Vec3& point) {
  const Vec3& a = vertices[tri.vertex[0]];
  const Vec3& b = vertices[tri.vertex[1]];
  const Vec3& c = vertices[tri.vertex[2]];
  const Vec3 n = glm::cross(b - a, c - a);
  const Vec3 unit = glm::normalize(n);
  double w[3];
  if (!tri.smooth() || !barycentric(a, b, c, n, point, w)) return unit;
  const Vec3 blend =
      w[0] * normals[tri.normal[0]] + w[1] * normals[tri.normal[1]] + w[2] * normals[tri.normal[2]];
  const double length = glm::length(blend);
  return length > 1e-12 ? blend / length : unit;
}

Vec3 liftedPoint(const Triangle& tri, const Vec3* vertices, const Vec3* normals,
                 const Vec3& point) {
  if (!tri.smooth()) return point;
  const Vec3* v[3] = {&vertices[tri.vertex[0]], &vertices[tri.vertex[1]], &vertices[tri.vertex[2]]};
  const Vec3 n = glm::cross(*v[1] - *v[0], *v[2] - *v[0]);
  double w[3];
  if (!barycentric(*v[0], *v[1], *v[2], n, point, w)) return point;
  Vec3 lifted(0.0);
  for (int i = 0; i < 3; ++i) {
    const Vec3& ni = normals[tri.normal[std::size_t(i)]];
    // The point raised onto vertex i's tangent plane when it lies below it;
    // never lowered (at a concave vertex the plane is below the face).
    const double below = std::min(0.0, glm::dot(point - *v[i], ni));
    lifted += w[i] * (point - below * ni);
  }
  // Outward is the side the vertex normals point to.
  const Vec3 outward =
      glm::dot(n, normals[tri.normal[0]] + normals[tri.normal[1]] + normals[tri.normal[2]]) >= 0.0
          ? n
          : -n;
  return isFinite(lifted) && glm::dot(lifted - point, outward) > 0.0 ? lifted : point;
}

Aabb boundsOf(const Triangle& tri, const Vec3* vertices) {
  Aabb box;
  for (const std::uint32_t i : tri.vertex)
    box.extend(vertices[i]);
  return box;
}

} // namespace prism
