// The closed solids (box, capped cone and cylinder) and the disc:
// intersections, normals, parts and coordinates against values worked out by
// hand; rays along axes, through edges, corners and rims, grazing, in a
// face's plane, from inside; far from the origin, tiny and huge; under
// rotation, non-uniform scale and shear; every crossing for CSG; the .sc
// commands and their errors; the hierarchies against brute force.
#include "core/accel/accel.h"
#include "core/io/scene_parser.h"
#include "core/render/tracer.h"
#include "core/shapes/crossings.h"
#include "core/shapes/shape_kinds.h"
#include "tests/test_expect.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace prism {
namespace {

Ray ray(Vec3 origin, Vec3 dir) { return Ray{origin, glm::normalize(dir)}; }

const ShapeArrays kNoArrays{};

std::vector<Crossing> crossingsOf(const auto& shape, const Ray& r, Interval range = Interval{}) {
  std::vector<Crossing> out;
  appendCrossings(shape, kNoArrays, r, range, out);
  return out;
}

// ---------------------------------------------------------------------------
// Boxes

// The box 0 <= x <= 1, 0 <= y <= 2, 0 <= z <= 3.
Box unitBox() { return makeBox(Vec3(1, 2, 3), Vec3(0, 0, 0)); }

TEST(Box, RaysAlongEachAxisHitTheFacesWithTheirNormals) {
  const Box b = unitBox();
  struct Case {
    Vec3 origin, dir;
    double t;
    std::uint32_t part;
    Vec3 normal;
  };
  const Case cases[] = {
      {{-4, 1, 1}, {1, 0, 0}, 4, 0, {-1, 0, 0}},   {{6, 1, 1}, {-1, 0, 0}, 5, 1, {1, 0, 0}},
      {{0.5, -3, 1}, {0, 1, 0}, 3, 2, {0, -1, 0}}, {{0.5, 9, 1}, {0, -1, 0}, 7, 3, {0, 1, 0}},
      {{0.5, 1, -2}, {0, 0, 1}, 2, 4, {0, 0, -1}}, {{0.5, 1, 10}, {0, 0, -1}, 7, 5, {0, 0, 1}},
  };
  for (const Case& c : cases) {
    double t = 0;
    const Ray r = ray(c.origin, c.dir);
    ASSERT_TRUE(intersect(b, r, Interval{}, t)) << c.part;
    EXPECT_EQ(t, c.t);
    const SurfacePoint s = surfaceAt(b, kNoArrays, r.at(t));
    EXPECT_EQ(s.part, c.part);
    EXPECT_EQ(s.outward, c.normal);
    EXPECT_EQ(normalAt(b, r.at(t)), c.normal);
  }
}

TEST(Box, FarWallFromInsideAndCrossings) {
  const Box b = unitBox();
  double t = 0;
  const Ray through = ray({-4, 1, 1}, {1, 0, 0});
  ASSERT_TRUE(intersect(b, through, Interval{4.5, 100}, t));
  EXPECT_EQ(t, 5.0);
  const std::vector<Crossing> all = crossingsOf(b, through);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].t, 4.0);
  EXPECT_TRUE(all[0].entering);
  EXPECT_EQ(all[0].part, 0u);
  EXPECT_EQ(all[1].t, 5.0);
  EXPECT_FALSE(all[1].entering);
  EXPECT_EQ(all[1].part, 1u);
  // From inside only the leaving crossing lies ahead; its normal points out.
  const Ray inside = ray({0.5, 1, 1}, {0, 0, 1});
  ASSERT_TRUE(intersect(b, inside, Interval{}, t));
  EXPECT_EQ(t, 2.0);
  EXPECT_GT(glm::dot(normalAt(b, inside.at(t)), inside.dir), 0.0);
  const std::vector<Crossing> ahead = crossingsOf(b, inside);
  ASSERT_EQ(ahead.size(), 1u);
  EXPECT_FALSE(ahead[0].entering);
  EXPECT_EQ(ahead[0].part, 5u);
  // A range that ends inside keeps only the entering crossing.
  EXPECT_EQ(crossingsOf(b, through, Interval{0, 4.5}).size(), 1u);
}

TEST(Box, EdgesAndCornersHitExactly) {
  const Box b = makeBox(Vec3(-1), Vec3(1));
  double t = 0;
  // Diagonally at the edge x = y = 1: in through it, out through the opposite edge.
  const Ray edge = ray({3, 3, 0}, {-1, -1, 0});
  ASSERT_TRUE(intersect(b, edge, Interval{}, t));
  EXPECT_NEAR(t, 2 * std::sqrt(2.0), 1e-15);
  std::vector<Crossing> c = crossingsOf(b, edge);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[1].t, 4 * std::sqrt(2.0), 1e-14);
  // At the corner (1, 1, 1) along the main diagonal.
  const Ray corner = ray({3, 3, 3}, {-1, -1, -1});
  ASSERT_TRUE(intersect(b, corner, Interval{}, t));
  EXPECT_NEAR(t, 2 * std::sqrt(3.0), 1e-14);
  // The normal there is one of the three faces meeting at the corner.
  const Vec3 n = normalAt(b, corner.at(t));
  EXPECT_TRUE(n == Vec3(1, 0, 0) || n == Vec3(0, 1, 0) || n == Vec3(0, 0, 1));
  // Touching only an edge from outside: a hit (as a tangent sphere), but the
  // ray is never inside, so no crossings.
  // (this one reaches x = 1 only at y = 3, and misses)
  EXPECT_FALSE(intersect(b, ray({3, 1, 0}, {-1, 1, 0}), Interval{}, t));
  const Ray graze = ray({2, 0, 0}, {-1, 1, 0}); // through (1, 1, 0), outside before and after
  ASSERT_TRUE(intersect(b, graze, Interval{}, t));
  EXPECT_NEAR(t, std::sqrt(2.0), 1e-15);
  EXPECT_TRUE(crossingsOf(b, graze).empty());
}

TEST(Box, RaysInAFacePlaneAndParallelToFaces) {
  const Box b = makeBox(Vec3(-1), Vec3(1));
  double t = 0;
  // In the plane of the top face: along it from one edge to the other.
  const Ray inPlane = ray({-5, 1, 0}, {1, 0, 0});
  ASSERT_TRUE(intersect(b, inPlane, Interval{}, t));
  EXPECT_EQ(t, 4.0);
  // Just above it: nothing, and no NaN on the way.
  EXPECT_FALSE(intersect(b, ray({-5, std::nextafter(1.0, 2.0), 0}, {1, 0, 0}), Interval{}, t));
  // Parallel to two axes' faces, outside one slab: nothing.
  EXPECT_FALSE(intersect(b, ray({-5, 0, 2}, {1, 0, 0}), Interval{}, t));
  EXPECT_TRUE(crossingsOf(b, ray({-5, 0, 2}, {1, 0, 0})).empty());
}

// Rays aimed exactly at random points of the edges, entering through both
// faces that meet there, never slip between them.
TEST(Box, WatertightAtEdges) {
  const Box b = makeBox(Vec3(-1, -2, -0.5), Vec3(1.5, 2, 3));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0, 1), along(0.05, 0.95);
  int rays = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const int j = (axis + 1) % 3, k = (axis + 2) % 3;
    for (int side = 0; side < 4; ++side) {
      for (int i = 0; i < 500; ++i) {
        Vec3 p, d;
        p[axis] = b.lo[axis] + along(rng) * (b.hi[axis] - b.lo[axis]);
        p[j] = (side & 1) ? b.hi[j] : b.lo[j];
        p[k] = (side & 2) ? b.hi[k] : b.lo[k];
        // Into the box through both faces: toward the inside on j and k.
        d[axis] = unit(rng) - 0.5;
        d[j] = ((side & 1) ? -1 : 1) * (0.01 + unit(rng));
        d[k] = ((side & 2) ? -1 : 1) * (0.01 + unit(rng));
        d = glm::normalize(d);
        const Ray r{p - 3.0 * d, d};
        double t = 0;
        ASSERT_TRUE(intersect(b, r, Interval{}, t)) << axis << " " << side << " " << i;
        // The origin's round-off, divided by a direction component as small as 0.007.
        EXPECT_NEAR(t, 3.0, 1e-12);
        ASSERT_EQ(crossingsOf(b, r).size(), 2u);
        ++rays;
      }
    }
  }
  EXPECT_EQ(rays, 6000);
}

TEST(Box, FarFromTheOriginTinyAndHuge) {
  double t = 0;
  const Box far = makeBox(Vec3(1e6), Vec3(1e6 + 1));
  ASSERT_TRUE(intersect(far, ray({1e6 + 0.5, 1e6 + 0.25, 1e6 - 10}, {0, 0, 1}), Interval{}, t));
  EXPECT_EQ(t, 10.0);
  const Box tiny = makeBox(Vec3(0), Vec3(1e-9));
  ASSERT_TRUE(intersect(tiny, ray({5e-10, 5e-10, -1}, {0, 0, 1}), Interval{}, t));
  EXPECT_NEAR(t, 1.0, 1e-16);
  ASSERT_TRUE(intersect(tiny, ray({5e-10, 5e-10, -1}, {0, 0, 1}), Interval{1.0, 2.0}, t));
  EXPECT_NEAR(t, 1.0 + 1e-9, 1e-16);
  const Box huge = makeBox(Vec3(-1e20), Vec3(1e20));
  ASSERT_TRUE(intersect(huge, ray({0, 0, -3e20}, {0, 0, 1}), Interval{}, t));
  EXPECT_EQ(t, 2e20);
}

// Rotated and stretched: the faces move as the map says, and the normals
// follow the inverse transpose.
TEST(Box, UnderRotationScaleAndShear) {
  const double c = std::sqrt(0.5);
  double t = 0;
  // Stretched along x, then turned 45 degrees about z: faces at 2 and 1.
  const Scene turned =
      parseScene("push rotate 0 0 1 45 scale 2 1 1 box -1 -1 -1 1 1 1 pop\n", "t.sc");
  ASSERT_EQ(turned.shapes<Box>().size(), 1u);
  const Box& a = turned.shapes<Box>()[0];
  EXPECT_FALSE(isWorldAligned(a));
  ASSERT_TRUE(intersect(a, ray({0, 0, 0}, {c, c, 0}), Interval{}, t));
  EXPECT_NEAR(t, 2.0, 1e-14);
  test::expectCloseTo(normalAt(a, Vec3(c * t, c * t, 0)), Vec3(c, c, 0), 1e-14);
  ASSERT_TRUE(intersect(a, ray({0, 0, 0}, {-c, c, 0}), Interval{}, t));
  EXPECT_NEAR(t, 1.0, 1e-14);
  // Turned, then stretched along x: a sheared solid. The object face x = 1
  // becomes c x / 2 + c y = 1, normal (1, 2, 0) / sqrt 5, at distance
  // 1 / sqrt(c^2 / 4 + c^2) from the origin.
  const Scene sheared =
      parseScene("push scale 2 1 1 rotate 0 0 1 45 box -1 -1 -1 1 1 1 pop\n", "t.sc");
  const Box& s = sheared.shapes<Box>()[0];
  const Vec3 n = glm::normalize(Vec3(1, 2, 0));
  ASSERT_TRUE(intersect(s, ray({0, 0, 0}, n), Interval{}, t));
  EXPECT_NEAR(t, 1.0 / std::sqrt(0.125 + 0.5), 1e-14);
  test::expectCloseTo(normalAt(s, t * n), n, 1e-14);
  // A translation and a mirror keep the box in world coordinates.
  const Scene moved = parseScene("translate 1 2 3 scale -1 1 2 box 0 0 0 1 1 1\n", "t.sc");
  const Box& m = moved.shapes<Box>()[0];
  EXPECT_TRUE(isWorldAligned(m));
  EXPECT_EQ(m.lo, Vec3(0, 2, 3));
  EXPECT_EQ(m.hi, Vec3(1, 3, 5));
}

// Circular solids squashed 1e160 times along their axis (circular, so no
// stretch limit applies): their frame gradients are 1e160 long, and the
// normals still come out unit length and right.
TEST(Solids, NormalsOfVeryFlatSolids) {
  const Scene s = parseScene("push scale 1e-160 1 1 disc 0 0 0  1 0 0  1 pop\n"
                             "push scale 1 1 1e-160 cylinder 0 0 0  0 0 1  1\n"
                             "  capped_cone 0 0 0 1  0 0 1 0.5 pop\n",
                             "t.sc");
  ASSERT_EQ(s.shapes<Disc>().size(), 1u);
  ASSERT_EQ(s.shapes<CappedCone>().size(), 2u);
  test::expectCloseTo(normalAt(s.shapes<Disc>()[0], Vec3(0)), Vec3(1, 0, 0), 1e-15);
  for (const CappedCone& c : s.shapes<CappedCone>()) {
    test::expectCloseTo(normalAt(c, Vec3(0.1, 0, 1e-160)), Vec3(0, 0, 1), 1e-15);
    test::expectCloseTo(normalAt(c, Vec3(0.1, 0.1, 0)), Vec3(0, 0, -1), 1e-15);
  }
  // The frustum's side, 1e160 times flatter than 45 degrees: along the axis.
  test::expectCloseTo(normalAt(s.shapes<CappedCone>()[1], Vec3(0.75, 0, 0.5e-160)), Vec3(0, 0, 1),
                      1e-15);
}

TEST(Box, FaceCoordinates) {
  const Box b = unitBox();
  // On the x = 1 face (part 1) u runs along y and v along z.
  EXPECT_EQ(uvAt(b, Vec3(1, 0.5, 0.75)), Vec2(0.25, 0.25));
  // On the x = 0 face u runs the other way, so it turns the same way seen
  // from outside.
  EXPECT_EQ(uvAt(b, Vec3(0, 0.5, 0.75)), Vec2(0.75, 0.25));
  // The top (z = 3): u along x, v along y.
  EXPECT_EQ(uvAt(b, Vec3(0.25, 1.5, 3)), Vec2(0.25, 0.75));
}

// ---------------------------------------------------------------------------
// Discs

TEST(Disc, HitsFromBothSidesWithTheOneNormal) {
  const Disc d = makeDisc(Vec3(1, 2, 3), Vec3(0, 0, 2), 2.0);
  double t = 0;
  ASSERT_TRUE(intersect(d, ray({1, 2, 10}, {0, 0, -1}), Interval{}, t));
  EXPECT_EQ(t, 7.0);
  EXPECT_EQ(normalAt(d, Vec3(1, 2, 3)), Vec3(0, 0, 1));
  ASSERT_TRUE(intersect(d, ray({1.5, 2, -1}, {0, 0, 1}), Interval{}, t));
  EXPECT_EQ(t, 4.0);
  // The rim is part of the disc; just beyond it is not.
  EXPECT_TRUE(intersect(d, ray({3, 2, 10}, {0, 0, -1}), Interval{}, t));
  EXPECT_FALSE(intersect(d, ray({std::nextafter(3.0, 4.0), 2, 10}, {0, 0, -1}), Interval{}, t));
  // In the plane or parallel to it: never, and no NaN.
  EXPECT_FALSE(intersect(d, ray({-5, 2, 3}, {1, 0, 0}), Interval{}, t));
  EXPECT_FALSE(intersect(d, ray({-5, 2, 4}, {1, 0, 0}), Interval{}, t));
  // Behind the range's start.
  EXPECT_FALSE(intersect(d, ray({1, 2, 10}, {0, 0, -1}), Interval{7.0, 100}, t));
}

TEST(Disc, TiltedFarTinyAndCoordinates) {
  double t = 0;
  const Disc tilted = makeDisc(Vec3(0), Vec3(1, 1, 0), 2.0);
  ASSERT_TRUE(intersect(tilted, ray({5, 1, 0}, {-1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 6.0, 1e-14); // at (-1, 1, 0), sqrt 2 from the centre
  test::expectCloseTo(normalAt(tilted, Vec3(-1, 1, 0)), glm::normalize(Vec3(1, 1, 0)), 1e-15);
  const Disc far = makeDisc(Vec3(1e6, -1e6, 1e6), Vec3(0, 1, 0), 1.0);
  ASSERT_TRUE(intersect(far, ray({1e6 + 0.5, -1e6 + 20, 1e6}, {0, -1, 0}), Interval{}, t));
  EXPECT_EQ(t, 20.0);
  const Disc tiny = makeDisc(Vec3(0), Vec3(0, 0, 1), 1e-10);
  EXPECT_TRUE(intersect(tiny, ray({0.9e-10, 0, 1}, {0, 0, -1}), Interval{}, t));
  EXPECT_FALSE(intersect(tiny, ray({1.1e-10, 0, 1}, {0, 0, -1}), Interval{}, t));
  // v is the distance from the centre as a fraction of the radius.
  const Disc flat = makeDisc(Vec3(0), Vec3(0, 0, 1), 2.0);
  EXPECT_NEAR(uvAt(flat, Vec3(1, 0, 0)).y, 0.5, 1e-15);
  EXPECT_NEAR(uvAt(flat, Vec3(0, -2, 0)).y, 1.0, 1e-15);
  // Half a turn apart, u differs by a half.
  EXPECT_NEAR(std::abs(uvAt(flat, Vec3(1, 0, 0)).x - uvAt(flat, Vec3(-1, 0, 0)).x), 0.5, 1e-15);
}

TEST(Disc, StretchedIntoAnEllipse) {
  // The disc in the plane x + y = 0 stretched twice along x: the plane
  // x / 2 + y = 0, normal (1, 2, 0) / sqrt 5; its rim point along (1, -1, 0)
  // / sqrt 2 moves to (sqrt 2, -1 / sqrt 2, 0).
  const Scene s = parseScene("scale 2 1 1 disc 0 0 0  1 1 0  1\n", "t.sc");
  ASSERT_EQ(s.shapes<Disc>().size(), 1u);
  const Disc& d = s.shapes<Disc>()[0];
  EXPECT_FALSE(isCircular(d));
  const Vec3 n = glm::normalize(Vec3(1, 2, 0));
  double t = 0;
  ASSERT_TRUE(intersect(d, ray(5.0 * n, -n), Interval{}, t));
  EXPECT_NEAR(t, 5.0, 1e-14);
  test::expectCloseTo(normalAt(d, Vec3(0)), n, 1e-15);
  const Vec3 rim(std::sqrt(2.0), -std::sqrt(0.5), 0);
  EXPECT_TRUE(intersect(d, ray(rim * (1 - 1e-9) + n, -n), Interval{}, t));
  EXPECT_FALSE(intersect(d, ray(rim * (1 + 1e-9) + n, -n), Interval{}, t));
}

// ---------------------------------------------------------------------------
// Capped cones and cylinders

// Radius 1 around the z axis from z = 0 to z = 2.
CappedCone unitCylinder() { return makeCappedCone(Vec3(0), 1.0, Vec3(0, 0, 2), 1.0); }

TEST(CappedCone, CylinderSideAndCaps) {
  const CappedCone c = unitCylinder();
  double t = 0;
  const Ray side = ray({-5, 0, 1}, {1, 0, 0});
  ASSERT_TRUE(intersect(c, side, Interval{}, t));
  EXPECT_EQ(t, 4.0);
  SurfacePoint s = surfaceAt(c, kNoArrays, side.at(t));
  EXPECT_EQ(s.part, CappedCone::kSide);
  test::expectCloseTo(s.outward, Vec3(-1, 0, 0), 1e-15);
  // Along the axis, off it: in through the base cap, out through the apex cap.
  const Ray up = ray({0.5, 0.2, -3}, {0, 0, 1});
  ASSERT_TRUE(intersect(c, up, Interval{}, t));
  EXPECT_EQ(t, 3.0);
  s = surfaceAt(c, kNoArrays, up.at(t));
  EXPECT_EQ(s.part, CappedCone::kBaseCap);
  EXPECT_EQ(s.outward, Vec3(0, 0, -1));
  const std::vector<Crossing> x = crossingsOf(c, up);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_EQ(x[0].t, 3.0);
  EXPECT_TRUE(x[0].entering);
  EXPECT_EQ(x[0].part, CappedCone::kBaseCap);
  EXPECT_EQ(x[1].t, 5.0);
  EXPECT_FALSE(x[1].entering);
  EXPECT_EQ(x[1].part, CappedCone::kApexCap);
  EXPECT_EQ(normalAt(c, up.at(5.0)), Vec3(0, 0, 1));
  // In through the side, out through the top.
  const Ray slant = ray({-2, 0, 0}, {1, 0, 1});
  const std::vector<Crossing> y = crossingsOf(c, slant);
  ASSERT_EQ(y.size(), 2u);
  EXPECT_NEAR(y[0].t, std::sqrt(2.0), 1e-15);
  EXPECT_EQ(y[0].part, CappedCone::kSide);
  EXPECT_NEAR(y[1].t, 2 * std::sqrt(2.0), 1e-15);
  EXPECT_EQ(y[1].part, CappedCone::kApexCap);
}

TEST(CappedCone, FromInsideGrazingAndInACapPlane) {
  const CappedCone c = unitCylinder();
  double t = 0;
  const Ray out = ray({0, 0, 1}, {0, 1, 0});
  ASSERT_TRUE(intersect(c, out, Interval{}, t));
  EXPECT_EQ(t, 1.0);
  test::expectCloseTo(normalAt(c, out.at(t)), Vec3(0, 1, 0), 1e-15);
  const std::vector<Crossing> ahead = crossingsOf(c, out);
  ASSERT_EQ(ahead.size(), 1u);
  EXPECT_FALSE(ahead[0].entering);
  // Tangent to the side: touches, never inside.
  const Ray tangent = ray({1, -5, 1}, {0, 1, 0});
  ASSERT_TRUE(intersect(c, tangent, Interval{}, t));
  EXPECT_EQ(t, 5.0);
  EXPECT_TRUE(crossingsOf(c, tangent).empty());
  // Just outside the side, and just above the top: misses, no NaN.
  EXPECT_FALSE(intersect(c, ray({1 + 1e-12, -5, 1}, {0, 1, 0}), Interval{}, t));
  EXPECT_FALSE(intersect(c, ray({-5, 0, std::nextafter(2.0, 3.0)}, {1, 0, 0}), Interval{}, t));
  // In the top cap's plane: across the cap from rim to rim.
  ASSERT_TRUE(intersect(c, ray({-5, 0, 2}, {1, 0, 0}), Interval{}, t));
  EXPECT_EQ(t, 4.0);
}

// Rays aimed exactly at random rim points, entering through both the side
// and the cap there, always hit: the side and the caps share the rim.
TEST(CappedCone, WatertightAtTheRims) {
  const CappedCone shapes[] = {unitCylinder(),
                               makeCappedCone(Vec3(0.3, -1, 2), 2.0, Vec3(1, 2, -1), 0.5)};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (const CappedCone& c : shapes) {
    const Cone& side = c.side;
    for (int i = 0; i < 2000; ++i) {
      const bool apex = i % 2 == 1;
      const double angle = 6.283185307179586 * unit(rng);
      const double radius = apex ? side.apexRadius : side.baseRadius;
      const Vec3 local(radius * std::cos(angle), radius * std::sin(angle), apex ? 1.0 : 0.0);
      const Vec3 p = side.objectToWorld * local + side.objectToWorldOffset;
      // Into the solid across both the side and the cap: against both
      // outward gradients in the frame (the sign of a direction against a
      // gradient is the same in the world), mixed nearly evenly so the
      // direction enters through each even where they meet at a sharp angle.
      const double k = side.apexRadius - side.baseRadius;
      const Vec3 sideOut = glm::normalize(Vec3(std::cos(angle), std::sin(angle), -k));
      const Vec3 capOut(0.0, 0.0, apex ? 1.0 : -1.0);
      const Vec3 tangent(-std::sin(angle), std::cos(angle), 0.0);
      const Vec3 local_d = -(0.95 + 0.05 * unit(rng)) * sideOut -
                           (0.95 + 0.05 * unit(rng)) * capOut + 0.5 * (unit(rng) - 0.5) * tangent;
      ASSERT_LT(glm::dot(local_d, sideOut), 0.0);
      ASSERT_LT(glm::dot(local_d, capOut), 0.0);
      const Vec3 d = glm::normalize(side.objectToWorld * local_d);
      const Ray r{p - 2.0 * d, d};
      double t = 0;
      ASSERT_TRUE(intersect(c, r, Interval{}, t)) << i;
      EXPECT_NEAR(t, 2.0, 1e-13);
      ASSERT_EQ(crossingsOf(c, r).size(), 2u) << i;
    }
  }
}

TEST(CappedCone, PointedConeAndFrustum) {
  // Radius 2 at z = 0 to a point at z = 2: a 45-degree cone.
  const CappedCone pointed = makeCappedCone(Vec3(0), 2.0, Vec3(0, 0, 2), 0.0);
  double t = 0;
  const Ray side = ray({-5, 0, 1}, {1, 0, 0});
  ASSERT_TRUE(intersect(pointed, side, Interval{}, t));
  EXPECT_NEAR(t, 4.0, 1e-15);
  test::expectCloseTo(normalAt(pointed, side.at(t)), glm::normalize(Vec3(-1, 0, 1)), 1e-15);
  // Up the axis: in through the base, out at the tip.
  const Ray axis = ray({0, 0, -3}, {0, 0, 1});
  std::vector<Crossing> x = crossingsOf(pointed, axis);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_EQ(x[0].t, 3.0);
  EXPECT_EQ(x[0].part, CappedCone::kBaseCap);
  EXPECT_NEAR(x[1].t, 5.0, 1e-15);
  EXPECT_EQ(x[1].part, CappedCone::kSide); // the tip: there is no cap of radius 0
  // Down the axis from above: in at the tip (the side's, there is no cap),
  // out through the base.
  x = crossingsOf(pointed, ray({0, 0, 5}, {0, 0, -1}));
  ASSERT_EQ(x.size(), 2u);
  EXPECT_NEAR(x[0].t, 3.0, 1e-15);
  EXPECT_TRUE(x[0].entering);
  EXPECT_EQ(x[0].part, CappedCone::kSide);
  EXPECT_EQ(x[1].t, 5.0);
  EXPECT_EQ(x[1].part, CappedCone::kBaseCap);
  // No cap at the point: whatever is near it is the side.
  EXPECT_EQ(partAt(pointed, Vec3(0.01, 0, 1.99)), CappedCone::kSide);
  // Beyond the tip is the other nappe of the quadric, not the cone.
  EXPECT_FALSE(intersect(pointed, ray({-5, 0, 3}, {1, 0, 0}), Interval{}, t));
  // A frustum, radius 2 at z = 0 and 1 at z = 1: down its axis onto the top.
  const CappedCone frustum = makeCappedCone(Vec3(0), 2.0, Vec3(0, 0, 1), 1.0);
  ASSERT_TRUE(intersect(frustum, ray({0.5, 0, 5}, {0, 0, -1}), Interval{}, t));
  EXPECT_EQ(t, 4.0);
  EXPECT_EQ(partAt(frustum, Vec3(0.5, 0, 1)), CappedCone::kApexCap);
  EXPECT_NEAR(uvAt(frustum, Vec3(0.5, 0, 1)).y, 0.5, 1e-15);
  EXPECT_NEAR(uvAt(frustum, Vec3(0, -1, 0)).y, 0.5, 1e-15);
  // Across at half height (radius 1.5): in and out through the side.
  const Ray steep = ray({-3, 0, 0.5}, {1, 0, 0});
  x = crossingsOf(frustum, steep);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_NEAR(x[0].t, 1.5, 1e-15); // radius 1.5 at z = 0.5
  EXPECT_NEAR(x[1].t, 4.5, 1e-15);
  EXPECT_TRUE(x[0].entering && !x[1].entering);
}

TEST(CappedCone, FarTinyHugeAndTransformed) {
  double t = 0;
  const CappedCone far = makeCappedCone(Vec3(1e6), 1.0, Vec3(1e6, 1e6, 1e6 + 2), 1.0);
  ASSERT_TRUE(intersect(far, ray({1e6 - 10, 1e6, 1e6 + 1}, {1, 0, 0}), Interval{}, t));
  EXPECT_EQ(t, 9.0);
  const CappedCone tiny = makeCappedCone(Vec3(0), 1e-9, Vec3(0, 0, 1e-9), 1e-9);
  ASSERT_TRUE(intersect(tiny, ray({-1, 0, 0.5e-9}, {1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 1.0 - 1e-9, 1e-17);
  const CappedCone huge = makeCappedCone(Vec3(0), 1e20, Vec3(0, 0, 1e20), 1e20);
  ASSERT_TRUE(intersect(huge, ray({0, 0, -1e20}, {0, 0, 1}), Interval{}, t));
  EXPECT_NEAR(t, 1e20, 1e5);
  // Stretched along x: the cross-section is an ellipse with semi-axes 2 and
  // 1; at 45 degrees of the parameter the rim point is (sqrt 2, 1 / sqrt 2)
  // and the normal (1, 2, 0) / sqrt 5.
  const Scene s = parseScene("scale 2 1 1 cylinder 0 0 0  0 0 1  1\n", "t.sc");
  ASSERT_EQ(s.shapes<CappedCone>().size(), 1u);
  const CappedCone& e = s.shapes<CappedCone>()[0];
  ASSERT_TRUE(intersect(e, ray({5, 0, 0.5}, {-1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 3.0, 1e-14);
  const Vec3 n = glm::normalize(Vec3(1, 2, 0));
  const Vec3 p(std::sqrt(2.0), std::sqrt(0.5), 0.5);
  ASSERT_TRUE(intersect(e, ray(p + 5.0 * n, -n), Interval{}, t));
  EXPECT_NEAR(t, 5.0, 1e-14);
  test::expectCloseTo(normalAt(e, p), n, 1e-14);
  // Turned so the axis is x: the caps face -x and +x.
  const Scene r = parseScene("rotate 0 1 0 90 capped_cone 0 0 0 1  0 0 3 0.5\n", "t.sc");
  const CappedCone& turned = r.shapes<CappedCone>()[0];
  ASSERT_TRUE(intersect(turned, ray({-5, 0.1, 0}, {1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 5.0, 1e-14);
  test::expectCloseTo(normalAt(turned, Vec3(0, 0.1, 0)), Vec3(-1, 0, 0), 1e-15);
  ASSERT_TRUE(intersect(turned, ray({9, 0.1, 0}, {-1, 0, 0}), Interval{}, t));
  EXPECT_NEAR(t, 6.0, 1e-14);
  test::expectCloseTo(normalAt(turned, Vec3(3, 0.1, 0)), Vec3(1, 0, 0), 1e-15);
}

// ---------------------------------------------------------------------------
// The .sc commands

TEST(Solids, ScCommandsWithGroupsMaterialsAndTransforms) {
  const Scene s = parseScene("surface 1 0 0 1 0 0 1 1\n"
                             "box 0 0 0 1 1 1\n"
                             "push\n"
                             "  surface 0 1 0 1 0 0 1 1\n"
                             "  translate 10 0 0\n"
                             "  disc 0 0 0  0 1 0  2\n"
                             "  cylinder 0 0 0  0 2 0  0.5\n"
                             "pop\n"
                             "capped_cone 0 0 5 1  0 0 6 0\n",
                             "t.sc");
  ASSERT_EQ(s.shapes<Box>().size(), 1u);
  ASSERT_EQ(s.shapes<Disc>().size(), 1u);
  ASSERT_EQ(s.shapes<CappedCone>().size(), 2u);
  EXPECT_EQ(s.materials[s.shapes<Disc>()[0].material].color, Color(0, 1, 0));
  EXPECT_EQ(s.materials[s.shapes<CappedCone>()[1].material].color, Color(1, 0, 0));
  EXPECT_EQ(s.shapes<Disc>()[0].frame.objectToWorldOffset, Vec3(10, 0, 0));
  EXPECT_EQ(s.shapes<CappedCone>()[0].side.objectToWorldOffset, Vec3(10, 0, 0));
  EXPECT_EQ(s.shapes<CappedCone>()[1].origin.line, 9u);
  EXPECT_EQ(s.groups.size(), 2u);
  EXPECT_EQ(s.kindCounts(), "1 box, 1 disc, 2 capped_cones");
  EXPECT_EQ(s.describe({kindOf<Box>, 0}), "box #0 (t.sc:2)");
}

TEST(Solids, IncludedFiles) {
  test::ScratchDir dir;
  test::writeFile(dir.path() / "part.sc", "box 0 0 0 1 1 1\ndisc 0 0 0 0 0 1 1\n");
  test::writeFile(dir.path() / "main.sc", "push translate 0 0 5 include part.sc pop\n"
                                          "cylinder 0 0 0 0 0 1 1\n");
  const Scene s = loadScene((dir.path() / "main.sc").string());
  ASSERT_EQ(s.shapes<Box>().size(), 1u);
  EXPECT_EQ(s.shapes<Box>()[0].lo, Vec3(0, 0, 5));
  EXPECT_EQ(s.describe({kindOf<Disc>, 0}), "disc #0 (part.sc:2)");
}

TEST(Solids, ScErrors) {
  using test::sceneErrorsOf;
  // box
  EXPECT_EQ(sceneErrorsOf("box 0 0 0 1 1"),
            "t.sc:1:1: error: box: expected Z1 but reached the end of the file");
  EXPECT_EQ(sceneErrorsOf("box 0 0 0 1 nan 1"),
            "t.sc:1:13: error: box: Y1 is not a finite number ('nan')");
  EXPECT_EQ(sceneErrorsOf("box 0 0 0 1 x 1"),
            "t.sc:1:13: error: box: expected Y1 (a number) but found 'x'");
  EXPECT_EQ(sceneErrorsOf("box 0 0 0 1 0 1"),
            "t.sc:1:1: error: box: degenerate box (both corners have the same Y)");
  EXPECT_EQ(sceneErrorsOf("scale 1e-300 1e-300 1e-300 box 0 0 0 1e-30 1e-30 1e-30"),
            "t.sc:1:28: error: box: too large or too small after the current transform");
  EXPECT_EQ(sceneErrorsOf("box 0 0 0 1e31 1 1"),
            "t.sc:1:1: error: box: lies outside the supported range: world coordinates (after "
            "the current transform) must be within +-1e30");
  EXPECT_EQ(sceneErrorsOf("Box 0 0 0 1 1 1"),
            "t.sc:1:1: error: unknown keyword 'Box' (keywords are lower case: 'box')");
  // disc
  EXPECT_EQ(sceneErrorsOf("disc 0 0 0 0 0 0 1"),
            "t.sc:1:12: error: disc: N (NX NY NZ) must not be the zero vector");
  EXPECT_EQ(sceneErrorsOf("disc 0 0 0 0 0 1 -1"), "t.sc:1:18: error: disc: negative radius '-1'");
  EXPECT_EQ(sceneErrorsOf("disc 0 0 0 0 0 1 0"),
            "t.sc:1:18: error: disc: radius must be positive, found '0'");
  EXPECT_EQ(sceneErrorsOf("disc 0 0 0 0 0 1"),
            "t.sc:1:1: error: disc: expected R but reached the end of the file");
  EXPECT_EQ(sceneErrorsOf("disc 0 0 inf 0 0 1 1"),
            "t.sc:1:10: error: disc: CZ is not a finite number ('inf')");
  // cylinder
  EXPECT_EQ(sceneErrorsOf("cylinder 0 0 0 0 0 1 -1"),
            "t.sc:1:22: error: cylinder: negative radius '-1'");
  EXPECT_EQ(sceneErrorsOf("cylinder 0 0 0 0 0 1 0"),
            "t.sc:1:22: error: cylinder: radius must be positive, found '0'");
  EXPECT_EQ(sceneErrorsOf("cylinder 1 2 3 1 2 3 1"),
            "t.sc:1:1: error: cylinder: base and apex are the same point");
  EXPECT_EQ(sceneErrorsOf("cylinder 0 0 0 0 0 1"),
            "t.sc:1:1: error: cylinder: expected R but reached the end of the file");
  // capped_cone
  EXPECT_EQ(sceneErrorsOf("capped_cone 0 0 0 -1 0 0 1 1"),
            "t.sc:1:19: error: capped_cone: negative radius '-1'");
  EXPECT_EQ(sceneErrorsOf("capped_cone 0 0 0 0 0 0 1 0"),
            "t.sc:1:1: error: capped_cone: both radii are zero");
  EXPECT_EQ(sceneErrorsOf("capped_cone 0 0 0 1 0 0 0 1"),
            "t.sc:1:1: error: capped_cone: base and apex are the same point");
  EXPECT_EQ(sceneErrorsOf("scale 1e-200 1e-200 1e-200 capped_cone 0 0 0 1e-200 0 0 1e-200 0"),
            "t.sc:1:28: error: capped_cone: too large or too small after the current transform");
  // Recovery: the next command is read after each error.
  EXPECT_EQ(sceneErrorsOf("box 0 0 0 1 1 light 0 0 0 1 1 1\ndisc 0 0 0 0 0 1 -2"),
            "t.sc:1:15: error: box: expected Z1 (a number) but found 'light'\n"
            "t.sc:2:18: error: disc: negative radius '-2'");
}

// ---------------------------------------------------------------------------
// The hierarchies and the tracer

TEST(Solids, AccelsAgreeWithBruteForce) {
  std::string text;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-10, 10), r(0.1, 1);
  const auto n = [&] { return std::to_string(u(rng)) + " "; };
  const auto rad = [&] { return std::to_string(r(rng)) + " "; };
  for (int i = 0; i < 60; ++i) {
    const double x = u(rng), y = u(rng), z = u(rng);
    text += "box " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + " " +
            std::to_string(x + r(rng)) + " " + std::to_string(y + r(rng)) + " " +
            std::to_string(z + r(rng)) + "\n";
    text += "disc " + n() + n() + n() + n() + n() + n() + rad() + "\n";
    text += "cylinder " + n() + n() + n() + n() + n() + n() + rad() + "\n";
    text += "capped_cone " + n() + n() + n() + rad() + n() + n() + n() + "0\n";
    text += "push rotate " + n() + n() + n() + "33 scale 1 2 0.5 box 0 0 0 1 1 1 pop\n";
  }
  const Scene s = parseScene(text, "t.sc");
  ASSERT_EQ(s.primitiveCount(), 300u);
  EXPECT_GT(test::expectAccelsAgreeWithBruteForce(s, 10.0, 3000), 500);
}

// The tracer's entering/leaving test: a ray from inside a box leaves it
// through the face ahead (the outward normal points along the ray); one from
// outside a cylinder enters it.
TEST(Solids, TheTracerEntersAndLeaves) {
  const Scene s = parseScene("eye 0 0 0  lookat 0 1 0  up 0 0 1\n"
                             "light 0 0 0.5  1 1 1\n"
                             "box -2 -2 -2  2 2 2\n"
                             "cylinder 0 5 -1  0 5 1  0.5\n",
                             "t.sc");
  const auto accel = makeAccel(s, AccelKind::Bvh);
  Tracer tracer(s, *accel, 1);
  RayCounts counts;
  RayTreeNode node;
  tracer.trace(ray({0, 0, 0}, {0, 1, 0}), 1, counts, &node);
  EXPECT_TRUE(node.hit);
  EXPECT_TRUE(node.leaving);
  test::expectCloseTo(node.shadingNormal, Vec3(0, -1, 0), 1e-15);
  RayTreeNode outside;
  tracer.trace(ray({0, 9, 0}, {0, -1, 0}), 1, counts, &outside);
  EXPECT_TRUE(outside.hit);
  EXPECT_FALSE(outside.leaving);
  test::expectCloseTo(outside.shadingNormal, Vec3(0, 1, 0), 1e-15);
}

} // namespace
} // namespace prism
