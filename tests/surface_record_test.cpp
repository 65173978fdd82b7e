// The surface record: the coordinates (u, v) each kind gives a hit point, the
// material looked up through it, and the crossings closed shapes list for
// CSG. Expected values are worked out by hand from each kind's documented
// parameterisation.
#include "core/render/ray_tree.h"
#include "core/render/tracer.h"
#include "core/shapes/crossings.h"
#include "tests/scene_builder.h"

#include <gtest/gtest.h>

#include <sstream>

namespace prism {
namespace {

constexpr double kEps = 1e-12;

void expectUv(const Vec2& got, double u, double v) {
  EXPECT_NEAR(got.x, u, kEps);
  EXPECT_NEAR(got.y, v, kEps);
}

TEST(SurfaceRecord, SphereLongitudeAndLatitude) {
  Sphere s;
  s.center = {1, 2, 3};
  s.radius = 2;
  expectUv(uvAt(s, s.center + Vec3(0, 0, 2)), 0.5, 0.5);  // facing +z: the middle
  expectUv(uvAt(s, s.center + Vec3(2, 0, 0)), 0.75, 0.5); // a quarter turn on
  expectUv(uvAt(s, s.center + Vec3(-2, 0, 0)), 0.25, 0.5);
  expectUv(uvAt(s, s.center + Vec3(0, 0, -2)), 1.0, 0.5);       // the seam, behind
  EXPECT_NEAR(uvAt(s, s.center + Vec3(0, 2, 0)).y, 1.0, kEps);  // north pole
  EXPECT_NEAR(uvAt(s, s.center + Vec3(0, -2, 0)).y, 0.0, kEps); // south pole
  // 30 degrees north: v = 0.5 + (pi / 6) / pi.
  expectUv(uvAt(s, s.center + 2.0 * Vec3(0, 0.5, std::sqrt(0.75))), 0.5, 0.5 + 1.0 / 6.0);
}

TEST(SurfaceRecord, EllipsoidCoordinatesMoveWithIt) {
  // The unit sphere scaled by (2, 3, 4), then moved to (5, 0, 0).
  const Ellipsoid e = makeEllipsoid(Mat3(Vec3(2, 0, 0), Vec3(0, 3, 0), Vec3(0, 0, 4)), {5, 0, 0});
  expectUv(uvAt(e, Vec3(7, 0, 0)), 0.75, 0.5);
  expectUv(uvAt(e, Vec3(5, 0, 4)), 0.5, 0.5);
  EXPECT_NEAR(uvAt(e, Vec3(5, 3, 0)).y, 1.0, kEps);
}

TEST(SurfaceRecord, ConeAngleAndHeight) {
  const Cone c = makeCone({0, 0, 0}, 1.0, {0, 0, 4}, 1.0);
  // v is the height as a fraction of the axis.
  EXPECT_NEAR(uvAt(c, Vec3(1, 0, 1)).y, 0.25, kEps);
  EXPECT_NEAR(uvAt(c, Vec3(0, 1, 3)).y, 0.75, kEps);
  // A quarter turn apart, at any height: u differs by a quarter (mod 1).
  const double du = uvAt(c, Vec3(0, 1, 2)).x - uvAt(c, Vec3(1, 0, 2)).x;
  EXPECT_NEAR(std::abs(std::remainder(du, 1.0)), 0.25, kEps);
  const double half = uvAt(c, Vec3(-1, 0, 2)).x - uvAt(c, Vec3(1, 0, 2)).x;
  EXPECT_NEAR(std::abs(std::remainder(half, 1.0)), 0.5, kEps);
}

TEST(SurfaceRecord, PolygonPlanarCoordinatesInSceneUnits) {
  Scene scene;
  const auto m = test::addMaterial(scene, Material{});
  // Counterclockwise seen from +z, first edge along +x: u = x, v = y.
  const PrimitiveRef square =
      test::addPolygon(scene, {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, m);
  expectUv(uvAt(scene.shapes<Polygon>()[square.index], scene.arrays(), {1.5, 0.5, 0}), 1.5, 0.5);
  // Standing in the plane x = 3, first edge along +y, facing +x: v = x cross y = +z.
  const PrimitiveRef wall =
      test::addPolygon(scene, {{3, 1, 1}, {3, 4, 1}, {3, 4, 5}, {3, 1, 5}}, m);
  expectUv(uvAt(scene.shapes<Polygon>()[wall.index], scene.arrays(), {3, 2, 4}), 1.0, 3.0);
}

TEST(SurfaceRecord, TriangleBarycentrics) {
  Scene scene;
  scene.meshVertices = {{0, 0, 0}, {4, 0, 0}, {0, 2, 0}};
  Triangle t;
  t.vertex = {0, 1, 2};
  // (1, 1, 0) = a + 0.25 (b - a) + 0.5 (c - a).
  expectUv(uvAt(t, scene.arrays(), {1, 1, 0}), 0.25, 0.5);
  expectUv(uvAt(t, scene.arrays(), {4, 0, 0}), 1.0, 0.0);
}

TEST(SurfaceRecord, SceneFillsMaterialAndCoordinatesOnlyWhenAsked) {
  Scene scene;
  test::addMaterial(scene, Material{});
  Material red;
  red.color = {1, 0, 0};
  red.ksr = 0.25;
  const auto m = test::addMaterial(scene, red);
  const PrimitiveRef ball = test::addSphere(scene, {0, 0, 0}, 1.0, m);
  const SurfacePoint plain = scene.surfaceAt(ball, {1, 0, 0});
  EXPECT_EQ(plain.material, m);
  EXPECT_EQ(plain.part, 0u);
  EXPECT_EQ(plain.uv, Vec2(0.0)); // not computed
  EXPECT_EQ(scene.materialAt(plain), red);
  const SurfacePoint full = scene.surfaceAt(ball, {1, 0, 0}, SurfaceDetail::WithCoordinates);
  expectUv(full.uv, 0.75, 0.5);
  EXPECT_EQ(full.outward, plain.outward);
}

TEST(SurfaceRecord, TheRayTreeShowsTheCoordinates) {
  Scene scene;
  const auto m = test::addMaterial(scene, test::diffuse({0.5, 0.5, 0.5}, 1.0));
  test::addSphere(scene, {0, 0, 0}, 1.0, m);
  const auto accel = makeAccel(scene, AccelKind::None);
  Tracer tracer(scene, *accel, 1);
  RayCounts counts;
  RayTreeNode root;
  tracer.trace({{0, 0, 5}, {0, 0, -1}}, 1, counts, &root);
  ASSERT_TRUE(root.hit);
  expectUv(root.uv, 0.5, 0.5); // the point facing +z
  EXPECT_EQ(root.material, scene.materials[m]);
  std::ostringstream text;
  printRayTree(text, root, scene);
  EXPECT_NE(text.str().find("surface (u, v) = (0.5, 0.5)"), std::string::npos) << text.str();
}

TEST(Crossings, ASphereIsEnteredThenLeft) {
  Sphere s;
  s.radius = 1;
  std::vector<Crossing> out;
  appendCrossings(s, ShapeArrays{}, {{-3, 0, 0}, {1, 0, 0}}, Interval{}, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(out[0].t, 2.0, kEps);
  EXPECT_TRUE(out[0].entering);
  EXPECT_NEAR(out[1].t, 4.0, kEps);
  EXPECT_FALSE(out[1].entering);
  // Only what lies in the range; from inside, only the way out.
  out.clear();
  appendCrossings(s, ShapeArrays{}, {{-3, 0, 0}, {1, 0, 0}}, Interval{0.0, 3.0}, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].entering);
  out.clear();
  appendCrossings(s, ShapeArrays{}, {{0, 0, 0}, {0, 1, 0}}, Interval{}, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].t, 1.0, kEps);
  EXPECT_FALSE(out[0].entering);
  // A tangent ray is never inside; a missing one crosses nothing.
  out.clear();
  appendCrossings(s, ShapeArrays{}, {{-3, 1, 0}, {1, 0, 0}}, Interval{}, out);
  appendCrossings(s, ShapeArrays{}, {{-3, 2, 0}, {1, 0, 0}}, Interval{}, out);
  EXPECT_TRUE(out.empty());
}

TEST(Crossings, AnEllipsoidInWorldUnits) {
  // Stretched to 2 along x: from x = -5 along +x it is entered at t = 3, left at 7.
  const Ellipsoid e = makeEllipsoid(Mat3(Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)), {0, 0, 0});
  std::vector<Crossing> out;
  appendCrossings(e, ShapeArrays{}, {{-5, 0, 0}, {1, 0, 0}}, Interval{}, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(out[0].t, 3.0, kEps);
  EXPECT_TRUE(out[0].entering);
  EXPECT_NEAR(out[1].t, 7.0, kEps);
  EXPECT_FALSE(out[1].entering);
}

} // namespace
} // namespace prism
