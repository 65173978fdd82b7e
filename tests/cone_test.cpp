// Open cones and cylinders: intersections against hand-computed values, the
// open ends, rays along the axis and grazing the rim, normals, bounds,
// transforms through the .sc `cone`, precision far from the origin, and the
// hierarchies agreeing with brute force.
#include "core/accel/accel.h"
#include "core/io/scene_parser.h"
#include "core/render/tracer.h"
#include "core/shapes/cone.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <random>

namespace prism {
namespace {

Ray ray(Vec3 origin, Vec3 dir) { return Ray{origin, glm::normalize(dir)}; }

// A cylinder of radius 1 around the z axis from z = 0 to z = 2.
Cone unitCylinder() { return makeCone(Vec3(0, 0, 0), 1.0, Vec3(0, 0, 2), 1.0); }

TEST(Cone, CylinderSideHitFromOutside) {
  const Cone c = unitCylinder();
  double t = 0;
  ASSERT_TRUE(intersect(c, ray({-5, 0, 1}, {1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 4.0, 1e-12);
  EXPECT_NEAR(glm::length(normalAt(c, Vec3(-1, 0, 1)) - Vec3(-1, 0, 0)), 0.0, 1e-12);
  // The far wall is the second root.
  ASSERT_TRUE(intersect(c, ray({-5, 0, 1}, {1, 0, 0}), Interval{4.5, 100}, t));
  EXPECT_NEAR(t, 6.0, 1e-12);
}

TEST(Cone, CylinderHitFromInsideHasOutwardNormal) {
  const Cone c = unitCylinder();
  double t = 0;
  const Ray r = ray({0, 0, 1}, {0, 1, 0});
  ASSERT_TRUE(intersect(c, r, Interval{}, t));
  EXPECT_NEAR(t, 1.0, 1e-12);
  const Vec3 n = normalAt(c, r.at(t));
  EXPECT_NEAR(glm::length(n - Vec3(0, 1, 0)), 0.0, 1e-12);
  EXPECT_GT(glm::dot(n, r.dir), 0.0); // the tracer calls this leaving, as for a lone polygon
}

TEST(Cone, EndsAreOpen) {
  const Cone c = unitCylinder();
  double t = 0;
  // Straight through both open ends, parallel to the axis, off the axis.
  EXPECT_FALSE(intersect(c, ray({0.5, 0.2, -3}, {0, 0, 1}), Interval{}, t));
  // Into the top opening at a slant: the inside wall, below the rim.
  const Ray slant = ray({0, 0, 3}, {0.5, 0, -1});
  ASSERT_TRUE(intersect(c, slant, Interval{}, t));
  const Vec3 p = slant.at(t);
  EXPECT_NEAR(p.x, 1.0, 1e-12);
  EXPECT_NEAR(p.z, 1.0, 1e-12);
  // Past the end: the infinite cylinder would be hit at z = 2.5, this one not.
  EXPECT_FALSE(intersect(c, ray({-5, 0, 2.5}, {1, 0, 0}), Interval{}, t));
}

TEST(Cone, RaysAlongTheAxis) {
  double t = 0;
  // A cylinder and a truncated cone are never hit by their own axis.
  EXPECT_FALSE(intersect(unitCylinder(), ray({0, 0, -5}, {0, 0, 1}), Interval{}, t));
  EXPECT_FALSE(intersect(unitCylinder(), ray({0, 0, 1}, {0, 0, -1}), Interval{}, t));
  const Cone frustum = makeCone(Vec3(0, 0, 0), 2.0, Vec3(0, 0, 1), 1.0);
  EXPECT_FALSE(intersect(frustum, ray({0, 0, -5}, {0, 0, 1}), Interval{}, t));
  // Parallel to the axis but off it, a frustum's slanted wall is hit once.
  ASSERT_TRUE(intersect(frustum, ray({1.5, 0, -5}, {0, 0, 1}), Interval{}, t));
  EXPECT_NEAR(t, 5.5, 1e-12); // radius 1.5 at z = 0.5
  // A pointed cone's axis meets only the tip: a hit there or none, never NaN.
  const Cone pointed = makeCone(Vec3(0, 0, 0), 1.0, Vec3(0, 0, 1), 0.0);
  if (intersect(pointed, ray({0, 0, 5}, {0, 0, -1}), Interval{}, t)) {
    EXPECT_NEAR(t, 4.0, 1e-9);
    EXPECT_NEAR(glm::length(normalAt(pointed, Vec3(0, 0, 1)) - Vec3(0, 0, 1)), 0.0, 1e-12);
  }
}

TEST(Cone, GrazingTheRim) {
  const Cone c = unitCylinder();
  double t = 0;
  // Horizontal rays just inside and just outside the top rim's height.
  EXPECT_TRUE(intersect(c, ray({-5, 0, 2 - 1e-9}, {1, 0, 0}), Interval{}, t));
  EXPECT_FALSE(intersect(c, ray({-5, 0, 2 + 1e-9}, {1, 0, 0}), Interval{}, t));
  // Tangent to the wall: just inside the radius hits, just outside misses.
  EXPECT_TRUE(intersect(c, ray({-5, 1 - 1e-9, 1}, {1, 0, 0}), Interval{}, t));
  EXPECT_FALSE(intersect(c, ray({-5, 1 + 1e-9, 1}, {1, 0, 0}), Interval{}, t));
  // Exactly tangent: a hit at the tangent point or a miss, nothing else.
  if (intersect(c, ray({-5, 1, 1}, {1, 0, 0}), Interval{}, t)) {
    EXPECT_NEAR(t, 5.0, 1e-6);
  }
  // Through the rim circle itself, from above at a slant.
  const Ray rim = ray({2, 0, 4}, {-1, 0, -2});
  ASSERT_TRUE(intersect(c, rim, Interval{}, t));
  EXPECT_NEAR(glm::length(rim.at(t) - Vec3(1, 0, 2)), 0.0, 1e-9);
}

TEST(Cone, TruncatedConeNormalsAndHits) {
  // Radius 2 at z = 0 narrowing to 1 at z = 2: the wall leans in by 1 over a
  // height of 2, so its outward normal is (2, 0, 1) / sqrt(5) facing +x.
  const Cone c = makeCone(Vec3(0, 0, 0), 2.0, Vec3(0, 0, 2), 1.0);
  double t = 0;
  const Ray r = ray({-5, 0, 1}, {1, 0, 0});
  ASSERT_TRUE(intersect(c, r, Interval{}, t));
  EXPECT_NEAR(t, 3.5, 1e-12); // radius 1.5 at z = 1
  const Vec3 n = normalAt(c, r.at(t));
  EXPECT_NEAR(glm::length(n - Vec3(-2, 0, 1) / std::sqrt(5.0)), 0.0, 1e-12);
  // A pointed cone, hit from above at its side.
  const Cone pointed = makeCone(Vec3(0, 0, 0), 1.0, Vec3(0, 0, 1), 0.0);
  ASSERT_TRUE(intersect(pointed, ray({5, 0, 0.5}, {-1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 4.5, 1e-12);
}

TEST(Cone, AnyAxisAndBounds) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200; ++i) {
    const Vec3 base(u(rng), u(rng), u(rng)), apex = base + 3.0 * Vec3(u(rng), u(rng), u(rng));
    const double rb = 0.1 + std::abs(u(rng)), ra = std::abs(u(rng));
    if (coneProblem(base, rb, apex, ra)) continue;
    const Cone c = makeCone(base, rb, apex, ra);
    // A point on the wall: along the axis by s, out by the radius there.
    const Vec3 w = glm::normalize(apex - base);
    const Vec3 side = glm::normalize(glm::cross(w, Vec3(u(rng), u(rng), u(rng))));
    const double s = 0.5 + 0.4 * u(rng);
    const Vec3 p = base + s * (apex - base) + (rb + (ra - rb) * s) * side;
    const Aabb b = boundsOf(c);
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(b.lo[a], p[a] + 1e-12);
      EXPECT_GE(b.hi[a], p[a] - 1e-12);
    }
    // A ray aimed at it from outside along the normal finds it.
    const Vec3 n = normalAt(c, p);
    double t = 0;
    const Ray r = ray(p + 10.0 * n, -n);
    ASSERT_TRUE(intersect(c, r, Interval{}, t));
    EXPECT_NEAR(glm::length(r.at(t) - p), 0.0, 1e-9);
  }
}

TEST(Cone, FarOriginKeepsPrecision) {
  // A thin cylinder (radius 1e-3) seen from 1e4 units: the quadratic is solved
  // from near the cone, so the hit is exact to round-off of the distance.
  const Cone c = makeCone(Vec3(0, 0, 0), 1e-3, Vec3(0, 0, 2e-3), 1e-3);
  double t = 0;
  ASSERT_TRUE(intersect(c, ray({-1e4, 0, 1e-3}, {1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 1e4 - 1e-3, 1e-11);
  ASSERT_TRUE(intersect(c, ray({-1e4, 0.5e-3, 1e-3}, {1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 1e4 - std::sqrt(0.75) * 1e-3, 1e-11);
}

TEST(Cone, ScLanguageWithTransforms) {
  const Scene s = parseScene("cone 0 0 0 1  0 0 2 1\n"
                             "push translate 5 0 0 scale 2 1 1 cone 0 0 0 1  0 0 1 0.5 pop\n",
                             "t.sc");
  ASSERT_EQ(s.shapes<Cone>().size(), 2u);
  EXPECT_TRUE(isCircular(s.shapes<Cone>()[0]));
  EXPECT_FALSE(isCircular(s.shapes<Cone>()[1])); // an elliptic cone after the uneven scale
  double t = 0;
  // The elliptic one has semi-axis 2 along x at z = 0: a ray along -x at
  // z ~ 0 from x = 10 reaches x = 7 (= 5 + 2).
  ASSERT_TRUE(intersect(s.shapes<Cone>()[1], ray({10, 0, 1e-9}, {-1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 3.0, 1e-6);
  // ... and semi-axis 1 along y.
  ASSERT_TRUE(intersect(s.shapes<Cone>()[1], ray({5, 5, 1e-9}, {0, -1, 0}), Interval{}, t));
  EXPECT_NEAR(t, 4.0, 1e-6);
}

TEST(Cone, ScLanguageErrors) {
  EXPECT_EQ(test::sceneErrorsOf("cone 0 0 0 -1 0 0 1 1"),
            "t.sc:1:12: error: cone: negative radius '-1'");
  EXPECT_EQ(test::sceneErrorsOf("cone 0 0 0 0 0 0 1 0"),
            "t.sc:1:1: error: cone: both radii are zero");
  EXPECT_EQ(test::sceneErrorsOf("cone 1 2 3 1 1 2 3 2"),
            "t.sc:1:1: error: cone: base and apex are the same point");
  EXPECT_EQ(test::sceneErrorsOf("cone 0 0 0 1 0 0 1"),
            "t.sc:1:1: error: cone: expected AR but reached the end of the file");
  EXPECT_EQ(test::sceneErrorsOf("cone 0 0 0 1 0 nan 1 1"),
            "t.sc:1:16: error: cone: AY is not a finite number ('nan')");
}

// The hierarchies report exactly the hits brute force does.
TEST(Cone, AccelsAgreeWithBruteForce) {
  std::string text;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-10, 10), r(0.1, 1);
  for (int i = 0; i < 150; ++i) {
    text += "cone " + std::to_string(u(rng)) + " " + std::to_string(u(rng)) + " " +
            std::to_string(u(rng)) + " " + std::to_string(r(rng)) + " " + std::to_string(u(rng)) +
            " " + std::to_string(u(rng)) + " " + std::to_string(u(rng)) + " " +
            std::to_string(r(rng) - 0.1) + "\n";
  }
  test::expectAccelsAgreeWithBruteForce(parseScene(text, "t.sc"), 10.0, 3000);
}

// The tracer's entering/leaving test: a tube seen from inside is left, like a
// lone polygon's back.
TEST(Cone, InsideOfATubeCountsAsLeaving) {
  const Scene s = parseScene("eye 0 0 0  lookat 0 1 0  up 0 0 1\n"
                             "light 0 0 0.5  1 1 1\n"
                             "cone 0 0 -1 2  0 0 1 2\n",
                             "t.sc");
  const auto accel = makeAccel(s, AccelKind::Bvh);
  Tracer tracer(s, *accel, 1);
  RayCounts counts;
  RayTreeNode node;
  const Color c = tracer.trace(ray({0, 0, 0}, {0, 1, 0}), 1, counts, &node);
  EXPECT_TRUE(node.hit);
  EXPECT_TRUE(node.leaving);
  EXPECT_NEAR(glm::length(node.shadingNormal - Vec3(0, -1, 0)), 0.0, 1e-12);
  // Lit from the light inside: 1 * N.L / r^2 with r^2 = 4 + 0.25.
  const double r2 = 4.25, cosine = 2.0 / std::sqrt(r2);
  EXPECT_NEAR(c.r, cosine / r2, 1e-12);
}

} // namespace
} // namespace prism
