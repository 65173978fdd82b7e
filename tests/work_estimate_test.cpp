// The work estimate made before a deep render (core/render/work_estimate.h,
// docs/rendering-model.md#work-estimate): it sees the ray tree of glass
// between mirrors explode, and the mirror chains and diffuse scenes not; it
// costs nothing up to depth 8; it is exact where it measures the render's
// own depth; and the warning `prism render` prints from it. The warning
// itself cannot be seen in a finished `prism render`: an estimate that
// explodes is a render that does not finish, so the message is tested
// through workWarning, and the command only for staying quiet.
#include "core/io/scene_parser.h"
#include "core/render/renderer.h"
#include "core/render/work_estimate.h"
#include "tests/mirror_scenes.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace prism {
namespace {

using test::kGlassMirrors;
using test::kMirrors;

const char* kDiffuse = "eye 0 0 4\nlookat 0 0 0\nlight 2 3 4  30 30 30\n"
                       "surface 1 0.5 0.2  0.8 0.2 0  20 1\nsphere 0 0 0 1\n"
                       "surface 0.5 0.5 0.5  0.9 0 0  1 1\n"
                       "polygon 4  -5 -1 -5  -5 -1 5  5 -1 5  5 -1 -5\n";

RenderSettings settingsFor(int size, int depth, double bailout = 0.0) {
  return test::squareSettings(size, depth, true, bailout);
}

WorkEstimate estimateFor(const char* text, const RenderSettings& settings) {
  const Scene scene = parseScene(text, "scene.sc");
  return estimateWork(scene, *makeAccel(scene, AccelKind::Bvh), settings);
}

TEST(WorkEstimate, GlassBetweenMirrorsExplodesAtDepth200) {
  const WorkEstimate e = estimateFor(kGlassMirrors, settingsFor(64, 200));
  ASSERT_TRUE(e.made);
  EXPECT_EQ(e.sampledPixels, 256);
  EXPECT_GE(e.measuredDepth, kEstimateFromDepth);
  EXPECT_LT(e.measuredDepth, 200);
  // Each glass hit doubles the rays, but a ray meets the glass again only
  // after a round trip between the mirrors: the tree doubles about every 8
  // levels (R(56) = 2069, R(64) = 4099 rays per pixel at 8 x 8), 1.09x per
  // level, reached from depth 25 or so (1.05 at depth 15).
  EXPECT_GT(e.growth, 1.06);
  EXPECT_LE(e.growth, 2.0);                // each hit makes at most two new rays
  EXPECT_GT(e.estimatedRaysPerPixel, 1e7); // about 4e8, from R(64) at 1.09x
  EXPECT_TRUE(e.explodes);
  // The tree still grows: the estimate went past its budget, never its cap.
  EXPECT_GT(e.sampleRays, kEstimateRayBudget);
  EXPECT_LE(e.sampleRays, kEstimateRayCap);
}

TEST(WorkEstimate, ABailoutThatBoundsTheTreeDoesNotExplode) {
  // tests/bailout_test.cpp: this render ends, with the same rays as at depth
  // 64 (0.56 million with antialiasing). Below depth 64 its tree grows as
  // the exact one does; the bound on the depth it can reach ends it.
  const WorkEstimate e = estimateFor(kGlassMirrors, settingsFor(64, 200, 0.5));
  ASSERT_TRUE(e.made);
  EXPECT_FALSE(e.explodes);
  EXPECT_LT(e.estimatedRaysPerPixel, 1e5);
}

TEST(WorkEstimate, MirrorChainsGrowLinearlyAndDoNotExplode) {
  const WorkEstimate e = estimateFor(kMirrors, settingsFor(64, 1000));
  ASSERT_TRUE(e.made);
  // A mirror chain makes at most one new ray per hit: no level gains more
  // rays than the one before. Extrapolated geometrically from R(k) itself,
  // which grows like k, the same chains would be 1.05^990 = 1e21 rays.
  EXPECT_LE(e.growth, 1.0);
  EXPECT_GT(e.estimatedRaysPerPixel, e.raysPerPixel);
  // Each of the 1000 levels adds a mirror ray and a shadow ray at most.
  EXPECT_LT(e.estimatedRaysPerPixel, 2.0 * 1000 + 1);
  EXPECT_FALSE(e.explodes);
}

TEST(WorkEstimate, ADiffuseSceneStopsGrowingAtOnce) {
  const WorkEstimate e = estimateFor(kDiffuse, settingsFor(64, 200));
  ASSERT_TRUE(e.made);
  EXPECT_EQ(e.measuredDepth, kEstimateFromDepth); // the tree ended at depth 2
  EXPECT_EQ(e.growth, 0.0);
  EXPECT_EQ(e.estimatedRaysPerPixel, e.raysPerPixel);
  EXPECT_FALSE(e.explodes);
}

TEST(WorkEstimate, IsNotMadeUpToDepth8) {
  for (int depth : {1, 5, kEstimateFromDepth}) {
    const WorkEstimate e = estimateFor(kGlassMirrors, settingsFor(64, depth));
    EXPECT_FALSE(e.made) << depth;
    EXPECT_EQ(e.sampleRays, 0.0) << depth;
    EXPECT_FALSE(e.explodes) << depth;
  }
  EXPECT_TRUE(estimateFor(kGlassMirrors, settingsFor(64, kEstimateFromDepth + 1)).made);
}

TEST(WorkEstimate, IsDeterministic) {
  for (const char* text : {kGlassMirrors, kMirrors, kDiffuse}) {
    const WorkEstimate a = estimateFor(text, settingsFor(64, 200));
    const WorkEstimate b = estimateFor(text, settingsFor(64, 200));
    EXPECT_TRUE(a.sameCounts(b));
    EXPECT_EQ(a.explodes, b.explodes);
  }
}

TEST(WorkEstimate, IsExactWhereItMeasuresTheRendersDepthOnEveryPixel) {
  // 8 x 8: the grid is the whole image; depth 10 is within the budget.
  const Scene scene = parseScene(kGlassMirrors, "glass-mirrors.sc");
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  const RenderSettings s = settingsFor(8, 10);
  const WorkEstimate e = estimateWork(scene, *accel, s);
  ASSERT_EQ(e.measuredDepth, 10);
  EXPECT_EQ(e.sampledPixels, 64);
  EXPECT_EQ(e.estimatedRaysPerPixel * 64, double(render(scene, *accel, s).counts.total()));
}

TEST(WorkEstimate, ExtrapolatesLinearGeometricAndEndedTrees) {
  // R(10) = 100 gaining 10 per level: 90 more levels to 100.
  EXPECT_DOUBLE_EQ(extrapolateRays(100, 10, 1.0, 10, 100), 100 + 10 * 90);
  // Doubling: 10 (2 + 4 + 8) more over three levels.
  EXPECT_DOUBLE_EQ(extrapolateRays(100, 10, 2.0, 10, 13), 100 + 10 * 14);
  // Shrinking by half: at most 10 more however deep.
  EXPECT_LT(extrapolateRays(100, 10, 0.5, 10, 1000), 110.0 + 1e-9);
  EXPECT_GT(extrapolateRays(100, 10, 0.5, 10, 1000), 109.99);
  EXPECT_EQ(extrapolateRays(100, 0, 0.0, 10, 1000), 100.0); // ended
  EXPECT_EQ(extrapolateRays(100, 10, 2.0, 10, 10), 100.0);  // measured at the depth
  // 2^991 fits a double, 10^20 times that does not: +infinity, not NaN.
  EXPECT_TRUE(std::isfinite(extrapolateRays(1, 1, 2.0, 10, 1000)));
  EXPECT_EQ(extrapolateRays(1, 1e20, 2.0, 10, 1000), std::numeric_limits<double>::infinity());
  EXPECT_EQ(extrapolateRays(1, 1, 2.0, 10, 1100), std::numeric_limits<double>::infinity());
  // A growth a hair above 1 keeps its digits: close to the linear count.
  EXPECT_NEAR(extrapolateRays(0, 1, 1.0 + 1e-12, 0, 1000), 1000.0, 1e-6);
}

TEST(WorkEstimate, TheWarningSaysHowFastAndWhatBoundsIt) {
  WorkEstimate e;
  e.made = true;
  e.measuredDepth = 12;
  e.growth = 1.93;
  e.estimatedRaysPerPixel = 3.2e58;
  e.estimatedSeconds = 4e52 * 365.25 * 86400;
  e.explodes = true;
  RenderSettings s = settingsFor(64, 200);
  EXPECT_EQ(workWarning(e, s),
            "depth 200: the ray tree grows 1.93x per level from depth 12; pass 1 alone may need "
            "about 3e58 rays per pixel (4e52 years on 2 threads); --bailout 0.5 or a lower "
            "--depth bounds it");
  s.bailout = 0.5; // the bailout is on: only the depth is left to suggest
  EXPECT_EQ(workWarning(e, s).substr(workWarning(e, s).rfind("; ")), "; a lower --depth bounds it");
  // Beyond a double: no number that is not one.
  e.estimatedRaysPerPixel = std::numeric_limits<double>::infinity();
  e.estimatedSeconds = std::numeric_limits<double>::infinity();
  const std::string endless = workWarning(e, s);
  EXPECT_NE(endless.find("more than 1e308 rays per pixel (forever, in practice"), std::string::npos)
      << endless;
  EXPECT_EQ(endless.find("inf"), std::string::npos) << endless;
  // Mirror chains that are merely long: no growth to speak of.
  e.growth = 1.0;
  e.estimatedRaysPerPixel = 2000;
  e.estimatedSeconds = 3 * 3600;
  EXPECT_EQ(workWarning(e, s), "depth 200: pass 1 alone may need about 2000 rays per pixel (3 "
                               "hours on 2 threads); a lower --depth bounds it");
}

TEST(WorkEstimate, DurationsReadAsPeopleSayThem) {
  EXPECT_EQ(roughDuration(30), "0.5 minutes");
  EXPECT_EQ(roughDuration(600), "10 minutes");
  EXPECT_EQ(roughDuration(7200), "2 hours");
  EXPECT_EQ(roughDuration(86400 * 3.5), "3.5 days");
  EXPECT_EQ(roughDuration(365.25 * 86400 * 250), "250 years");
  EXPECT_EQ(roughDuration(365.25 * 86400 * 4e52), "4e52 years");
}

TEST(WorkEstimate, ADeepRenderThatEndsPrintsNoWarning) {
  test::ScratchDir dir;
  test::writeFile(dir.path() / "mirrors.sc", kMirrors);
  const test::RunResult run =
      test::run(dir.path(), test::quoted(PRISM_BINARY) +
                                " render mirrors.sc -o out.tiff --size 16 16 --depth 1000");
  EXPECT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
}

} // namespace
} // namespace prism
