// --no-aa (RenderSettings::noAa): pass 1 alone. Its counts per eye ray are
// those of a plain one-ray-per-pixel Whitted trace of the same scene, summed
// here by tracing every pixel centre with a Tracer directly (no pass
// schedule, no bundles), and its picture is the pass-1 centres of a normal
// render.
#include "core/render/pass_schedule.h"
#include "core/render/renderer.h"
#include "core/render/stats.h"
#include "tests/render_fixtures.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace prism {
namespace {

using test::shipped;
using test::smallSettings;

struct PlainTrace {
  std::vector<Rgb> radiance; // row-major
  RayCounts counts;          // eye rays not included: the Tracer counts only what it starts
};

// One eye ray through each pixel centre, each traced alone.
PlainTrace onePerPixel(const Scene& scene, const Accel& accel, const RenderSettings& s) {
  const Camera camera(scene.camera, s.width, s.height);
  Tracer tracer(scene, accel, s.maxDepth);
  PlainTrace out;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      out.radiance.push_back(toRgb(tracer.trace(camera.eyeRay(x + 0.5, y + 0.5), 1, out.counts)));
  return out;
}

class NoAa : public testing::TestWithParam<const char*> {};

TEST_P(NoAa, CountsAndPictureAreThoseOfOneRayPerPixel) {
  const Scene scene = shipped(GetParam());
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  RenderSettings settings = smallSettings();
  const RenderResult normal = render(scene, *accel, settings);
  settings.noAa = true;
  const RenderResult plain = render(scene, *accel, settings);
  const PlainTrace expected = onePerPixel(scene, *accel, settings);
  const std::uint64_t pixels = std::uint64_t(settings.width) * std::uint64_t(settings.height);

  EXPECT_EQ(plain.counts.eyePrimary, pixels);
  EXPECT_EQ(plain.counts.eyeAntialias, 0u);
  EXPECT_EQ(plain.supersampledPixels, 0);
  EXPECT_EQ(plain.counts.shadow, expected.counts.shadow);
  EXPECT_EQ(plain.counts.reflected, expected.counts.reflected);
  EXPECT_EQ(plain.counts.transmitted, expected.counts.transmitted);
  EXPECT_EQ(plain.counts.tirEvents, expected.counts.tirEvents);
  EXPECT_EQ(plain.counts.total(), pixels + expected.counts.total());
  // The scenes do antialias normally: the knob changed something.
  EXPECT_GT(normal.supersampledPixels, 0);

  EXPECT_EQ(plain.film.radiance, expected.radiance);
  EXPECT_EQ(plain.film.centre, normal.film.centre);
  EXPECT_EQ(plain.film.radiance, normal.film.centre);
  EXPECT_EQ(plain.avgmax, normal.avgmax); // the exposure is pass 1's, as ever
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, NoAa, testing::Values("table.sc", "glass.sc", "chex.sc"));

TEST(NoAa, StatisticsSayIt) {
  RenderStats stats;
  stats.noAa = true;
  EXPECT_NE(formatStatsText(stats).find("(no antialiasing)"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(formatStatsJson(stats))["no_aa"], true);
  stats.noAa = false;
  EXPECT_EQ(formatStatsText(stats).find("(no antialiasing)"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(formatStatsJson(stats))["no_aa"], false);
}

} // namespace
} // namespace prism
