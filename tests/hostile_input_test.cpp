// Regression tests for input made to break the renderer (issue 10): each case
// is the smallest input that crashed, hung or gave a silently wrong result,
// and each asserts the behaviour the documentation promises instead. The OBJ
// reader's cases live in obj_test.cpp, the triangulator's in
// triangulate_test.cpp.
#include "core/accel/accel.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/render/exposure.h"
#include "core/render/renderer.h"
#include "core/render/tracer.h"
#include "core/scene/camera.h"

#include "tests/scene_builder.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace prism {
namespace {

constexpr AccelKind kEveryAccel[] = {AccelKind::Bvh, AccelKind::Groups, AccelKind::None};

RenderResult renderText(const std::string& text, int width, int height, AccelKind kind,
                        int maxDepth = 5) {
  const Scene scene = parseScene(text, "t.sc");
  const auto accel = makeAccel(scene, kind);
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.maxDepth = maxDepth;
  settings.threads = 1;
  return render(scene, *accel, settings);
}

bool allFinite(const std::vector<Rgb>& pixels) {
  for (const Rgb& p : pixels)
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) return false;
  return true;
}

// Enough spheres that the BVH has inner nodes with unused child slots.
std::string manySpheres() {
  std::string text;
  for (int i = 1; i <= 40; ++i)
    text += "sphere " + std::to_string(i) + " 3 -5 0.3\n";
  return text;
}

// An index of refraction of 1e300 squared is infinite, and infinity times the
// zero sine of normal incidence was a NaN refracted direction; the BVH then
// entered every box, unused slots included, until its stack overflowed.
TEST(Hostile, RefractionWithAnIndexTooLargeToSquareIsTotalReflection) {
  const std::string text = "eye 0 0 5\nlight 0 5 5 1 1 1\nsurface 1 1 1  0 0 1  1 1e300\n"
                           "sphere 0 0 0 1\n" +
                           manySpheres();
  for (AccelKind kind : kEveryAccel) {
    const RenderResult r = renderText(text, 1, 1, kind);
    EXPECT_TRUE(allFinite(r.film.radiance)) << accelKindName(kind);
    // Entering, the index ratio is 1/1e300: the ray goes in. Leaving, 1e300:
    // every direction reflects totally (the critical angle is below 1e-300).
    EXPECT_EQ(r.counts.transmitted, 1) << accelKindName(kind);
    EXPECT_EQ(r.counts.tirEvents, 1) << accelKindName(kind);
  }
}

// Defence in depth: whatever makes a ray with a NaN or an infinity, every
// Accel answers "no hit" instead of walking forever.
TEST(Hostile, NonFiniteRaysHitNothing) {
  const Scene scene = parseScene(manySpheres(), "t.sc");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Ray rays[] = {{Vec3(0, 3, 0), Vec3(nan, 0, -1)},
                      {Vec3(nan, 3, 0), Vec3(0, 0, -1)},
                      {Vec3(0, 3, inf), Vec3(0, 0, -1)},
                      {Vec3(-inf, 3, -5), Vec3(1, 0, 0)}};
  for (AccelKind kind : kEveryAccel) {
    const auto accel = makeAccel(scene, kind);
    for (const Ray& ray : rays) {
      Hit hit;
      EXPECT_FALSE(accel->closestHit(ray, Interval{}, nullptr, hit)) << accelKindName(kind);
      EXPECT_FALSE(accel->anyHit(ray, Interval{}, nullptr)) << accelKindName(kind);
    }
    // The same rays as bundles (one origin each): no hits either.
    for (const Ray& ray : rays) {
      const Ray bundle[4] = {ray, ray, ray, ray};
      Hit hits[4];
      EXPECT_EQ(accel->closestHits(bundle, hits), 0u) << accelKindName(kind);
    }
  }
}

// The radiance of pixel (x, y)'s centre ray, in double precision.
Color centreRadiance(const std::string& text, int width, int height, int x, int y) {
  const Scene scene = parseScene(text, "t.sc");
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  Tracer tracer(scene, *accel, 5);
  RayCounts counts;
  return tracer.trace(Camera(scene.camera, width, height).eyeRay(x + 0.5, y + 0.5), 1, counts);
}

// Lights of 1e308 just above two floors put radiance beyond a double and far
// beyond a float. It saturates: the tracer returns the largest double (never
// NaN, which 0 * inf would be: the left floor has ksr = 0 under an infinite highlight,
// the right one kdr = 0 under an infinite diffuse term), the film holds the
// largest float, and the exposure is finite.
TEST(Hostile, OverflowingRadianceSaturatesInsteadOfBecomingNaN) {
  const std::string text = "eye 0 5 0\nlookat 0 0 0\nup 0 0 -1\nfov 90\n"
                           "light -5 0.1 0 1e308 1e308 1e308\nlight 5 0.1 0 1e308 1e308 1e308\n"
                           "surface 1 1 1 1 0 0 1 1\npolygon 4 -9 0 -9 -9 0 9 0 0 9 0 0 -9\n"
                           "surface 1 1 1 0 1 0 1 1\npolygon 4 0 0 -9 0 0 9 9 0 9 9 0 -9\n";
  const double largestDouble = std::numeric_limits<double>::max();
  EXPECT_EQ(centreRadiance(text, 2, 1, 0, 0), Color(largestDouble)); // diffuse: I / 0.1^2
  EXPECT_EQ(centreRadiance(text, 2, 1, 1, 0), Color(largestDouble)); // highlight
  const RenderResult r = renderText(text, 2, 1, AccelKind::Bvh, 1);
  const float largest = std::numeric_limits<float>::max();
  EXPECT_EQ(r.film.radiance[0], Rgb(largest));
  EXPECT_EQ(r.film.radiance[1], Rgb(largest));
  EXPECT_EQ(r.avgmax, double(largest));
  EXPECT_EQ(exposeChannel(r.film.radiance[0].r, exposureScale(r.avgmax)), 128);

  // Coefficients whose product overflows, under no light: exactly 0.
  EXPECT_EQ(centreRadiance("surface 1e300 1e300 1e300 1e300 0 0 1 1\nsphere 0 0 0 1\n", 1, 1, 0, 0),
            Color(0.0));
}

// A picture so dark that 128 / avgmax is beyond a float: the scale is the
// largest float, and a black pixel stays 0 (infinity times 0 would be NaN).
TEST(Hostile, ExposureOfAnExtremelyDarkPictureIsFinite) {
  const float scale = exposureScale(1e-40);
  EXPECT_EQ(scale, std::numeric_limits<float>::max());
  EXPECT_EQ(exposeChannel(0.0f, scale), 0);
  EXPECT_EQ(exposeChannel(1e-40f, scale), 0);
  EXPECT_EQ(exposeChannel(1e-30f, scale), 255);
  EXPECT_EQ(exposureScale(std::numeric_limits<double>::infinity()), 0.0f);
}

// `levels` nested groups with a sphere in the innermost.
std::string nestedGroups(int levels) {
  std::string text;
  for (int i = 0; i < levels; ++i)
    text += "push ";
  text += "\nsphere 0 0 0 1\n";
  for (int i = 0; i < levels; ++i)
    text += "pop ";
  return text;
}

// 10^5 nested groups (the limit): the groups hierarchy is built without
// recursion (it overflowed the machine stack near 30,800 levels), finds the
// innermost sphere, and the scene writer neither recurses nor indents without
// bound (its output grew with the square of the depth: 2.4 GB here).
TEST(Hostile, GroupsNestedToTheLimitBuildRenderAndWriteBack) {
  const int levels = 100000;
  const Scene scene = parseScene(nestedGroups(levels), "t.sc");
  ASSERT_EQ(scene.groups.size(), std::size_t(levels) + 1);
  for (AccelKind kind : kEveryAccel) {
    const auto accel = makeAccel(scene, kind);
    Hit hit;
    ASSERT_TRUE(accel->closestHit({Vec3(0, 0, 5), Vec3(0, 0, -1)}, Interval{}, nullptr, hit))
        << accelKindName(kind);
    EXPECT_EQ(hit.t, 4.0);
  }
  std::ostringstream out;
  writeScene(out, scene);
  const std::string text = out.str();
  // push and pop per level, each indented by at most 32 spaces.
  EXPECT_LT(text.size(), std::size_t(levels) * 2 * (32 + 6) + 1000);
  const Scene back = parseScene(text, "back.sc");
  EXPECT_EQ(back.groups.size(), scene.groups.size());
  EXPECT_EQ(back.shapes<Sphere>().size(), 1u);
}

// One more level is refused with one located error (each open group costs
// memory), and the parse stops there rather than reporting every later pop.
TEST(Hostile, GroupsNestedBeyondTheLimitAreOneError) {
  const std::string text = nestedGroups(100001);
  EXPECT_EQ(test::sceneErrorsOf(text),
            "t.sc:1:500001: error: push: groups nested more than 100000 deep");
}

} // namespace
} // namespace prism
