// --bailout W (docs/rendering-model.md#bailout): the radiance bound it decides
// by, computed by hand; its promise, checked pixel by pixel against the exact
// trace of deep mirror and glass scenes; the rays it saves; and the depth at
// which only the bailout finishes.
#include "core/io/scene_parser.h"
#include "core/render/bailout.h"
#include "core/render/exposure.h"
#include "core/render/renderer.h"
#include "tests/mirror_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace prism {
namespace {

using test::kGlassMirrors;
using test::kMirrors;

// One light 2 units above a 2 x 2 square (its box is the square): S = 8 / 2^2 = 2.
const char* kOneSquare = "background 0.2 0.2 0.2\nambient 0.1 0.1 0.1\nlight 0 0 2  8 8 8\n"
                         "surface 1 1 1  0.5 0.25 0.5  10 1.5\n"
                         "polygon 4  -1 -1 0  1 -1 0  1 1 0  -1 1 0\n";

TEST(BailoutBound, IsTheGeometricSeriesOfTheBrightestLocalTerm) {
  const Scene scene = parseScene(kOneSquare, "square.sc");
  EXPECT_DOUBLE_EQ(lightClearances(scene)[0], 2.0 * (1.0 - 1e-6));
  const std::vector<double> beyond = radianceBounds(scene, 3);
  ASSERT_EQ(beyond.size(), 4u);
  // local = C kdr (A + S) + ksr S = 0.5 * 2.1 + 0.25 * 2 = 1.55 (S a hair
  // larger for the clearance's margin); ksr + kst = 0.75.
  const double s = 8.0 / std::pow(2.0 * (1.0 - 1e-6), 2);
  const double local = 0.5 * (0.1 + s) + 0.25 * s;
  EXPECT_NEAR(beyond[3], local, 1e-8);
  EXPECT_NEAR(beyond[2], local + 0.75 * local, 1e-8);
  EXPECT_NEAR(beyond[1], local + 0.75 * (local + 0.75 * local), 1e-8);
  EXPECT_GT(beyond[1], 1.55 + 0.75 * (1.55 + 0.75 * 1.55)); // never below the hand value
}

// kOneSquare at depth 3: beyond = 3.5844, 2.7125, 1.55 (by hand, above), and
// (ksr + kst) = 0.75 is the only one. A ray of depth 3 could be skipped at
// best when 1.55 * 0.75^2 = 0.8719 <= W * 3.5844 / 128: from W = 31.14 on.
TEST(BailoutBound, SaysWhenNoRayCouldEverBeSkipped) {
  const Scene scene = parseScene(kOneSquare, "square.sc");
  const std::vector<double> beyond = radianceBounds(scene, 3);
  EXPECT_FALSE(bailoutCanSkip(scene, beyond, 0.5));
  EXPECT_FALSE(bailoutCanSkip(scene, beyond, 31.0));
  EXPECT_TRUE(bailoutCanSkip(scene, beyond, 32.0));
  // Then the render is the exact one, without a pilot.
  RenderSettings s;
  s.width = s.height = 8;
  s.maxDepth = 3;
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  const RenderResult exact = render(scene, *accel, s);
  s.bailout = 0.5;
  const RenderResult bailed = render(scene, *accel, s);
  EXPECT_EQ(bailed.counts, exact.counts);
  EXPECT_EQ(bailed.film.radiance, exact.film.radiance);
  // A scene whose materials start no new rays has nothing to skip.
  const Scene matte = parseScene("light 0 0 2  1 1 1\nsphere 0 0 0 1\n", "matte.sc");
  EXPECT_FALSE(bailoutCanSkip(matte, radianceBounds(matte, 5), 255.0));
}

TEST(BailoutBound, NoBoundWhenALightTouchesABox) {
  const Scene scene =
      parseScene("light 0 0 0  1 1 1\npolygon 4  -1 -1 0  1 -1 0  1 1 0  -1 1 0\n", "touch.sc");
  EXPECT_EQ(lightClearances(scene)[0], 0.0);
  for (int k = 1; k <= 4; ++k)
    EXPECT_TRUE(std::isinf(radianceBounds(scene, 4)[std::size_t(k)]));
}

TEST(BailoutBound, TheBackgroundBoundsARayThatMissesEverything) {
  const Scene scene = parseScene("background 3 0 0\nlight 0 0 10  1 1 1\n"
                                 "surface 1 1 1  1 0 0  1 1\nsphere 0 0 0 1\n",
                                 "sky.sc");
  // Local: 1 * (1 / 9^2) < 3, the background's red.
  EXPECT_NEAR(radianceBounds(scene, 2)[2], 3.0, 1e-8);
}

RenderResult renderWith(const Scene& scene, int size, int depth, bool noAa, double bailout) {
  return render(scene, *makeAccel(scene, AccelKind::Bvh),
                test::squareSettings(size, depth, noAa, bailout));
}

// The promise for one pair of renders, at every sample where both took the
// same samples (all with --no-aa; where both or neither supersampled
// otherwise). In radiance: 0 <= exact - bailout <= W * avgmax / 128, avgmax
// the bailout render's (a lower bound on the exact one's), up to the two
// roundings to float of the film (2^-24 each, relative). In 8-bit values
// exposed with either render's scale: at most ceil(W + 1e-4) levels apart
// (docs/rendering-model.md#bailout). Returns how many pixels were compared.
int expectWithinW(const RenderResult& exact, const RenderResult& bailed, double w) {
  EXPECT_LE(bailed.avgmax, exact.avgmax);
  const double allowance = w * bailed.avgmax / 128.0;
  const int maxLevels = int(std::ceil(w + 1e-4));
  int compared = 0;
  for (std::size_t i = 0; i < exact.film.radiance.size(); ++i) {
    if (exact.film.supersampled[i] != bailed.film.supersampled[i]) continue;
    ++compared;
    for (int c = 0; c < 3; ++c) {
      const double e = exact.film.radiance[i][c], b = bailed.film.radiance[i][c];
      const double rounding = std::ldexp(e + b, -23);
      EXPECT_GE(e - b, -rounding) << "pixel " << i << " channel " << c;
      EXPECT_LE(e - b, allowance + rounding) << "pixel " << i << " channel " << c;
      for (const double avgmax : {exact.avgmax, bailed.avgmax}) {
        const float scale = exposureScale(avgmax);
        const int levels = std::abs(int(exposeChannel(exact.film.radiance[i][c], scale)) -
                                    int(exposeChannel(bailed.film.radiance[i][c], scale)));
        EXPECT_LE(levels, maxLevels) << "pixel " << i << " channel " << c;
      }
    }
  }
  return compared;
}

// A scene where the bound is tight: no lights, a sky of radiance 1, and a
// half mirror (kdr 0, ksr 0.5) filling the lower half of the view, whose
// mirror rays all go to the sky. So beyond[2] = 1, exactly what each mirror
// ray brings back; the pilot's avgmax is 0.5 (the sky's half), and a mirror
// ray, weight 0.5, is skipped iff 0.5 <= W * 0.5 / 128: iff W >= 128.
TEST(Bailout, SkipsExactlyWhenTheBoundFitsTheAllowance) {
  const Scene scene = parseScene("eye 0 0 0\nlookat 0 0 -1\nbackground 1 1 1\n"
                                 "surface 1 1 1  0 0.5 0  1 1\n"
                                 "polygon 4  -1e6 -1 1  1e6 -1 1  1e6 -1 -1e6  -1e6 -1 -1e6\n",
                                 "sky.sc");
  const RenderResult exact = renderWith(scene, 8, 2, true, 0.0);
  EXPECT_DOUBLE_EQ(exact.avgmax, 0.75);
  const RenderResult below = renderWith(scene, 8, 2, true, 127.0);
  EXPECT_EQ(below.counts.reflectedSkipped, 0u);
  EXPECT_EQ(below.film.radiance, exact.film.radiance);
  const RenderResult above = renderWith(scene, 8, 2, true, 129.0);
  EXPECT_EQ(above.counts.reflectedSkipped, 32u);
  EXPECT_EQ(above.counts.reflected, 0u);
  EXPECT_DOUBLE_EQ(above.avgmax, 0.5);
  // Each mirror pixel lost 0.5, 128 of its 129 levels.
  EXPECT_EQ(expectWithinW(exact, above, 129.0), 64);
  EXPECT_EQ(exposeChannel(exact.film.radiance[63][0], exposureScale(0.5)), 128);
  EXPECT_EQ(exposeChannel(above.film.radiance[63][0], exposureScale(0.5)), 0);
}

TEST(Bailout, StaysWithinHalfALevelOfTheExactTraceBetweenMirrors) {
  const Scene scene = parseScene(kMirrors, "mirrors.sc");
  const RenderResult exact = renderWith(scene, 16, 64, true, 0.0);
  const RenderResult bailed = renderWith(scene, 16, 64, true, 0.5);
  EXPECT_EQ(expectWithinW(exact, bailed, 0.5), 256);
  // Exactness is the default: nothing skipped, no pilot.
  EXPECT_EQ(exact.counts.reflectedSkipped + exact.counts.transmittedSkipped, 0u);
  EXPECT_EQ(exact.counts.bailoutPilot, 0u);
  // Each skipped ray ends a chain of bounces the exact trace follows to depth
  // 64: 0.7^n falls below the allowance over the bound after some 25 to 30
  // bounces, so the bailout traces less than half as many mirror rays.
  EXPECT_GT(bailed.counts.reflectedSkipped, 0u);
  EXPECT_LT(2 * bailed.counts.reflected, exact.counts.reflected);
}

TEST(Bailout, StaysWithinHalfALevelOfTheExactTraceThroughGlassBetweenMirrors) {
  const Scene scene = parseScene(kGlassMirrors, "glass-mirrors.sc");
  const RenderResult exact = renderWith(scene, 12, 64, true, 0.0);
  const RenderResult bailed = renderWith(scene, 12, 64, true, 0.5);
  EXPECT_EQ(expectWithinW(exact, bailed, 0.5), 144);
  EXPECT_GT(bailed.counts.transmittedSkipped, 0u);
  EXPECT_LT(3 * bailed.counts.total(), exact.counts.total());
  // With W = 2 it may skip more, within 2 levels.
  const RenderResult loose = renderWith(scene, 12, 64, true, 2.0);
  EXPECT_EQ(expectWithinW(exact, loose, 2.0), 144);
  EXPECT_LE(loose.counts.total(), bailed.counts.total());
}

TEST(Bailout, KeepsItsPromiseWhereAntialiasingDecidedAlike) {
  const Scene scene = parseScene(kMirrors, "mirrors.sc");
  const RenderResult exact = renderWith(scene, 16, 64, false, 0.0);
  const RenderResult bailed = renderWith(scene, 16, 64, false, 0.5);
  // Pass 2's decisions read pass 1, which the bailout may change by up to W
  // levels: a pixel near the threshold may flip. All others are compared.
  EXPECT_GT(expectWithinW(exact, bailed, 0.5), 200);
  EXPECT_GT(bailed.supersampledPixels, 0);
}

TEST(Bailout, ThePilotIsADepthOneTraceOfEveryPixelCentre) {
  const Scene scene = parseScene(kMirrors, "mirrors.sc");
  const RenderResult bailed = renderWith(scene, 16, 8, true, 0.5);
  const RenderResult depth1 = renderWith(scene, 16, 1, true, 0.0);
  EXPECT_EQ(bailed.counts.bailoutPilot, depth1.counts.total());
  EXPECT_EQ(bailed.counts.total(), bailed.counts.eye() + bailed.counts.shadow +
                                       bailed.counts.reflected + bailed.counts.transmitted +
                                       depth1.counts.total());
}

// Each tracer keeps its allowance to itself and the pilot's avgmax is summed
// in pixel order: the same picture and counts on one thread as on two.
TEST(Bailout, IsTheSameForAnyThreadCount) {
  const Scene scene = parseScene(kGlassMirrors, "glass-mirrors.sc");
  RenderSettings s;
  s.width = s.height = 24;
  s.maxDepth = 64;
  s.bailout = 0.5;
  s.tileSize = 8;
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  s.threads = 1;
  const RenderResult one = render(scene, *accel, s);
  s.threads = 2;
  const RenderResult two = render(scene, *accel, s);
  EXPECT_GT(one.counts.reflectedSkipped, 0u);
  EXPECT_EQ(one.counts, two.counts);
  EXPECT_EQ(one.avgmax, two.avgmax);
  EXPECT_EQ(one.film.radiance, two.film.radiance);
}

TEST(Bailout, GlassBetweenMirrorsAtDepth200Ends) {
  // Exact, the ray tree doubles at every glass hit and this never ends.
  const Scene scene = parseScene(kGlassMirrors, "glass-mirrors.sc");
  const RenderResult bailed = renderWith(scene, 8, 200, true, 0.5);
  EXPECT_LT(bailed.counts.total(), 2'000'000u);
  EXPECT_GT(bailed.counts.reflectedSkipped + bailed.counts.transmittedSkipped, 0u);
  // The same rays as at depth 64: no chain the bound lets through is deeper.
  EXPECT_EQ(bailed.counts, renderWith(scene, 8, 64, true, 0.5).counts);
}

} // namespace
} // namespace prism
