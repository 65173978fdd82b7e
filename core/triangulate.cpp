#include "core/triangulate.h"

#include <cmath>

namespace prism {

namespace {

struct P2 {
  double u, v;
};

double cross2(const P2& o, const P2& a, const P2& b) {
  return (a.u - o.u) * (b.v - o.v) - (a.v - o.v) * (b.u - o.u);
}

// Whether p lies inside or on triangle abc (counterclockwise).
bool inTriangle(const P2& p, const P2& a, const P2& b, const P2& c) {
  return cross2(a, b, p) >= 0.0 && cross2(b, c, p) >= 0.0 && cross2(c, a, p) >= 0.0;
}

} // namespace

std::vector<std::array<std::uint32_t, 3>> triangulate(std::span<const Vec3> points) {
  std::vector<std::array<std::uint32_t, 3>> out;
  const std::size_t n = points.size();
  if (n < 3) return out;
  if (n == 3) return {{0, 1, 2}};

  // Newell's normal gives the plane and the winding, for concave faces too.
  Vec3 normal(0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = points[i];
    const Vec3& b = points[(i + 1) % n];
    normal += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  const Vec3 an = glm::abs(normal);
  const int drop = an.x >= an.y && an.x >= an.z ? 0 : (an.y >= an.z ? 1 : 2);
  // Projected so that the polygon runs counterclockwise in (u, v).
  const bool flip = normal[drop] < 0.0;
  std::vector<P2> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& q = points[i];
    P2 r = drop == 0 ? P2{q.y, q.z} : drop == 1 ? P2{q.z, q.x} : P2{q.x, q.y};
    if (flip) std::swap(r.u, r.v);
    p[i] = r;
  }

  bool convex = true;
  for (std::size_t i = 0; i < n && convex; ++i) {
    convex = cross2(p[i], p[(i + 1) % n], p[(i + 2) % n]) >= 0.0;
  }
  if (convex || n > kMaxEarClipping) {
    for (std::uint32_t i = 1; i + 1 < n; ++i)
      out.push_back({0, i, i + 1});
    return out;
  }

  // Ear clipping: O(n^2), for the few concave faces a mesh may have.
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
    // No ear: the polygon is not simple. Fan the rest rather than loop.
    if (!clipped) break;
  }
  for (std::uint32_t i = 1; i + 1 < ring.size(); ++i)
    out.push_back({ring[0], ring[i], ring[i + 1]});
  return out;
}

} // namespace prism
