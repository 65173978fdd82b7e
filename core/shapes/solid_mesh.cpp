#include "core/shapes/solid_mesh.h"

#include "core/shapes/crossings.h"
#include "core/shapes/roundoff.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

namespace {

// The point of triangle abc nearest p (Ericson, Real-Time Collision
// Detection, 5.1.5): by the region of the triangle's plane p projects into.
Vec3 nearestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

} // namespace

void appendCrossings(const SolidMesh& m, const ShapeArrays& arrays, const Ray& ray, Interval range,
                     std::vector<Crossing>& out) {
  thread_local std::vector<Crossing> hits;
  hits.clear();
  const std::span<const Triangle> tris = trianglesOf(m, arrays);
  const Vec3* v = arrays.meshVertices.data();
  const Interval line{-std::numeric_limits<double>::infinity(),
                      std::numeric_limits<double>::infinity()};
  visitMeshTree(arrays.meshTreeNodes.subspan(m.firstNode, m.nodeCount),
                arrays.meshTreeOrder.subspan(m.firstTriangle, m.triangleCount), ray,
                [&](std::uint32_t i) {
                  const Triangle& tri = tris[i];
                  double t = 0.0;
                  if (!intersect(tri, v, ray, line, t)) return;
                  // The sign intersect divided by: the outward normal against the ray.
                  const Vec3 n = glm::cross(v[tri.vertex[1]] - v[tri.vertex[0]],
                                            v[tri.vertex[2]] - v[tri.vertex[0]]);
                  hits.push_back({t, glm::dot(n, ray.dir) < 0.0, i});
                });
  std::sort(hits.begin(), hits.end(), [](const Crossing& a, const Crossing& b) {
    return a.t < b.t || (a.t == b.t && a.part < b.part);
  });
  // Triangles meeting at an edge or a vertex the ray passes through each
  // compute its t with their own round-off: hits this close are one place.
  // (2^-36 of the numbers involved: far above the test's round-off, far
  // below any feature a mesh at that scale can have.)
  const double near = 0x1p-36 * (m.roundoff + maxAbsComponent(ray.origin)) / glm::length(ray.dir);
  bool inside = false; // the line begins outside the bounded solid
  for (std::size_t i = 0; i < hits.size();) {
    // (From i + 1: a cluster holds at least its first hit, even where `near`
    // is not a number.)
    int net = hits[i].entering ? 1 : -1;
    std::size_t j = i + 1;
    for (; j < hits.size() && hits[j].t - hits[i].t <= near; ++j)
      net += hits[j].entering ? 1 : -1;
    // A touch (as many in as out), or a repeat of the way the line already
    // went (a crossing reported twice across the cluster's edge), is no
    // crossing.
    if (net != 0 && (net > 0) != inside) {
      inside = net > 0;
      std::size_t k = i;
      while (hits[k].entering != inside)
        ++k;
      if (range.contains(hits[k].t)) out.push_back(hits[k]);
    }
    i = j;
  }
}

SurfacePoint surfaceAt(const SolidMesh& m, const ShapeArrays& arrays, const Vec3& point,
                       std::uint32_t part, SurfaceDetail detail) {
  const Triangle& t = trianglesOf(m, arrays)[part];
  SurfacePoint s = surfaceAt(t, arrays, point);
  s.part = part;
  if (detail == SurfaceDetail::WithCoordinates) s.uv = uvAt(t, arrays, point);
  return s;
}

std::uint32_t nearestTriangle(const SolidMesh& m, const ShapeArrays& arrays, const Vec3& point) {
  const std::span<const Triangle> tris = trianglesOf(m, arrays);
  const Vec3* v = arrays.meshVertices.data();
  std::uint32_t best = 0;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = 0; i < tris.size(); ++i) {
    const Triangle& t = tris[i];
    const Vec3 d = point - nearestOnTriangle(point, v[t.vertex[0]], v[t.vertex[1]], v[t.vertex[2]]);
    const double distance = glm::dot(d, d);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = i;
    }
  }
  return best;
}

Vec3 outwardNormal(const SolidMesh& m, const ShapeArrays& arrays, const Vec3& point) {
  return geometricNormal(trianglesOf(m, arrays)[nearestTriangle(m, arrays, point)],
                         arrays.meshVertices.data());
}

} // namespace prism
