// Quadrics clipped by a box: intersections and normals against values worked
// out by hand (a paraboloid along and off its axis and parallel to it, where
// the equation along the ray is linear; a hyperboloid of one sheet entered
// and left; a sphere written as a quadric; a cone's apex; tangent rays; a ray
// lying in the surface), clipping (the first root outside the box, the second
// inside), an elliptic cylinder against the Cone kind, far from the origin,
// tiny and huge, under rotation and non-uniform scale against the
// analytically transformed surface, coordinates, the .sc `quadric` and its
// errors, the writers, and the hierarchies against brute force.
#include "core/accel/accel.h"
#include "core/io/pov_writer.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/render/tracer.h"
#include "core/shapes/cone.h"
#include "core/shapes/quadric_surface.h"
#include "core/shapes/shape_kinds.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

namespace prism {
namespace {

using Coefficients = std::array<double, 10>;

Ray ray(Vec3 origin, Vec3 dir) { return Ray{origin, glm::normalize(dir)}; }

// z = x^2 + y^2 as x^2 + y^2 - z = 0, clipped to |x|, |y| <= 2, -1 <= z <= 4.
Quadric paraboloid(Vec3 lo = Vec3(-2, -2, -1), Vec3 hi = Vec3(2, 2, 4)) {
  return makeQuadric({1, 1, 0, 0, 0, 0, 0, 0, -1, 0}, lo, hi);
}

// The nearest hit's t, or -1 for none.
double hitT(const Quadric& q, const Ray& r, Interval range = Interval{}) {
  double t = 0;
  return intersect(q, r, range, t) ? t : -1.0;
}

TEST(Quadric, ParaboloidAlongItsAxis) {
  const Quadric q = paraboloid();
  // Down the axis: the vertex at z = 0. The positive side x^2 + y^2 - z > 0
  // is below the dish: the normal there is -z.
  EXPECT_NEAR(hitT(q, ray({0, 0, 10}, {0, 0, -1})), 10.0, 1e-14);
  test::expectCloseTo(normalAt(q, {0, 0, 0}), {0, 0, -1}, 1e-15);
  // Up the axis from below: the same point.
  EXPECT_NEAR(hitT(q, ray({0, 0, -0.5}, {0, 0, 1})), 0.5, 1e-15);
}

TEST(Quadric, ParaboloidParallelToItsAxisIsLinear) {
  const Quadric q = paraboloid();
  // Along z the x^2 + y^2 term is constant: a == 0, one root, at z = 1.25.
  EXPECT_NEAR(hitT(q, ray({1, 0.5, 10}, {0, 0, -1})), 10.0 - 1.25, 1e-14);
  // Gradient (2x, 2y, -1) = (2, 1, -1).
  test::expectCloseTo(normalAt(q, {1, 0.5, 1.25}), Vec3(2, 1, -1) / std::sqrt(6.0), 1e-15);
  // Outside the rim (1.9^2 + 1.9^2 = 7.22 > 4): the root is above the box.
  EXPECT_EQ(hitT(q, ray({1.9, 1.9, 10}, {0, 0, -1})), -1.0);
}

TEST(Quadric, ParaboloidAcrossItsAxis) {
  const Quadric q = paraboloid();
  // At z = 1 the dish is the circle x^2 + y^2 = 1: in at x = -1, out at x = 1.
  const Ray r = ray({-5, 0, 1}, {1, 0, 0});
  EXPECT_NEAR(hitT(q, r), 4.0, 1e-14);
  EXPECT_NEAR(hitT(q, r, Interval{4.5}), 6.0, 1e-14);
  test::expectCloseTo(normalAt(q, {-1, 0, 1}), Vec3(-2, 0, -1) / std::sqrt(5.0), 1e-15);
  test::expectCloseTo(normalAt(q, {1, 0, 1}), Vec3(2, 0, -1) / std::sqrt(5.0), 1e-15);
  // Off axis and slanted: from (0, -3, 0) toward (0, 3, 4.5), z = 0.75 (y + 3)
  // meets y^2 = z at y = (0.75 -+ sqrt(0.5625 + 9)) / 2.
  const Vec3 from(0, -3, 0), dir = glm::normalize(Vec3(0, 6, 4.5));
  const double y0 = (0.75 - std::sqrt(0.5625 + 9.0)) / 2.0;
  EXPECT_NEAR(hitT(q, Ray{from, dir}), (y0 + 3.0) / dir.y, 1e-14);
}

TEST(Quadric, ClippingKeepsTheSecondRootWhenTheFirstIsOutsideTheBox) {
  // The box starts at x = -0.5: the ray enters it past the first root (x =
  // -1) and meets the second (x = 1) inside.
  const Quadric q = paraboloid(Vec3(-0.5, -2, -1), Vec3(2, 2, 4));
  EXPECT_NEAR(hitT(q, ray({-5, 0, 1}, {1, 0, 0})), 6.0, 1e-14);
  // Both roots outside: none.
  const Quadric narrow = paraboloid(Vec3(-0.5, -2, -1), Vec3(0.5, 2, 4));
  EXPECT_EQ(hitT(narrow, ray({-5, 0, 1}, {1, 0, 0})), -1.0);
  // The ray starting inside the box, past the first root.
  EXPECT_NEAR(hitT(paraboloid(), ray({0, 0, 1}, {1, 0, 0})), 1.0, 1e-15);
}

TEST(Quadric, HyperboloidOfOneSheetEnteredAndLeft) {
  // x^2 + y^2 - z^2 = 1: the waist is the unit circle.
  const Quadric q = makeQuadric({1, 1, -1, 0, 0, 0, 0, 0, 0, -1}, Vec3(-3), Vec3(3));
  const Ray waist = ray({-5, 0, 0}, {1, 0, 0});
  EXPECT_NEAR(hitT(q, waist), 4.0, 1e-14);
  EXPECT_NEAR(hitT(q, waist, Interval{4.5}), 6.0, 1e-14);
  // Entering against the normal, leaving along it.
  EXPECT_LT(glm::dot(normalAt(q, {-1, 0, 0}), waist.dir), 0.0);
  EXPECT_GT(glm::dot(normalAt(q, {1, 0, 0}), waist.dir), 0.0);
  test::expectCloseTo(normalAt(q, {-1, 0, 0}), {-1, 0, 0}, 1e-15);
  // At height 2 the section is x^2 + y^2 = 5; gradient (2x, 2y, -2z).
  const double r5 = std::sqrt(5.0);
  const Ray high = ray({-5, 0, 2}, {1, 0, 0});
  EXPECT_NEAR(hitT(q, high), 5.0 - r5, 1e-14);
  EXPECT_NEAR(hitT(q, high, Interval{5.0}), 5.0 + r5, 1e-14);
  test::expectCloseTo(normalAt(q, {-r5, 0, 2}), Vec3(-r5, 0, -2) / 3.0, 1e-15);
  // Along the axis: inside the waist, never meeting the sheet.
  EXPECT_EQ(hitT(q, ray({0, 0, -5}, {0, 0, 1})), -1.0);
}

TEST(Quadric, SphereAsAQuadricIsTheSphere) {
  // x^2 + y^2 + z^2 = 4, the clip box around it.
  const Quadric q = makeQuadric({1, 1, 1, 0, 0, 0, 0, 0, 0, -4}, Vec3(-2.5), Vec3(2.5));
  EXPECT_NEAR(hitT(q, ray({0.3, -0.2, -10}, {0, 0, 1})), 10.0 - std::sqrt(4.0 - 0.13), 1e-14);
  EXPECT_NEAR(hitT(q, ray({0.3, -0.2, 0}, {0, 0, 1})), std::sqrt(4.0 - 0.13), 1e-14);
  test::expectCloseTo(normalAt(q, {0, 2, 0}), {0, 1, 0}, 1e-15);
  // The same sphere as (x - 1)^2 + (y - 2)^2 + (z - 3)^2 = 4 expanded.
  const Quadric moved = makeQuadric({1, 1, 1, 0, 0, 0, -2, -4, -6, 1 + 4 + 9 - 4},
                                    Vec3(-1.5, -0.5, 0.5), Vec3(3.5, 4.5, 5.5));
  EXPECT_NEAR(hitT(moved, ray({1, 2, -10}, {0, 0, 1})), 11.0, 1e-13);
  test::expectCloseTo(normalAt(moved, {1, 2, 1}), {0, 0, -1}, 1e-15);
}

TEST(Quadric, EllipticCylinderEqualsTheConeKind) {
  // x^2 / 4 + y^2 = 1 for 0 <= z <= 5, and the Cone kind's cylinder of radius
  // 1 from z = 0 to 5 stretched by 2 along x: the same surface, solved
  // independently.
  const Quadric q = makeQuadric({0.25, 1, 0, 0, 0, 0, 0, 0, 0, -1}, Vec3(-3, -2, 0), Vec3(3, 2, 5));
  const Cone c = makeCone(Vec3(0, 0, 0), 1.0, Vec3(0, 0, 5), 1.0,
                          Mat3(Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)), Vec3(0.0));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    // From all around toward points near the tube.
    const Vec3 from(6 * u(rng), 6 * u(rng), 2.5 + 6 * u(rng));
    const Ray r = ray(from, Vec3(2.5 * u(rng), 1.2 * u(rng), 2.5 + 3 * u(rng)) - from);
    double tc = 0;
    const bool hc = intersect(c, r, Interval{}, tc);
    const double tq = hitT(q, r);
    // Within round-off of the rims the two may disagree: skip those rays.
    const Vec3 atRim = r.at(hc ? tc : std::max(tq, 0.0));
    if (std::abs(atRim.z) < 1e-9 || std::abs(atRim.z - 5) < 1e-9) continue;
    ASSERT_EQ(hc, tq >= 0) << i;
    if (!hc) continue;
    ++hits;
    EXPECT_NEAR(tq, tc, 1e-12 * std::max(1.0, tc)) << i;
    test::expectCloseTo(normalAt(q, r.at(tq)), normalAt(c, r.at(tc)), 1e-12);
  }
  EXPECT_GT(hits, 300);
}

TEST(Quadric, TheApexOfACone) {
  // x^2 + y^2 - z^2 = 0.
  const Quadric q = makeQuadric({1, 1, -1, 0, 0, 0, 0, 0, 0, 0}, Vec3(-1), Vec3(1));
  // Along the axis and across it through the apex: a double root there.
  EXPECT_NEAR(hitT(q, ray({0, 0, -5}, {0, 0, 1})), 5.0, 1e-15);
  EXPECT_NEAR(hitT(q, ray({-5, 0, 0}, {1, 0, 0})), 5.0, 1e-15);
  // A slanted ray through the apex: f = -8 (s - 1)^2 along it.
  EXPECT_NEAR(hitT(q, Ray{{-0.1, 0, -0.3}, glm::normalize(Vec3(1, 0, 3))}),
              glm::length(Vec3(0.1, 0, 0.3)), 1e-15);
  // No gradient at the apex: the frame's z axis, as documented.
  test::expectCloseTo(normalAt(q, {0, 0, 0}), {0, 0, 1}, 0.0);
  // Off the apex, on the upper nappe: gradient (2x, 2y, -2z).
  test::expectCloseTo(normalAt(q, {0.6, 0.8, 1}), Vec3(0.6, 0.8, -1) / std::sqrt(2.0), 1e-15);
  // A ray lying in the surface (one of its lines) meets it nowhere.
  EXPECT_EQ(hitT(q, ray({-1, 0, -1}, {1, 0, 1})), -1.0);
  // Crossing both nappes: z = 0.5 enters the upper at x = -0.5, leaves at 0.5.
  EXPECT_NEAR(hitT(q, ray({-1, 0, 0.5}, {1, 0, 0})), 0.5, 1e-15);
}

TEST(Quadric, TangentRays) {
  // The paraboloid's vertex plane touches it at the origin: a double root.
  EXPECT_NEAR(hitT(paraboloid(), ray({-5, 0, 0}, {1, 0, 0})), 5.0, 1e-15);
  // Just below it, a miss; just above, two close roots.
  EXPECT_EQ(hitT(paraboloid(), ray({-5, 0, -1e-9}, {1, 0, 0})), -1.0);
  EXPECT_NEAR(hitT(paraboloid(), ray({-5, 0, 1e-8}, {1, 0, 0})), 5.0 - 1e-4, 1e-12);
  // The hyperboloid's waist touched by the line x = 1 along y.
  const Quadric h = makeQuadric({1, 1, -1, 0, 0, 0, 0, 0, 0, -1}, Vec3(-3), Vec3(3));
  EXPECT_NEAR(hitT(h, ray({1, -5, 0}, {0, 1, 0})), 5.0, 1e-15);
  test::expectCloseTo(normalAt(h, {1, 0, 0}), {1, 0, 0}, 1e-15);
}

TEST(Quadric, FarFromTheOriginTinyAndHuge) {
  // The paraboloid moved 1e6 away along each axis by its frame.
  const Quadric far = makeQuadric({1, 1, 0, 0, 0, 0, 0, 0, -1, 0}, Vec3(-2, -2, -1), Vec3(2, 2, 4),
                                  Mat3(1.0), Vec3(1e6));
  EXPECT_NEAR(hitT(far, ray(Vec3(1e6) + Vec3(0.3, 0.4, 10), {0, 0, -1})), 10.0 - 0.25, 1e-9);
  // A ray from 1e6 away: t of order 1e6, the hit point within round-off.
  const Ray from = ray({0.3, 0.4, 1e6}, {0, 0, -1});
  const double t = hitT(paraboloid(), from);
  EXPECT_NEAR(t, 1e6 - 0.25, 1e-9);
  EXPECT_NEAR(from.at(t).z, 0.25, 1e-9);
  // A sphere of radius 1e-6 and one of radius 1e6.
  const Quadric tiny = makeQuadric({1, 1, 1, 0, 0, 0, 0, 0, 0, -1e-12}, Vec3(-2e-6), Vec3(2e-6));
  EXPECT_NEAR(hitT(tiny, ray({0, 0, -1}, {0, 0, 1})), 1.0 - 1e-6, 1e-16);
  EXPECT_NEAR(hitT(tiny, ray({0, 0, 0}, {0, 1, 0})), 1e-6, 1e-21);
  test::expectCloseTo(normalAt(tiny, {0, 0, -1e-6}), {0, 0, -1}, 1e-15);
  const Quadric huge = makeQuadric({1, 1, 1, 0, 0, 0, 0, 0, 0, -1e12}, Vec3(-2e6), Vec3(2e6));
  EXPECT_NEAR(hitT(huge, ray({0, 0, -1e7}, {0, 0, 1})), 9e6, 1e-8);
  EXPECT_NEAR(hitT(huge, ray({0, 0, 0}, {1, 0, 0})), 1e6, 1e-9);
  // A thin cylinder (radius 1e-3) in a large box keeps its precision.
  const Quadric thin = makeQuadric({1, 1, 0, 0, 0, 0, 0, 0, 0, -1e-6}, Vec3(-100), Vec3(100));
  EXPECT_NEAR(hitT(thin, ray({-90, 0, 50}, {1, 0, 0})), 90.0 - 1e-3, 1e-13);
  // Coefficients of any size: the same surface scaled by 1e200 and 1e-200.
  for (const double k : {1e200, 1e-200}) {
    const Quadric scaled =
        makeQuadric({k, k, 0, 0, 0, 0, 0, 0, -k, 0}, Vec3(-2, -2, -1), Vec3(2, 2, 4));
    EXPECT_NEAR(hitT(scaled, ray({1, 0.5, 10}, {0, 0, -1})), 10.0 - 1.25, 1e-14);
    EXPECT_EQ(givenCoefficients(scaled)[0], k);
  }
}

TEST(Quadric, TransformedLikeTheAnalyticSurface) {
  // x -> (1, 2, 3) + Rz(90) diag(2, 1, 1) x takes frame (x, y, z) to the
  // world (1 - y, 2 + 2x, 3 + z); the paraboloid z = x^2 + y^2 becomes
  // wz - 3 = ((wy - 2) / 2)^2 + (1 - wx)^2.
  const Scene s = parseScene("push translate 1 2 3 rotate 0 0 1 90 scale 2 1 1\n"
                             "quadric 1 1 0 0 0 0 0 0 -1 0  -2 -2 -1  2 2 4\npop\n",
                             "t.sc");
  ASSERT_EQ(s.shapes<Quadric>().size(), 1u);
  const Quadric& q = s.shapes<Quadric>()[0];
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 50; ++i) {
    const double wx = 1 + 1.5 * u(rng), wy = 2 + 3 * u(rng);
    const double wz = 3 + (wy - 2) * (wy - 2) / 4 + (1 - wx) * (1 - wx);
    EXPECT_NEAR(hitT(q, ray({wx, wy, 100}, {0, 0, -1})), 100 - wz, 1e-12);
    // The world gradient of (1 - wx)^2 + ((wy - 2) / 2)^2 - (wz - 3).
    const Vec3 g(-2 * (1 - wx), (wy - 2) / 2, -1);
    test::expectCloseTo(normalAt(q, {wx, wy, wz}), glm::normalize(g), 1e-14);
  }
  // Rotated about a slanted axis and sheared: a point of the frame's surface
  // carried out is on the world surface, with the inverse transpose's
  // normal, found by a ray aimed at it from outside along the normal.
  const Scene sheared = parseScene("push rotate 1 1 0 30 scale 1 3 0.5 rotate 0 1 1 50\n"
                                   "quadric 1 1 -1 0 0 0 0 0 0 -1  -3 -3 -3  3 3 3\npop\n",
                                   "t.sc");
  const Quadric& h = sheared.shapes<Quadric>()[0];
  const Mat3& m = h.frame.objectToWorld;
  const Mat3 inverseTranspose = glm::transpose(glm::inverse(m));
  for (int i = 0; i < 50; ++i) {
    const double angle = 3.1 * u(rng), z = 1.5 * u(rng), rho = std::sqrt(1 + z * z);
    const Vec3 frame(rho * std::cos(angle), rho * std::sin(angle), z);
    const Vec3 world = m * frame;
    const Vec3 n = glm::normalize(inverseTranspose * Vec3(frame.x, frame.y, -frame.z));
    test::expectCloseTo(normalAt(h, world), n, 1e-13);
    const double t = hitT(h, Ray{world + 0.01 * n, -n});
    EXPECT_NEAR(t, 0.01, 1e-13);
  }
}

TEST(Quadric, CoordinatesAndBounds) {
  const Quadric q = paraboloid();
  // u around z through the box's centre (0.5 toward +x, 0.75 toward +y), v
  // the height in the box.
  const Vec2 a = uvAt(q, {1, 0, 1});
  EXPECT_DOUBLE_EQ(a.x, 0.5);
  EXPECT_DOUBLE_EQ(a.y, 0.4);
  EXPECT_DOUBLE_EQ(uvAt(q, {0, 1, 1}).x, 0.75);
  EXPECT_DOUBLE_EQ(uvAt(q, {0, 0, 4}).y, 1.0);
  // The bounds are the clip box's image.
  EXPECT_EQ(boundsOf(q).lo, Vec3(-2, -2, -1));
  EXPECT_EQ(boundsOf(q).hi, Vec3(2, 2, 4));
  const Quadric turned = makeQuadric({1, 1, 0, 0, 0, 0, 0, 0, -1, 0}, Vec3(-1), Vec3(1),
                                     Mat3(Vec3(0, 1, 0), Vec3(-2, 0, 0), Vec3(0, 0, 1)), Vec3(5));
  test::expectVecNear(boundsOf(turned).lo, {3, 4, 4}, 1e-15);
  test::expectVecNear(boundsOf(turned).hi, {7, 6, 6}, 1e-15);
}

TEST(Quadric, ScLanguage) {
  const Scene s = parseScene("quadric 1 1 0 0 0 0 0 0 -1 0  2 2 4  -2 -2 -1\n"
                             "push translate 0 0 10 quadric 1 1 -1 0 0 0 0 0 0 -1  -3 -3 -3 3 3 3 "
                             "pop\n",
                             "t.sc");
  ASSERT_EQ(s.shapes<Quadric>().size(), 2u);
  EXPECT_EQ(s.kindCounts(), "2 quadrics");
  EXPECT_EQ(s.describe({kindOf<Quadric>, 1}), "quadric #1 (t.sc:2)");
  // The corners in any order, as for `box`.
  const Quadric& a = s.shapes<Quadric>()[0];
  EXPECT_EQ(a.lo, Vec3(-2, -2, -1));
  EXPECT_EQ(a.hi, Vec3(2, 2, 4));
  EXPECT_TRUE(isUnplaced(a));
  EXPECT_NEAR(hitT(s.shapes<Quadric>()[1], ray({-5, 0, 10}, {1, 0, 0})), 4.0, 1e-14);
  // The tracer: a ray into the dish from above meets its inside (the side
  // where the polynomial is negative) and leaves no hole.
  EXPECT_FALSE(isFlat(kindOf<Quadric>));
}

TEST(Quadric, ScLanguageErrors) {
  using test::sceneErrorsOf;
  EXPECT_EQ(sceneErrorsOf("quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  1 1"),
            "t.sc:1:1: error: quadric: expected Z1 but reached the end of the file");
  EXPECT_EQ(sceneErrorsOf("quadric 1 1 1 0 0 0 0 0 0 -1\nsphere 0 0 0 1"),
            "t.sc:2:1: error: quadric: expected X0 (a number) but found 'sphere'");
  EXPECT_EQ(sceneErrorsOf("quadric 1 1 1 0 0 0 0 0 0 nan  -1 -1 -1  1 1 1"),
            "t.sc:1:27: error: quadric: J is not a finite number ('nan')");
  EXPECT_EQ(sceneErrorsOf("quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  1 inf 1"),
            "t.sc:1:43: error: quadric: Y1 is not a finite number ('inf')");
  EXPECT_EQ(sceneErrorsOf("quadric 0 0 0 0 0 0 0 0 0 1  -1 -1 -1  1 1 1"),
            "t.sc:1:1: error: quadric: the coefficients A to I are all zero (no surface)");
  EXPECT_EQ(sceneErrorsOf("quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  1 -1 1"),
            "t.sc:1:1: error: quadric: clip box: degenerate box (both corners have the same Y)");
  EXPECT_EQ(sceneErrorsOf("quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  1 1 1 2"),
            "t.sc:1:47: error: expected a command but found the number '2' (too many numbers "
            "for the command before it?)");
  EXPECT_EQ(sceneErrorsOf("quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  2e30 1 1"),
            "t.sc:1:1: error: quadric: lies outside the supported range: world coordinates "
            "(after the current transform) must be within +-1e30");
  EXPECT_EQ(sceneErrorsOf("push scale 1 1 1e-11 quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  1 1 1 pop"),
            "t.sc:1:22: error: quadric: the current transform stretches it too unevenly: one "
            "direction more than 1e10 times another");
  EXPECT_EQ(
      sceneErrorsOf("scale 1e-300 1e-300 1e-300 quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  1 1 1"),
      "t.sc:1:28: error: quadric: too large or too small after the current transform");
  EXPECT_EQ(sceneErrorsOf("Quadric 1 1 1 0 0 0 0 0 0 -1  -1 -1 -1  1 1 1"),
            "t.sc:1:1: error: unknown keyword 'Quadric' (keywords are lower case: 'quadric')");
}

TEST(Quadric, WriterRoundTrip) {
  const std::string text = "surface 0.5 0.6 0.7  0.3 0.4 0.2  20 1.5\n"
                           "quadric 3 1 0 0.5 0 0 0 0 -1 0.25  -2 -2 -1  2 2 4\n"
                           "push translate 1 0 0 rotate 1 2 3 40 scale 1 2 0.5\n"
                           "  quadric 1 1 -1 0 0.1 0 0 0 0 -1  -3 -3 -3  3 3 3\n"
                           "pop\n";
  const Scene a = parseScene(text, "t.sc");
  std::ostringstream out;
  writeScene(out, a);
  // The unplaced one as it was given.
  EXPECT_NE(out.str().find("quadric 3 1 0 0.5 0 0 0 0 -1 0.25  -2 -2 -1  2 2 4\n"),
            std::string::npos)
      << out.str();
  const Scene b = parseScene(out.str(), "t2.sc");
  ASSERT_EQ(b.shapes<Quadric>().size(), 2u) << out.str();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::uint32_t k = 0; k < 2; ++k) {
    const Quadric& qa = a.shapes<Quadric>()[k];
    const Quadric& qb = b.shapes<Quadric>()[k];
    EXPECT_EQ(a.material({kindOf<Quadric>, k}), b.material({kindOf<Quadric>, k}));
    EXPECT_EQ(qa.coef, qb.coef);
    EXPECT_EQ(qa.lo, qb.lo);
    EXPECT_EQ(qa.hi, qb.hi);
    test::expectVecNear(qa.bounds.lo, qb.bounds.lo, 1e-12);
    test::expectVecNear(qa.bounds.hi, qb.bounds.hi, 1e-12);
    for (int i = 0; i < 200; ++i) {
      const Ray q = ray(Vec3(u(rng), u(rng), u(rng)) * 8.0, Vec3(u(rng), u(rng), u(rng)));
      const double ta = hitT(qa, q), tb = hitT(qb, q);
      if ((ta < 0) != (tb < 0)) continue; // within round-off of a rim or a tangent
      EXPECT_NEAR(ta, tb, 1e-9);
    }
  }
}

TEST(Quadric, ConvertWritesPovRayQuadric) {
  // POV-Ray's second vector is xy, xz, yz: Prism's D, F, E.
  const Scene s = parseScene("quadric 1 2 3 4 5 6 7 8 9 -10  -1 -1 -1  1 1 1\n"
                             "push translate 1 2 3 quadric 1 1 0 0 0 0 0 0 -1 0  -2 -2 -1  2 2 4 "
                             "pop\n",
                             "t.sc");
  std::ostringstream out;
  writePov(out, s);
  EXPECT_NE(out.str().find("quadric { <1, 2, 3>, <4, 6, 5>, <7, 8, 9>, -10 clipped_by { box { "
                           "<-1, -1, -1>, <1, 1, 1> } } material { Prism_M0 } }\n"),
            std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, -1>, 0 clipped_by { box { "
                           "<-2, -2, -1>, <2, 2, 4> } } matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 2, "
                           "3> material { Prism_M0 } }\n"),
            std::string::npos)
      << out.str();
}

// The tracer sees the open surface from both sides: from inside the
// hyperboloid's waist a ray leaves through it (the outward normal along the
// ray) and is shaded on the inner side; from outside one enters.
TEST(Quadric, TheTracerSeesBothSides) {
  const Scene s = parseScene("eye 0 0 0  lookat 1 0 0  up 0 0 1\n"
                             "light 0 0 0.5  1 1 1\n"
                             "quadric 1 1 -1 0 0 0 0 0 0 -1  -3 -3 -3  3 3 3\n",
                             "t.sc");
  const auto accel = makeAccel(s, AccelKind::Bvh);
  Tracer tracer(s, *accel, 1);
  RayCounts counts;
  RayTreeNode inside;
  tracer.trace(ray({0, 0, 0}, {1, 0, 0}), 1, counts, &inside);
  EXPECT_TRUE(inside.hit);
  EXPECT_TRUE(inside.leaving);
  test::expectCloseTo(inside.shadingNormal, Vec3(-1, 0, 0), 1e-15);
  RayTreeNode outside;
  tracer.trace(ray({9, 0, 0}, {-1, 0, 0}), 1, counts, &outside);
  EXPECT_TRUE(outside.hit);
  EXPECT_FALSE(outside.leaving);
  test::expectCloseTo(outside.shadingNormal, Vec3(1, 0, 0), 1e-15);
}

TEST(Quadric, AccelsAgreeWithBruteForce) {
  std::string text;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-10, 10), r(0.2, 1.5);
  const auto n = [&] { return std::to_string(u(rng)) + " "; };
  const char* const kShapes[] = {
      "quadric 1 1 0 0 0 0 0 0 -1 0  -1 -1 -0.5  1 1 1.5",  // paraboloid
      "quadric 1 1 -1 0 0 0 0 0 0 -0.3  -1 -1 -1  1 1 1",   // hyperboloid
      "quadric 0.25 1 0 0 0 0 0 0 0 -0.5  -2 -1 -1  2 1 1", // elliptic cylinder
      "quadric 1 1 -0.5 0 0 0 0 0 0 0  -1 -1 -1  1 1 1",    // cone
      "quadric 1 -1 0 0 0 0 0 0 -1 0  -1 -1 -1  1 1 1",     // saddle
  };
  for (int i = 0; i < 150; ++i) {
    const double k = r(rng);
    text += "push translate " + n() + n() + n() + "rotate " + n() + n() + n() + "37 scale " +
            std::to_string(k) + " " + std::to_string(r(rng)) + " " + std::to_string(k) + " " +
            kShapes[i % 5] + " pop\n";
  }
  const Scene s = parseScene(text, "t.sc");
  ASSERT_EQ(s.primitiveCount(), 150u);
  EXPECT_GT(test::expectAccelsAgreeWithBruteForce(s, 10.0, 3000), 300);
}

} // namespace
} // namespace prism
