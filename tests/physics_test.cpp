// The tracer against radiance computed by hand from the model of docs/rendering-model.md: the
// cosine and inverse-square laws, the Phong half-vector highlight, shadows, mirrors, Snell's law,
// total internal reflection, depth limits and ray statistics. Scenes are built in code; every
// expected value is closed-form math written out in the test, never output of the renderer.
#include "core/accel/accel.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"
#include "tests/scene_builder.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace prism {
namespace {

using test::addHorizontalSquare;
using test::addLight;
using test::addMaterial;
using test::addPolygon;
using test::addSphere;
using test::expectVecNear;

constexpr double kPi = std::numbers::pi;

double deg(double degrees) { return degrees * kPi / 180.0; }

struct Traced {
  Color radiance{0.0};
  RayCounts counts;
  RayTreeNode tree;
};

// Traces one eye ray with a ray-tree record, and again without one (which must
// give the same radiance and counts).
Traced run(const Scene& scene, const Ray& ray, int maxDepth, AccelKind kind = AccelKind::Groups) {
  const auto accel = makeAccel(scene, kind);
  Tracer tracer(scene, *accel, maxDepth);
  Traced out;
  out.radiance = tracer.trace(ray, 1, out.counts, &out.tree);
  RayCounts plainCounts;
  const Color plain = tracer.trace(ray, 1, plainCounts);
  EXPECT_EQ(plain, out.radiance);
  EXPECT_EQ(plainCounts, out.counts);
  EXPECT_TRUE(isFinite(out.radiance));
  return out;
}

Ray makeRay(const Vec3& origin, const Vec3& dir) { return {origin, glm::normalize(dir)}; }

// Per channel |got - want| <= rel * max(|want|, floor).
void expectColorNear(const Color& got, const Color& want, double rel = 1e-12,
                     double floor = 1e-12) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], rel * std::max(std::abs(want[c]), floor))
        << "channel " << c << ": got (" << got.x << ", " << got.y << ", " << got.z << ") want ("
        << want.x << ", " << want.y << ", " << want.z << ")";
}

// A scene with one large floor square at z = 0 facing +z.
Scene floorScene(const Material& m, double half = 100.0) {
  Scene scene;
  const std::uint32_t mat = addMaterial(scene, m);
  addHorizontalSquare(scene, 0.0, half, mat);
  return scene;
}

Material makeMaterial(const Color& c, double kdr, double ksr, double kst, double e = 1.0,
                      double ir = 1.0) {
  Material m;
  m.color = c;
  m.kdr = kdr;
  m.ksr = ksr;
  m.kst = kst;
  m.e = e;
  m.ir = ir;
  return m;
}

Ray straightDown(double x, double y, double height = 10.0) {
  return {Vec3(x, y, height), Vec3(0, 0, -1)};
}

// ---------------------------------------------------------------------------
// Diffuse and ambient

TEST(Diffuse, CosineOverDistanceSquared) {
  const Color c(0.9, 0.5, 0.2);
  Scene scene = floorScene(makeMaterial(c, 0.8, 0.0, 0.0));
  const double h = 3.0;
  const Color light(10, 20, 30);
  addLight(scene, Vec3(0, 0, h), light);
  const std::vector<std::pair<double, double>> points{{0, 0},    {1, 0},  {2, 3},
                                                      {-4, 1.5}, {7, -7}, {0.25, -30}};
  for (const auto& [x, y] : points) {
    const Traced tr = run(scene, straightDown(x, y), 4);
    const double r = std::sqrt(x * x + y * y + h * h);
    const double cosine = h / r; // N = +z, L = (−x, −y, h) / r
    expectColorNear(tr.radiance, c * 0.8 * light * (cosine / (r * r)));
    EXPECT_EQ(tr.counts.shadow, 1u);
    EXPECT_EQ(tr.counts.reflected, 0u);
    EXPECT_EQ(tr.counts.transmitted, 0u);
    ASSERT_EQ(tr.tree.lights.size(), 1u);
    EXPECT_NEAR(tr.tree.lights[0].distance, r, 1e-12);
    EXPECT_NEAR(tr.tree.lights[0].cosine, cosine, 1e-12);
    EXPECT_FALSE(tr.tree.lights[0].shadowed);
    EXPECT_TRUE(tr.tree.hit);
    EXPECT_NEAR(tr.tree.where.t, 10.0, 1e-12);
  }
}

TEST(Diffuse, SeveralLightsAddAndOnlyLightsInFrontCastShadowRays) {
  const Color c(0.3, 0.6, 0.9);
  Scene scene = floorScene(makeMaterial(c, 0.8, 0.0, 0.0));
  const Vec3 p(2, -1, 0);
  struct L {
    Vec3 pos;
    Color intensity;
  };
  const std::vector<L> lights{
      {{0, 0, 4}, {5, 5, 5}},         // in front
      {{3, 2, 1}, {1, 2, 3}},         // in front
      {{-6, -1, 0.5}, {7, 1, 0.5}},   // in front, grazing
      {{2, -1, -3}, {100, 100, 100}}, // below the floor: N.L < 0
      {{9, -1, 0}, {100, 100, 100}},  // in the floor's plane: N.L = 0
  };
  Color expected(0.0);
  for (const L& l : lights) {
    addLight(scene, l.pos, l.intensity);
    const Vec3 d = l.pos - p;
    const double r2 = glm::dot(d, d);
    expected += c * 0.8 * l.intensity * (std::max(d.z / std::sqrt(r2), 0.0) / r2);
  }
  const Traced tr = run(scene, straightDown(p.x, p.y), 1);
  expectColorNear(tr.radiance, expected);
  EXPECT_EQ(tr.counts.shadow, 3u);
  ASSERT_EQ(tr.tree.lights.size(), 5u);
  EXPECT_FALSE(tr.tree.lights[0].behind);
  EXPECT_TRUE(tr.tree.lights[3].behind);
  EXPECT_TRUE(tr.tree.lights[4].behind);
}

TEST(Diffuse, AmbientOnly) {
  const Color c(0.5, 1.0, 0.25);
  Scene scene = floorScene(makeMaterial(c, 0.8, 0.0, 0.0));
  scene.ambient = Color(0.1, 0.2, 0.3);
  scene.background = Color(7, 8, 9);
  for (double x : {0.0, 3.0, -50.0}) {
    const Traced tr = run(scene, straightDown(x, 1.0), 3);
    expectColorNear(tr.radiance, c * 0.8 * Color(0.1, 0.2, 0.3));
    EXPECT_EQ(tr.counts.shadow, 0u);
  }
  // Oblique view of the same point: ambient does not depend on the angle.
  const Traced oblique = run(scene, makeRay(Vec3(-5, 1, 1), Vec3(5, 0, -1)), 3);
  expectColorNear(oblique.radiance, c * 0.8 * Color(0.1, 0.2, 0.3));
  // A ray that misses everything sees the background.
  const Traced miss = run(scene, Ray{Vec3(0, 0, 1), Vec3(0, 0, 1)}, 3);
  expectColorNear(miss.radiance, Color(7, 8, 9), 0.0);
  EXPECT_FALSE(miss.tree.hit);
}

// ---------------------------------------------------------------------------
// The Phong half-vector highlight

TEST(Highlight, HalfVectorAt45Degrees) {
  // Eye at (-1,0,1) looking at the origin, light at (0,0,2): L is the normal,
  // -D is 45 degrees from it, so H is 22.5 degrees from the normal.
  const Color light(4, 8, 12);
  for (double e : {1.0, 10.0, 57.0}) {
    Scene scene = floorScene(makeMaterial(Color(0.3, 0.2, 0.1), 0.0, 1.0, 0.0, e));
    scene.background = Color(1.0); // any spawned mirror ray would add this
    addLight(scene, Vec3(0, 0, 2), light);
    const Traced tr = run(scene, makeRay(Vec3(-1, 0, 1), Vec3(1, 0, -1)), 1);
    expectColorNear(tr.radiance, light * (std::pow(std::cos(deg(22.5)), e) / 4.0));
    EXPECT_EQ(tr.counts.reflected, 0u);
    EXPECT_EQ(tr.counts.shadow, 1u);
    expectColorNear(tr.tree.reflected, Color(0.0), 0.0);
  }
}

TEST(Highlight, GeneralPositionWithDiffuse) {
  const Color c(0.8, 0.4, 0.6);
  const double kdr = 0.5, ksr = 0.3, e = 12.0;
  Scene scene = floorScene(makeMaterial(c, kdr, ksr, 0.0, e));
  const Vec3 lightPos(-1, 1.5, 2.5), eye(0.3, -0.7, 2.1), p(0.5, 0.2, 0.0);
  const Color light(2, 3, 5);
  addLight(scene, lightPos, light);
  const Traced tr = run(scene, makeRay(eye, p - eye), 1);
  const Vec3 n(0, 0, 1);
  const double r2 = glm::dot(lightPos - p, lightPos - p);
  const Vec3 l = glm::normalize(lightPos - p), v = glm::normalize(eye - p);
  const Vec3 hv = glm::normalize(l + v);
  const Color want =
      c * kdr * light * (glm::dot(n, l) / r2) + ksr * light * (std::pow(glm::dot(n, hv), e) / r2);
  expectColorNear(tr.radiance, want, 1e-10);
}

TEST(Highlight, ExponentZeroGivesIntensityOverDistanceSquared) {
  const Color light(4, 8, 12);
  Scene scene = floorScene(makeMaterial(Color(1.0), 0.0, 1.0, 0.0, 0.0));
  addLight(scene, Vec3(0, 0, 2), light);
  // Any viewing direction: max(N.H, 0)^0 = 1 where N.L > 0.
  for (const Vec3& eye : {Vec3(-1, 0, 1), Vec3(3, 4, 0.1), Vec3(0, 0, 9)}) {
    const Traced tr = run(scene, makeRay(eye, Vec3(0.0) - eye), 1);
    expectColorNear(tr.radiance, light / 4.0);
  }
  // Seen from far off, the point (-2, 0, 0) lies at r^2 = 8 from the light.
  const Traced tr = run(scene, makeRay(Vec3(-3, 0, 5), Vec3(1, 0, -5)), 1);
  expectColorNear(tr.radiance, light / 8.0);
}

// The highlight's power: whole exponents by repeated squaring, within a few
// ulps of the exact power (long double's powl as the reference); exact where
// the products are; other exponents exactly std::pow.
TEST(Highlight, PowerOfTheCosine) {
  EXPECT_EQ(powNonNegative(0.5, 60.0), std::ldexp(1.0, -60));
  EXPECT_EQ(powNonNegative(0.75, 3.0), 0.421875); // 27/64, exact in binary
  EXPECT_EQ(powNonNegative(0.3, 1.0), 0.3);
  EXPECT_EQ(powNonNegative(0.3, 0.0), 1.0);
  EXPECT_EQ(powNonNegative(0.0, 0.0), 1.0); // as std::pow: 0^0 = 1
  EXPECT_EQ(powNonNegative(0.0, 7.0), 0.0);
  EXPECT_EQ(powNonNegative(1.0, 1024.0), 1.0);
  EXPECT_EQ(powNonNegative(1e-10, 900.0), 0.0); // underflows, no NaN
  for (const double e : {2.5, 0.1, 1025.0, 1e6})
    for (const double x : {0.0, 0.2, 0.9, 1.0})
      EXPECT_EQ(powNonNegative(x, e), std::pow(x, e)) << x << "^" << e;
  for (int e = 0; e <= 1024; e += 7)
    for (double x = 0.05; x <= 1.0; x += 0.0625) {
      const long double exact = powl((long double)x, (long double)e);
      if (exact < 1e-290L) continue; // subnormal results: absolute error only
      EXPECT_LE(std::abs((long double)powNonNegative(x, e) / exact - 1.0L), 1e-13L)
          << x << "^" << e;
    }
}

TEST(Highlight, LightBehindSurfaceGivesNothingAndNoShadowRay) {
  for (double e : {0.0, 1.0, 20.0}) {
    Scene scene = floorScene(makeMaterial(Color(1.0), 0.7, 1.0, 0.0, e));
    addLight(scene, Vec3(0, 0, -2), Color(9.0));
    const Traced tr = run(scene, makeRay(Vec3(-1, 0, 1), Vec3(1, 0, -1)), 1);
    expectColorNear(tr.radiance, Color(0.0), 0.0);
    EXPECT_EQ(tr.counts.shadow, 0u);
    ASSERT_EQ(tr.tree.lights.size(), 1u);
    EXPECT_TRUE(tr.tree.lights[0].behind);
  }
}

TEST(Highlight, BackOfAPolygonIsShadedWithTheFlippedNormal) {
  // Seen from below, the floor's shading normal is -z: a light below lights it,
  // a light above does not (and casts no shadow ray).
  const Color c(0.5, 0.6, 0.7);
  Scene below = floorScene(makeMaterial(c, 1.0, 0.0, 0.0));
  addLight(below, Vec3(0, 0, -2), Color(8.0));
  const Traced lit = run(below, Ray{Vec3(1, 0, -5), Vec3(0, 0, 1)}, 1);
  const double r = std::sqrt(5.0);
  expectColorNear(lit.radiance, c * 8.0 * ((2.0 / r) / 5.0));
  EXPECT_TRUE(lit.tree.leaving);
  expectVecNear(lit.tree.shadingNormal, Vec3(0, 0, -1), 0.0);

  Scene above = floorScene(makeMaterial(c, 1.0, 0.0, 0.0));
  addLight(above, Vec3(0, 0, 2), Color(8.0));
  const Traced dark = run(above, Ray{Vec3(1, 0, -5), Vec3(0, 0, 1)}, 1);
  expectColorNear(dark.radiance, Color(0.0), 0.0);
  EXPECT_EQ(dark.counts.shadow, 0u);
}

// ---------------------------------------------------------------------------
// Shadows

TEST(Shadow, BlockerBetweenPointAndLightLeavesOnlyAmbient) {
  const Color c(0.9, 0.8, 0.7);
  for (AccelKind kind : {AccelKind::Groups, AccelKind::None}) {
    Scene scene = floorScene(makeMaterial(c, 0.8, 0.5, 0.0, 5.0));
    scene.ambient = Color(0.1, 0.1, 0.2);
    const std::uint32_t blockerMat = addMaterial(scene, makeMaterial(Color(1.0), 1.0, 0.0, 0.0));
    // Point (2,0,0), light (0,0,4); the sphere sits on the segment's midpoint.
    const PrimitiveRef blocker = addSphere(scene, Vec3(1, 0, 2), 0.3, blockerMat);
    addLight(scene, Vec3(0, 0, 4), Color(50.0));
    const Traced tr = run(scene, straightDown(2, 0), 1, kind);
    expectColorNear(tr.radiance, c * 0.8 * Color(0.1, 0.1, 0.2));
    EXPECT_EQ(tr.counts.shadow, 1u);
    ASSERT_EQ(tr.tree.lights.size(), 1u);
    EXPECT_TRUE(tr.tree.lights[0].shadowed);
    EXPECT_EQ(tr.tree.lights[0].blocker.primitive, blocker);
  }
}

TEST(Shadow, BlockerBeyondTheLightDoesNotCount) {
  const Color c(0.9, 0.8, 0.7);
  const Color ambient(0.1, 0.1, 0.2), light(50.0);
  const Vec3 lightPos(0, 0, 4), p(2, 0, 0);
  const double r2 = 4.0 + 16.0;
  const Color lit = c * 0.8 * (ambient + light * ((4.0 / std::sqrt(r2)) / r2));
  for (AccelKind kind : {AccelKind::Groups, AccelKind::None}) {
    Scene scene = floorScene(makeMaterial(c, 0.8, 0.0, 0.0));
    scene.ambient = ambient;
    const std::uint32_t m = addMaterial(scene, makeMaterial(Color(1.0), 1.0, 0.0, 0.0));
    // On the line from p through the light, half as far again beyond the light.
    addSphere(scene, p + 1.5 * (lightPos - p), 0.5, m);
    // A large square above everything, facing down.
    addHorizontalSquare(scene, 6.0, 100.0, m, true);
    addLight(scene, lightPos, light);
    const Traced tr = run(scene, straightDown(p.x, p.y, 5.0), 1, kind);
    expectColorNear(tr.radiance, lit);
    EXPECT_EQ(tr.counts.shadow, 1u);
    ASSERT_EQ(tr.tree.lights.size(), 1u);
    EXPECT_FALSE(tr.tree.lights[0].shadowed);
  }
}

// ---------------------------------------------------------------------------
// Mirrors and depth

struct MirrorScene {
  Scene scene;
  Color light{3.0, 2.0, 1.0};
  Color ambient{0.05, 0.1, 0.15};
  Color wallColor{0.2, 0.6, 1.0};
  double wallKdr = 0.9;
  double mirrorKsr = 0.5;
  double mirrorE = 8.0;
};

// A mirror floor (x in [-5, 1.5]) and a diffuse wall in the plane x = 2 facing
// -x; light at (0, 0, 2). The eye ray from (-1, 0, 1) meets the mirror at the
// origin and is reflected to the wall point (2, 0, 2).
MirrorScene mirrorScene(bool withWall) {
  MirrorScene s;
  s.scene.ambient = s.ambient;
  s.scene.background = Color(0.25, 0.5, 0.75);
  const std::uint32_t mirror =
      addMaterial(s.scene, makeMaterial(Color(1.0), 0.0, s.mirrorKsr, 0.0, s.mirrorE));
  const std::uint32_t wall = addMaterial(s.scene, makeMaterial(s.wallColor, s.wallKdr, 0.0, 0.0));
  addPolygon(s.scene, {{-5, -5, 0}, {1.5, -5, 0}, {1.5, 5, 0}, {-5, 5, 0}}, mirror);
  if (withWall) addPolygon(s.scene, {{2, -5, 0.5}, {2, -5, 5}, {2, 5, 5}, {2, 5, 0.5}}, wall);
  addLight(s.scene, Vec3(0, 0, 2), s.light);
  return s;
}

TEST(Mirror, ReflectsALitWall) {
  const MirrorScene s = mirrorScene(true);
  const Ray eye = makeRay(Vec3(-1, 0, 1), Vec3(1, 0, -1));
  // Mirror highlight: N.H = cos 22.5 degrees, r = 2.
  const Color highlight = s.mirrorKsr * s.light * (std::pow(std::cos(deg(22.5)), s.mirrorE) / 4.0);
  // The wall at (2,0,2): normal -x points straight at the light 2 away.
  const Color wallRadiance = s.wallColor * s.wallKdr * (s.ambient + s.light / 4.0);

  const Traced d1 = run(s.scene, eye, 1);
  expectColorNear(d1.radiance, highlight);
  EXPECT_EQ(d1.counts.reflected, 0u);
  EXPECT_EQ(d1.counts.shadow, 1u);
  EXPECT_TRUE(d1.tree.children.empty());

  for (int depth : {2, 3, 7}) {
    const Traced tr = run(s.scene, eye, depth);
    expectColorNear(tr.radiance, highlight + s.mirrorKsr * wallRadiance);
    EXPECT_EQ(tr.counts.reflected, 1u) << depth; // the wall has ksr = 0
    EXPECT_EQ(tr.counts.shadow, 2u);
    ASSERT_EQ(tr.tree.children.size(), 1u);
    const RayTreeNode& child = tr.tree.children[0];
    EXPECT_EQ(child.kind, RayKind::Reflected);
    EXPECT_EQ(child.depth, 2);
    expectVecNear(child.ray.dir, glm::normalize(Vec3(1, 0, 1)), 1e-12);
    ASSERT_TRUE(child.hit);
    expectVecNear(child.point, Vec3(2, 0, 2), 1e-8);
    expectColorNear(child.radiance, wallRadiance, 1e-8);
    expectColorNear(tr.tree.reflected, s.mirrorKsr * wallRadiance, 1e-8);
    expectColorNear(tr.tree.highlight, highlight, 1e-12);
  }
}

TEST(Mirror, ReflectionThatMissesSeesTheBackground) {
  const MirrorScene s = mirrorScene(false);
  const Color highlight = s.mirrorKsr * s.light * (std::pow(std::cos(deg(22.5)), s.mirrorE) / 4.0);
  const Traced tr = run(s.scene, makeRay(Vec3(-1, 0, 1), Vec3(1, 0, -1)), 2);
  expectColorNear(tr.radiance, highlight + s.mirrorKsr * s.scene.background);
  EXPECT_EQ(tr.counts.reflected, 1u);
  ASSERT_EQ(tr.tree.children.size(), 1u);
  EXPECT_FALSE(tr.tree.children[0].hit);
}

// Mirrors at z = 0 (facing up) and z = 1 (facing down), each with a little
// diffuse ambient a = C kdr Ia; an eye ray bounces between them.
Scene facingMirrors(const Color& ambient) {
  Scene scene;
  scene.ambient = ambient;
  scene.background = Color(5.0); // never reached while depth lasts
  const std::uint32_t m = addMaterial(scene, makeMaterial(Color(1.0, 0.5, 0.25), 0.2, 0.5, 0.0));
  addHorizontalSquare(scene, 0.0, 2000.0, m); // wide enough for 1000 bounces at 45 degrees
  addHorizontalSquare(scene, 1.0, 2000.0, m, true);
  return scene;
}

TEST(Mirror, FacingMirrorsStopAtMaxDepth) {
  const Color ia(0.1, 0.2, 0.4);
  const Scene scene = facingMirrors(ia);
  const Color a = Color(1.0, 0.5, 0.25) * 0.2 * ia;
  const Ray eye = makeRay(Vec3(0, 0, 0.5), Vec3(1, 0, -1));
  for (int maxDepth : {1, 2, 5, 50, 1000}) { // 1000: the deepest --depth allows
    const Traced tr = run(scene, eye, maxDepth);
    EXPECT_EQ(tr.counts.reflected, std::uint64_t(maxDepth - 1));
    EXPECT_EQ(tr.counts.shadow, 0u);
    // L_d = a + 0.5 L_{d+1}, L_D = a: a geometric series of D terms.
    const double sum = (1.0 - std::pow(0.5, maxDepth)) / 0.5;
    expectColorNear(tr.radiance, a * sum, 1e-12);
    // Walk the record: one reflected child per level, depths 1..D.
    const RayTreeNode* node = &tr.tree;
    for (int d = 1; d <= maxDepth; ++d) {
      ASSERT_TRUE(node->hit);
      EXPECT_EQ(node->depth, d);
      // Each bounce starts 512 u of its coordinates off the surface (docs/rendering-model.md),
      // which shifts the next hit by as much: summed over 1000 bounces out to x = 1000, 6e-8.
      EXPECT_NEAR(node->point.x, d - 0.5, 1e-6);
      if (d == maxDepth) {
        EXPECT_TRUE(node->children.empty());
      } else {
        ASSERT_EQ(node->children.size(), 1u);
        node = &node->children[0];
      }
    }
  }
}

// ---------------------------------------------------------------------------
// Refraction

TEST(Refraction, SnellThroughASlab) {
  const double ir = 1.5, thickness = 0.8;
  Scene scene;
  scene.background = Color(0.3, 0.5, 0.7);
  const std::uint32_t glass = addMaterial(scene, makeMaterial(Color(1.0), 0.0, 0.0, 1.0, 1.0, ir));
  addHorizontalSquare(scene, 0.0, 50.0, glass);              // top, normal +z
  addHorizontalSquare(scene, -thickness, 50.0, glass, true); // bottom, normal -z
  for (double degrees : {0.0, 20.0, 40.0, 70.0}) {
    const double theta = deg(degrees);
    const double thetaR = std::asin(std::sin(theta) / ir);
    const Vec3 d(std::sin(theta), 0.0, -std::cos(theta));
    const Vec3 start = -2.0 * d; // reaches the top at the origin
    const Traced tr = run(scene, Ray{start, d}, 5);
    EXPECT_EQ(tr.counts.transmitted, 2u) << degrees;
    EXPECT_EQ(tr.counts.reflected, 0u);
    EXPECT_EQ(tr.counts.tirEvents, 0u);
    expectColorNear(tr.radiance, scene.background, 1e-12); // kst = 1 twice, then background

    ASSERT_TRUE(tr.tree.hit);
    EXPECT_FALSE(tr.tree.leaving);
    ASSERT_EQ(tr.tree.children.size(), 1u);
    const RayTreeNode& inside = tr.tree.children[0];
    EXPECT_EQ(inside.kind, RayKind::Transmitted);
    EXPECT_EQ(inside.depth, 2);
    expectVecNear(inside.ray.dir, Vec3(std::sin(thetaR), 0.0, -std::cos(thetaR)), 1e-12);
    ASSERT_TRUE(inside.hit);
    EXPECT_TRUE(inside.leaving); // the bottom's outward normal is -z
    expectVecNear(inside.point, Vec3(thickness * std::tan(thetaR), 0.0, -thickness), 1e-8);

    ASSERT_EQ(inside.children.size(), 1u);
    const RayTreeNode& out = inside.children[0];
    EXPECT_EQ(out.kind, RayKind::Transmitted);
    EXPECT_EQ(out.depth, 3);
    expectVecNear(out.ray.dir, d, 1e-12); // parallel to the incident ray
    EXPECT_FALSE(out.hit);
    // Lateral offset between the exit ray and the incident line.
    const double offset = glm::length(glm::cross(out.ray.origin - start, d));
    EXPECT_NEAR(offset, thickness * std::sin(theta - thetaR) / std::cos(thetaR), 1e-8);
  }
}

TEST(Refraction, BallLensBendsTwiceBySnellsLaw) {
  // A ray parallel to the x axis at height h through a glass sphere of radius R:
  // incidence theta1 = asin(h/R), refraction theta2 = asin(sin(theta1)/ir); it
  // turns by theta1 - theta2 toward the axis on entering and again on leaving,
  // after a chord of 2 R cos(theta2).
  const double radius = 2.0, ir = 1.5;
  Scene scene;
  scene.background = Color(0.3, 0.2, 0.1);
  const std::uint32_t glass = addMaterial(scene, makeMaterial(Color(1.0), 0.0, 0.0, 1.0, 1.0, ir));
  addSphere(scene, Vec3(0.0), radius, glass);
  for (double h : {0.0, 0.5, 1.0, 1.9}) {
    const double theta1 = std::asin(h / radius), theta2 = std::asin(h / radius / ir);
    const double turn = theta1 - theta2;
    const Vec3 entry(-std::sqrt(radius * radius - h * h), h, 0.0);
    const Traced tr = run(scene, Ray{Vec3(-10, h, 0), Vec3(1, 0, 0)}, 4);
    EXPECT_EQ(tr.counts.transmitted, 2u) << h;
    EXPECT_EQ(tr.counts.tirEvents, 0u);
    expectColorNear(tr.radiance, scene.background, 1e-12);
    ASSERT_TRUE(tr.tree.hit);
    EXPECT_FALSE(tr.tree.leaving);
    expectVecNear(tr.tree.point, entry, 1e-12);
    ASSERT_EQ(tr.tree.children.size(), 1u);
    const RayTreeNode& inside = tr.tree.children[0];
    expectVecNear(inside.ray.dir, Vec3(std::cos(turn), -std::sin(turn), 0.0), 1e-12);
    ASSERT_TRUE(inside.hit);
    EXPECT_TRUE(inside.leaving);
    // The inner ray starts 512 u of the coordinates off the surface (docs/rendering-model.md),
    // which moves the exit by about 1e-13 here, far inside the tolerance.
    EXPECT_NEAR(inside.where.t, 2.0 * radius * std::cos(theta2), 1e-7);
    expectVecNear(inside.point, entry + 2.0 * radius * std::cos(theta2) * inside.ray.dir, 1e-7);
    expectVecNear(inside.shadingNormal, -inside.point / radius, 1e-7);
    ASSERT_EQ(inside.children.size(), 1u);
    const RayTreeNode& out = inside.children[0];
    expectVecNear(out.ray.dir, Vec3(std::cos(2 * turn), -std::sin(2 * turn), 0.0), 1e-7);
    EXPECT_FALSE(out.hit);
  }
}

TEST(Refraction, TotalInternalReflectionAtAndPastTheCriticalAngle) {
  // A lone transparent polygon met from its back: leaving, eta = ir.
  const double ir = 1.5, ksr = 0.5, kst = 1.0;
  const double critical = std::asin(1.0 / ir);
  Scene scene;
  scene.background = Color(0.2, 0.4, 0.6);
  const std::uint32_t m = addMaterial(scene, makeMaterial(Color(1.0), 0.0, ksr, kst, 1.0, ir));
  addHorizontalSquare(scene, 0.0, 50.0, m);
  auto fromBelow = [](double theta) {
    const Vec3 d(std::sin(theta), 0.0, std::cos(theta));
    return Ray{-2.0 * d, d};
  };

  const double below = critical - 0.01;
  const Traced t0 = run(scene, fromBelow(below), 3);
  EXPECT_TRUE(t0.tree.leaving);
  EXPECT_EQ(t0.counts.transmitted, 1u);
  EXPECT_EQ(t0.counts.reflected, 1u);
  EXPECT_EQ(t0.counts.tirEvents, 0u);
  EXPECT_FALSE(t0.tree.totalInternalReflection);
  expectColorNear(t0.radiance, (ksr + kst) * scene.background, 1e-12);
  ASSERT_EQ(t0.tree.children.size(), 2u);
  const RayTreeNode& refl = t0.tree.children[0];
  const RayTreeNode& trans = t0.tree.children[1];
  EXPECT_EQ(refl.kind, RayKind::Reflected);
  EXPECT_EQ(trans.kind, RayKind::Transmitted);
  expectVecNear(refl.ray.dir, Vec3(std::sin(below), 0.0, -std::cos(below)), 1e-12);
  const double sinOut = ir * std::sin(below); // Snell: glass to air
  expectVecNear(trans.ray.dir, Vec3(sinOut, 0.0, std::sqrt(1.0 - sinOut * sinOut)), 1e-9);
  const Color reflectedBelow = t0.tree.reflected;
  expectColorNear(reflectedBelow, ksr * scene.background, 1e-12);

  for (double theta : {critical, critical + 0.01, deg(80.0)}) {
    const Traced tr = run(scene, fromBelow(theta), 3);
    EXPECT_TRUE(tr.tree.leaving);
    EXPECT_EQ(tr.counts.transmitted, 0u) << theta;
    EXPECT_EQ(tr.counts.tirEvents, 1u);
    EXPECT_EQ(tr.counts.reflected, 1u);
    EXPECT_TRUE(tr.tree.totalInternalReflection);
    expectColorNear(tr.tree.transmitted, Color(0.0), 0.0);
    // TIR moves no energy: the reflected term is what it is without TIR.
    expectColorNear(tr.tree.reflected, reflectedBelow, 1e-12);
    expectColorNear(tr.radiance, ksr * scene.background, 1e-12);
    ASSERT_EQ(tr.tree.children.size(), 1u);
    EXPECT_EQ(tr.tree.children[0].kind, RayKind::Reflected);
  }

  // The critical angle itself is total internal reflection for any index,
  // however the direction is written down: sin = 1/ir exactly, or via asin.
  for (double index : {1.1, 1.33, 1.5, 1.7, 2.0, 2.42, 3.0}) {
    Scene glass;
    const std::uint32_t g = addMaterial(glass, makeMaterial(Color(1.0), 0.0, ksr, kst, 1.0, index));
    addHorizontalSquare(glass, 0.0, 50.0, g);
    const double s = 1.0 / index;
    const double angle = std::asin(s);
    for (const Vec3& dir :
         {Vec3(s, 0.0, std::sqrt(1.0 - s * s)), Vec3(std::sin(angle), 0.0, std::cos(angle)),
          Vec3(0.0, std::sin(angle), std::cos(angle)),
          glm::normalize(Vec3(s, 0.0, std::sqrt((1.0 - s) * (1.0 + s))))}) {
      const Traced tr = run(glass, Ray{-3.0 * dir, dir}, 2);
      EXPECT_EQ(tr.counts.transmitted, 0u) << "ir " << index;
      EXPECT_EQ(tr.counts.tirEvents, 1u) << "ir " << index;
    }
  }

  // Entering from the front, even at grazing incidence, never reflects totally.
  const Vec3 d(std::sin(deg(89.0)), 0.0, -std::cos(deg(89.0)));
  const Traced front = run(scene, Ray{-2.0 * d, d}, 3);
  EXPECT_FALSE(front.tree.leaving);
  EXPECT_EQ(front.counts.transmitted, 1u);
  EXPECT_EQ(front.counts.tirEvents, 0u);
  ASSERT_EQ(front.tree.children.size(), 2u);
  const double sinIn = std::sin(deg(89.0)) / ir;
  expectVecNear(front.tree.children[1].ray.dir, Vec3(sinIn, 0.0, -std::sqrt(1 - sinIn * sinIn)),
                1e-9);
}

TEST(Refraction, ZeroCoefficientsSpawnNothing) {
  struct Case {
    double ksr, kst;
    std::uint64_t reflected, transmitted;
  };
  for (const Case& k :
       {Case{0.0, 0.0, 0, 0}, Case{0.0, 0.7, 0, 1}, Case{0.6, 0.0, 1, 0}, Case{0.6, 0.7, 1, 1}}) {
    Scene scene = floorScene(makeMaterial(Color(0.5), 0.5, k.ksr, k.kst, 1.0, 1.3));
    scene.background = Color(1.0);
    const Traced tr = run(scene, makeRay(Vec3(-1, 0, 1), Vec3(1, 0, -1)), 5);
    EXPECT_EQ(tr.counts.reflected, k.reflected) << k.ksr << " " << k.kst;
    EXPECT_EQ(tr.counts.transmitted, k.transmitted) << k.ksr << " " << k.kst;
    // Both secondary rays (if any) escape to the background of 1.
    expectColorNear(tr.radiance, Color(k.ksr + k.kst), 1e-12);
  }
}

// ---------------------------------------------------------------------------
// Normals flipped inside a solid

TEST(Inside, PointLightInsideASphereLightsTheInnerWall) {
  const Color c(0.7, 0.8, 0.9);
  const double kdr = 0.6, radius = 10.0;
  const Vec3 lightPos(3, 0, 0);
  const Color light(50.0);
  Scene scene;
  const std::uint32_t m = addMaterial(scene, makeMaterial(c, kdr, 0.0, 0.0));
  addSphere(scene, Vec3(0.0), radius, m);
  addLight(scene, lightPos, light);
  for (const Vec3& dir : {Vec3(0, 0, 1), Vec3(1, 1, 0), Vec3(-1, 0.3, -0.2)}) {
    const Vec3 d = glm::normalize(dir);
    const Traced tr = run(scene, Ray{Vec3(0.0), d}, 1);
    const Vec3 p = radius * d;
    const Vec3 inward = -d; // the outward normal is d; shading uses its flip
    const Vec3 toLight = lightPos - p;
    const double r2 = glm::dot(toLight, toLight);
    const double cosine = glm::dot(inward, toLight) / std::sqrt(r2);
    ASSERT_GT(cosine, 0.0);
    expectColorNear(tr.radiance, c * kdr * light * (cosine / r2), 1e-10);
    EXPECT_TRUE(tr.tree.leaving);
    expectVecNear(tr.tree.shadingNormal, inward, 1e-12);
    EXPECT_EQ(tr.counts.shadow, 1u);
  }
}

TEST(Inside, LightOutsideAClosedSphereLeavesItsInsideDark) {
  const Color c(0.7, 0.8, 0.9);
  Scene scene;
  scene.ambient = Color(0.01, 0.02, 0.03);
  const std::uint32_t m = addMaterial(scene, makeMaterial(c, 0.6, 0.4, 0.0, 3.0));
  addSphere(scene, Vec3(0.0), 10.0, m);
  addLight(scene, Vec3(0, 0, -20), Color(1000.0));
  // The inner wall at (0,0,10) faces the light (N.L = 1) but the far wall blocks it.
  const Traced tr = run(scene, Ray{Vec3(0.0), Vec3(0, 0, 1)}, 1);
  expectColorNear(tr.radiance, c * 0.6 * scene.ambient);
  EXPECT_EQ(tr.counts.shadow, 1u);
  ASSERT_EQ(tr.tree.lights.size(), 1u);
  EXPECT_TRUE(tr.tree.lights[0].shadowed);
}

// ---------------------------------------------------------------------------
// Degenerate light positions and numbers

TEST(Degenerate, LightAtTheShadedPointContributesNothing) {
  const Color c(0.4, 0.5, 0.6);
  Scene scene = floorScene(makeMaterial(c, 0.8, 0.5, 0.0, 3.0));
  scene.ambient = Color(0.1, 0.2, 0.3);
  addLight(scene, Vec3(0.25, 0.5, 0.0), Color(100.0)); // exactly where the ray lands
  const Traced alone = run(scene, straightDown(0.25, 0.5, 5.0), 1);
  expectColorNear(alone.radiance, c * 0.8 * scene.ambient);
  EXPECT_EQ(alone.counts.shadow, 0u);

  // A second light straight above, 2 away: N.L = 1 and H = N, so it adds
  // C kdr I/4 + ksr I/4.
  addLight(scene, Vec3(0.25, 0.5, 2.0), Color(8.0));
  const Traced both = run(scene, straightDown(0.25, 0.5, 5.0), 1);
  expectColorNear(both.radiance, c * 0.8 * (scene.ambient + Color(2.0)) + 0.5 * Color(2.0));
  EXPECT_EQ(both.counts.shadow, 1u);
}

TEST(Degenerate, GrazingAndTangentRaysStayFinite) {
  Scene scene;
  scene.ambient = Color(0.1);
  scene.background = Color(0.2, 0.3, 0.4);
  const std::uint32_t glass =
      addMaterial(scene, makeMaterial(Color(0.9), 0.2, 0.4, 0.6, 20.0, 1.5));
  addHorizontalSquare(scene, 0.0, 100.0, glass);
  addSphere(scene, Vec3(0, 0, 2), 1.0, glass);
  addLight(scene, Vec3(3, 3, 5), Color(20.0));
  addLight(scene, Vec3(0, 0, 1e-300), Color(20.0)); // almost on the floor

  // Exactly tangent to the sphere at (0, 1, 2): N.D = 0 counts as entering.
  const Traced tangent = run(scene, Ray{Vec3(-5, 1, 2), Vec3(1, 0, 0)}, 10);
  ASSERT_TRUE(tangent.tree.hit);
  EXPECT_EQ(tangent.tree.where.primitive.kind, kindOf<Sphere>);
  EXPECT_FALSE(tangent.tree.leaving);
  EXPECT_GE(tangent.counts.transmitted, 1u);

  for (double slope : {1e-3, 1e-8, 1e-12, 1e-15}) {
    for (const Vec3& dir : {Vec3(1, 0, -slope), Vec3(1, 0.3, -slope), Vec3(-1, 0, slope)}) {
      const Traced tr = run(scene, makeRay(Vec3(-50, 0, 50 * slope), dir), 10);
      EXPECT_TRUE(isFinite(tr.radiance)) << slope;
    }
    const Traced nearTangent = run(scene, Ray{Vec3(-5, 1 - slope, 2), Vec3(1, 0, 0)}, 10);
    EXPECT_TRUE(isFinite(nearTangent.radiance)) << slope;
  }
}

TEST(Degenerate, AllBlackSceneIsExactlyBlack) {
  Scene scene; // background and ambient default to black
  const std::uint32_t m = addMaterial(scene, makeMaterial(Color(0.0), 1.0, 0.5, 0.5, 10.0, 1.5));
  addHorizontalSquare(scene, 0.0, 10.0, m);
  addSphere(scene, Vec3(0, 0, 1), 1.0, m);
  addLight(scene, Vec3(1, 2, 3), Color(0.0));
  CameraSpec spec;
  spec.eye = Vec3(0, -6, 3);
  spec.lookat = Vec3(0, 0, 0.5);
  spec.up = Vec3(0, 0, 1);
  const Camera cam(spec, 16, 16);
  const auto accel = makeAccel(scene, AccelKind::Groups);
  Tracer tracer(scene, *accel, 8);
  RayCounts counts;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const Color r = tracer.trace(cam.eyeRay(x + 0.5, y + 0.5), 1, counts);
      EXPECT_EQ(r, Color(0.0)) << x << "," << y;
    }
  EXPECT_GT(counts.reflected + counts.transmitted, 0u);
}

// ---------------------------------------------------------------------------
// Self-intersection: one scene at scales 1e-4, 1 and 1e4

struct ScaledScene {
  Scene scene;
  double scale;
};

// Sphere of radius 1 resting on a floor, one light; coordinates scaled by s
// and the light's intensity by s^2, so every radiance is the same.
constexpr double kFloorHalf = 20.0;
const Vec3 kSphereCentre(0, 0, 1);
const Vec3 kLightPos(3, 1, 3);
const Color kLight(30.0, 25.0, 20.0);
const Color kAmbient(0.05, 0.04, 0.03);
const Material kFloorMat = makeMaterial(Color(0.9, 0.85, 0.8), 0.7, 0.3, 0.0, 15.0);
const Material kBallMat = makeMaterial(Color(0.8, 0.3, 0.2), 0.9, 0.4, 0.0, 30.0);

Scene sphereOnFloor(double s) {
  Scene scene;
  scene.ambient = kAmbient;
  scene.background = Color(0.1, 0.2, 0.3);
  const std::uint32_t floorMat = addMaterial(scene, kFloorMat);
  const std::uint32_t ballMat = addMaterial(scene, kBallMat);
  addHorizontalSquare(scene, 0.0, kFloorHalf * s, floorMat);
  addSphere(scene, kSphereCentre * s, s, ballMat);
  addLight(scene, kLightPos * s, kLight * (s * s));
  scene.camera.eye = Vec3(0, -6, 3.5) * s;
  scene.camera.lookat = Vec3(0, 0, 0.8) * s;
  scene.camera.up = Vec3(0, 0, 1);
  scene.camera.fov = 45;
  return scene;
}

enum class Expect { Value, Ambiguous };

// Independent closed-form shading of an eye ray in the unit-scale scene at
// depth 1 (highlight, no mirror ray): returns Ambiguous near silhouettes and
// shadow boundaries, where round-off may legitimately decide either way.
Expect analyticRadiance(const Ray& ray, Color& out, bool& shadowed) {
  constexpr double margin = 1e-6;
  shadowed = false;
  // Sphere: |o + t d - c|^2 = 1.
  const Vec3 f = ray.origin - kSphereCentre;
  const double b = glm::dot(f, ray.dir);
  const double closest2 = glm::dot(f, f) - b * b; // squared distance of the line to c
  if (std::abs(std::sqrt(std::max(closest2, 0.0)) - 1.0) < margin) return Expect::Ambiguous;
  double t = std::numeric_limits<double>::infinity();
  Vec3 n(0.0);
  Material m;
  bool onFloor = false;
  if (closest2 < 1.0 && -b - std::sqrt(1.0 - closest2) > 0) {
    t = -b - std::sqrt(1.0 - closest2);
    n = glm::normalize(ray.at(t) - kSphereCentre);
    m = kBallMat;
  }
  if (ray.dir.z < 0) {
    const double tf = -ray.origin.z / ray.dir.z;
    const Vec3 p = ray.at(tf);
    if (tf < t && std::abs(p.x) < kFloorHalf && std::abs(p.y) < kFloorHalf) {
      t = tf;
      n = Vec3(0, 0, 1);
      m = kFloorMat;
      onFloor = true;
    }
  }
  if (!std::isfinite(t)) {
    out = Color(0.1, 0.2, 0.3);
    return Expect::Value;
  }
  const Vec3 p = ray.at(t);
  const Vec3 toLight = kLightPos - p;
  const double r2 = glm::dot(toLight, toLight);
  const Vec3 l = toLight / std::sqrt(r2);
  const double cosine = glm::dot(n, l);
  if (std::abs(cosine) < margin) return Expect::Ambiguous;
  if (cosine > 0 && onFloor) {
    // Floor point: shadowed iff the segment to the light passes within 1 of c.
    const double along = std::clamp(glm::dot(kSphereCentre - p, l), 0.0, std::sqrt(r2));
    const double dist = glm::length(p + along * l - kSphereCentre);
    if (std::abs(dist - 1.0) < margin) return Expect::Ambiguous;
    shadowed = dist < 1.0;
  }
  out = m.color * m.kdr * kAmbient;
  if (cosine > 0 && !shadowed) {
    const Vec3 h = glm::normalize(l - ray.dir);
    out += m.color * m.kdr * kLight * (cosine / r2) +
           m.ksr * kLight * (std::pow(std::max(glm::dot(n, h), 0.0), m.e) / r2);
  }
  return Expect::Value;
}

std::vector<Color> renderGrid(const Scene& scene, int size, int maxDepth, RayCounts& counts) {
  const auto accel = makeAccel(scene, AccelKind::Groups);
  Tracer tracer(scene, *accel, maxDepth);
  const Camera cam(scene.camera, size, size);
  std::vector<Color> out;
  out.reserve(std::size_t(size * size));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      out.push_back(tracer.trace(cam.eyeRay(x + 0.5, y + 0.5), 1, counts));
  return out;
}

TEST(SelfIntersection, SameRadianceFromScale1em4To1e4AndNoFalseShadows) {
  constexpr int kSize = 64;
  const Camera unitCam(sphereOnFloor(1.0).camera, kSize, kSize);
  std::vector<std::optional<Color>> expected;
  int ambiguous = 0, shadowedCount = 0, litCount = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      Color c;
      bool shadowed = false;
      if (analyticRadiance(unitCam.eyeRay(x + 0.5, y + 0.5), c, shadowed) == Expect::Ambiguous) {
        expected.emplace_back();
        ++ambiguous;
      } else {
        expected.emplace_back(c);
        (shadowed ? shadowedCount : litCount) += 1;
      }
    }
  ASSERT_LT(ambiguous, kSize * kSize / 100);
  ASSERT_GT(shadowedCount, 50); // the picture does contain a shadow
  ASSERT_GT(litCount, 1000);

  for (double s : {1e-4, 1.0, 1e4}) {
    const Scene scene = sphereOnFloor(s);
    RayCounts counts;
    const std::vector<Color> got = renderGrid(scene, kSize, 1, counts);
    EXPECT_EQ(counts.reflected, 0u);
    int wrong = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
      ASSERT_TRUE(isFinite(got[i]));
      if (!expected[i]) continue;
      const Color& want = *expected[i];
      const double tol = 1e-6 * maxComponent(glm::abs(want)) + 1e-12;
      if (maxAbsComponent(got[i] - want) > tol) {
        if (++wrong <= 5)
          ADD_FAILURE() << "scale " << s << " pixel " << i % kSize << "," << i / kSize << ": got ("
                        << got[i].x << ", " << got[i].y << ", " << got[i].z << ") want (" << want.x
                        << ", " << want.y << ", " << want.z << ")";
      }
    }
    EXPECT_EQ(wrong, 0) << "scale " << s;
  }
}

TEST(SelfIntersection, RecursiveImagesAgreeAcrossScales) {
  constexpr int kSize = 64;
  RayCounts unitCounts;
  const std::vector<Color> unit = renderGrid(sphereOnFloor(1.0), kSize, 4, unitCounts);
  EXPECT_GT(unitCounts.reflected, 0u);
  for (double s : {1e-4, 1e4}) {
    RayCounts counts;
    const std::vector<Color> got = renderGrid(sphereOnFloor(s), kSize, 4, counts);
    int differ = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
      ASSERT_TRUE(isFinite(got[i]));
      const double tol = 1e-6 * maxComponent(glm::abs(unit[i])) + 1e-12;
      if (maxAbsComponent(got[i] - unit[i]) > tol) ++differ;
    }
    EXPECT_EQ(differ, 0) << "scale " << s;
    EXPECT_EQ(counts.shadow, unitCounts.shadow) << "scale " << s;
    EXPECT_EQ(counts.reflected, unitCounts.reflected) << "scale " << s;
  }
}

} // namespace
} // namespace prism
