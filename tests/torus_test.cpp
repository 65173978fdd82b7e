// Tori: intersections against hand-computed values (rays along the axis,
// through the centre, tangent to the equators, from inside the tube), a sweep
// of rays grazing the inner rim against an independent extended-precision
// reference, sizes from 1e-6 to 1e6 and 1e6 units away, thin tori, transforms
// against the analytically transformed torus, normals against the gradient,
// the crossings CSG will use, the .sc `torus` and its errors, and the
// writers. The hierarchies against brute force: accel_test's
// ToriMatchBruteForce.
#include "core/io/pov_writer.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/io/shape_text/shape_text.h"
#include "core/shapes/crossings.h"
#include "core/shapes/torus.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <vector>

namespace prism {
namespace {

Ray ray(Vec3 origin, Vec3 dir) { return Ray{origin, glm::normalize(dir)}; }

// Major radius 1, minor 0.25, around the z axis at the origin.
Torus unitTorus() { return makeTorus(Vec3(0.0), Vec3(0, 0, 1), 1.0, 0.25); }

std::vector<Crossing> crossingsOf(const Torus& torus, const Ray& r, Interval range = {}) {
  std::vector<Crossing> out;
  appendCrossings(torus, ShapeArrays{}, r, range, out);
  return out;
}

// (rho - R)^2 + z^2 - r^2 in the torus's frame, in extended precision, over
// 2 r: the distance from the surface to first order.
long double tubeDistance(const Torus& torus, const Vec3& world) {
  long double q[3];
  for (int i = 0; i < 3; ++i) {
    q[i] = (long double)torus.worldToObjectOffset[i];
    for (int j = 0; j < 3; ++j)
      q[i] += (long double)torus.worldToObject[j][i] * world[j];
  }
  const long double rho = std::sqrt(q[0] * q[0] + q[1] * q[1]);
  return std::sqrt((rho - torus.major) * (rho - torus.major) + q[2] * q[2]) - torus.minor;
}

// The crossings a ray along +x at height z through the x axis must have, by
// hand: the annulus of the plane z is rho in [R - w, R + w] with w =
// sqrt(r^2 - z^2), met at x = -(R + w), -(R - w), R - w, R + w.
void expectFourInPlane(const Torus& torus, double R, double r, double z, double from,
                       double tolerance) {
  const Ray q = ray({-from, 0, z}, {1, 0, 0});
  const double w = std::sqrt(r * r - z * z);
  const double want[4] = {from - (R + w), from - (R - w), from + (R - w), from + (R + w)};
  const std::vector<Crossing> c = crossingsOf(torus, q);
  ASSERT_EQ(c.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(c[i].t, want[i], tolerance) << i;
    EXPECT_EQ(c[i].entering, i % 2 == 0) << i;
  }
  double t = 0;
  ASSERT_TRUE(intersect(torus, q, Interval{}, t));
  EXPECT_EQ(t, c[0].t);
}

TEST(Torus, ThroughTheCentreInItsPlane) {
  const Torus torus = unitTorus();
  expectFourInPlane(torus, 1.0, 0.25, 0.0, 5.0, 1e-14);
  expectFourInPlane(torus, 1.0, 0.25, 0.2, 5.0, 1e-14); // above the equator: w = 0.15
  // The range picks out the later crossings; the normals point out of the tube.
  const Ray q = ray({-5, 0, 0}, {1, 0, 0});
  double t = 0;
  ASSERT_TRUE(intersect(torus, q, Interval{3.8, 100}, t));
  EXPECT_NEAR(t, 4.25, 1e-14);
  test::expectCloseTo(normalAt(torus, q.at(t)), {1, 0, 0});
  ASSERT_TRUE(intersect(torus, q, Interval{4.25 + 1e-9, 100}, t));
  EXPECT_NEAR(t, 5.75, 1e-14);
  test::expectCloseTo(normalAt(torus, q.at(t)), {-1, 0, 0});
  test::expectCloseTo(normalAt(torus, {-1.25, 0, 0}), {-1, 0, 0});
  EXPECT_FALSE(intersect(torus, q, Interval{6.25 + 1e-9, 100}, t));
  const std::vector<Crossing> later = crossingsOf(torus, q, Interval{4.0, 6.0});
  ASSERT_EQ(later.size(), 2u);
  EXPECT_FALSE(later[0].entering); // out of the tube into the hole
  EXPECT_TRUE(later[1].entering);
}

TEST(Torus, RaysAlongTheAxis) {
  const Torus torus = unitTorus();
  double t = 0;
  // Through the hole: nothing, from either side, also from the centre.
  EXPECT_FALSE(intersect(torus, ray({0, 0, -5}, {0, 0, 1}), Interval{}, t));
  EXPECT_FALSE(intersect(torus, ray({0, 0, 5}, {0, 0, -1}), Interval{}, t));
  EXPECT_TRUE(crossingsOf(torus, ray({0, 0, 0}, {0, 0, 1})).empty());
  // Parallel to it through the hole, just inside the inner equator.
  EXPECT_FALSE(intersect(torus, ray({0.7499, 0, -5}, {0, 0, 1}), Interval{}, t));
  // Parallel to it through the tube's centre circle: z = -r and z = r.
  const std::vector<Crossing> c = crossingsOf(torus, ray({0, 1, -5}, {0, 0, 1}));
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].t, 4.75, 1e-14);
  EXPECT_NEAR(c[1].t, 5.25, 1e-14);
  EXPECT_TRUE(c[0].entering);
  EXPECT_FALSE(c[1].entering);
  test::expectCloseTo(normalAt(torus, {0, 1, -0.25}), {0, 0, -1});
}

TEST(Torus, FromInsideTheTube) {
  const Torus torus = unitTorus();
  // From the tube's centre circle every direction across the tube leaves at r.
  for (const Vec3 dir : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, -1)}) {
    const Ray q = ray({1, 0, 0}, dir);
    double t = 0;
    ASSERT_TRUE(intersect(torus, q, Interval{}, t));
    EXPECT_NEAR(t, 0.25, 1e-15);
    const std::vector<Crossing> c = crossingsOf(torus, q);
    ASSERT_FALSE(c.empty());
    EXPECT_FALSE(c[0].entering);
    EXPECT_GT(glm::dot(normalAt(torus, q.at(t)), q.dir), 0.0); // leaving
  }
  // Along the tube (tangent to its centre circle): leaves where the line
  // passes rho = R + r, at y = sqrt(1.25^2 - 1).
  double t = 0;
  ASSERT_TRUE(intersect(torus, ray({1, 0, 0}, {0, 1, 0}), Interval{}, t));
  EXPECT_NEAR(t, 0.75, 1e-14);
}

TEST(Torus, TangentToTheOuterEquatorAndTheTop) {
  const Torus torus = unitTorus();
  for (const Ray& q : {ray({-5, 1.25, 0}, {1, 0, 0}), ray({-5, 0, 0.25}, {1, 0, 0}),
                       ray({0, 1.25, -5}, {0, 0, 1})}) {
    // A tangent touch: nothing, or a touch within round-off; never NaN.
    const std::vector<Crossing> c = crossingsOf(torus, q);
    double t = 0;
    const bool hit = intersect(torus, q, Interval{}, t);
    EXPECT_EQ(hit, !c.empty());
    for (const Crossing& x : c) {
      EXPECT_TRUE(std::isfinite(x.t));
      EXPECT_LT(std::abs(double(tubeDistance(torus, q.at(x.t)))), 1e-7);
    }
  }
  // Just below the top (z = r - 1e-9): four crossings around x = -1 and 1,
  // each sqrt(r^2 - z^2) = sqrt(2 r 1e-9 - 1e-18) from it.
  expectFourInPlane(torus, 1.0, 0.25, 0.25 - 1e-9, 5.0, 1e-12);
  EXPECT_TRUE(crossingsOf(torus, ray({-5, 0, 0.25 + 1e-9}, {1, 0, 0})).empty());
  // Just outside the outer equator: nothing.
  EXPECT_TRUE(crossingsOf(torus, ray({-5, 1.25 + 1e-12, 0}, {1, 0, 0})).empty());
}

TEST(Torus, TangentToTheInnerRim) {
  const Torus torus = unitTorus();
  // In the plane, along y = R - r: inside the solid all the way from x =
  // -2 sqrt(R r) to 2 sqrt(R r), touching the hole at x = 0.
  const Ray q = ray({-5, 0.75, 0}, {1, 0, 0});
  const std::vector<Crossing> c = crossingsOf(torus, q);
  ASSERT_TRUE(c.size() == 2u || c.size() == 4u) << c.size();
  EXPECT_NEAR(c.front().t, 5.0 - 1.0, 1e-14);
  EXPECT_NEAR(c.back().t, 5.0 + 1.0, 1e-14);
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_EQ(c[i].entering, i % 2 == 0);
    if (i > 0) {
      EXPECT_LE(c[i - 1].t, c[i].t);
    }
  }
  // Vertical, on the inner equator: touches the hole's wall at z = 0.
  const Ray v = ray({0.75, 0, -5}, {0, 0, 1});
  const std::vector<Crossing> cv = crossingsOf(torus, v);
  EXPECT_TRUE(cv.empty() || cv.size() == 2u);
  for (const Crossing& x : cv)
    EXPECT_NEAR(x.t, 5.0, 1e-7);
  // About 1e-12 into the tube (e exactly: the difference is exact): z =
  // +-sqrt(2 r e - e^2).
  const double x = 0.75 + 1e-12, e = x - 0.75;
  const std::vector<Crossing> in = crossingsOf(torus, ray({x, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(in.size(), 2u);
  // The line meets the surface at a slope of z / r = 3e-6 there, so a point
  // within u of the surface may lie u r / z = 1e-11 along the line from it.
  const double z = std::sqrt(0.5 * e - e * e);
  EXPECT_NEAR(in[0].t, 5.0 - z, 4 * 0x1p-53 * 0.25 / z);
  EXPECT_NEAR(in[1].t, 5.0 + z, 4 * 0x1p-53 * 0.25 / z);
}

// Rays grazing the inner rim at offsets from 1e-16 to 1e-3 of the minor
// radius into the hole or
// into the tube, at every angle around the axis and tilted along the rim, on
// a rotated, displaced torus and a thin one. The reference is independent:
// the ray's line carried into the torus's frame in extended precision, the
// least tube distance along it found by ternary search, and the crossings by
// bisection on the tube distance. Where the reference's line dips into the
// tube by more than round-off, both crossings must be found and lie where the
// reference puts them; where it passes by more than round-off, none; every
// crossing found lies on the surface to round-off.
TEST(Torus, GrazingTheInnerRimLeavesNoHoles) {
  struct Case {
    Vec3 center, axis;
    double major, minor;
  };
  const Case cases[] = {{{0.3, -0.2, 0.5}, {0.2, 0.5, 1.0}, 1.0, 0.25},
                        {{0, 0, 0}, {0, 0, 1}, 1.0, 1e-3},
                        {{2, 1, -3}, {1, -1, 0.3}, 5.0, 4.0}};
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586), tilt(-0.3, 0.3);
  int dipping = 0, passing = 0, ambiguous = 0;
  for (const Case& k : cases) {
    const Torus torus = makeTorus(k.center, k.axis, k.major, k.minor);
    const Mat3& m = torus.objectToWorld;
    const double size = k.major + k.minor;
    const double roundoff = 64.0 * 0x1p-53 * (size + maxAbsComponent(k.center));
    for (int i = 0; i < 400; ++i) {
      const double phi = angle(rng);
      const Vec3 radial(std::cos(phi), std::sin(phi), 0.0), along(-radial.y, radial.x, 0.0);
      const double offset = (i % 2 ? 1.0 : -1.0) * std::pow(10.0, -16.0 + 13.0 * (i % 97) / 96.0);
      // On the inner equator, moved along the outward normal (-radial) by
      // offset * minor (positive: into the hole), heading up the wall.
      const Vec3 at = (k.major - k.minor - offset * k.minor) * radial;
      const Vec3 dir = glm::normalize(Vec3(0, 0, 1) + tilt(rng) * along);
      const Vec3 worldAt = m * at + torus.objectToWorldOffset, worldDir = glm::normalize(m * dir);
      const double back = 3.0 * size;
      const Ray q{worldAt - back * worldDir, worldDir};
      // The reference: the least distance on [back - w, back + w].
      const double w = 0.5 * k.minor;
      long double lo = back - w, hi = back + w;
      const auto g = [&](long double t) {
        long double p[3], o[3];
        for (int j = 0; j < 3; ++j)
          p[j] = (long double)q.origin[j] + t * (long double)q.dir[j];
        for (int a = 0; a < 3; ++a) {
          o[a] = (long double)torus.worldToObjectOffset[a];
          for (int b = 0; b < 3; ++b)
            o[a] += (long double)torus.worldToObject[b][a] * p[b];
        }
        const long double rho = std::sqrt(o[0] * o[0] + o[1] * o[1]);
        return std::sqrt((rho - torus.major) * (rho - torus.major) + o[2] * o[2]) - torus.minor;
      };
      for (int it = 0; it < 200; ++it) {
        const long double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
        (g(a) < g(b) ? hi : lo) = (g(a) < g(b) ? b : a);
      }
      const long double tMin = 0.5L * (lo + hi), least = g(tMin);
      const std::vector<Crossing> c = crossingsOf(torus, q, Interval{back - w, back + w});
      for (const Crossing& x : c)
        EXPECT_LT(std::abs(double(g(x.t))), roundoff) << "case " << k.minor << " ray " << i;
      if (least < -roundoff) {
        ++dipping;
        ASSERT_EQ(c.size(), 2u) << "a hole: case " << k.minor << " ray " << i << " dips "
                                << double(least);
        // The reference crossings by bisection, on either side of the least.
        long double roots[2];
        for (int side = 0; side < 2; ++side) {
          long double in = tMin, out = side == 0 ? back - w : back + w;
          for (int it = 0; it < 200; ++it) {
            const long double mid = 0.5L * (in + out);
            (g(mid) < 0 ? in : out) = mid;
          }
          roots[side] = in;
        }
        // Where the line is nearly tangent a point off the surface by
        // round-off moves along it by that over the tube distance's slope.
        for (int side = 0; side < 2; ++side) {
          const long double h = 1e-9L * size;
          const double slope = double(std::abs(g(roots[side] + h) - g(roots[side] - h)) / (2 * h));
          EXPECT_NEAR(c[side].t, double(roots[side]), 4.0 * roundoff / slope + 1e-12 * size)
              << "case " << k.minor << " ray " << i;
        }
        EXPECT_TRUE(c[0].entering);
        EXPECT_FALSE(c[1].entering);
      } else if (least > roundoff) {
        ++passing;
        EXPECT_TRUE(c.empty()) << "a speckle: case " << k.minor << " ray " << i;
      } else {
        ++ambiguous;
        EXPECT_TRUE(c.empty() || c.size() == 2u);
      }
    }
  }
  std::printf("dipping %d, passing %d, within round-off %d\n", dipping, passing, ambiguous);
  EXPECT_GT(dipping, 300);
  EXPECT_GT(passing, 300);
}

TEST(Torus, FarAwayTinyAndHugeTori) {
  // A unit torus seen from 1e6 units: exact to round-off of the distance.
  expectFourInPlane(unitTorus(), 1.0, 0.25, 0.1, 1e6, 1e-9);
  // Tiny and huge, also far from the world's origin.
  for (const double s : {1e-6, 1e6}) {
    const Torus torus = makeTorus(Vec3(0.0), Vec3(0, 0, 1), s, 0.25 * s);
    expectFourInPlane(torus, s, 0.25 * s, 0.1 * s, 5 * s, 1e-14 * s);
    const Vec3 far(1e6, -2e6, 3e6);
    const Torus moved = makeTorus(far, Vec3(0, 0, 1), s, 0.25 * s);
    const std::vector<Crossing> c = crossingsOf(moved, ray(far - Vec3(5 * s, 0, 0), {1, 0, 0}));
    ASSERT_EQ(c.size(), 4u) << s;
    EXPECT_NEAR(c[0].t, 3.75 * s, 1e-9 + 1e-14 * s);
    EXPECT_NEAR(c[3].t, 6.25 * s, 1e-9 + 1e-14 * s);
  }
}

TEST(Torus, ThinTorus) {
  // r / R = 1e-3: in the plane, and parallel to the axis across the tube at
  // rho = R - r / 2, where z = +-sqrt(r^2 - r^2 / 4).
  const double r = 1e-3;
  const Torus torus = makeTorus(Vec3(0.0), Vec3(0, 0, 1), 1.0, r);
  expectFourInPlane(torus, 1.0, r, 0.0, 5.0, 1e-14);
  expectFourInPlane(torus, 1.0, r, 0.9 * r, 5.0, 1e-13);
  const std::vector<Crossing> c = crossingsOf(torus, ray({1.0 - 0.5 * r, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(c.size(), 2u);
  const double z = std::sqrt(0.75) * r;
  EXPECT_NEAR(c[0].t, 5.0 - z, 1e-14);
  EXPECT_NEAR(c[1].t, 5.0 + z, 1e-14);
  test::expectCloseTo(normalAt(torus, {1.0 - 0.5 * r, 0, -z}), {-0.5, 0, -std::sqrt(0.75)}, 1e-12);
}

// A torus of radii 1 and 0.25 around z, scaled by 2 along x, then turned 90
// degrees about z (post-multiplied: the scale acts first), then moved to
// (1, 2, 3): the world torus stretched along y, points (x, y, z) -> (-y, 2x,
// z) + (1, 2, 3).
TEST(Torus, TransformedLikeTheAnalyticTorus) {
  const Scene s = parseScene("push translate 1 2 3 rotate 0 0 1 90 scale 2 1 1\n"
                             "  torus 0 0 0  0 0 1  1 0.25\n"
                             "pop\n",
                             "t.sc");
  ASSERT_EQ(s.shapes<Torus>().size(), 1u);
  const Torus& torus = s.shapes<Torus>()[0];
  EXPECT_FALSE(isRound(torus));
  // Along world y through the centre: y - 2 = +-2 (R +- r).
  const std::vector<Crossing> c = crossingsOf(torus, ray({1, -10, 3}, {0, 1, 0}));
  ASSERT_EQ(c.size(), 4u);
  const double want[4] = {12 - 2.5, 12 - 1.5, 12 + 1.5, 12 + 2.5};
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(c[i].t, want[i], 1e-13);
  // Along world x: x - 1 = +-(R +- r).
  const std::vector<Crossing> cx = crossingsOf(torus, ray({-10, 2, 3}, {1, 0, 0}));
  ASSERT_EQ(cx.size(), 4u);
  EXPECT_NEAR(cx[0].t, 11 - 1.25, 1e-13);
  EXPECT_NEAR(cx[1].t, 11 - 0.75, 1e-13);
  // Bounds: 2.5 along y, 1.25 along x, 0.25 along z.
  test::expectVecNear(torus.bounds.lo, {1 - 1.25, 2 - 2.5, 3 - 0.25}, 1e-14);
  test::expectVecNear(torus.bounds.hi, {1 + 1.25, 2 + 2.5, 3 + 0.25}, 1e-14);
  // Normals: the object normal n at object point p becomes (-n.y, n.x / 2,
  // n.z) normalised (the inverse transpose of the map), at (-p.y, 2 p.x, p.z)
  // + (1, 2, 3).
  for (const double a : {0.3, 1.7, 2.9, 4.4}) {
    for (const double b : {0.2, 1.9, 3.5, 5.6}) {
      const Vec3 n(std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b));
      const Vec3 p = Vec3(std::cos(a), std::sin(a), 0.0) + 0.25 * n;
      const Vec3 world = Vec3(-p.y, 2 * p.x, p.z) + Vec3(1, 2, 3);
      test::expectCloseTo(normalAt(torus, world), glm::normalize(Vec3(-n.y, n.x / 2, n.z)), 1e-12);
      // And a ray from outside along the analytic normal back to the point.
      const Vec3 worldNormal = glm::normalize(Vec3(-n.y, n.x / 2, n.z));
      double t = 0;
      const Ray q{world + 0.01 * worldNormal, -worldNormal};
      ASSERT_TRUE(intersect(torus, q, Interval{}, t));
      EXPECT_NEAR(t, 0.01, 1e-13);
    }
  }
}

TEST(Torus, NormalsAndCoordinatesOnARotatedTorus) {
  // The axis along x: the frame's z is world x.
  const Torus torus = makeTorus(Vec3(0, 0, 0), Vec3(3, 0, 0), 2.0, 0.5);
  EXPECT_TRUE(isRound(torus));
  test::expectCloseTo(normalAt(torus, {0, 0, 2.5}), {0, 0, 1});
  test::expectCloseTo(normalAt(torus, {0, 1.5, 0}), {0, -1, 0});
  test::expectCloseTo(normalAt(torus, {0.5, 2, 0}), {1, 0, 0});
  // v around the tube: 0 on the outer equator, 0.25 on the side the axis
  // points to, 0.5 on the inner equator.
  EXPECT_NEAR(uvAt(torus, {0, 0, 2.5}).y, 0.0, 1e-15);
  EXPECT_NEAR(uvAt(torus, {0.5, 0, 2}).y, 0.25, 1e-15);
  EXPECT_NEAR(uvAt(torus, {0, 0, 1.5}).y, 0.5, 1e-15);
  EXPECT_NEAR(uvAt(torus, {-0.5, 0, 2}).y, 0.75, 1e-15);
  // u around the axis: a quarter turn apart for points a quarter turn apart.
  const double u0 = uvAt(torus, {0, 0, 2.5}).x, u1 = uvAt(torus, {0, 2.5, 0}).x;
  EXPECT_NEAR(std::abs(u1 - u0), 0.25, 1e-15);
}

TEST(Torus, ScLanguage) {
  const Scene s = parseScene("torus 1 2 3  0 2 0  2 0.5\n"
                             "push scale 2 2 2 torus 0 0 0  0 0 1  1 0.25 pop\n",
                             "t.sc");
  ASSERT_EQ(s.shapes<Torus>().size(), 2u);
  EXPECT_EQ(s.kindCounts(), "2 tori"); // as prism convert counts them
  EXPECT_EQ(parseScene("torus 0 0 0  0 0 1  1 0.5", "t.sc").kindCounts(), "1 torus");
  const Torus& a = s.shapes<Torus>()[0];
  EXPECT_TRUE(isRound(a));
  test::expectVecNear(a.bounds.lo, {1 - 2.5, 2 - 0.5, 3 - 2.5}, 1e-14);
  test::expectVecNear(a.bounds.hi, {1 + 2.5, 2 + 0.5, 3 + 2.5}, 1e-14);
  const Torus& b = s.shapes<Torus>()[1];
  EXPECT_TRUE(isRound(b)); // a uniform scale keeps it round: radii 2 and 0.5
  double t = 0;
  ASSERT_TRUE(intersect(b, ray({-10, 0, 0}, {1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 7.5, 1e-14);
}

TEST(Torus, ScLanguageErrors) {
  EXPECT_EQ(test::sceneErrorsOf("torus 0 0 0  0 0 1  1"),
            "t.sc:1:1: error: torus: expected MINOR but reached the end of the file");
  EXPECT_EQ(test::sceneErrorsOf("torus 0 0 0  0 0 1  1\nsphere 0 0 0 1"),
            "t.sc:2:1: error: torus: expected MINOR (a number) but found 'sphere'");
  EXPECT_EQ(test::sceneErrorsOf("torus 0 0 0  0 0 1  1 nan"),
            "t.sc:1:23: error: torus: MINOR is not a finite number ('nan')");
  EXPECT_EQ(test::sceneErrorsOf("torus 0 0 0  0 0 0  1 0.5"),
            "t.sc:1:14: error: torus: the axis (AX AY AZ) must not be zero");
  EXPECT_EQ(test::sceneErrorsOf("torus 0 0 0  0 0 1  -1 0.5"),
            "t.sc:1:21: error: torus: MAJOR must be positive, found '-1'");
  EXPECT_EQ(test::sceneErrorsOf("torus 0 0 0  0 0 1  1 0"),
            "t.sc:1:23: error: torus: MINOR must be positive, found '0'");
  EXPECT_EQ(test::sceneErrorsOf("torus 0 0 0  0 0 1  1 1"),
            "t.sc:1:23: error: torus: MINOR must be less than MAJOR, found '1' (horn and "
            "spindle tori are not supported)");
  EXPECT_EQ(test::sceneErrorsOf("torus 0 0 0  0 0 1  1 2"),
            "t.sc:1:23: error: torus: MINOR must be less than MAJOR, found '2' (horn and "
            "spindle tori are not supported)");
  EXPECT_EQ(test::sceneErrorsOf("torus 0 0 0  0 0 1  1 0.5 0.2"),
            "t.sc:1:27: error: expected a command but found the number '0.2' (too many numbers "
            "for the command before it?)");
  EXPECT_EQ(test::sceneErrorsOf("torus 0 0 0  0 0 1  2e30 0.5"),
            "t.sc:1:1: error: torus: lies outside the supported range: world coordinates (after "
            "the current transform) must be within +-1e30");
  EXPECT_EQ(test::sceneErrorsOf("push scale 1 1 1e-11 torus 0 0 0  0 0 1  1 0.5 pop"),
            "t.sc:1:22: error: torus: the current transform stretches it too unevenly: one "
            "direction more than 1e10 times another");
}

TEST(Torus, WriterRoundTrip) {
  const std::string text = "surface 0.5 0.6 0.7  0.3 0.4 0.2  20 1.5\n"
                           "torus 1 2 3  0 2 0  2 0.5\n"
                           "push translate 1 0 0 rotate 1 2 3 40 scale 1 2 0.5\n"
                           "  torus 0.5 0 0  1 1 0  1 0.25\n"
                           "pop\n";
  const Scene a = parseScene(text, "t.sc");
  std::ostringstream out;
  writeScene(out, a);
  const Scene b = parseScene(out.str(), "t2.sc");
  ASSERT_EQ(b.shapes<Torus>().size(), 2u) << out.str();
  EXPECT_NE(out.str().find("torus 1 2 3  0 1 0  2 0.5\n"), std::string::npos) << out.str();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 2; ++k) {
    const Torus& ta = a.shapes<Torus>()[k];
    const Torus& tb = b.shapes<Torus>()[k];
    EXPECT_EQ(a.material({kindOf<Torus>, std::uint32_t(k)}),
              b.material({kindOf<Torus>, std::uint32_t(k)}));
    test::expectVecNear(ta.bounds.lo, tb.bounds.lo, 1e-12);
    test::expectVecNear(ta.bounds.hi, tb.bounds.hi, 1e-12);
    for (int i = 0; i < 200; ++i) {
      const Ray q = ray(Vec3(u(rng), u(rng), u(rng)) * 8.0, Vec3(u(rng), u(rng), u(rng)));
      const std::vector<Crossing> ca = crossingsOf(ta, q), cb = crossingsOf(tb, q);
      // A ray within round-off of tangent may differ; all others agree.
      if (ca.size() != cb.size()) continue;
      for (std::size_t j = 0; j < ca.size(); ++j)
        EXPECT_NEAR(ca[j].t, cb[j].t, 1e-9);
    }
  }
}

TEST(Torus, ConvertWritesPovRayTorus) {
  const Scene s = parseScene("torus 1 2 3  0 0 1  2 0.5\n", "t.sc");
  std::ostringstream out;
  writePov(out, s);
  // POV-Ray's torus is around its y axis: the matrix takes it to the frame's
  // z (here world z), its x and z to the frame's x and y.
  const Torus& t = s.shapes<Torus>()[0];
  const Mat3& m = t.objectToWorld;
  std::ostringstream want;
  want << "torus { 2, 0.5 sturm matrix <";
  for (const Vec3& column : {m[0], m[2], m[1]})
    want << sc::num(column.x) << ", " << sc::num(column.y) << ", " << sc::num(column.z) << ", ";
  want << "1, 2, 3> material { Prism_M0 } }\n";
  EXPECT_NE(out.str().find(want.str()), std::string::npos) << out.str();
  test::expectCloseTo(m[2], {0, 0, 1});
}

} // namespace
} // namespace prism
