// The edge index of polygons with many vertices (core/shapes/polygon_edges.h): the
// same answer as testing every edge, on random rays over star polygons,
// self-intersecting polygons, combs and grid polygons whose vertices sit on
// the rays' rows, in every orientation; and a 10^6-vertex polygon, whose
// full test took O(n) per ray, against the disc it approximates.
#include "core/accel/accel.h"
#include "core/scene/scene.h"
#include "core/scene/scene_builder.h"
#include "core/shapes/shape_kinds.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <random>

namespace prism {
namespace {

constexpr double kPi = std::numbers::pi;

// A polygon in the plane z = 0 turned into 3D: the plane's axes (x, y) go to
// (x, y, 0), (y, 0, x) or (0, x, y), so each axis is the dropped one once.
std::vector<Vec3> placed(const std::vector<glm::dvec2>& points, int orientation) {
  std::vector<Vec3> out;
  for (const glm::dvec2& p : points) {
    if (orientation == 0) out.emplace_back(p.x, p.y, 0.0);
    if (orientation == 1) out.emplace_back(p.y, 0.0, p.x);
    if (orientation == 2) out.emplace_back(0.0, p.x, p.y);
  }
  return out;
}

Vec3 normalOf(int orientation) {
  return orientation == 0 ? Vec3(0, 0, 1) : orientation == 1 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
}

// Compares the indexed test with the full one on `rays` rays aimed at points
// of the plane drawn from `target`; returns how many hit.
template <class Target>
int expectSameAsEveryEdge(const std::vector<glm::dvec2>& points, int orientation, int rays,
                          Target target, std::mt19937& rng) {
  Scene scene;
  SceneBuilder build(scene);
  const std::vector<Vec3> vertices = placed(points, orientation);
  const PrimitiveRef ref = build.polygon(vertices, build.material(Material{}), Origin{});
  const Polygon& p = scene.shapes<Polygon>()[ref.index];
  EXPECT_NE(p.edgeIndex, Polygon::kNoEdgeIndex);
  const PolygonEdgeIndex& index = scene.polygonEdgeIndices.at(p.edgeIndex);
  const Vec3 n = normalOf(orientation);
  std::uniform_real_distribution<double> tilt(-0.3, 0.3);
  int hits = 0;
  for (int i = 0; i < rays; ++i) {
    const Vec3 aim = placed({target(rng)}, orientation)[0];
    const Vec3 dir = glm::normalize(-n + tilt(rng) * Vec3(n.z, n.x, n.y));
    const Ray ray{aim - 5.0 * dir, dir};
    double tIndexed = -1.0, tFull = -1.0;
    const bool indexed =
        intersect(p, scene.polygonVertices.data(), &index, ray, Interval{}, tIndexed);
    const bool full = intersect(p, scene.polygonVertices.data(), ray, Interval{}, tFull);
    EXPECT_EQ(indexed, full) << "ray " << i << " at " << aim.x << " " << aim.y << " " << aim.z;
    if (indexed && full) {
      EXPECT_EQ(tIndexed, tFull);
    }
    hits += full ? 1 : 0;
  }
  return hits;
}

// Star-shaped: n vertices at random radii around the origin (concave).
std::vector<glm::dvec2> star(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> radius(0.3, 1.0);
  std::vector<glm::dvec2> points;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    const double r = radius(rng);
    points.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return points;
}

glm::dvec2 inSquare(std::mt19937& rng, double half = 1.1) {
  std::uniform_real_distribution<double> u(-half, half);
  return {u(rng), u(rng)};
}

TEST(PolygonEdges, StarPolygonsInEveryOrientationMatchTheFullTest) {
  std::mt19937 rng(7);
  for (int orientation = 0; orientation < 3; ++orientation) {
    for (const int n : {64, 65, 100, 1000, 5000}) {
      const int hits = expectSameAsEveryEdge(
          star(n, rng), orientation, 2000, [](auto& r) { return inSquare(r); }, rng);
      EXPECT_GT(hits, 300) << n; // the polygon covers about a third of the square
      EXPECT_LT(hits, 1800) << n;
    }
  }
}

// Self-intersecting polygons (random points): every edge crosses others, so
// the index scans its nodes edge by edge and the even-odd answer is kept.
TEST(PolygonEdges, SelfIntersectingPolygonsMatchTheFullTest) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<glm::dvec2> points;
    for (int i = 0; i < 64 + trial * 10; ++i)
      points.push_back(inSquare(rng, 1.0));
    expectSameAsEveryEdge(
        points, trial % 3, 500, [](auto& r) { return inSquare(r); }, rng);
  }
}

// A comb: `teeth` thin teeth side by side, so one horizontal line crosses
// 2 * teeth edges; nodes that large are searched by bisection.
std::vector<glm::dvec2> comb(int teeth) {
  std::vector<glm::dvec2> points{{0.0, 0.0}, {double(teeth), 0.0}};
  for (int i = teeth - 1; i >= 0; --i) {
    // Slanted tops, none level with another: the two sides of a tooth end at
    // different heights, so nodes hold odd numbers of edges too.
    points.emplace_back(i + 0.8, 10.0 + 0.001 * i);
    points.emplace_back(i + 0.2, 10.0005 + 0.001 * i);
    points.emplace_back(i + 0.2, 1.0);
    if (i > 0) points.emplace_back(i - 0.2, 1.0);
  }
  return points;
}

// A sawtooth: one straight side spanning the whole height (listed at the
// tree's root) and `teeth` zigzags on the other.
std::vector<glm::dvec2> sawtooth(int teeth) {
  std::vector<glm::dvec2> points{{0.0, 0.0}, {1.0, 0.0}, {1.0, double(teeth)}};
  for (int i = teeth - 1; i >= 0; --i) {
    points.emplace_back(0.5, i + 1.0);
    points.emplace_back(0.0, i + 0.5);
  }
  return points;
}

TEST(PolygonEdges, CombsSearchedByBisectionMatchTheFullTest) {
  std::mt19937 rng(3);
  for (const int teeth : {20, 500, 5000}) {
    std::uniform_real_distribution<double> u(-0.5, teeth + 0.5), v(-0.5, 11.0);
    const int hits = expectSameAsEveryEdge(
        comb(teeth), teeth % 3, 4000, [&](auto& r) { return glm::dvec2(u(r), v(r)); }, rng);
    EXPECT_GT(hits, 1000) << teeth;
    // At least kIndexedPolygonVertices vertices, and a power of two of slabs
    // (2 * saw), where the side spanning them all is listed at the root.
    const int saw = int(std::bit_ceil(unsigned(teeth + 40)));
    std::uniform_real_distribution<double> x(-0.2, 1.2), y(-0.5, saw + 0.5);
    const int sawHits = expectSameAsEveryEdge(
        sawtooth(saw), teeth % 3, 4000, [&](auto& r) { return glm::dvec2(x(r), y(r)); }, rng);
    EXPECT_GT(sawHits, 1000) << teeth;
  }
}

// Vertices on a grid and rays aimed exactly at the grid's rows and columns:
// the half-open rule (a vertex counts as above when its v is greater) decides,
// and the index must decide exactly as the full test does.
TEST(PolygonEdges, RaysThroughVertexRowsFollowTheHalfOpenRuleExactly) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> cell(-8, 8);
  for (int trial = 0; trial < 10; ++trial) {
    // A staircase: steps up then down, all vertices on integer coordinates.
    std::vector<glm::dvec2> points;
    const int steps = 40 + trial;
    for (int i = 0; i < steps; ++i) {
      points.emplace_back(i, (i * 7) % 9);
      points.emplace_back(i + 1, (i * 7) % 9);
    }
    points.emplace_back(steps, -10.0);
    points.emplace_back(0.0, -10.0);
    std::uniform_int_distribution<int> column(-1, steps + 1), row(-11, 10);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    expectSameAsEveryEdge(
        points, trial % 3, 3000,
        [&](auto& r) {
          // Exactly on a row, a column, or both, or anywhere.
          const int kind = cell(r) & 3;
          const double x = column(r) + (kind & 1 ? 0.0 : jitter(r));
          const double y = row(r) + (kind & 2 ? 0.0 : jitter(r));
          return glm::dvec2(x, y);
        },
        rng);
  }
}

// A gear as the SPD gears scene draws one: `teeth` teeth of four vertices
// each between radii 0.8 and 1, around `centre`.
std::vector<glm::dvec2> gear(int teeth, glm::dvec2 centre = {0.0, 0.0}) {
  std::vector<glm::dvec2> points;
  for (int i = 0; i < teeth; ++i)
    for (const auto& [step, radius] : {std::pair{0.0, 0.8}, {0.1, 1.0}, {0.4, 1.0}, {0.5, 0.8}}) {
      const double a = 2.0 * kPi * (i + step) / teeth;
      points.push_back(centre + radius * glm::dvec2(std::cos(a), std::sin(a)));
    }
  return points;
}

// The grid in front of the tree (polygon_edges.h) answers where no edge is
// near, and there as the full test does: a ray straight down the normal
// meets the plane exactly at the point asked, so the full test of that ray
// is the independent check. Points: random over the box, on the cells'
// borders, and at distances from 1e-15 to 1e-2 of the edges on both sides.
TEST(PolygonEdges, TheGridAnswersAwayFromTheEdgesAsTheFullTestDoes) {
  std::mt19937 rng(13);
  for (const glm::dvec2 centre : {glm::dvec2(0.0, 0.0), glm::dvec2(1e6, -3e5)}) {
    const std::vector<glm::dvec2> points = gear(36, centre);
    Scene scene;
    SceneBuilder build(scene);
    const PrimitiveRef ref = build.polygon(placed(points, 0), build.material(Material{}), Origin{});
    const Polygon& p = scene.shapes<Polygon>()[ref.index];
    const PolygonEdgeIndex& index = scene.polygonEdgeIndices.at(p.edgeIndex);
    int known = 0, asked = 0;
    const auto check = [&](glm::dvec2 q) {
      ++asked;
      const PolygonEdgeIndex::GridAnswer answer = index.gridAnswer(q.x, q.y);
      if (answer == PolygonEdgeIndex::kNearEdge) return;
      ++known;
      double t = 0.0;
      const bool full = intersect(p, scene.polygonVertices.data(),
                                  Ray{Vec3(q.x, q.y, 2.0), Vec3(0, 0, -1)}, Interval{}, t);
      EXPECT_EQ(answer == PolygonEdgeIndex::kInside, full) << q.x << " " << q.y;
    };
    std::uniform_real_distribution<double> unit(-1.05, 1.05), along(0.0, 1.0);
    for (int i = 0; i < 20000; ++i)
      check(centre + glm::dvec2(unit(rng), unit(rng)));
    // The hand-known answers: the centre is inside, the box's corners outside.
    EXPECT_EQ(index.gridAnswer(centre.x, centre.y), PolygonEdgeIndex::kInside);
    EXPECT_EQ(index.gridAnswer(centre.x - 0.99, centre.y - 0.99), PolygonEdgeIndex::kOutside);
    const int random = known;
    EXPECT_GT(random, 20000 / 2) << "the grid should know most of a gear's box";
    // Next to every edge, on both sides, and on the lines of a fine lattice
    // (which holds every cell border of a grid that divides the box evenly).
    for (std::size_t e = 0; e < points.size(); ++e) {
      const glm::dvec2 a = points[e], b = points[(e + 1) % points.size()];
      const glm::dvec2 normal = glm::normalize(glm::dvec2(b.y - a.y, a.x - b.x));
      for (double d = 1e-15; d < 2e-2; d *= 3.0)
        for (const double side : {-1.0, 1.0})
          check(a + along(rng) * (b - a) + side * d * normal);
      check(a);
    }
    for (int i = 0; i <= 512; ++i)
      for (int j = 0; j <= 64; ++j)
        check(centre + glm::dvec2(-1.0 + i / 256.0, -1.0 + j / 32.0));
    EXPECT_GT(known, random);
    EXPECT_LT(known, asked);
  }
}

// A polygon of many long edges crossing one another (random points) would
// have a grid nearly all near an edge, made slowly: it goes without one, and
// the tree answers as the full test does.
TEST(PolygonEdges, APolygonOfCrossingEdgesGoesWithoutAGrid) {
  std::mt19937 rng(17);
  std::vector<glm::dvec2> points;
  for (int i = 0; i < 20000; ++i)
    points.push_back(inSquare(rng, 1.0));
  Scene scene;
  SceneBuilder build(scene);
  build.polygon(placed(points, 0), build.material(Material{}), Origin{});
  const PolygonEdgeIndex& index = scene.polygonEdgeIndices.at(0);
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec2 q = inSquare(rng, 1.0);
    EXPECT_EQ(index.gridAnswer(q.x, q.y), PolygonEdgeIndex::kNearEdge);
  }
  expectSameAsEveryEdge(
      points, 0, 200, [](auto& r) { return inSquare(r); }, rng);
}

// A regular polygon of 10^6 vertices approximates the disc of radius 1: rays
// that meet the plane clearly inside the inscribed circle hit it, rays
// clearly outside the circumscribed one miss, through every BVH and the
// brute force (which tests the polygon through its index too).
TEST(PolygonEdges, AMillionVertexPolygonIsTheDiscItApproximates) {
  const int n = 1000000;
  std::vector<Vec3> vertices;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    vertices.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  Scene scene;
  SceneBuilder build(scene);
  build.polygon(vertices, build.material(Material{}), Origin{});
  ASSERT_EQ(scene.polygonEdgeIndices.size(), 1u);
  EXPECT_LT(scene.polygonEdgeIndices[0].memoryBytes(), std::size_t(n) * 64);
  const double inscribed = std::cos(kPi / n);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::None}) {
    const auto accel = makeAccel(scene, kind);
    int tested = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec3 aim(u(rng), u(rng), 0.0);
      const double r = glm::length(aim);
      if (std::abs(r - 1.0) < 1e-9) continue; // within round-off of the border
      ++tested;
      Hit hit;
      const bool found =
          accel->closestHit({aim + Vec3(0, 0, 3), Vec3(0, 0, -1)}, Interval{}, nullptr, hit);
      EXPECT_EQ(found, r < inscribed) << "at radius " << r;
    }
    EXPECT_GT(tested, 19000);
  }
}

} // namespace
} // namespace prism
