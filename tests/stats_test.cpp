// Statistics (docs/statistics.md): counts that can be derived by hand for simple scenes, and
// the identities every render must satisfy.
#include "core/io/scene_parser.h"
#include "core/render/renderer.h"
#include "core/render/stats.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace prism {
namespace {

// A camera looking straight down at a plane far larger than its view: every eye
// ray hits the plane, which faces the camera.
Scene floorScene(const std::string& surface, const std::string& light) {
  return parseScene("eye 0 0 5  lookat 0 0 0  up 0 1 0  fov 40\n" + surface + "\n" + light +
                        "\npolygon 4  -100 -100 0  100 -100 0  100 100 0  -100 100 0\n",
                    "floor.sc");
}

RenderResult renderScene(const Scene& scene, int w, int h, int depth, double thresh) {
  RenderSettings settings;
  settings.width = w;
  settings.height = h;
  settings.maxDepth = depth;
  settings.thresh = thresh;
  const auto accel = makeAccel(scene, AccelKind::Groups);
  return render(scene, *accel, settings);
}

TEST(Stats, OneShadowRayPerHitPerVisibleLight) {
  const Scene scene = floorScene("surface 1 1 1 1 0 0 1 1", "light 0 0 3 10 10 10");
  // thresh 1: the falloff is smooth, no neighbours differ by avgmax, no pass 2.
  const RenderResult r = renderScene(scene, 16, 12, 5, 1.0);
  EXPECT_EQ(r.counts.eyePrimary, 16u * 12u);
  EXPECT_EQ(r.counts.eyeAntialias, 0u);
  EXPECT_EQ(r.counts.shadow, 16u * 12u);
  EXPECT_EQ(r.counts.reflected, 0u);
  EXPECT_EQ(r.counts.transmitted, 0u);
  EXPECT_EQ(r.counts.total(), 2u * 16u * 12u);
}

TEST(Stats, NoShadowRayTowardALightBehindTheSurface) {
  const Scene scene = floorScene("surface 1 1 1 1 0 0 1 1", "light 0 0 -3 10 10 10");
  const RenderResult r = renderScene(scene, 8, 8, 5, 0.0);
  EXPECT_EQ(r.counts.shadow, 0u);
  EXPECT_EQ(r.avgmax, 0.0); // no ambient: the lit side faces away, all black
  EXPECT_EQ(r.supersampledPixels, 0);
}

TEST(Stats, MirrorSpawnsOneReflectedRayPerHitBelowMaxDepth) {
  // A half-mirror floor; the reflected rays go up into the empty sky.
  const Scene scene = floorScene("surface 1 1 1 0.5 0.5 0 10 1", "light 0 0 3 10 10 10");
  const RenderResult d1 = renderScene(scene, 8, 8, 1, 1.0);
  EXPECT_EQ(d1.counts.reflected, 0u);
  const RenderResult d2 = renderScene(scene, 8, 8, 2, 1.0);
  EXPECT_EQ(d2.counts.reflected, 64u);
  EXPECT_EQ(d2.counts.shadow, 64u); // the sky casts no shadow rays
}

TEST(Stats, TotalsAddUpOnARichScene) {
  const Scene scene = parseScene(R"(
    eye 0 1 6  lookat 0 0 0  fov 50  ambient 0.1 0.1 0.1
    light 3 5 4  40 40 40
    light -4 3 2  20 20 30
    surface 0.8 0.8 0.8  0.7 0.3 0  20 1
    polygon 4  -5 -1 -5  -5 -1 5  5 -1 5  5 -1 -5
    surface 1 1 1  0.05 0.2 0.8  50 1.5
    # A glass ellipsoid: unlike a sphere it traps some rays by total internal reflection.
    push scale 1.6 0.6 1 sphere 0 0 0 1 pop
    surface 1 0.2 0.2  0.6 0.4 0  30 1
    sphere 1.8 -0.3 -1 0.7
  )",
                                 "rich.sc");
  const RenderResult r = renderScene(scene, 40, 30, 6, 0.05);
  const RayCounts& c = r.counts;
  EXPECT_EQ(c.eyePrimary, 1200u);
  EXPECT_EQ(c.eyeAntialias, 16u * std::uint64_t(r.supersampledPixels));
  EXPECT_GT(r.supersampledPixels, 0);
  EXPECT_GT(c.transmitted, 0u);
  EXPECT_GT(c.tirEvents, 0u);
  EXPECT_EQ(c.total(), c.eyePrimary + c.eyeAntialias + c.shadow + c.reflected + c.transmitted);

  RenderStats stats;
  stats.width = 40;
  stats.height = 30;
  stats.counts = c;
  stats.supersampledPixels = r.supersampledPixels;
  stats.avgmax = r.avgmax;
  EXPECT_DOUBLE_EQ(stats.raysPerPixel(), double(c.total()) / 1200.0);
  EXPECT_DOUBLE_EQ(stats.supersampledShare(), double(r.supersampledPixels) / 1200.0);

  const auto json = nlohmann::json::parse(formatStatsJson(stats));
  EXPECT_EQ(json["pixels"], 1200);
  EXPECT_EQ(json["rays"]["total"], c.total());
  EXPECT_EQ(json["rays"]["eye"].get<std::uint64_t>() + json["rays"]["shadow"].get<std::uint64_t>() +
                json["rays"]["reflected"].get<std::uint64_t>() +
                json["rays"]["transmitted"].get<std::uint64_t>(),
            c.total());
  EXPECT_DOUBLE_EQ(json["rays_per_pixel"].get<double>(), stats.raysPerPixel());
  EXPECT_EQ(json["tir_events"], c.tirEvents);

  const std::string text = formatStatsText(stats);
  EXPECT_NE(text.find("total rays          " + std::to_string(c.total())), std::string::npos);
  EXPECT_NE(text.find("1200 pixels"), std::string::npos);
}

} // namespace
} // namespace prism

namespace prism {
namespace {

// A distributed render's statistics: one JSON object and one text row per
// rank, and the load balance as the mean CPU over the busiest rank's
// (1.5 and 3.0 seconds: mean 2.25, balance 0.75).
TEST(Stats, RanksOfADistributedRenderAndTheirLoadBalance) {
  RenderStats stats;
  EXPECT_EQ(stats.loadBalance(), 0.0);
  EXPECT_EQ(formatStatsText(stats).find("ranks"), std::string::npos);
  EXPECT_FALSE(nlohmann::json::parse(formatStatsJson(stats)).contains("ranks"));
  stats.ranks = {{0, "node-a", 2, 30, 1000, 1.5}, {1, "node-b", 4, 50, 3000, 3.0}};
  EXPECT_DOUBLE_EQ(stats.loadBalance(), 0.75);
  const auto json = nlohmann::json::parse(formatStatsJson(stats));
  EXPECT_DOUBLE_EQ(json["load_balance"].get<double>(), 0.75);
  ASSERT_EQ(json["ranks"].size(), 2u);
  EXPECT_EQ(json["ranks"][1]["host"], "node-b");
  EXPECT_EQ(json["ranks"][1]["threads"], 4);
  EXPECT_EQ(json["ranks"][1]["tiles"], 50);
  EXPECT_EQ(json["ranks"][1]["rays"], 3000);
  EXPECT_DOUBLE_EQ(json["ranks"][1]["cpu_seconds"].get<double>(), 3.0);
  const std::string text = formatStatsText(stats);
  EXPECT_NE(text.find("ranks               2 (load balance 0.750"), std::string::npos) << text;
  EXPECT_NE(text.find("node-b"), std::string::npos) << text;
}

} // namespace
} // namespace prism
