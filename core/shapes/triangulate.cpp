#include "core/shapes/triangulate.h"

#include "core/shapes/sweep_triangulation.h"

#include <algorithm>
#include <cmath>

namespace prism {

namespace {

// Beyond this many vertices the sweep's pieces (at most 3 n corners) could
// overflow 32-bit indices.
constexpr std::size_t kMaxVertices = std::size_t(1) << 30;
// Beyond this, products of coordinate differences could overflow.
constexpr double kMaxDecidableCoordinate = 1e100;

// The polygon in the coordinate plane its Newell normal is most nearly
// perpendicular to, mirrored there if needed to run counterclockwise.
std::vector<P2> projectCounterclockwise(std::span<const Vec3> points) {
  const std::size_t n = points.size();
  // Newell's normal gives the plane and the winding, for concave faces too.
  Vec3 normal(0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = points[i];
    const Vec3& b = points[(i + 1) % n];
    normal += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  const Vec3 an = glm::abs(normal);
  const int drop = an.x >= an.y && an.x >= an.z ? 0 : (an.y >= an.z ? 1 : 2);
  const bool flip = normal[drop] < 0.0;
  std::vector<P2> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& q = points[i];
    P2 r = drop == 0 ? P2{q.y, q.z} : drop == 1 ? P2{q.z, q.x} : P2{q.x, q.y};
    if (flip) std::swap(r.u, r.v);
    p[i] = r;
  }
  return p;
}

// Twice the signed area (shoelace, about p[0] to keep round-off small).
double twiceArea(const std::vector<P2>& p) {
  double sum = 0.0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i)
    sum += cross2(p[0], p[i], p[i + 1]);
  return sum;
}

std::vector<Triangle2> fan(std::size_t n) {
  std::vector<Triangle2> out;
  for (std::uint32_t i = 1; i + 1 < n; ++i)
    out.push_back({0, i, i + 1});
  return out;
}

// No corner turns right: the polygon is fanned, as Prism always did.
bool turnsLeftEverywhere(const std::vector<P2>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    if (!(cross2(p[i], p[(i + 1) % n], p[(i + 2) % n]) >= 0.0)) return false;
  return true;
}

// For a polygon that never turns right: simple when no edge is empty or doubles
// back and it winds around once, i.e. has a single topmost corner (each time
// around adds one).
bool windsOnce(const std::vector<P2>& p) {
  const std::size_t n = p.size();
  std::size_t tops = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const P2& a = p[(i + n - 1) % n];
    const P2& b = p[i];
    const P2& c = p[(i + 1) % n];
    if (b == c) return false;
    if (cross2(a, b, c) == 0.0 && dot2(b, a, c) > 0.0) return false; // doubles back
    if (above(b, a) && above(b, c)) ++tops;
  }
  return tops == 1;
}

// Ear clipping, O(n^2) to O(n^3): only for small polygons (see
// kEarClippingLimit). False when it finds no ear before the end, which a
// polygon that is not simple or has collinear corners in the way can cause.
bool earClip(const std::vector<P2>& p, std::vector<Triangle2>& out) {
  const std::size_t n = p.size();
  std::vector<std::uint32_t> ring(n);
  for (std::uint32_t i = 0; i < n; ++i)
    ring[i] = i;
  while (ring.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const std::uint32_t a = ring[(i + ring.size() - 1) % ring.size()];
      const std::uint32_t b = ring[i];
      const std::uint32_t c = ring[(i + 1) % ring.size()];
      if (!(cross2(p[a], p[b], p[c]) > 0.0)) continue; // reflex or flat corner
      bool empty = true;
      for (const std::uint32_t k : ring) {
        if (k == a || k == b || k == c) continue;
        if (inTriangle(p[k], p[a], p[b], p[c])) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      ring.erase(ring.begin() + std::ptrdiff_t(i));
      clipped = true;
      break;
    }
    if (!clipped) return false;
  }
  out.push_back({ring[0], ring[1], ring[2]});
  return true;
}

} // namespace

Triangulation triangulatePolygon(std::span<const Vec3> points, std::size_t earClippingLimit) {
  Triangulation result;
  const std::size_t n = points.size();
  if (n < 3 || n > kMaxVertices) {
    result.simple = false;
    return result;
  }
  // NaN, infinite coordinates or ones so large that areas could overflow:
  // nothing below could decide anything. The fan is what callers always got.
  const bool decidable = std::all_of(points.begin(), points.end(), [](const Vec3& q) {
    return isFinite(q) && maxAbsComponent(q) <= kMaxDecidableCoordinate;
  });
  if (!decidable) {
    result.triangles = fan(n);
    result.simple = false;
    return result;
  }
  const std::vector<P2> p = projectCounterclockwise(points);
  const double area2 = twiceArea(p);
  if (n == 3) {
    result.triangles = {{0, 1, 2}};
    result.simple = area2 > 0.0;
    return result;
  }
  if (turnsLeftEverywhere(p)) {
    result.triangles = fan(n);
    result.simple = area2 > 0.0 && windsOnce(p);
    return result;
  }

  // The sweep needs no empty edges: drop each vertex equal to the one before.
  std::vector<P2> kept;
  std::vector<std::uint32_t> original;
  kept.reserve(n);
  original.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!kept.empty() && p[i] == kept.back()) continue;
    kept.push_back(p[i]);
    original.push_back(i);
  }
  while (kept.size() > 1 && kept.back() == kept.front()) {
    kept.pop_back();
    original.pop_back();
  }
  const bool repeats = kept.size() != n;
  if (kept.size() < 3) {
    result.triangles = fan(n);
    result.simple = false;
    return result;
  }
  SweepResult swept = sweepTriangulate(std::move(kept), std::move(original));
  result.simple = area2 > 0.0 && !repeats && swept.simple && swept.certified;
  if (n <= earClippingLimit) {
    std::vector<Triangle2> clipped;
    if (earClip(p, clipped)) {
      // Ear clipping needs no certificate: each ear it cuts off is empty.
      result.triangles = std::move(clipped);
      result.simple = area2 > 0.0 && !repeats && swept.simple;
      return result;
    }
  }
  // Uncertified triangles (a polygon crossing itself) may be more than n - 2
  // and cover anything: the fan is no worse and is what callers always got.
  result.triangles = swept.certified ? std::move(swept.triangles) : fan(n);
  return result;
}

std::vector<std::array<std::uint32_t, 3>> triangulate(std::span<const Vec3> points) {
  return triangulatePolygon(points).triangles;
}

std::string notSimpleWarning(std::size_t count, const std::string& what) {
  const bool one = count == 1;
  return std::to_string(count) + " " + what +
         (one ? " is not a simple polygon" : "s are not simple polygons") +
         " (edges cross or touch, or a vertex repeats): " + (one ? "its" : "their") +
         " triangles are a best effort";
}

} // namespace prism
