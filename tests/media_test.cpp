// Fog and absorbing solids (core/render/media.h) against exp() on segments of
// known length: every expected value below is the formula written out by hand
// for a scene whose distances are chosen to be exact, never the renderer's
// output. Also the .sc keywords, their errors and round trip, the bailout
// bound and the thread count.
#include "core/accel/accel.h"
#include "core/io/pov_writer.h"
#include "core/io/scene_parser.h"
#include "core/io/scene_writer.h"
#include "core/render/bailout.h"
#include "core/render/media.h"
#include "core/render/renderer.h"
#include "core/render/tracer.h"
#include "tests/test_expect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace prism {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Color traced(const Scene& scene, const Vec3& origin, const Vec3& dir, int depth = 5,
             RayTreeNode* record = nullptr) {
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  Tracer tracer(scene, *accel, depth);
  RayCounts counts;
  return tracer.trace({origin, glm::normalize(dir)}, 1, counts, record);
}

void expectColor(const Color& got, const Color& want, double rel = 1e-13) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], rel * std::max(1.0, std::abs(want[c]))) << "channel " << c;
}

// fog(d, L) written out: exp(-density d) L + (1 - exp(-density d)) F.
Color fogged(double density, const Color& fog, double d, const Color& far) {
  const double e = std::exp(-density * d);
  return e * far + (1.0 - e) * fog;
}

TEST(Media, TransmittanceIsExpAndSafeAtTheExtremes) {
  EXPECT_DOUBLE_EQ(transmittance(0.5, 3.0), std::exp(-1.5));
  EXPECT_EQ(transmittance(0.0, kInf), 1.0); // clear across any distance: not 0 * inf
  EXPECT_EQ(transmittance(2.0, kInf), 0.0);
  EXPECT_EQ(transmittance(1e300, 1e300), 0.0);
  // Overflowed radiance through a medium that lets nothing through is 0, not NaN.
  const Color huge(kInf, 1e308, 1.0);
  EXPECT_EQ(throughAbsorber(huge, kInf, Color(1.0)), Color(0.0));
  const Color misty = throughFog(huge, kInf, Fog{Color(0.25, 0.5, 0.75), 1.0});
  EXPECT_EQ(misty, Color(0.25, 0.5, 0.75));
  const Color half = throughFog(Color(1.0), std::log(2.0), Fog{Color(0.0), 1.0});
  expectColor(half, Color(0.5));
}

// A wall at z = -4 lit only by the ambient light: it sends C kdr Ia = 0.5
// back. The eye at the origin sees it through fog 4 away straight ahead, 5
// away along (3, 0, -4).
constexpr const char* kFoggyWall = R"(
fog 0.2 0.4 0.6  0.3
background 0.9 0.1 0.1
ambient 1 1 1
surface 0.5 0.5 0.5  1 0 0  1 1
polygon 4  -50 -50 -4  50 -50 -4  50 50 -4  -50 50 -4
)";

TEST(Media, FogMixesTowardItsColourByDistance) {
  const Scene scene = parseScene(kFoggyWall, "fog.sc");
  const Color fog(0.2, 0.4, 0.6);
  expectColor(traced(scene, Vec3(0.0), {0, 0, -1}), fogged(0.3, fog, 4.0, Color(0.5)));
  expectColor(traced(scene, Vec3(0.0), {3, 0, -4}), fogged(0.3, fog, 5.0, Color(0.5)));
  // A ray that meets nothing crosses infinite fog: the fog's colour, not the background.
  EXPECT_EQ(traced(scene, Vec3(0.0), {0, 0, 1}), fog);
}

TEST(Media, NoFogAtZeroDensity) {
  std::string text = kFoggyWall;
  text.replace(text.find("0.3\n"), 3, "0  ");
  const Scene scene = parseScene(text, "fog.sc");
  EXPECT_FALSE(scene.fog.active());
  EXPECT_EQ(traced(scene, Vec3(0.0), {0, 0, -1}), Color(0.5));
  EXPECT_EQ(traced(scene, Vec3(0.0), {0, 0, 1}), Color(0.9, 0.1, 0.1));
}

// A clear slab of glass of index 1 (rays go straight through) and thickness
// 2, between z = -1 and z = -3, in front of the background.
constexpr const char* kSlab = R"(
background 0.3 0.6 0.9
surface 1 1 1  0 0 1  1 1
absorption 0.5 1 2
box -1 -1 -3  1 1 -1
)";

TEST(Media, AbsorptionIsBeerLambertOverThePathInside) {
  const Scene scene = parseScene(kSlab, "slab.sc");
  const Color b(0.3, 0.6, 0.9), sigma(0.5, 1.0, 2.0);
  const auto expected = [&](double path) {
    return Color(b.r * std::exp(-sigma.r * path), b.g * std::exp(-sigma.g * path),
                 b.b * std::exp(-sigma.b * path));
  };
  expectColor(traced(scene, Vec3(0.0), {0, 0, -1}), expected(2.0));
  // Obliquely the path inside is 2 / cos: 2 sqrt(1.09) along (0.3, 0, -1).
  expectColor(traced(scene, Vec3(0.0), {0.3, 0, -1}), expected(2.0 * std::sqrt(1.09)));
  // Depth 2 stops inside: the refracted ray's own radiance (depth 3) is never traced.
  EXPECT_EQ(traced(scene, Vec3(0.0), {0, 0, -1}, 2), Color(0.0));
}

TEST(Media, FogOutsideTheSolidAbsorptionInside) {
  std::string text = kSlab;
  text = "fog 0.2 0.4 0.6  0.7\n" + text;
  const Scene scene = parseScene(text, "slab.sc");
  const Color fog(0.2, 0.4, 0.6), sigma(0.5, 1.0, 2.0);
  // Eye to the slab: 1 of fog. Inside: 2 of absorption, no fog. Behind it the
  // ray meets nothing: the fog's colour.
  Color inside = fog;
  for (int c = 0; c < 3; ++c)
    inside[c] *= std::exp(-2.0 * sigma[c]);
  RayTreeNode record;
  expectColor(traced(scene, Vec3(0.0), {0, 0, -1}, 5, &record), fogged(0.7, fog, 1.0, inside));
  // The ray tree names each segment's medium.
  EXPECT_EQ(record.medium, SegmentMedium::Fog);
  EXPECT_EQ(record.segmentLength, 1.0);
  ASSERT_EQ(record.children.size(), 1u);
  EXPECT_EQ(record.children[0].medium, SegmentMedium::Absorber);
  EXPECT_NEAR(record.children[0].segmentLength, 2.0, 1e-12);
  EXPECT_NEAR(record.children[0].transmittance.b, std::exp(-4.0), 1e-12 * std::exp(-4.0));
  ASSERT_EQ(record.children[0].children.size(), 1u);
  EXPECT_EQ(record.children[0].children[0].medium, SegmentMedium::Fog);
  EXPECT_EQ(record.children[0].children[0].segmentLength, kInf);
}

// A mirror 2 in front of the eye sends the ray 5 back to a wall behind it
// (z = 3, sending C kdr Ia = 0.5): fog on both segments.
TEST(Media, AMirrorRayStaysInTheFog) {
  const Scene scene = parseScene(R"(
fog 0.1 0.2 0.3  0.25
ambient 1 1 1
surface 1 1 1  0 1 0  1 1
polygon 4  -50 -50 -2  50 -50 -2  50 50 -2  -50 50 -2
surface 0.5 0.5 0.5  1 0 0  1 1
polygon 4  -50 -50 3  -50 50 3  50 50 3  50 -50 3
)",
                                 "mirror.sc");
  const Color fog(0.1, 0.2, 0.3);
  expectColor(traced(scene, Vec3(0.0), {0, 0, -1}),
              fogged(0.25, fog, 2.0, fogged(0.25, fog, 5.0, Color(0.5))));
}

// Eye rays traced as a bundle (how the renderer sends them) meet the same
// fog and absorption as one by one.
TEST(Media, BundlesOfEyeRaysAreFoggedLikeSingleRays) {
  const Scene scene = parseScene(std::string("fog 0.2 0.4 0.6 0.7\nambient 1 1 1\n") + kSlab +
                                     "surface 0.5 0.5 0.5  1 0 0  1 1\n"
                                     "polygon 4  -50 -50 -9  50 -50 -9  50 50 -9  -50 50 -9\n",
                                 "bundle.sc");
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  Tracer tracer(scene, *accel, 5);
  std::vector<Ray> rays;
  for (int i = 0; i < 8; ++i) // through the slab, and past it to the wall
    rays.push_back({Vec3(0.0), glm::normalize(Vec3(0.1 * i, 0.05 * i * i, -1.0))});
  rays.push_back({Vec3(0.0), Vec3(0.0, 1.0, 0.0)});
  std::vector<Color> bundled(rays.size());
  RayCounts counts;
  tracer.traceBundle(rays, bundled, counts);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    RayCounts one;
    EXPECT_EQ(bundled[i], tracer.trace(rays[i], 1, one)) << "ray " << i;
  }
  EXPECT_EQ(bundled[8], Color(0.2, 0.4, 0.6)); // straight up: misses, the fog's colour
}

TEST(Media, TheBailoutBoundCoversTheFogColour) {
  const Scene scene = parseScene(R"(
fog 4 5 6  0.1
background 0.1 0.1 0.1
surface 0.1 0.1 0.1  0.5 0.5 0  1 1
sphere 0 0 -5  1
)",
                                 "b.sc");
  const std::vector<double> beyond = radianceBounds(scene, 3);
  for (int k = 1; k <= 3; ++k)
    EXPECT_GE(beyond[std::size_t(k)], 6.0) << "depth " << k;
}

TEST(Media, SameImageForAnyThreadCount) {
  const Scene scene =
      parseScene(std::string("fog 0.5 0.5 0.5 0.2\nlight 0 5 0  20 20 20\n") + kSlab, "t.sc");
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  RenderSettings s;
  s.width = 40;
  s.height = 30;
  s.thresh = 0.02;
  s.threads = 1;
  const RenderResult one = render(scene, *accel, s);
  s.threads = 2;
  const RenderResult two = render(scene, *accel, s);
  EXPECT_EQ(one.film.radiance, two.film.radiance);
  EXPECT_GT(one.supersampledPixels, 0);
}

TEST(Media, ScLanguage) {
  const Scene scene = parseScene(R"(
fog 0.1 0.2 0.3  0.04
surface 1 1 1  0 0 1  1 1.5
absorption 0.1 0.2 0.3
sphere 0 0 0 1
push
  absorption 1 1 1
  sphere 3 0 0 1
pop
sphere 6 0 0 1
surface 1 1 1  0 0 1  1 1.5
sphere 9 0 0 1
)",
                                 "s.sc");
  EXPECT_EQ(scene.fog.color, Color(0.1, 0.2, 0.3));
  EXPECT_EQ(scene.fog.density, 0.04);
  const auto& spheres = scene.shapes<Sphere>();
  ASSERT_EQ(spheres.size(), 4u);
  EXPECT_EQ(scene.materials[spheres[0].material].absorption, Color(0.1, 0.2, 0.3));
  EXPECT_EQ(scene.materials[spheres[1].material].absorption, Color(1.0));
  // pop restores the surface as it was at push; a new `surface` is clear.
  EXPECT_EQ(spheres[2].material, spheres[0].material);
  EXPECT_EQ(scene.materials[spheres[3].material].absorption, Color(0.0));
  EXPECT_NE(spheres[3].material, spheres[0].material);
}

TEST(Media, ScLanguageErrors) {
  EXPECT_EQ(test::sceneErrorsOf("fog 1 1 1 -0.5\n"),
            "t.sc:1:11: error: fog: DENSITY must not be negative, found '-0.5'");
  EXPECT_NE(test::sceneErrorsOf("fog 1 1 1 0.1\nfog 1 1 1 0.2\n")
                .find("t.sc:2:1: error: duplicate 'fog'"),
            std::string::npos);
  EXPECT_EQ(test::sceneErrorsOf("fog 1 1 1\n"),
            "t.sc:1:1: error: fog: expected DENSITY but reached the end of the file");
  EXPECT_NE(test::sceneErrorsOf("absorption 1 -1 1\n").find("t.sc:1:14: error: absorption"),
            std::string::npos)
      << test::sceneErrorsOf("absorption 1 -1 1\n");
}

TEST(Media, WriterRoundTrip) {
  const Scene scene =
      parseScene(std::string("fog 0.1 0.2 0.3 0.04\nsphere 5 0 0 1\n") + kSlab, "w.sc");
  std::ostringstream text;
  writeScene(text, scene);
  const Scene again = parseScene(text.str(), "again.sc");
  EXPECT_EQ(again.fog.color, scene.fog.color);
  EXPECT_EQ(again.fog.density, scene.fog.density);
  EXPECT_EQ(again.materials, scene.materials);
  // A scene without either writes neither keyword.
  std::ostringstream plain;
  writeScene(plain, parseScene("sphere 0 0 0 1\n", "p.sc"));
  EXPECT_EQ(plain.str().find("fog"), std::string::npos);
  EXPECT_EQ(plain.str().find("absorption"), std::string::npos);
}

// POV-Ray's constant fog and exponential fade are the same formulas: fog
// distance 1 / density; fade_distance 1 / max sigma = 0.5 and fade_color
// 1 - sigma / max sigma = (0.75, 0.5, 0), so (1 - fade_color) / fade_distance
// is sigma again.
TEST(Media, ConvertWritesPovRayFogAndFade) {
  const Scene scene = parseScene(std::string("fog 0.1 0.2 0.3 0.04\n") + kSlab, "p.sc");
  std::ostringstream out;
  writePov(out, scene);
  const std::string text = out.str();
  EXPECT_NE(text.find("fog { fog_type 1 distance 25 color rgb <0.1, 0.2, 0.3> }"),
            std::string::npos)
      << text;
  EXPECT_NE(
      text.find(
          "interior { ior 1 fade_distance 0.5 fade_power 1001 fade_color rgb <0.75, 0.5, 0> }"),
      std::string::npos)
      << text;
  std::ostringstream plain;
  writePov(plain, parseScene("sphere 0 0 0 1\n", "p.sc"));
  EXPECT_EQ(plain.str().find("fog"), std::string::npos);
  EXPECT_EQ(plain.str().find("fade_power 1001"), std::string::npos);
}

} // namespace
} // namespace prism
