// Ray-primitive intersection, polygons, transforms, the camera and the group
// hierarchy. Every expected value is derived by hand or by closed-form math
// written out here, independently of the code under test.
#include "core/accel/accel.h"
#include "core/accel/group_bvh.h"
#include "core/math/transform.h"
#include "core/scene/camera.h"
#include "core/shapes/shape_kinds.h"
#include "tests/scene_builder.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace prism {
namespace {

using test::addEllipsoid;
using test::addGroup;
using test::addMaterial;
using test::addPolygon;
using test::addSphere;
using test::expectVecNear;

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

double deg(double degrees) { return degrees * kPi / 180.0; }

Ray makeRay(const Vec3& origin, const Vec3& dir) { return {origin, glm::normalize(dir)}; }

// Angle between two vectors, accurate also for tiny angles.
double angleBetween(const Vec3& a, const Vec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// ---------------------------------------------------------------------------
// Spheres

Sphere unitSphereAt(const Vec3& c, double r = 1.0) {
  Sphere s;
  s.center = c;
  s.radius = r;
  return s;
}

// The projection axis of the ray-frame tests: the largest component in
// size, the first of equals.
TEST(LargestAbsAxis, LargestInSizeFirstOfEquals) {
  EXPECT_EQ(largestAbsAxis(Vec3(-3, 2, 1)), 0);
  EXPECT_EQ(largestAbsAxis(Vec3(0, -2, 1)), 1);
  EXPECT_EQ(largestAbsAxis(Vec3(0.5, 1, -4)), 2);
  EXPECT_EQ(largestAbsAxis(Vec3(1, -1, 1)), 0);
  EXPECT_EQ(largestAbsAxis(Vec3(0, 1, -1)), 1);
  EXPECT_EQ(largestAbsAxis(Vec3(0, 0, 0)), 0);
  EXPECT_EQ(largestAbsAxis(Vec3(2, 1, -2)), 0);
}

TEST(Sphere, HitFromOutsideGivesNearRoot) {
  const Sphere s = unitSphereAt(Vec3(1, 2, 3), 2.0);
  double t = -1;
  // From 10 units along +x of the centre toward it: enters at distance 10 - 2.
  ASSERT_TRUE(intersect(s, makeRay(Vec3(11, 2, 3), Vec3(-1, 0, 0)), Interval{}, t));
  EXPECT_DOUBLE_EQ(t, 8.0);
  // An off-centre ray: the line passes 1.2 from the centre, so the chord half
  // length is sqrt(4 - 1.44) = 1.6 and the entry is at 10 - 1.6.
  ASSERT_TRUE(intersect(s, makeRay(Vec3(1, 3.2, -7), Vec3(0, 0, 1)), Interval{}, t));
  EXPECT_NEAR(t, 10.0 - 1.6, 1e-12);
}

TEST(Sphere, HitFromInsideGivesFarRoot) {
  const Sphere s = unitSphereAt(Vec3(0.0));
  double t = -1;
  ASSERT_TRUE(intersect(s, makeRay(Vec3(0.0), Vec3(0, 0, 1)), Interval{}, t));
  EXPECT_DOUBLE_EQ(t, 1.0);
  ASSERT_TRUE(intersect(s, makeRay(Vec3(0.5, 0, 0), Vec3(1, 0, 0)), Interval{}, t));
  EXPECT_DOUBLE_EQ(t, 0.5);
  ASSERT_TRUE(intersect(s, makeRay(Vec3(0.5, 0, 0), Vec3(-1, 0, 0)), Interval{}, t));
  EXPECT_DOUBLE_EQ(t, 1.5);
  // Oblique from an inside point: |(0.5,0,0) + t d| = 1 with d = (0,1,0): t = sqrt(0.75).
  ASSERT_TRUE(intersect(s, makeRay(Vec3(0.5, 0, 0), Vec3(0, 1, 0)), Interval{}, t));
  EXPECT_NEAR(t, std::sqrt(0.75), 1e-15);
}

TEST(Sphere, TangentAndNearTangentRays) {
  const Sphere s = unitSphereAt(Vec3(0.0));
  double t = -1;
  // Exactly tangent: the line touches the sphere at (0, 1, 0), five units ahead.
  ASSERT_TRUE(intersect(s, makeRay(Vec3(-5, 1, 0), Vec3(1, 0, 0)), Interval{}, t));
  EXPECT_NEAR(t, 5.0, 1e-12);
  // Just inside the tangent line: two roots 5 -/+ sqrt(1 - y^2).
  const double y = 1.0 - 1e-8;
  ASSERT_TRUE(intersect(s, makeRay(Vec3(-5, y, 0), Vec3(1, 0, 0)), Interval{}, t));
  EXPECT_NEAR(t, 5.0 - std::sqrt(1.0 - y * y), 1e-12);
  // Just outside: miss.
  EXPECT_FALSE(intersect(s, makeRay(Vec3(-5, 1.0 + 1e-8, 0), Vec3(1, 0, 0)), Interval{}, t));
}

TEST(Sphere, BehindTheRayMisses) {
  const Sphere s = unitSphereAt(Vec3(0.0));
  double t = -1;
  EXPECT_FALSE(intersect(s, makeRay(Vec3(5, 0, 0), Vec3(1, 0, 0)), Interval{}, t));
  EXPECT_FALSE(intersect(s, makeRay(Vec3(3, 3, 3), Vec3(1, 1, 1)), Interval{}, t));
  // A ray pointing away that starts right next to the surface.
  EXPECT_FALSE(intersect(s, makeRay(Vec3(1.0 + 1e-9, 0, 0), Vec3(1, 0, 0)), Interval{}, t));
}

TEST(Sphere, RangeLimitsAreOpenAndRespected) {
  const Sphere s = unitSphereAt(Vec3(0.0));
  const Ray r = makeRay(Vec3(-5, 0, 0), Vec3(1, 0, 0)); // roots at t = 4 and t = 6
  double t = -1;
  ASSERT_TRUE(intersect(s, r, Interval{0.0, 4.5}, t));
  EXPECT_DOUBLE_EQ(t, 4.0);
  ASSERT_TRUE(intersect(s, r, Interval{4.5, kInf}, t));
  EXPECT_DOUBLE_EQ(t, 6.0);
  EXPECT_FALSE(intersect(s, r, Interval{0.0, 3.9}, t));
  EXPECT_FALSE(intersect(s, r, Interval{6.1, kInf}, t));
  EXPECT_FALSE(intersect(s, r, Interval{4.1, 5.9}, t));
  // The interval is open: neither root is inside (4, 6).
  EXPECT_FALSE(intersect(s, r, Interval{4.0, 6.0}, t));
  ASSERT_TRUE(intersect(s, r, Interval{4.0, 6.5}, t));
  EXPECT_DOUBLE_EQ(t, 6.0);
}

// A ray aimed at a chosen point P of the sphere from `distance` away along -dir:
// the entry is at t = distance exactly (the segment reaches P while outside).
void checkFarHit(const Vec3& center, double radius, const Vec3& normalAtP, const Vec3& dirIn,
                 double distance) {
  const Vec3 n = glm::normalize(normalAtP);
  const Vec3 d = glm::normalize(dirIn);
  ASSERT_LT(glm::dot(n, d), -0.1) << "test setup: the ray must enter at P";
  const Vec3 p = center + radius * n;
  const Ray ray{p - distance * d, d};
  const Sphere s = unitSphereAt(center, radius);
  double t = -1;
  ASSERT_TRUE(intersect(s, ray, Interval{}, t));
  // Round-off in the origin alone is ~distance * 1e-16; allow 1e-5 of the radius.
  EXPECT_NEAR(t, distance, 1e-5 * radius);
  EXPECT_NEAR(glm::length(ray.at(t) - center), radius, 1e-5 * radius);
  expectVecNear(ray.at(t), p, 1e-5 * radius);
}

TEST(Sphere, FarOriginKeepsPrecision) {
  // Radius 1 seen from 1e6 away: a naive b^2 - ac loses ~1e-4 here.
  checkFarHit(Vec3(0.0), 1.0, Vec3(-0.3, 0.5, -0.8), Vec3(0.4, -0.2, 1.0), 1e6);
  checkFarHit(Vec3(3.0, -2.0, 7.0), 1.0, Vec3(1, 1, 1), Vec3(-1, -2, -0.5), 1e6);
}

TEST(Sphere, TinySphereFromFarAway) {
  // Radius 1e-4 seen from 1e4: r^2 = 1e-8 is below the ulp of |f|^2 = 1e8.
  checkFarHit(Vec3(0.0), 1e-4, Vec3(0.2, -0.7, 0.1), Vec3(-0.1, 1.0, -0.2), 1e4);
  checkFarHit(Vec3(5.0, 1.0, -2.0), 1e-4, Vec3(0, 0, 1), Vec3(0, 0, -1), 1e4);
  // Lines passing 0.99 and 1.01 radii from the centre hit and miss.
  const Sphere s = unitSphereAt(Vec3(0.0), 1e-4);
  double t = -1;
  EXPECT_TRUE(intersect(s, makeRay(Vec3(-1e4, 0.99e-4, 0), Vec3(1, 0, 0)), Interval{}, t));
  EXPECT_NEAR(t, 1e4 - std::sqrt(1e-8 - 0.99e-4 * 0.99e-4), 1e-9);
  EXPECT_FALSE(intersect(s, makeRay(Vec3(-1e4, 1.01e-4, 0), Vec3(1, 0, 0)), Interval{}, t));
}

TEST(Sphere, NormalAndBounds) {
  const Sphere s = unitSphereAt(Vec3(1, 2, 3), 2.0);
  expectVecNear(normalAt(s, Vec3(1, 2, 5)), Vec3(0, 0, 1), 1e-15);
  expectVecNear(normalAt(s, Vec3(1, 2 - std::sqrt(2.0), 3 + std::sqrt(2.0))),
                Vec3(0, -1, 1) / std::sqrt(2.0), 1e-15);
  const Aabb b = boundsOf(s);
  expectVecNear(b.lo, Vec3(-1, 0, 1), 0.0);
  expectVecNear(b.hi, Vec3(3, 4, 5), 0.0);
}

// ---------------------------------------------------------------------------
// Ellipsoids

Mat3 diag(double a, double b, double c) {
  return Mat3(Vec3(a, 0, 0), Vec3(0, b, 0), Vec3(0, 0, c)); // glm: columns
}

Mat3 rotationZ(double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  return Mat3(Vec3(c, s, 0), Vec3(-s, c, 0), Vec3(0, 0, 1));
}

// Entry point of a ray into the axis-aligned ellipsoid with semi-axes `axes`
// centred at the origin: the textbook quadratic in t.
bool analyticEllipsoid(const Vec3& axes, const Vec3& o, const Vec3& d, double& t) {
  const Vec3 os = o / axes, ds = d / axes;
  const double a = glm::dot(ds, ds), b = 2.0 * glm::dot(os, ds), c = glm::dot(os, os) - 1.0;
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return false;
  const double t0 = (-b - std::sqrt(disc)) / (2 * a), t1 = (-b + std::sqrt(disc)) / (2 * a);
  t = t0 > 0 ? t0 : t1;
  return t > 0;
}

TEST(Ellipsoid, ScaledSphereAxisHits) {
  const Ellipsoid e = makeEllipsoid(diag(2, 1, 1), Vec3(0.0));
  double t = -1;
  ASSERT_TRUE(intersect(e, makeRay(Vec3(-5, 0, 0), Vec3(1, 0, 0)), Interval{}, t));
  EXPECT_NEAR(t, 3.0, 1e-12); // enters at x = -2
  expectVecNear(normalAt(e, Vec3(-2, 0, 0)), Vec3(-1, 0, 0), 1e-12);
  ASSERT_TRUE(intersect(e, makeRay(Vec3(0, -5, 0), Vec3(0, 1, 0)), Interval{}, t));
  EXPECT_NEAR(t, 4.0, 1e-12); // enters at y = -1
  ASSERT_TRUE(intersect(e, makeRay(Vec3(0, 0, 0), Vec3(1, 0, 0)), Interval{}, t));
  EXPECT_NEAR(t, 2.0, 1e-12); // from inside: far side
  // Passing at y = 1.01 misses although |y| < 2 would hit an unscaled radius-2 sphere.
  EXPECT_FALSE(intersect(e, makeRay(Vec3(-5, 1.01, 0), Vec3(1, 0, 0)), Interval{}, t));
  EXPECT_TRUE(intersect(e, makeRay(Vec3(1.9, -5, 0), Vec3(0, 1, 0)), Interval{}, t));
}

TEST(Ellipsoid, ScaledSphereGenericHitAndAnalyticNormal) {
  const Vec3 axes(2, 1, 1), center(1, -1, 0.5);
  const Ellipsoid e = makeEllipsoid(diag(axes.x, axes.y, axes.z), center);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 200; ++i) {
    const Vec3 o = center + Vec3(4 * u(rng), 4 * u(rng), 4 * u(rng));
    const Vec3 d = glm::normalize(center + Vec3(u(rng), u(rng), u(rng)) * 1.5 - o);
    double want = 0, got = 0;
    const bool expected = analyticEllipsoid(axes, o - center, d, want);
    const bool found = intersect(e, Ray{o, d}, Interval{}, got);
    ASSERT_EQ(found, expected) << i;
    if (!found) continue;
    ++hits;
    EXPECT_NEAR(got, want, 1e-9);
    const Vec3 p = o + got * d - center;
    const Vec3 analytic = glm::normalize(
        Vec3(p.x / (axes.x * axes.x), p.y / (axes.y * axes.y), p.z / (axes.z * axes.z)));
    expectVecNear(normalAt(e, o + got * d), analytic, 1e-9);
  }
  EXPECT_GT(hits, 50);
}

TEST(Ellipsoid, RotatedEllipsoid) {
  // Semi-axes (3, 1, 0.5) turned 30 degrees about z, centred at (2, 0, -1).
  const Vec3 axes(3, 1, 0.5), center(2, 0, -1);
  const double angle = deg(30);
  const Mat3 r = rotationZ(angle);
  const Ellipsoid e = makeEllipsoid(r * diag(axes.x, axes.y, axes.z), center);
  // Along the long axis from outside: enters 3 from the centre.
  const Vec3 longAxis(std::cos(angle), std::sin(angle), 0);
  double t = -1;
  ASSERT_TRUE(intersect(e, Ray{center - 10.0 * longAxis, longAxis}, Interval{}, t));
  EXPECT_NEAR(t, 7.0, 1e-12);
  expectVecNear(normalAt(e, center - 3.0 * longAxis), -longAxis, 1e-12);

  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const Mat3 rt = glm::transpose(r);
  int hits = 0;
  for (int i = 0; i < 200; ++i) {
    const Vec3 o = center + Vec3(5 * u(rng), 5 * u(rng), 5 * u(rng));
    const Vec3 d = glm::normalize(center + Vec3(u(rng), u(rng), u(rng)) * 2.0 - o);
    // The ray in the ellipsoid's own frame, where it is axis-aligned.
    const Vec3 ol = rt * (o - center), dl = rt * d;
    double want = 0, got = 0;
    const bool expected = analyticEllipsoid(axes, ol, dl, want);
    ASSERT_EQ(intersect(e, Ray{o, d}, Interval{}, got), expected) << i;
    if (!expected) continue;
    ++hits;
    EXPECT_NEAR(got, want, 1e-9);
    const Vec3 pl = ol + want * dl;
    const Vec3 nl =
        Vec3(pl.x / (axes.x * axes.x), pl.y / (axes.y * axes.y), pl.z / (axes.z * axes.z));
    expectVecNear(normalAt(e, o + got * d), glm::normalize(r * nl), 1e-9);
  }
  EXPECT_GT(hits, 50);
}

TEST(Ellipsoid, Bounds) {
  const Ellipsoid a = makeEllipsoid(diag(2, 1, 3), Vec3(1, 2, 3));
  expectVecNear(a.bounds.lo, Vec3(-1, 1, 0), 1e-12);
  expectVecNear(a.bounds.hi, Vec3(3, 3, 6), 1e-12);

  // Semi-axes (2, 1, 1) turned by phi about z: the extent along x is
  // sqrt(4 cos^2 + sin^2), along y sqrt(4 sin^2 + cos^2), along z 1.
  const double phi = deg(35);
  const Vec3 c(0.5, -0.5, 2);
  const Ellipsoid b = makeEllipsoid(rotationZ(phi) * diag(2, 1, 1), c);
  const double cs = std::cos(phi), sn = std::sin(phi);
  const Vec3 half(std::sqrt(4 * cs * cs + sn * sn), std::sqrt(4 * sn * sn + cs * cs), 1.0);
  expectVecNear(b.bounds.lo, c - half, 1e-12);
  expectVecNear(b.bounds.hi, c + half, 1e-12);
}

// ---------------------------------------------------------------------------
// Polygons

struct PolySet {
  std::vector<Vec3> vertices;
  std::vector<Polygon> polygons;

  void add(const std::vector<Vec3>& v) {
    ASSERT_FALSE(polygonProblem(v).has_value()) << *polygonProblem(v);
    Polygon p = makePolygon(v);
    p.firstVertex = std::uint32_t(vertices.size());
    vertices.insert(vertices.end(), v.begin(), v.end());
    polygons.push_back(p);
  }
  bool hit(std::size_t i, const Ray& ray, Interval range, double& t) const {
    return intersect(polygons[i], vertices.data(), ray, range, t);
  }
  bool hit(std::size_t i, const Ray& ray) const {
    double t;
    return hit(i, ray, Interval{}, t);
  }
  int countHits(const Ray& ray) const {
    int n = 0;
    for (std::size_t i = 0; i < polygons.size(); ++i)
      n += hit(i, ray) ? 1 : 0;
    return n;
  }
};

Ray down(double x, double y) { return {Vec3(x, y, 5), Vec3(0, 0, -1)}; }

TEST(Polygon, ConvexSquare) {
  PolySet ps;
  ps.add({{0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}});
  double t = -1;
  ASSERT_TRUE(ps.hit(0, down(1, 1), Interval{}, t));
  EXPECT_DOUBLE_EQ(t, 4.0);
  EXPECT_TRUE(ps.hit(0, down(0.01, 1.99)));
  EXPECT_FALSE(ps.hit(0, down(-0.01, 1)));
  EXPECT_FALSE(ps.hit(0, down(1, 2.01)));
  EXPECT_FALSE(ps.hit(0, down(2.5, 2.5)));
  // Oblique ray: from (0,0,3) toward (1.5,0.5,1), t = |(1.5,0.5,-2)|.
  ASSERT_TRUE(ps.hit(0, makeRay(Vec3(0, 0, 3), Vec3(1.5, 0.5, -2)), Interval{}, t));
  EXPECT_NEAR(t, std::sqrt(1.5 * 1.5 + 0.25 + 4), 1e-12);
}

TEST(Polygon, ConcaveUShapeNotchMisses) {
  // A U open toward +y: the notch is x in (1, 2), y in (1, 3).
  PolySet ps;
  ps.add({{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0}, {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}});
  EXPECT_FALSE(ps.hit(0, down(1.5, 2)));
  EXPECT_FALSE(ps.hit(0, down(1.5, 1.01)));
  EXPECT_FALSE(ps.hit(0, down(1.01, 2.99)));
  EXPECT_FALSE(ps.hit(0, down(1.99, 1.5)));
  EXPECT_TRUE(ps.hit(0, down(1.5, 0.99)));
  EXPECT_TRUE(ps.hit(0, down(0.5, 2.5)));
  EXPECT_TRUE(ps.hit(0, down(2.5, 2.5)));
  EXPECT_TRUE(ps.hit(0, down(0.99, 2)));
  EXPECT_FALSE(ps.hit(0, down(3.01, 1)));
  // Grid against a hand-written inside test of the U.
  auto insideU = [](double x, double y) {
    if (x <= 0 || x >= 3 || y <= 0 || y >= 3) return false;
    return !(x > 1 && x < 2 && y > 1);
  };
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const double x = -0.4 + 0.1 * i + 0.0123, y = -0.4 + 0.1 * j + 0.0371;
      EXPECT_EQ(ps.hit(0, down(x, y)), insideU(x, y)) << x << "," << y;
    }
}

TEST(Polygon, ConcaveLShapeInTiltedPlane) {
  // An L in the plane spanned by u, v through c; rays come along the normal.
  const Vec3 u = glm::normalize(Vec3(1, 1, 0)), v = glm::normalize(Vec3(-1, 1, 2));
  const Vec3 n = glm::cross(u, v), c(1, -2, 3);
  auto at = [&](double a, double b) { return c + a * u + b * v; };
  PolySet ps;
  ps.add({at(0, 0), at(2, 0), at(2, 1), at(1, 1), at(1, 2), at(0, 2)});
  expectVecNear(ps.polygons[0].normal, n, 1e-12);
  auto through = [&](double a, double b) { return Ray{at(a, b) + 3.0 * n, -n}; };
  EXPECT_TRUE(ps.hit(0, through(0.5, 0.5)));
  EXPECT_TRUE(ps.hit(0, through(1.5, 0.5)));
  EXPECT_TRUE(ps.hit(0, through(0.5, 1.5)));
  EXPECT_FALSE(ps.hit(0, through(1.5, 1.5))); // the notch
  EXPECT_FALSE(ps.hit(0, through(1.05, 1.05)));
  EXPECT_FALSE(ps.hit(0, through(2.5, 0.5)));
  double t = -1;
  ASSERT_TRUE(ps.hit(0, through(0.3, 1.7), Interval{}, t));
  EXPECT_NEAR(t, 3.0, 1e-12);
}

TEST(Polygon, BackFaceIsHit) {
  PolySet ps;
  ps.add({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}); // faces +z
  double t = -1;
  ASSERT_TRUE(ps.hit(0, Ray{Vec3(0.5, 0.5, -2), Vec3(0, 0, 1)}, Interval{}, t));
  EXPECT_DOUBLE_EQ(t, 2.0);
  EXPECT_FALSE(ps.hit(0, Ray{Vec3(1.5, 0.5, -2), Vec3(0, 0, 1)}));
}

TEST(Polygon, ParallelRaysMiss) {
  PolySet ps;
  ps.add({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  EXPECT_FALSE(ps.hit(0, Ray{Vec3(-1, 0.5, 0.1), Vec3(1, 0, 0)}));
  EXPECT_FALSE(ps.hit(0, Ray{Vec3(-1, 0.5, 0.0), Vec3(1, 0, 0)})); // lying in the plane
  EXPECT_FALSE(ps.hit(0, Ray{Vec3(0.5, 0.5, 0.0), Vec3(0, 1, 0)}));
  EXPECT_FALSE(ps.hit(0, Ray{Vec3(-1, -1, -0.1), glm::normalize(Vec3(1, 1, 0))}));
}

TEST(Polygon, RangeRespected) {
  PolySet ps;
  ps.add({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const Ray r = down(0.5, 0.5); // hits at t = 5
  double t = -1;
  EXPECT_TRUE(ps.hit(0, r, Interval{0, 5.5}, t));
  EXPECT_FALSE(ps.hit(0, r, Interval{0, 4.5}, t));
  EXPECT_FALSE(ps.hit(0, r, Interval{5.5, kInf}, t));
  EXPECT_FALSE(ps.hit(0, r, Interval{0, 5.0}, t)); // open at the top
  EXPECT_FALSE(ps.hit(0, r, Interval{5.0, kInf}, t));
  EXPECT_FALSE(ps.hit(0, Ray{Vec3(0.5, 0.5, -1), Vec3(0, 0, -1)})); // behind
}

TEST(Polygon, SharedEdgeBelongsToExactlyOne) {
  // Two unit squares sharing the edge x = 1, and two quads in the same plane
  // sharing a slanted edge from (3, 0.2) to (3.7, 1.9).
  PolySet ps;
  ps.add({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  ps.add({{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}});
  for (int i = 1; i < 64; ++i) {
    const double y = i / 64.0;
    EXPECT_EQ(ps.countHits(down(1.0, y)), 1) << y;
    // Through the same point on the edge from oblique directions, and from below.
    const Vec3 p(1.0, y, 0.0);
    const Vec3 d = glm::normalize(Vec3(0.3, -0.2, -1.0));
    EXPECT_EQ(ps.countHits(Ray{p - 4.0 * d, d}), 1) << y;
    EXPECT_EQ(ps.countHits(Ray{p + 4.0 * d, -d}), 1) << "from below " << y;
  }
  PolySet slanted;
  const Vec3 a(3, 0.2, 0), b(3.7, 1.9, 0);
  slanted.add({{2, 0, 0}, a, b, {2.5, 2, 0}});
  slanted.add({a, {5, 0, 0}, {5, 2, 0}, b});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const Vec3 p = a + u(rng) * (b - a);
    EXPECT_EQ(slanted.countHits(down(p.x, p.y)), 1) << p.x << "," << p.y;
  }
}

TEST(Polygon, SharedEdgeInOtherProjectionPlanes) {
  // Squares in the plane x = 0.3 (projected along x) and y = -0.7 (along y).
  PolySet px, py;
  px.add({{0.3, 0, 0}, {0.3, 1, 0}, {0.3, 1, 1}, {0.3, 0, 1}});
  px.add({{0.3, 1, 0}, {0.3, 2, 0}, {0.3, 2, 1}, {0.3, 1, 1}});
  py.add({{0, -0.7, 0}, {0, -0.7, 1}, {1, -0.7, 1}, {1, -0.7, 0}});
  py.add({{0, -0.7, 1}, {0, -0.7, 2}, {1, -0.7, 2}, {1, -0.7, 1}});
  for (int i = 1; i < 32; ++i) {
    const double s = i / 32.0;
    EXPECT_EQ(px.countHits(Ray{Vec3(5, 1.0, s), Vec3(-1, 0, 0)}), 1) << s;
    EXPECT_EQ(py.countHits(Ray{Vec3(s, 4, 1.0), Vec3(0, -1, 0)}), 1) << s;
  }
}

TEST(Polygon, SharedVertexBelongsToExactlyOne) {
  PolySet ps; // four unit squares around (1, 1)
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const double x = i, y = j;
      ps.add({{x, y, 0}, {x + 1, y, 0}, {x + 1, y + 1, 0}, {x, y + 1, 0}});
    }
  EXPECT_EQ(ps.countHits(down(1, 1)), 1);
  EXPECT_EQ(ps.countHits(Ray{Vec3(1, 1, -3), Vec3(0, 0, 1)}), 1);
  EXPECT_EQ(ps.countHits(down(1, 0.5)), 1);
  EXPECT_EQ(ps.countHits(down(0.5, 1)), 1);
  EXPECT_EQ(ps.countHits(down(1.5, 1)), 1);
  EXPECT_EQ(ps.countHits(down(1, 1.5)), 1);

  // A fan of seven triangles at irregular angles around (0.25, -0.5).
  PolySet fan;
  const Vec3 c(0.25, -0.5, 0);
  const std::array<double, 7> angles{0.1, 0.9, 1.7, 2.2, 3.6, 4.4, 5.5};
  std::array<Vec3, 7> rim; // each outer vertex computed once, so neighbours share it exactly
  for (std::size_t k = 0; k < angles.size(); ++k)
    rim[k] = c + Vec3(std::cos(angles[k]), std::sin(angles[k]), 0);
  for (std::size_t k = 0; k < rim.size(); ++k)
    fan.add({c, rim[k], rim[(k + 1) % rim.size()]});
  EXPECT_EQ(fan.countHits(down(c.x, c.y)), 1);
  EXPECT_EQ(fan.countHits(Ray{c + Vec3(0.0, 0.0, -1.0), Vec3(0, 0, 1)}), 1);
  for (std::size_t k = 0; k < rim.size(); ++k) { // points on the fan's spokes
    for (double f : {0.37, 0.5, 0.81}) {
      const Vec3 p = c + f * (rim[k] - c);
      EXPECT_EQ(fan.countHits(down(p.x, p.y)), 1) << k << " " << f;
    }
  }
  // Just off the fan's outline, inside the fan's hull edges: exactly one as well.
  EXPECT_EQ(fan.countHits(down(c.x + 0.2, c.y + 0.1)), 1);
}

TEST(Polygon, ProblemDetection) {
  using V = std::vector<Vec3>;
  EXPECT_TRUE(polygonProblem(V{}).has_value());
  EXPECT_TRUE(polygonProblem(V{{0, 0, 0}, {1, 0, 0}}).has_value());
  EXPECT_TRUE(polygonProblem(V{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}).has_value());
  EXPECT_TRUE(polygonProblem(V{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {1, 0, 0}}).has_value());
  EXPECT_TRUE(polygonProblem(V{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}).has_value()); // collinear
  EXPECT_TRUE(polygonProblem(V{{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {2, 0, 0}}).has_value());
  // Non-planar: one corner of a unit square lifted by 0.5.
  EXPECT_TRUE(polygonProblem(V{{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}}).has_value());
  // Fine: triangle, convex square, concave U, a tiny and a huge square.
  EXPECT_FALSE(polygonProblem(V{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).has_value());
  EXPECT_FALSE(polygonProblem(V{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}).has_value());
  EXPECT_FALSE(
      polygonProblem(
          V{{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0}, {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}})
          .has_value());
  EXPECT_FALSE(
      polygonProblem(V{{0, 0, 0}, {1e-4, 0, 0}, {1e-4, 1e-4, 1e-4}, {0, 1e-4, 1e-4}}).has_value());
  EXPECT_FALSE(
      polygonProblem(V{{1e4, 0, 0}, {2e4, 0, 0}, {2e4, 1e4, 0}, {1e4, 1e4, 0}}).has_value());
}

TEST(Polygon, NormalFollowsRightHandRule) {
  using V = std::vector<Vec3>;
  const V ccw{{0, 0, 3}, {1, 0, 3}, {1, 1, 3}, {0, 1, 3}};
  const Polygon up = makePolygon(ccw);
  expectVecNear(up.normal, Vec3(0, 0, 1), 1e-15);
  EXPECT_NEAR(up.planeOffset, 3.0, 1e-15);
  EXPECT_EQ(up.vertexCount, 4u);
  const Polygon downFacing = makePolygon(V{ccw[0], ccw[3], ccw[2], ccw[1]});
  expectVecNear(downFacing.normal, Vec3(0, 0, -1), 1e-15);
  EXPECT_NEAR(downFacing.planeOffset, -3.0, 1e-15);
  // A concave U listed from its reflex corner (2, 1): the first three vertices
  // turn clockwise, yet the polygon as a whole runs counterclockwise.
  const Polygon u = makePolygon(
      V{{2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}, {0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0}});
  expectVecNear(u.normal, Vec3(0, 0, 1), 1e-15);
  // Counterclockwise seen from +x: (y, z) = (0,0), (1,0), (1,1), (0,1).
  const Polygon px = makePolygon(V{{2, 0, 0}, {2, 1, 0}, {2, 1, 1}, {2, 0, 1}});
  expectVecNear(px.normal, Vec3(1, 0, 0), 1e-15);
  EXPECT_NEAR(px.planeOffset, 2.0, 1e-15);
  // A tilted triangle: normal (b - a) x (c - a) normalised.
  const Vec3 a(1, 2, 3), b(2, 2, 4), c(1, 5, 3);
  expectVecNear(makePolygon(V{a, b, c}).normal, glm::normalize(glm::cross(b - a, c - a)), 1e-15);
}

// ---------------------------------------------------------------------------
// Transforms

TEST(Transform, PostMultiplicationOrder) {
  const Transform t = Transform::translate(Vec3(5, 0, 0)) * Transform::rotate(Vec3(0, 0, 1), 90);
  expectVecNear(t.point(Vec3(1, 0, 0)), Vec3(5, 1, 0), 1e-14);
  // The other order rotates the translated point.
  const Transform s = Transform::rotate(Vec3(0, 0, 1), 90) * Transform::translate(Vec3(5, 0, 0));
  expectVecNear(s.point(Vec3(1, 0, 0)), Vec3(0, 6, 0), 1e-14);
  // Vectors ignore translation.
  expectVecNear(t.vector(Vec3(1, 0, 0)), Vec3(0, 1, 0), 1e-14);
  // scale then translate as written: translate acts last.
  const Transform st = Transform::translate(Vec3(1, 2, 3)) * Transform::scale(Vec3(2, 3, 4));
  expectVecNear(st.point(Vec3(1, 1, 1)), Vec3(3, 5, 7), 1e-14);
}

TEST(Transform, RotationIsRightHanded) {
  // 120 degrees about (1,1,1) cycles the axes x -> y -> z -> x.
  const Transform r = Transform::rotate(Vec3(1, 1, 1), 120);
  expectVecNear(r.point(Vec3(1, 0, 0)), Vec3(0, 1, 0), 1e-14);
  expectVecNear(r.point(Vec3(0, 1, 0)), Vec3(0, 0, 1), 1e-14);
  const Transform rx = Transform::rotate(Vec3(2, 0, 0), 90); // axis need not be unit
  expectVecNear(rx.point(Vec3(0, 1, 0)), Vec3(0, 0, 1), 1e-14);
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
  const Transform t = Transform::translate(Vec3(1, -2, 3)) * Transform::scale(Vec3(3, 1, 0.5)) *
                      Transform::rotate(Vec3(1, 2, 3), 40) * Transform::scale(Vec3(1, 4, 1));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 100; ++i) {
    const Vec3 t1(u(rng), u(rng), u(rng)), t2(u(rng), u(rng), u(rng));
    const Vec3 n = glm::cross(t1, t2);
    const Vec3 nn = glm::normalize(t.normal(n));
    EXPECT_NEAR(glm::dot(nn, glm::normalize(t.vector(t1))), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(nn, glm::normalize(t.vector(t2))), 0.0, 1e-12);
  }
  // On the unit sphere under scale(2,1,1) the normal is prop. to (x/4, y, z).
  const Transform s = Transform::scale(Vec3(2, 1, 1));
  const double a = 0.7;
  const Vec3 p = s.point(Vec3(std::cos(a), std::sin(a), 0));
  expectVecNear(glm::normalize(s.normal(Vec3(std::cos(a), std::sin(a), 0))),
                glm::normalize(Vec3(p.x / 4, p.y, p.z)), 1e-14);
}

TEST(Transform, Inverse) {
  const Transform t = Transform::translate(Vec3(1, -2, 3)) * Transform::rotate(Vec3(0, 1, 1), 33) *
                      Transform::scale(Vec3(2, -0.5, 7));
  const Mat4 product = t.matrix() * t.inverse();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      EXPECT_NEAR(product[c][r], c == r ? 1.0 : 0.0, 1e-13);
  const Vec3 p(0.3, -4, 9);
  const Vec3 back = Vec3(t.inverse() * glm::dvec4(t.point(p), 1.0));
  expectVecNear(back, p, 1e-13);
  EXPECT_NEAR(t.determinant(), 2 * -0.5 * 7, 1e-12);
}

TEST(Transform, IsSimilarity) {
  double k = 0;
  EXPECT_TRUE(Transform().isSimilarity(&k));
  EXPECT_NEAR(k, 1.0, 1e-15);
  const Transform sim = Transform::translate(Vec3(4, 5, 6)) * Transform::rotate(Vec3(1, 2, 3), 71) *
                        Transform::scale(Vec3(2.5, 2.5, 2.5)) *
                        Transform::rotate(Vec3(0, 0, 1), 10);
  EXPECT_TRUE(sim.isSimilarity(&k));
  EXPECT_NEAR(k, 2.5, 1e-12);
  EXPECT_TRUE(Transform::scale(Vec3(-3, 3, 3)).isSimilarity(&k)); // a mirror image
  EXPECT_NEAR(k, 3.0, 1e-15);
  EXPECT_FALSE(Transform::scale(Vec3(2, 1, 1)).isSimilarity());
  EXPECT_FALSE((Transform::rotate(Vec3(1, 1, 0), 30) * Transform::scale(Vec3(1, 1, 1.001)) *
                Transform::rotate(Vec3(0, 1, 1), 50))
                   .isSimilarity());
  // Sheared: scale(1,2,1) after a rotation keeps column lengths unequal.
  EXPECT_FALSE(
      (Transform::scale(Vec3(1, 2, 1)) * Transform::rotate(Vec3(0, 0, 1), 45)).isSimilarity());
}

// ---------------------------------------------------------------------------
// Camera

struct CameraFrame {
  Vec3 forward, up, right;
};

CameraFrame frameOf(const CameraSpec& spec) {
  CameraFrame f;
  f.forward = glm::normalize(spec.lookat - spec.eye);
  f.up = glm::normalize(spec.up - glm::dot(spec.up, f.forward) * f.forward);
  f.right = glm::cross(f.forward, f.up);
  return f;
}

TEST(Camera, CentreLooksAtLookat) {
  CameraSpec spec;
  spec.eye = Vec3(1, 2, 3);
  spec.lookat = Vec3(4, -1, 7);
  spec.up = Vec3(0, 1, 0);
  spec.fov = 50;
  const Camera cam(spec, 201, 101);
  const Ray r = cam.eyeRay(100.5, 50.5); // centre of the middle pixel
  expectVecNear(r.origin, spec.eye, 0.0);
  EXPECT_NEAR(angleBetween(r.dir, spec.lookat - spec.eye), 0.0, 1e-14);
  EXPECT_NEAR(glm::length(r.dir), 1.0, 1e-15);
}

TEST(Camera, EdgesMatchFieldOfView) {
  CameraSpec spec;
  spec.eye = Vec3(-2, 1, 4);
  spec.lookat = Vec3(1, 0.5, -3);
  spec.up = Vec3(0.2, 1, 0.4); // not perpendicular to the view: made so
  spec.fov = 37;
  const int w = 320, h = 200;
  const Camera cam(spec, w, h);
  const CameraFrame f = frameOf(spec);
  const double half = deg(spec.fov / 2);

  const Vec3 top = cam.eyeRay(w / 2.0, 0).dir;
  EXPECT_NEAR(angleBetween(top, f.forward), half, 1e-12);
  EXPECT_GT(glm::dot(top, f.up), 0.0);
  EXPECT_NEAR(glm::dot(top, f.right), 0.0, 1e-14);
  const Vec3 bottom = cam.eyeRay(w / 2.0, h).dir;
  EXPECT_NEAR(angleBetween(bottom, f.forward), half, 1e-12);
  EXPECT_LT(glm::dot(bottom, f.up), 0.0);

  const Vec3 right = cam.eyeRay(w, h / 2.0).dir;
  EXPECT_NEAR(glm::dot(right, f.right) / glm::dot(right, f.forward),
              std::tan(half) * double(w) / double(h), 1e-12);
  EXPECT_NEAR(glm::dot(right, f.up), 0.0, 1e-14);
  const Vec3 left = cam.eyeRay(0, h / 2.0).dir;
  EXPECT_NEAR(glm::dot(left, f.right) / glm::dot(left, f.forward),
              -std::tan(half) * double(w) / double(h), 1e-12);

  // Top-left corner: (-tan*W/H, +tan, 1) in (right, up, forward).
  const Vec3 corner = cam.eyeRay(0, 0).dir;
  const double fc = glm::dot(corner, f.forward);
  EXPECT_NEAR(glm::dot(corner, f.right) / fc, -std::tan(half) * w / h, 1e-12);
  EXPECT_NEAR(glm::dot(corner, f.up) / fc, std::tan(half), 1e-12);
  // The up vector of the spec ends up perpendicular: vertical lines stay in the
  // plane of forward and up.
  EXPECT_NEAR(glm::dot(cam.eyeRay(w / 2.0, 17.0).dir, f.right), 0.0, 1e-14);
}

TEST(Camera, RowZeroIsAtTheTopAndColumnZeroAtTheLeft) {
  CameraSpec spec; // eye (0,0,5) looking at the origin, up +y
  const int w = 8, h = 6;
  const Camera cam(spec, w, h);
  EXPECT_EQ(cam.width(), w);
  EXPECT_EQ(cam.height(), h);
  for (int ix = 0; ix < w; ++ix) {
    EXPECT_GT(cam.eyeRay(ix + 0.5, 0.5).dir.y, 0.0);
    EXPECT_LT(cam.eyeRay(ix + 0.5, h - 0.5).dir.y, 0.0);
  }
  for (int iy = 0; iy < h; ++iy) {
    EXPECT_LT(cam.eyeRay(0.5, iy + 0.5).dir.x, 0.0);
    EXPECT_GT(cam.eyeRay(w - 0.5, iy + 0.5).dir.x, 0.0);
  }
  // Pixel (0, 0)'s centre: screen (0.5, 0.5) is at u = -1 + 1/w, v = 1 - 1/h.
  const double t = std::tan(deg(22.5));
  const Vec3 want = glm::normalize(Vec3((-1.0 + 1.0 / w) * t * w / h, (1.0 - 1.0 / h) * t, -1.0));
  expectVecNear(cam.eyeRay(0.5, 0.5).dir, want, 1e-14);
}

// ---------------------------------------------------------------------------
// The group hierarchy against brute force

std::vector<Vec3> randomPolygon(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> kind(0, 3);
  const Vec3 c(10 * u(rng), 10 * u(rng), 10 * u(rng));
  switch (kind(rng)) {
  case 0: { // triangle
    return {c + 2.0 * Vec3(u(rng), u(rng), u(rng)), c + 2.0 * Vec3(u(rng), u(rng), u(rng)),
            c + 2.0 * Vec3(u(rng), u(rng), u(rng))};
  }
  case 1: { // axis-aligned rectangle on a half-unit grid (coplanar neighbours, shared edges)
    std::uniform_int_distribution<int> axis(0, 2), cell(-16, 16), size(1, 6);
    const int a = axis(rng), b = (a + 1) % 3, cc = (a + 2) % 3;
    Vec3 lo;
    lo[a] = cell(rng) * 0.5;
    lo[b] = cell(rng) * 0.5;
    lo[cc] = cell(rng) * 0.5;
    const double db = size(rng) * 0.5, dc = size(rng) * 0.5;
    Vec3 p1 = lo, p2 = lo, p3 = lo;
    p1[b] += db;
    p2[b] += db;
    p2[cc] += dc;
    p3[cc] += dc;
    return {lo, p1, p2, p3};
  }
  default: { // convex n-gon or concave L in a random plane
    const Vec3 n = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(1e-3));
    const Vec3 e1 =
        glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 e2 = glm::cross(n, e1);
    const double r = 0.3 + 2 * std::abs(u(rng));
    if (u(rng) < 0) {
      const std::array<std::array<double, 2>, 6> l{
          {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
      std::vector<Vec3> v;
      for (const auto& q : l)
        v.push_back(c + r * (q[0] * e1 + q[1] * e2));
      return v;
    }
    std::vector<Vec3> v;
    const int count = 3 + int(std::abs(u(rng)) * 6);
    for (int i = 0; i < count; ++i) {
      const double a = 2 * kPi * (i + 0.4 * u(rng)) / count;
      v.push_back(c + r * (std::cos(a) * e1 + std::sin(a) * e2));
    }
    return v;
  }
  }
}

Scene randomScene(std::mt19937& rng, int primitives, int groups) {
  std::uniform_real_distribution<double> u(-1, 1);
  Scene scene;
  const std::uint32_t mat = addMaterial(scene, Material{});
  for (int g = 1; g <= groups; ++g) {
    // Mostly deep chains, sometimes a fresh branch.
    std::uniform_int_distribution<int> parent(std::max(0, g - 3), g - 1);
    addGroup(scene, std::uint32_t(u(rng) < -0.7 ? 0 : parent(rng)));
  }
  std::uniform_int_distribution<std::uint32_t> pickGroup(0, std::uint32_t(scene.groups.size() - 1));
  std::uniform_int_distribution<int> kind(0, 2);
  for (int i = 0; i < primitives; ++i) {
    const std::uint32_t g = pickGroup(rng);
    switch (kind(rng)) {
    case 0:
      addSphere(scene, Vec3(10 * u(rng), 10 * u(rng), 10 * u(rng)), 0.1 + 1.9 * std::abs(u(rng)),
                mat, g);
      break;
    case 1: {
      Mat3 m;
      do {
        m = Mat3(Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)),
                 Vec3(u(rng), u(rng), u(rng))) *
            2.0;
      } while (std::abs(glm::determinant(m)) < 0.2);
      addEllipsoid(scene, m, Vec3(10 * u(rng), 10 * u(rng), 10 * u(rng)), mat, g);
      break;
    }
    default: {
      const std::vector<Vec3> v = randomPolygon(rng);
      if (!polygonProblem(v)) addPolygon(scene, v, mat, g);
      break;
    }
    }
  }
  return scene;
}

Vec3 randomDirection(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> pick(0, 9);
  const int k = pick(rng);
  if (k < 3) { // axis-parallel
    Vec3 d(0.0);
    d[k] = u(rng) < 0 ? -1.0 : 1.0;
    return d;
  }
  Vec3 d;
  do
    d = Vec3(u(rng), u(rng), u(rng));
  while (glm::dot(d, d) < 1e-3 || glm::dot(d, d) > 1);
  return glm::normalize(d);
}

// Both accelerations agree on one query; returns false if the ray hit nothing.
bool compareQuery(const Scene& scene, const Accel& groups, const Accel& brute, const Ray& ray,
                  Interval range, const PrimitiveRef* skip, int& ties) {
  Hit hg, hb;
  const bool fg = groups.closestHit(ray, range, skip, hg);
  const bool fb = brute.closestHit(ray, range, skip, hb);
  EXPECT_EQ(fg, fb);
  EXPECT_EQ(groups.anyHit(ray, range, skip), fb);
  EXPECT_EQ(brute.anyHit(ray, range, skip), fb);
  if (!fg || !fb) return false;
  // The same intersection routine gives the same t bit for bit.
  EXPECT_EQ(hg.t, hb.t);
  EXPECT_TRUE(range.contains(hg.t));
  // Coincident hits go to the smaller PrimitiveRef in every accel.
  EXPECT_TRUE(hg.primitive == hb.primitive);
  for (const PrimitiveRef& other : scene.allPrimitives()) {
    double t = -1;
    if (other == hb.primitive || (skip != nullptr && other == *skip)) continue;
    if (!intersectPrimitive(scene, other, ray, range, t)) continue;
    EXPECT_GE(t, hb.t);
    if (t == hb.t) {
      EXPECT_TRUE(hb.primitive < other);
      ++ties;
    }
  }
  if (skip != nullptr) {
    EXPECT_FALSE(hg.primitive == *skip);
  }
  // A range ending just before the hit finds nothing closer.
  Interval shorter = range;
  shorter.max = hb.t;
  EXPECT_FALSE(groups.anyHit(ray, shorter, skip));
  return true;
}

TEST(GroupBvh, MatchesBruteForceOnRandomScenes) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> u(-1, 1);
  int queries = 0, hits = 0, surfaceStarts = 0, ties = 0;
  for (int sceneIndex = 0; sceneIndex < 24; ++sceneIndex) {
    const int prims = 20 + sceneIndex * 7;
    const int groups = sceneIndex % 4 == 0 ? 0 : 1 + sceneIndex * 2;
    const Scene scene = randomScene(rng, prims, groups);
    const auto bvh = makeAccel(scene, AccelKind::Groups);
    const auto brute = makeAccel(scene, AccelKind::None);
    ASSERT_NE(bvh, nullptr);
    ASSERT_NE(brute, nullptr);
    for (int i = 0; i < 500; ++i) {
      const Ray ray{Vec3(15 * u(rng), 15 * u(rng), 15 * u(rng)), randomDirection(rng)};
      Interval range;
      if (i % 5 == 1) range.max = 5 + 20 * std::abs(u(rng));
      if (i % 5 == 2) range.min = 3 * std::abs(u(rng));
      ++queries;
      if (!compareQuery(scene, *bvh, *brute, ray, range, nullptr, ties)) continue;
      ++hits;
      // A secondary ray starting exactly on the surface just hit.
      Hit h;
      ASSERT_TRUE(brute->closestHit(ray, range, nullptr, h));
      const Ray onSurface{ray.at(h.t), randomDirection(rng)};
      const PrimitiveRef* skip =
          h.primitive.kind == kindOf<Polygon> && i % 2 == 0 ? &h.primitive : nullptr;
      ++queries;
      ++surfaceStarts;
      compareQuery(scene, *bvh, *brute, onSurface, Interval{}, skip, ties);
    }
    // Rays lying in the planes of the grid-aligned rectangles, along an axis.
    for (int i = 0; i < 200; ++i) {
      std::uniform_int_distribution<int> cell(-16, 16), axis(0, 2);
      Vec3 o(cell(rng) * 0.5, cell(rng) * 0.5, cell(rng) * 0.5);
      o[axis(rng)] += 0.25 * u(rng);
      Vec3 d(0.0);
      d[axis(rng)] = u(rng) < 0 ? -1 : 1;
      ++queries;
      compareQuery(scene, *bvh, *brute, Ray{o, d}, Interval{}, nullptr, ties);
    }
  }
  EXPECT_GT(queries, 15000);
  EXPECT_GT(hits, 2000);
  EXPECT_GT(surfaceStarts, 2000);
  EXPECT_LT(ties, queries / 20);
}

TEST(GroupBvh, DeepAndWideNesting) {
  // A chain of 150 nested groups (deeper than any fixed traversal stack) and a
  // group with 40 sub-groups, each holding one sphere on the x axis.
  Scene scene;
  const std::uint32_t mat = addMaterial(scene, Material{});
  std::uint32_t g = 0;
  for (int i = 0; i < 150; ++i) {
    g = addGroup(scene, g);
    addSphere(scene, Vec3(3.0 * i, 0, 0), 1.0, mat, g);
  }
  const std::uint32_t wide = addGroup(scene, 0);
  for (int i = 0; i < 40; ++i) {
    const std::uint32_t child = addGroup(scene, wide);
    addSphere(scene, Vec3(3.0 * i, 10, 0), 1.0, mat, child);
    addGroup(scene, child); // an empty group
  }
  const auto bvh = makeAccel(scene, AccelKind::Groups);
  const auto brute = makeAccel(scene, AccelKind::None);
  // Along +x from x = -5: the first sphere is entered at x = -1, t = 4.
  Hit h;
  ASSERT_TRUE(bvh->closestHit(Ray{Vec3(-5, 0, 0), Vec3(1, 0, 0)}, Interval{}, nullptr, h));
  EXPECT_DOUBLE_EQ(h.t, 4.0);
  EXPECT_EQ(h.primitive, (PrimitiveRef{kindOf<Sphere>, 0}));
  // From the far end backwards: sphere 149 (at x = 447) entered at x = 448.
  ASSERT_TRUE(bvh->closestHit(Ray{Vec3(500, 0, 0), Vec3(-1, 0, 0)}, Interval{}, nullptr, h));
  EXPECT_DOUBLE_EQ(h.t, 52.0);
  EXPECT_EQ(h.primitive, (PrimitiveRef{kindOf<Sphere>, 149}));
  // Straight down onto sphere k of the chain and of the wide group.
  for (std::uint32_t k = 0; k < 150; k += 7) {
    ASSERT_TRUE(bvh->closestHit(Ray{Vec3(3.0 * k, 0, 9), Vec3(0, 0, -1)}, Interval{}, nullptr, h));
    EXPECT_DOUBLE_EQ(h.t, 8.0);
    EXPECT_EQ(h.primitive.index, k);
  }
  for (std::uint32_t k = 0; k < 40; k += 3) {
    ASSERT_TRUE(bvh->closestHit(Ray{Vec3(3.0 * k, 10, 9), Vec3(0, 0, -1)}, Interval{}, nullptr, h));
    EXPECT_EQ(h.primitive.index, 150 + k);
    EXPECT_TRUE(bvh->anyHit(Ray{Vec3(3.0 * k, 10, 9), Vec3(0, 0, -1)}, Interval{}, nullptr));
  }
  EXPECT_FALSE(bvh->anyHit(Ray{Vec3(1.5, 0, 9), Vec3(0, 0, -1)}, Interval{}, nullptr));
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1, 1);
  int ties = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray ray{Vec3(225 + 240 * u(rng), 5 + 10 * u(rng), 10 * u(rng)), randomDirection(rng)};
    compareQuery(scene, *bvh, *brute, ray, Interval{}, nullptr, ties);
  }
  EXPECT_EQ(ties, 0);
}

TEST(GroupBvh, CoincidentSurfacesResolveToTheFirstPrimitive) {
  // Identical squares and identical spheres, listed in different groups so the
  // hierarchy visits them in another order than the primitive order.
  Scene scene;
  const std::uint32_t mat = addMaterial(scene, Material{});
  const std::uint32_t deep = addGroup(scene, addGroup(scene, 0));
  const std::vector<Vec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<Vec3> flipped{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
  addPolygon(scene, square, mat, deep);          // polygon 0
  addPolygon(scene, flipped, mat, 0);            // polygon 1, same plane, facing -z
  addPolygon(scene, square, mat, 0);             // polygon 2
  addSphere(scene, Vec3(5, 5, 0), 1, mat, deep); // sphere 0
  addSphere(scene, Vec3(5, 5, 0), 1, mat, 0);    // sphere 1
  for (int extra = 0; extra < 10; ++extra)       // force a split tree in group 0
    addSphere(scene, Vec3(-10.0 - 3 * extra, 0, 0), 1, mat, 0);
  for (AccelKind kind : {AccelKind::Groups, AccelKind::None}) {
    const auto accel = makeAccel(scene, kind);
    Hit h;
    for (const Ray& r :
         {Ray{Vec3(0.5, 0.25, 2), Vec3(0, 0, -1)}, Ray{Vec3(0.5, 0.25, -2), Vec3(0, 0, 1)},
          makeRay(Vec3(-1, -1, 1), Vec3(1.3, 1.6, -1))}) {
      ASSERT_TRUE(accel->closestHit(r, Interval{}, nullptr, h));
      EXPECT_EQ(h.primitive, (PrimitiveRef{kindOf<Polygon>, 0})) << accelKindName(kind);
    }
    const PrimitiveRef first{kindOf<Polygon>, 0};
    ASSERT_TRUE(accel->closestHit(Ray{Vec3(0.5, 0.25, 2), Vec3(0, 0, -1)}, Interval{}, &first, h));
    EXPECT_EQ(h.primitive, (PrimitiveRef{kindOf<Polygon>, 1}));
    ASSERT_TRUE(accel->closestHit(Ray{Vec3(5, 5, 9), Vec3(0, 0, -1)}, Interval{}, nullptr, h));
    EXPECT_EQ(h.primitive, (PrimitiveRef{kindOf<Sphere>, 0}));
    EXPECT_DOUBLE_EQ(h.t, 8.0);
  }
}

TEST(GroupBvh, EmptySceneAndSkip) {
  Scene empty;
  const auto bvh = makeAccel(empty, AccelKind::Groups);
  Hit h;
  EXPECT_FALSE(bvh->closestHit(Ray{Vec3(0.0), Vec3(0, 0, 1)}, Interval{}, nullptr, h));
  EXPECT_FALSE(bvh->anyHit(Ray{Vec3(0.0), Vec3(0, 0, 1)}, Interval{}, nullptr));

  // Two stacked squares: skipping the nearer one reports the farther one.
  Scene scene;
  const std::uint32_t mat = addMaterial(scene, Material{});
  const PrimitiveRef near = test::addHorizontalSquare(scene, 1.0, 1.0, mat);
  const PrimitiveRef far = test::addHorizontalSquare(scene, -1.0, 1.0, mat);
  for (AccelKind kind : {AccelKind::Groups, AccelKind::None}) {
    const auto accel = makeAccel(scene, kind);
    const Ray ray{Vec3(0.1, 0.2, 3), Vec3(0, 0, -1)};
    ASSERT_TRUE(accel->closestHit(ray, Interval{}, nullptr, h));
    EXPECT_EQ(h.primitive, near);
    EXPECT_DOUBLE_EQ(h.t, 2.0);
    ASSERT_TRUE(accel->closestHit(ray, Interval{}, &near, h));
    EXPECT_EQ(h.primitive, far);
    EXPECT_DOUBLE_EQ(h.t, 4.0);
    EXPECT_FALSE(accel->anyHit(ray, Interval{0.0, 3.5}, &near));
    EXPECT_TRUE(accel->anyHit(ray, Interval{0.0, 4.5}, &near));
  }
}

} // namespace
} // namespace prism
