// Splitting polygons into triangles (core/shapes/triangulate.h), checked against
// truth computed here independently of it: the shoelace area, an even-odd
// crossing test for each triangle's centroid, the edges any tiling must have
// and a brute-force test of simplicity.
#include "core/shapes/triangulate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

namespace prism {
namespace {

using Triangle = std::array<std::uint32_t, 3>;
// Polygons are built in the xy plane; the tests that need 3D embed them.
using Polygon = std::vector<Vec3>;

constexpr double kPi = std::numbers::pi;

// Twice the signed area of triangle a b c in the xy plane.
double cross(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Twice the signed area of a polygon in the xy plane (shoelace formula).
double shoelace(const Polygon& p) {
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    sum += cross(p[0], p[i], p[(i + 1) % p.size()]);
  return sum;
}

// Whether (x, y) is inside the polygon, by the even-odd crossing number of a
// ray going right.
bool inside(const Polygon& p, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    if ((p[i].y > y) == (p[j].y > y)) continue;
    const double crossing = p[j].x + (y - p[j].y) * (p[i].x - p[j].x) / (p[i].y - p[j].y);
    if (x < crossing) in = !in;
  }
  return in;
}

// Whether the closed segments ab and cd share a point (exact for the small
// integer coordinates the brute-force tests use).
bool segmentsTouch(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  auto sign = [](double v) { return (v > 0.0) - (v < 0.0); };
  auto onSegment = [](const Vec3& s, const Vec3& t, const Vec3& q) {
    return std::min(s.x, t.x) <= q.x && q.x <= std::max(s.x, t.x) && std::min(s.y, t.y) <= q.y &&
           q.y <= std::max(s.y, t.y);
  };
  const int d1 = sign(cross(c, d, a)), d2 = sign(cross(c, d, b));
  const int d3 = sign(cross(a, b, c)), d4 = sign(cross(a, b, d));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && onSegment(c, d, a)) || (d2 == 0 && onSegment(c, d, b)) ||
         (d3 == 0 && onSegment(a, b, c)) || (d4 == 0 && onSegment(a, b, d));
}

// Simple by definition, pair by pair: no vertex repeated, edges that do not
// share a vertex never touch, edges that do meet only there (collinear ones
// must continue, not double back).
bool bruteForceSimple(const Polygon& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (p[i] == p[j]) return false;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec3 &a = p[i], &b = p[(i + 1) % n], &c = p[j], &d = p[(j + 1) % n];
      if (j == i + 1 || (i == 0 && j == n - 1)) {
        // Shared vertex s, other ends x and y.
        const bool sharedAtB = j == i + 1;
        const Vec3& s = sharedAtB ? b : a;
        const Vec3& x = sharedAtB ? a : b;
        const Vec3& y = sharedAtB ? d : c;
        const double along = (x.x - s.x) * (y.x - s.x) + (x.y - s.y) * (y.y - s.y);
        if (cross(x, s, y) == 0.0 && along > 0.0) return false;
      } else if (segmentsTouch(a, b, c, d)) {
        return false;
      }
    }
  }
  return shoelace(p) != 0.0;
}

// Every check a triangulation of a simple polygon must pass: n - 2 triangles
// of its own indices, each turning the polygon's way, areas summing to its
// area, each (non-degenerate) one's centroid inside it, and every polygon edge
// used once in its own direction and every other edge once each way (which,
// with no triangle turning backwards, means the triangles cover the polygon
// exactly once). Centroids are tested for every `centroidStride`-th triangle:
// the crossing test costs O(n) each.
void expectTiles(const Polygon& poly, const Triangulation& result, std::size_t centroidStride = 1) {
  const std::size_t n = poly.size();
  EXPECT_TRUE(result.simple);
  ASSERT_EQ(result.triangles.size(), n - 2);
  const double area = shoelace(poly);
  const double winding = area > 0.0 ? 1.0 : -1.0;
  const double tolerance = 1e-12 * std::abs(area);
  double sum = 0.0;
  std::size_t backwards = 0, outside = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * result.triangles.size());
  for (std::size_t k = 0; k < result.triangles.size(); ++k) {
    const Triangle& t = result.triangles[k];
    for (const std::uint32_t corner : t)
      ASSERT_LT(corner, n);
    const Vec3 &a = poly[t[0]], &b = poly[t[1]], &c = poly[t[2]];
    const double twice = cross(a, b, c);
    sum += twice;
    if (winding * twice < -tolerance) ++backwards;
    if (k % centroidStride == 0 && std::abs(twice) > tolerance) {
      const Vec3 centroid = (a + b + c) / 3.0;
      if (!inside(poly, centroid.x, centroid.y)) ++outside;
    }
    for (int e = 0; e < 3; ++e)
      edges.emplace_back(t[std::size_t(e)], t[std::size_t((e + 1) % 3)]);
  }
  EXPECT_EQ(backwards, 0u);
  EXPECT_EQ(outside, 0u);
  EXPECT_NEAR(sum, area, 1e-9 * std::abs(area));

  std::sort(edges.begin(), edges.end());
  EXPECT_EQ(std::adjacent_find(edges.begin(), edges.end()), edges.end()) << "an edge used twice";
  std::size_t polygonEdges = 0, unpaired = 0;
  for (const auto& [from, to] : edges) {
    const bool onBoundary = to == (from + 1) % n;
    const bool reversed = std::binary_search(edges.begin(), edges.end(), std::pair{to, from});
    if (onBoundary) ++polygonEdges;
    if (onBoundary == reversed) ++unpaired;
  }
  EXPECT_EQ(polygonEdges, n);
  EXPECT_EQ(unpaired, 0u);
}

// What any result must satisfy, even for input that is not a polygon:
// at most n - 2 triangles, only of the polygon's own indices.
void expectWellFormed(const Polygon& poly, const Triangulation& result) {
  EXPECT_LE(result.triangles.size(), poly.size() < 2 ? 0 : poly.size() - 2);
  for (const Triangle& t : result.triangles)
    for (const std::uint32_t corner : t)
      EXPECT_LT(corner, poly.size());
}

Polygon reversed(Polygon p) {
  std::reverse(p.begin(), p.end());
  return p;
}

Polygon regular(std::size_t n, double radius) {
  Polygon p;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * double(i) / double(n);
    p.emplace_back(radius * std::cos(a), radius * std::sin(a), 0.0);
  }
  return p;
}

// 2 * points corners alternating between two radii; `wobble` varies the outer
// ones so that no two tips are alike.
Polygon star(std::size_t points, double outer, double inner, double wobble = 0.0) {
  Polygon p;
  for (std::size_t i = 0; i < 2 * points; ++i) {
    const double a = kPi * double(i) / double(points);
    const double r = i % 2 == 0 ? outer * (1.0 + wobble * std::sin(double(i) * 0.7)) : inner;
    p.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
  }
  return p;
}

// A base [0, 2 teeth - 1] x [0, 1] with `teeth` unit-wide teeth up to `height`:
// every tip at one height, every gap's floor at another, all edges axis-aligned.
Polygon comb(std::size_t teeth, double height) {
  Polygon p{{0.0, 0.0, 0.0}, {double(2 * teeth - 1), 0.0, 0.0}};
  for (std::size_t t = teeth; t-- > 0;) {
    p.emplace_back(double(2 * t + 1), height, 0.0);
    p.emplace_back(double(2 * t), height, 0.0);
    if (t > 0) {
      p.emplace_back(double(2 * t), 1.0, 0.0);
      p.emplace_back(double(2 * t - 1), 1.0, 0.0);
    }
  }
  return p;
}

// A band winding `turns` times around the origin, `samples` corners along
// each of its two sides.
Polygon spiral(double turns, std::size_t samples) {
  Polygon p;
  const double end = 2.0 * kPi * turns;
  for (std::size_t i = 0; i < samples; ++i) { // outer side, outwards
    const double a = end * double(i) / double(samples - 1);
    const double r = 1.0 + a / (2.0 * kPi);
    p.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
  }
  for (std::size_t i = samples; i-- > 0;) { // inner side, back in
    const double a = end * double(i) / double(samples - 1);
    const double r = 0.5 + a / (2.0 * kPi);
    p.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
  }
  return p;
}

// A small deterministic generator (the standard distributions differ between
// library versions).
class Random {
public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint32_t below(std::uint32_t n) {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return std::uint32_t((state_ >> 33) % n);
  }

private:
  std::uint64_t state_;
};

// A polygon through random points of a small grid (so collinear corners,
// equal heights and touching edges are common), untangled by reversing the
// path between properly crossing edges until none cross; what remains may
// still touch or overlap, which the tests want too.
Polygon randomGridPolygon(Random& random, std::size_t n, std::uint32_t grid) {
  Polygon p;
  for (std::size_t i = 0; i < n; ++i)
    p.emplace_back(double(random.below(grid)), double(random.below(grid)), 0.0);
  auto properlyCross = [](const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
  };
  // Each reversal shortens the polygon, so this ends; the bound is a guard.
  for (int pass = 0, changed = 1; changed && pass < 1000; ++pass) {
    changed = 0;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      for (std::size_t j = i + 2; j < n; ++j) {
        if (properlyCross(p[i], p[i + 1], p[j], p[(j + 1) % n])) {
          std::reverse(p.begin() + std::ptrdiff_t(i + 1), p.begin() + std::ptrdiff_t(j + 1));
          changed = 1;
        }
      }
    }
  }
  return p;
}

TEST(Triangulate, TriangleStaysAsItIs) {
  const Polygon tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Triangulation result = triangulatePolygon(tri);
  EXPECT_EQ(result.triangles, (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_TRUE(result.simple);
  // Clockwise as well: the triangle is the polygon's own winding.
  EXPECT_EQ(triangulate(reversed(tri)), (std::vector<Triangle>{{0, 1, 2}}));
}

TEST(Triangulate, FewerThanThreePointsGiveNothing) {
  EXPECT_TRUE(triangulatePolygon({}).triangles.empty());
  const Polygon two{{0, 0, 0}, {1, 0, 0}};
  const Triangulation result = triangulatePolygon(two);
  EXPECT_TRUE(result.triangles.empty());
  EXPECT_FALSE(result.simple);
}

// Convex faces keep exactly the fan they always had, so pictures of existing
// scenes do not change.
TEST(Triangulate, ConvexPolygonIsFannedFromItsFirstVertex) {
  for (const Polygon& poly :
       {regular(4, 1.0), regular(7, 2.0), regular(500, 1.0), reversed(regular(9, 1.0))}) {
    const Triangulation result = triangulatePolygon(poly);
    std::vector<Triangle> expected;
    for (std::uint32_t i = 1; i + 1 < poly.size(); ++i)
      expected.push_back({0, i, i + 1});
    EXPECT_EQ(result.triangles, expected);
    expectTiles(poly, result);
  }
}

// Straight corners (collinear runs along the sides) keep a convex polygon
// convex and simple.
TEST(Triangulate, ConvexPolygonWithCollinearRunsIsSimple) {
  Polygon square;
  for (int i = 0; i < 4; ++i)
    square.emplace_back(double(i), 0.0, 0.0);
  for (int i = 0; i < 4; ++i)
    square.emplace_back(4.0, double(i), 0.0);
  for (int i = 4; i > 0; --i)
    square.emplace_back(double(i), 4.0, 0.0);
  for (int i = 4; i > 0; --i)
    square.emplace_back(0.0, double(i), 0.0);
  const Triangulation result = triangulatePolygon(square);
  std::vector<Triangle> expected;
  for (std::uint32_t i = 1; i + 1 < square.size(); ++i)
    expected.push_back({0, i, i + 1});
  EXPECT_EQ(result.triangles, expected);
  // Some of the fan's triangles are flat (along the first side), which a
  // tiling allows.
  expectTiles(square, result);
}

// Small concave polygons are still ear clipped as before: these are the
// triangles the former code gave this L.
TEST(Triangulate, SmallConcavePolygonKeepsItsEarClipping) {
  const Polygon ell{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  const Triangulation result = triangulatePolygon(ell);
  EXPECT_EQ(result.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {5, 0, 3}, {3, 4, 5}}));
  expectTiles(ell, result);
  // The sweep tiles it too.
  expectTiles(ell, triangulatePolygon(ell, 0));
}

TEST(Triangulate, StarPolygons) {
  for (const std::size_t points : {3u, 5u, 17u, 40u, 200u}) {
    const Polygon poly = star(points, 2.0, 0.7, 0.2);
    SCOPED_TRACE(points);
    expectTiles(poly, triangulatePolygon(poly));
    expectTiles(poly, triangulatePolygon(poly, 0));
    expectTiles(reversed(poly), triangulatePolygon(reversed(poly), 0));
  }
}

// Before the sweep, concave polygons of more than 256 vertices were fanned:
// from a tip of this star, the fan's triangles cover about 70 times its area.
// Now they cover it exactly.
TEST(Triangulate, ConcavePolygonOf300VerticesCoversOnlyItsArea) {
  const Polygon poly = star(150, 1.0, 0.3);
  const Triangulation result = triangulatePolygon(poly);
  double sum = 0.0;
  for (const Triangle& t : result.triangles)
    sum += std::abs(cross(poly[t[0]], poly[t[1]], poly[t[2]]));
  EXPECT_NEAR(sum, shoelace(poly), 1e-9 * shoelace(poly));
  expectTiles(poly, result);
}

// Teeth with every tip level and every gap floor level: many vertices at equal
// height and horizontal edges, a row of merge vertices (the gap floors) met at
// one height.
TEST(Triangulate, CombsWithLevelTeeth) {
  for (const std::size_t teeth : {2u, 5u, 40u, 1000u}) {
    SCOPED_TRACE(teeth);
    const Polygon up = comb(teeth, 3.0);
    expectTiles(up, triangulatePolygon(up, 0), teeth > 100 ? 37 : 1);
    // Upside down, the gaps open downwards: a row of split vertices.
    Polygon down = up;
    for (Vec3& v : down)
      v = Vec3(-v.x, -v.y, 0.0);
    expectTiles(down, triangulatePolygon(down, 0), teeth > 100 ? 37 : 1);
    // On its side, the teeth point left and the sweep meets them edge on.
    Polygon side = up;
    for (Vec3& v : side)
      v = Vec3(-v.y, v.x, 0.0);
    expectTiles(side, triangulatePolygon(side, 0), teeth > 100 ? 37 : 1);
  }
}

// A sawtooth top over a flat bottom, then the same on its side: vertices
// alternate between two heights (or two abscissas).
TEST(Triangulate, Zigzags) {
  for (const std::size_t teeth : {3u, 50u, 999u}) {
    SCOPED_TRACE(teeth);
    Polygon poly{{0.0, 0.0, 0.0}, {double(2 * teeth), 0.0, 0.0}};
    for (std::size_t i = 2 * teeth + 1; i-- > 0;)
      poly.emplace_back(double(i), i % 2 == 0 ? 1.0 : 2.0, 0.0);
    expectTiles(poly, triangulatePolygon(poly, 0), teeth > 100 ? 31 : 1);
    Polygon side = poly;
    for (Vec3& v : side)
      v = Vec3(v.y, -v.x, 0.0);
    expectTiles(side, triangulatePolygon(side, 0), teeth > 100 ? 31 : 1);
  }
}

TEST(Triangulate, Spirals) {
  for (const double turns : {1.5, 4.0}) {
    SCOPED_TRACE(turns);
    const Polygon poly = spiral(turns, 400);
    expectTiles(poly, triangulatePolygon(poly), 7);
    expectTiles(reversed(poly), triangulatePolygon(reversed(poly)), 7);
  }
}

// Rectilinear "histograms" with runs of equal heights: collinear corners on
// horizontal edges and many vertices level with each other. Turned a quarter,
// the runs become vertical.
TEST(Triangulate, CollinearRunsAndHorizontalEdges) {
  Random random(7);
  for (int round = 0; round < 50; ++round) {
    const std::size_t columns = 3 + random.below(60);
    Polygon poly{{0.0, 0.0, 0.0}, {double(columns), 0.0, 0.0}};
    for (std::size_t x = columns; x > 0; --x) {
      const double h = 1.0 + double(random.below(4));
      poly.emplace_back(double(x), h, 0.0);
      poly.emplace_back(double(x - 1), h, 0.0);
    }
    // Drop corners that repeat (two columns of equal height meet there twice).
    poly.erase(std::unique(poly.begin(), poly.end()), poly.end());
    SCOPED_TRACE(round);
    expectTiles(poly, triangulatePolygon(poly, 0));
    Polygon turned = poly;
    for (Vec3& v : turned)
      v = Vec3(-v.y, v.x, 0.0);
    expectTiles(turned, triangulatePolygon(turned, 0));
  }
}

// Random polygons on a small grid, where degenerate configurations are the
// rule: the sweep's verdict must match the brute-force test exactly (every
// computation is exact on small integers), and when simple, it must tile.
TEST(Triangulate, RandomGridPolygonsAgreeWithBruteForce) {
  Random random(2024);
  std::size_t simpleOnes = 0;
  for (int round = 0; round < 3000; ++round) {
    const std::size_t n = 4 + random.below(round < 1500 ? 8 : 30);
    const Polygon poly = randomGridPolygon(random, n, round % 2 == 0 ? 5 : 9);
    const bool simple = bruteForceSimple(poly);
    SCOPED_TRACE(round);
    for (const std::size_t limit : {std::size_t(0), kEarClippingLimit}) {
      const Triangulation result = triangulatePolygon(poly, limit);
      EXPECT_EQ(result.simple, simple);
      expectWellFormed(poly, result);
      if (simple) expectTiles(poly, result);
    }
    simpleOnes += simple;
  }
  // Both kinds are well represented.
  EXPECT_GT(simpleOnes, 500u);
  EXPECT_LT(simpleOnes, 2500u);
}

// The same for polygons of 65 to 200 vertices, which take the sweep without
// being asked to, on a coarse grid (degenerate) and a fine one (general
// position).
TEST(Triangulate, LargerRandomPolygonsAgreeWithBruteForce) {
  Random random(4242);
  std::size_t simpleOnes = 0;
  for (int round = 0; round < 200; ++round) {
    const std::size_t n = 65 + random.below(136);
    const Polygon poly = randomGridPolygon(random, n, round % 2 == 0 ? 40 : 1000000);
    const bool simple = bruteForceSimple(poly);
    SCOPED_TRACE(round);
    const Triangulation result = triangulatePolygon(poly);
    EXPECT_EQ(result.simple, simple);
    expectWellFormed(poly, result);
    if (simple) expectTiles(poly, result);
    simpleOnes += simple;
  }
  EXPECT_GT(simpleOnes, 50u);
}

// The same plane figure in each coordinate plane (the dropped axis), tilted,
// a little non-planar, in both windings: the triangles are the same tiling,
// turning the polygon's own way.
TEST(Triangulate, PolygonsInEveryOrientation) {
  const Polygon flat = star(60, 2.0, 1.0, 0.3);
  for (int axis = 0; axis < 3; ++axis) {
    for (const bool flip : {false, true}) {
      const Polygon plane = flip ? reversed(flat) : flat;
      Polygon solid;
      for (std::size_t i = 0; i < plane.size(); ++i) {
        const Vec3& q = plane[i];
        const double height = 5.0 + 0.2 * q.x - 0.1 * q.y + 1e-3 * std::sin(double(i));
        Vec3 v;
        v[(axis + 1) % 3] = q.x;
        v[(axis + 2) % 3] = q.y;
        v[axis] = height;
        solid.push_back(v);
      }
      SCOPED_TRACE(testing::Message() << "axis " << axis << (flip ? " clockwise" : ""));
      // The triangles index the plane figure too, which the checks use.
      expectTiles(plane, triangulatePolygon(solid));
      expectTiles(plane, triangulatePolygon(solid, 0));
    }
  }
}

// Far beyond what ear clipping could do: a million corners, checked through
// the areas and the edges (which prove the tiling), centroids sampled.
TEST(Triangulate, MillionVertexConcavePolygon) {
  const Polygon poly = star(500000, 1.0, 0.6, 0.3);
  const Triangulation result = triangulatePolygon(poly);
  expectTiles(poly, result, 50000);
}

TEST(Triangulate, SelfIntersectingBowTieIsNotSimple) {
  const Polygon bowTie{{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}};
  const Triangulation result = triangulatePolygon(bowTie);
  EXPECT_FALSE(result.simple);
  expectWellFormed(bowTie, result);
  // Lobes of different sizes: the polygon winds one way after projection, its
  // small lobe the other way.
  const Polygon lopsided{{0, 0, 0}, {3, 3, 0}, {3, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  for (const std::size_t limit : {std::size_t(0), kEarClippingLimit}) {
    const Triangulation r = triangulatePolygon(lopsided, limit);
    EXPECT_FALSE(r.simple);
    expectWellFormed(lopsided, r);
  }
}

TEST(Triangulate, CollinearPointsAreNotSimple) {
  const Polygon line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  EXPECT_FALSE(triangulatePolygon(line).simple);
  expectWellFormed(line, triangulatePolygon(line));
  const Polygon diagonal{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 2, 2}, {5, 5, 5}};
  EXPECT_FALSE(triangulatePolygon(diagonal).simple);
  expectWellFormed(diagonal, triangulatePolygon(diagonal));
  const Polygon degenerateTriangle{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  EXPECT_FALSE(triangulatePolygon(degenerateTriangle).simple);
}

// Non-finite coordinates, even on the axis the projection drops, and ones so
// large that areas could overflow: no verdict is possible, the fan is returned.
TEST(Triangulate, NonFiniteCoordinatesAreNotSimple) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const Vec3& bad : {Vec3(nan, 1, 0), Vec3(1, 1, nan), Vec3(inf, 1, 0), Vec3(1, -inf, 0),
                          Vec3(1e300, 1e300, 0), Vec3(0, 0, -1e200)}) {
    Polygon poly = star(40, 2.0, 1.0);
    poly[17] = bad;
    const Triangulation result = triangulatePolygon(poly);
    EXPECT_FALSE(result.simple);
    EXPECT_EQ(result.triangles.size(), poly.size() - 2);
    expectWellFormed(poly, result);
  }
}

// A repeated corner (an empty edge) or one visited twice (the polygon touches
// itself there) is not simple; an empty edge costs nothing but its triangle.
TEST(Triangulate, RepeatedVerticesAreNotSimple) {
  Polygon repeated = star(40, 2.0, 1.0);
  repeated.insert(repeated.begin() + 11, repeated[10]);
  repeated.push_back(repeated[0]);
  for (const std::size_t limit : {std::size_t(0), kEarClippingLimit}) {
    const Triangulation result = triangulatePolygon(repeated, limit);
    EXPECT_FALSE(result.simple);
    expectWellFormed(repeated, result);
    double sum = 0.0;
    for (const Triangle& t : result.triangles)
      sum += cross(repeated[t[0]], repeated[t[1]], repeated[t[2]]);
    EXPECT_NEAR(sum, shoelace(repeated), 1e-9 * shoelace(repeated));
  }
  // Two squares meeting at a corner, walked as one polygon.
  const Polygon pinched{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0},
                        {2, 2, 0}, {1, 2, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const std::size_t limit : {std::size_t(0), kEarClippingLimit}) {
    const Triangulation result = triangulatePolygon(pinched, limit);
    EXPECT_FALSE(result.simple);
    expectWellFormed(pinched, result);
  }
}

// A corner resting on another edge, and an edge doubling back on itself.
TEST(Triangulate, TouchingEdgesAreNotSimple) {
  const Polygon touching{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {2, 0, 0}, {0, 4, 0}};
  const Polygon spike{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {2, 2, 0}, {3, 3, 0}, {0, 4, 0}};
  for (const Polygon& poly : {touching, spike}) {
    for (const std::size_t limit : {std::size_t(0), kEarClippingLimit}) {
      const Triangulation result = triangulatePolygon(poly, limit);
      EXPECT_FALSE(result.simple);
      expectWellFormed(poly, result);
    }
  }
}

// Every corner turns left but the polygon winds twice: it passes the convex
// test, keeps its fan, and is reported.
TEST(Triangulate, ConvexPolygonWindingTwiceIsNotSimple) {
  Polygon twice = regular(7, 1.0);
  const Polygon again = twice;
  twice.insert(twice.end(), again.begin(), again.end());
  for (std::size_t i = 7; i < 14; ++i)
    twice[i] *= 1.0 + 1e-3; // no repeated corners
  const Triangulation result = triangulatePolygon(twice);
  EXPECT_FALSE(result.simple);
  EXPECT_EQ(result.triangles.size(), twice.size() - 2);
}

// Random points in random order: crossings everywhere, which must neither
// crash, hang nor grow anything beyond O(n).
TEST(Triangulate, LargeRandomTangleReturnsABestEffort) {
  Random random(99);
  Polygon tangle;
  for (int i = 0; i < 100000; ++i)
    tangle.emplace_back(double(random.below(100000)), double(random.below(100000)), 0.0);
  const Triangulation result = triangulatePolygon(tangle);
  EXPECT_FALSE(result.simple);
  expectWellFormed(tangle, result);
}

} // namespace
} // namespace prism
