// `prism sweep` (docs/choosing-settings.md): the image error measures, the
// reference picture, the sweep of settings and the command. Expected values
// are worked out by hand or taken from an independent path (plain render()
// calls), never from the code under test.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/accel/accel.h"
#include "core/io/scene_parser.h"
#include "core/render/exposure.h"
#include "core/render/image_formation.h"
#include "core/render/parallel.h"
#include "core/render/renderer.h"
#include "core/sweep/image_error.h"
#include "core/sweep/reference.h"
#include "core/sweep/sweep_runner.h"
#include "core/sweep/sweep_table.h"

#include "counting_accel.h"
#include "render_fixtures.h"
#include "test_files.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace prism {
namespace {

namespace fs = std::filesystem;

// ----------------------------------------------------------------- compareImages

// Pixel values given as 8-bit levels at an avgmax of 1 (exposure scale 128):
// radiance = levels / 128, exact in float for the levels used here.
Rgb levels(double r, double g, double b) {
  return Rgb(float(r / 128.0), float(g / 128.0), float(b / 128.0));
}

TEST(SweepCompareImages, IdenticalPicturesHaveNoError) {
  const std::vector<Rgb> picture{levels(10, 20, 30),    levels(200, 0, 5), levels(0, 0, 0),
                                 levels(128, 128, 128), levels(255, 1, 2), levels(7, 70, 140)};
  const ImageError e = compareImages(picture, 0.8, picture, 0.8, 3, 2);
  EXPECT_EQ(e.rmse, 0.0);
  EXPECT_TRUE(std::isinf(e.psnr) && e.psnr > 0.0);
  EXPECT_EQ(e.worstLevels, 0);
  EXPECT_EQ(e.worstX, 0);
  EXPECT_EQ(e.worstY, 0);
  EXPECT_EQ(e.over2, 0.0);
}

TEST(SweepCompareImages, OneChannelOffGivesTheHandComputedPsnrAndWorstPixel) {
  // 3 x 2 pixels, both exposed by avgmax 1 (scale 128).
  const std::vector<Rgb> reference{levels(10, 20, 30), levels(40, 50, 60), levels(70, 80, 90),
                                   levels(1, 2, 3),    levels(4, 5, 6),    levels(100, 64, 7)};
  std::vector<Rgb> shown = reference;
  // Pixel (2, 1), green: 0.5 -> 0.625 radiance, 64 -> 80 levels.
  shown[5].g = 0.625f;
  const ImageError e = compareImages(shown, 1.0, reference, 1.0, 3, 2);
  // 18 channel values, one off by 0.125 radiance.
  EXPECT_DOUBLE_EQ(e.rmse, std::sqrt(0.125 * 0.125 / 18.0));
  // One channel 16 levels off: MSE = 256 / 18, PSNR = 10 log10(65025 * 18 / 256).
  EXPECT_NEAR(e.psnr, 36.6011, 1e-4);
  EXPECT_DOUBLE_EQ(e.psnr, 10.0 * std::log10(255.0 * 255.0 / (256.0 / 18.0)));
  EXPECT_EQ(e.worstLevels, 16);
  EXPECT_EQ(e.worstX, 2);
  EXPECT_EQ(e.worstY, 1);
  EXPECT_DOUBLE_EQ(e.over2, 1.0 / 6.0);
}

TEST(SweepCompareImages, ExposureRoundsHalvesAwayFromZeroAndCapsAt255) {
  // Pixel 0: 100.5 levels rounds to 101 (not to the even 100): 1 level off
  // 100. Pixel 1: 384 and 320 levels both show as 255: no 8-bit difference,
  // though their radiance differs by 0.5.
  const std::vector<Rgb> reference{levels(100, 0, 0), levels(320, 0, 0)};
  const std::vector<Rgb> shown{levels(100.5, 0, 0), levels(384, 0, 0)};
  const ImageError e = compareImages(shown, 1.0, reference, 1.0, 2, 1);
  // Squared radiance differences: (0.5/128)^2 + 0.5^2 over 6 values.
  EXPECT_DOUBLE_EQ(e.rmse, std::sqrt((std::pow(0.5 / 128.0, 2) + 0.25) / 6.0));
  EXPECT_EQ(e.worstLevels, 1);
  EXPECT_EQ(e.worstX, 0);
  EXPECT_EQ(e.worstY, 0);
  EXPECT_EQ(e.over2, 0.0);
  EXPECT_DOUBLE_EQ(e.psnr, 10.0 * std::log10(255.0 * 255.0 * 6.0));
}

TEST(SweepCompareImages, EachPictureIsExposedByItsOwnAvgmax) {
  // The same radiance; the shown picture exposed by avgmax 2 (scale 64)
  // against the reference's 1 (scale 128): every level halves.
  //   pixel (0,0):  0  0 0 ->  0 0 0  off 0 0 0
  //   pixel (1,0):  2  4 0 ->  1 2 0  off 1 2 0
  //   pixel (0,1):  6  0 0 ->  3 0 0  off 3 0 0   > 2 levels
  //   pixel (1,1): 10  6 0 ->  5 3 0  off 5 3 0   > 2 levels, the worst
  const std::vector<Rgb> picture{levels(0, 0, 0), levels(2, 4, 0), levels(6, 0, 0),
                                 levels(10, 6, 0)};
  const ImageError e = compareImages(picture, 2.0, picture, 1.0, 2, 2);
  EXPECT_EQ(e.rmse, 0.0);
  EXPECT_EQ(e.worstLevels, 5);
  EXPECT_EQ(e.worstX, 1);
  EXPECT_EQ(e.worstY, 1);
  EXPECT_DOUBLE_EQ(e.over2, 0.5);
  // Squares 1 + 4 + 9 + 25 + 9 = 48 over 12 values: MSE 4.
  EXPECT_DOUBLE_EQ(e.psnr, 10.0 * std::log10(255.0 * 255.0 / 4.0));
  EXPECT_NEAR(e.psnr, 42.1102, 1e-4);
}

TEST(SweepCompareImages, TheFirstWorstPixelInRowMajorOrderIsReported) {
  const std::vector<Rgb> reference(6, levels(50, 50, 50));
  std::vector<Rgb> shown = reference;
  shown[4] = levels(50, 59, 50); // (1, 1): 9 levels
  shown[2] = levels(41, 50, 50); // (2, 0): 9 levels, earlier in row-major order
  shown[5] = levels(50, 50, 52); // (2, 1): 2 levels, not more than 2
  const ImageError e = compareImages(shown, 1.0, reference, 1.0, 3, 2);
  EXPECT_EQ(e.worstLevels, 9);
  EXPECT_EQ(e.worstX, 2);
  EXPECT_EQ(e.worstY, 0);
  EXPECT_DOUBLE_EQ(e.over2, 2.0 / 6.0);
}

TEST(SweepCompareImages, MismatchedSizesThrow) {
  const std::vector<Rgb> four(4, Rgb(0.5f)), six(6, Rgb(0.5f));
  EXPECT_THROW(compareImages(four, 1.0, six, 1.0, 2, 2), std::invalid_argument);
  EXPECT_THROW(compareImages(six, 1.0, four, 1.0, 2, 2), std::invalid_argument);
  EXPECT_THROW(compareImages(six, 1.0, six, 1.0, 2, 2), std::invalid_argument);
  EXPECT_NO_THROW(compareImages(six, 1.0, six, 1.0, 3, 2));
}

// ------------------------------------------------------------ referenceSamplePoint

TEST(SweepReferenceSamplePoint, EveryPointLiesInItsOwnStratum) {
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {5, 3}, {17, 11}, {0, 9}}) {
    std::set<std::pair<double, double>> points;
    for (int j = 0; j < kReferenceSide; ++j) {
      for (int i = 0; i < kReferenceSide; ++i) {
        double px = -1.0, py = -1.0;
        referenceSamplePoint(x, y, i, j, px, py);
        EXPECT_GE(px, x + double(i) / 8.0) << x << "," << y << " stratum " << i << "," << j;
        EXPECT_LT(px, x + double(i + 1) / 8.0) << x << "," << y << " stratum " << i << "," << j;
        EXPECT_GE(py, y + double(j) / 8.0) << x << "," << y << " stratum " << i << "," << j;
        EXPECT_LT(py, y + double(j + 1) / 8.0) << x << "," << y << " stratum " << i << "," << j;
        points.insert({px, py});
      }
    }
    EXPECT_EQ(points.size(), 64u);
  }
}

// Where in its stratum a sample lies, 0..1 on each axis.
std::pair<double, double> offsetInStratum(int x, int y, int i, int j) {
  double px = 0.0, py = 0.0;
  referenceSamplePoint(x, y, i, j, px, py);
  return {(px - x) * 8.0 - i, (py - y) * 8.0 - j};
}

TEST(SweepReferenceSamplePoint, JitteredDifferentlyPerPixelAndStratumAndDeterministic) {
  // Within a pixel: not all at one place of their strata (not a grid).
  std::set<std::pair<double, double>> offsets;
  for (int j = 0; j < kReferenceSide; ++j)
    for (int i = 0; i < kReferenceSide; ++i)
      offsets.insert(offsetInStratum(3, 4, i, j));
  EXPECT_EQ(offsets.size(), 64u);
  // Between pixels, the same stratum is sampled at different places.
  const std::vector<std::pair<int, int>> pixels{{0, 0}, {1, 0}, {0, 1}, {1, 1}, {7, 5}, {5, 7}};
  for (int j = 0; j < kReferenceSide; ++j) {
    for (int i = 0; i < kReferenceSide; ++i) {
      std::set<std::pair<double, double>> perPixel;
      for (const auto& [x, y] : pixels)
        perPixel.insert(offsetInStratum(x, y, i, j));
      EXPECT_EQ(perPixel.size(), pixels.size()) << "stratum " << i << "," << j;
    }
  }
  // The same answer every time.
  for (int j = 0; j < kReferenceSide; ++j) {
    for (int i = 0; i < kReferenceSide; ++i) {
      double ax = 0, ay = 0, bx = 1, by = 1;
      referenceSamplePoint(9, 2, i, j, ax, ay);
      referenceSamplePoint(1, 1, 0, 0, bx, by); // something else in between
      referenceSamplePoint(9, 2, i, j, bx, by);
      EXPECT_EQ(ax, bx);
      EXPECT_EQ(ay, by);
    }
  }
}

// ---------------------------------------------------------------- renderReference

// A camera looking straight at a plane far larger than the view, lit by
// ambient light only: every eye ray hits the plane and returns
// C * kdr * ambient = (0.8 0.6 0.4) * 0.5 * (0.5 0.4 0.3) = (0.2 0.12 0.06),
// at any depth (no mirror, no glass, no light for shadow rays).
const char* kAmbientPlane = R"(
eye 0 0 5
lookat 0 0 0
up 0 1 0
fov 40
background 0.9 0.9 0.9
ambient 0.5 0.4 0.3
surface 0.8 0.6 0.4  0.5 0 0  1 1
polygon 4  -1000 -1000 0  1000 -1000 0  1000 1000 0  -1000 1000 0
)";

TEST(SweepReference, AmbientLitPlaneIsKnownByHand) {
  const Scene scene = parseScene(kAmbientPlane, "plane.sc");
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  ThreadPoolExecutor executor(2);
  ReferenceSettings settings;
  settings.width = 12;
  settings.height = 9;
  const ReferencePicture r = renderReference(scene, *accel, settings, executor);
  const std::size_t pixels = 12 * 9;
  ASSERT_EQ(r.width, 12);
  ASSERT_EQ(r.height, 9);
  ASSERT_EQ(r.radiance.size(), pixels);
  ASSERT_EQ(r.centres.size(), pixels);
  ASSERT_EQ(r.depth.size(), pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    EXPECT_NEAR(r.radiance[i].r, 0.2, 1e-6) << i;
    EXPECT_NEAR(r.radiance[i].g, 0.12, 1e-6) << i;
    EXPECT_NEAR(r.radiance[i].b, 0.06, 1e-6) << i;
    EXPECT_NEAR(r.centres[i].r, 0.2, 1e-6) << i;
    EXPECT_NEAR(r.centres[i].g, 0.12, 1e-6) << i;
    EXPECT_NEAR(r.centres[i].b, 0.06, 1e-6) << i;
    // Traced at 8 and at 10, unchanged: settled, at the depth last traced.
    EXPECT_EQ(r.depth[i], 10) << i;
  }
  EXPECT_NEAR(r.avgmax, 0.2, 1e-6);
  EXPECT_EQ(r.deepest, 10);
  EXPECT_TRUE(r.converged);
  // Every centre traced twice (depths 8 and 10), then 64 rays per pixel.
  EXPECT_EQ(r.counts.eyePrimary, 2 * pixels);
  EXPECT_EQ(r.counts.eyeAntialias, 64 * pixels);
  EXPECT_EQ(r.counts.shadow, 0u);
  EXPECT_EQ(r.counts.reflected, 0u);
  EXPECT_EQ(r.counts.transmitted, 0u);
  EXPECT_EQ(r.counts.total(), 66 * pixels);
  EXPECT_GE(r.cpuSeconds, 0.0);
  EXPECT_GT(r.wallSeconds, 0.0);
}

// Two facing mirrors, the camera between them looking at the small one (the
// other, huge, behind the camera). Every hit adds kdr * ambient = 0.2 and
// reflects 0.7 of what lies behind, so a ray caught between them returns
// 0.2 (1 + 0.7 + ... + 0.7^(D-1)) at depth D: it settles to 8 bits only
// near depth 16. Rays that leave the small mirror's edge see the grey
// background, so the picture is not uniform (a uniform one always exposes
// to 128, whatever the depth).
const char* kFacingMirrors = R"(
eye 0 0 2
lookat 0 0 0
up 0 1 0
fov 40
background 0.3 0.3 0.3
ambient 1 1 1
surface 1 1 1  0.2 0.7 0  1 1
polygon 4  -0.6 -0.6 -1  0.6 -0.6 -1  0.6 0.6 -1  -0.6 0.6 -1
polygon 4  -100 -100 3  -100 100 3  100 100 3  100 -100 3
)";

// Odd sizes: the middle pixel's centre ray runs along the axis, hitting both
// mirrors square on for ever.
constexpr int kMirrorW = 13, kMirrorH = 9;

TEST(SweepReference, FacingMirrorsNeedDeeperThan8AndMatchPlainRenders) {
  const Scene scene = parseScene(kFacingMirrors, "mirrors.sc");
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  ThreadPoolExecutor executor(2);
  ReferenceSettings settings;
  settings.width = kMirrorW;
  settings.height = kMirrorH;
  const ReferencePicture r = renderReference(scene, *accel, settings, executor);
  EXPECT_TRUE(r.converged);
  EXPECT_GT(r.deepest, 8);
  EXPECT_LT(r.deepest, 32);

  // The depth search redone from plain renders without antialiasing, one per
  // depth: each pixel centre deepened in steps of 2 from 8 until its 8-bit
  // value (all compared at the exposure of the deeper centres) stops changing.
  auto centresAt = [&](int depth) {
    RenderSettings s;
    s.width = kMirrorW;
    s.height = kMirrorH;
    s.maxDepth = depth;
    s.noAa = true;
    s.threads = 1;
    return render(scene, *accel, s).film.centre;
  };
  const std::size_t pixels = std::size_t(kMirrorW) * kMirrorH;
  std::map<int, std::vector<Rgb>> byDepth;
  std::vector<Rgb> centres = byDepth[8] = centresAt(8);
  std::vector<int> centreDepth(pixels, 8);
  std::vector<bool> unsettled(pixels, true);
  int depth = 10;
  for (; depth <= 32 && std::count(unsettled.begin(), unsettled.end(), true) > 0; depth += 2) {
    const std::vector<Rgb>& deeper = byDepth[depth] = centresAt(depth);
    std::vector<Rgb> next = centres;
    for (std::size_t i = 0; i < pixels; ++i)
      if (unsettled[i]) next[i] = deeper[i];
    double sum = 0.0;
    for (const Rgb& c : next)
      sum += std::max({c.r, c.g, c.b});
    const float scale = float(128.0 / (sum / double(pixels)));
    for (std::size_t i = 0; i < pixels; ++i) {
      if (!unsettled[i]) continue;
      bool changed = false;
      for (int c = 0; c < 3; ++c)
        changed =
            changed || exposeChannel(centres[i][c], scale) != exposeChannel(next[i][c], scale);
      centreDepth[i] = depth;
      unsettled[i] = changed;
    }
    centres = next;
  }
  ASSERT_EQ(std::count(unsettled.begin(), unsettled.end(), true), 0);

  int deepest = 0;
  int deeperThan8 = 0;
  for (int y = 0; y < kMirrorH; ++y) {
    for (int x = 0; x < kMirrorW; ++x) {
      const std::size_t i = std::size_t(y) * kMirrorW + std::size_t(x);
      // The centres: bit for bit a plain render's at the depth found.
      EXPECT_EQ(r.centres[i], byDepth[centreDepth[i]][i]) << x << "," << y;
      int expected = 0;
      for (int ny = std::max(0, y - 1); ny <= std::min(kMirrorH - 1, y + 1); ++ny)
        for (int nx = std::max(0, x - 1); nx <= std::min(kMirrorW - 1, x + 1); ++nx)
          expected = std::max(expected, centreDepth[std::size_t(ny) * kMirrorW + std::size_t(nx)]);
      EXPECT_EQ(int(r.depth[i]), expected) << x << "," << y;
      deepest = std::max(deepest, expected);
      deeperThan8 += centreDepth[i] > 10 ? 1 : 0;
    }
  }
  EXPECT_EQ(r.deepest, deepest);
  EXPECT_GT(deeperThan8, 0);
  double sum = 0.0;
  for (const Rgb& c : centres)
    sum += std::max({c.r, c.g, c.b});
  EXPECT_DOUBLE_EQ(r.avgmax, sum / double(pixels));

  // The middle pixel's centre by hand: 0.2 (1 - 0.7^D) / 0.3 at its depth D.
  const std::size_t middle = std::size_t(kMirrorH / 2) * kMirrorW + std::size_t(kMirrorW / 2);
  const int d = centreDepth[middle];
  EXPECT_GE(d, 14);
  const double expected = 0.2 * (1.0 - std::pow(0.7, d)) / 0.3;
  EXPECT_NEAR(r.centres[middle].r, expected, 1e-5);
  EXPECT_NEAR(r.centres[middle].g, expected, 1e-5);
  EXPECT_NEAR(r.centres[middle].b, expected, 1e-5);
  // No sample can be brighter than the limit of the series, 2/3 (a ray that
  // leaves the mirrors ends on the darker background).
  for (const Rgb& c : r.radiance)
    EXPECT_LE(std::max({c.r, c.g, c.b}), 2.0f / 3.0f + 1e-5f);
}

TEST(SweepReference, ThreadCountDoesNotChangeIt) {
  for (const char* text : {kFacingMirrors, kAmbientPlane}) {
    const Scene scene = parseScene(text, "t.sc");
    const auto accel = makeAccel(scene, AccelKind::Bvh);
    ReferenceSettings settings;
    settings.width = 19; // tiles of 16: two columns, uneven
    settings.height = 17;
    ThreadPoolExecutor one(1), two(2);
    const ReferencePicture a = renderReference(scene, *accel, settings, one);
    const ReferencePicture b = renderReference(scene, *accel, settings, two);
    ASSERT_EQ(a.radiance.size(), b.radiance.size());
    EXPECT_EQ(std::memcmp(a.radiance.data(), b.radiance.data(), a.radiance.size() * sizeof(Rgb)),
              0);
    EXPECT_EQ(std::memcmp(a.centres.data(), b.centres.data(), a.centres.size() * sizeof(Rgb)), 0);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.avgmax, b.avgmax);
    EXPECT_EQ(a.deepest, b.deepest);
    EXPECT_EQ(a.converged, b.converged);
    EXPECT_EQ(a.counts, b.counts);
  }
}

TEST(SweepReference, ProgressRisesToOne) {
  const Scene scene = parseScene(kFacingMirrors, "mirrors.sc");
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  ThreadPoolExecutor executor(1);
  ReferenceSettings settings;
  settings.width = kMirrorW;
  settings.height = kMirrorH;
  std::vector<double> seen;
  renderReference(scene, *accel, settings, executor, [&](double f) { seen.push_back(f); });
  ASSERT_FALSE(seen.empty());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_GE(seen.front(), 0.0);
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
}

// ------------------------------------------------------------------- SweepGrid

TEST(SweepGrid, DefaultHas408SettingsInTheDocumentedOrder) {
  const std::vector<SweepSetting> all = SweepGrid{}.settings();
  // 8 depths x 3 bailouts x (no-aa + 2 jitters x 8 thresholds).
  ASSERT_EQ(all.size(), 408u);
  // By depth, then bailout; --no-aa first, then jitter, then threshold.
  EXPECT_EQ(all[0], (SweepSetting{false, 0.1, 1, false, 0.0}));
  EXPECT_EQ(all[1], (SweepSetting{true, 0.0, 1, false, 0.0}));
  EXPECT_EQ(all[8], (SweepSetting{true, 1.0, 1, false, 0.0}));
  EXPECT_EQ(all[9], (SweepSetting{true, 0.0, 1, true, 0.0}));
  EXPECT_EQ(all[17], (SweepSetting{false, 0.1, 1, false, 0.5}));
  EXPECT_EQ(all[51], (SweepSetting{false, 0.1, 2, false, 0.0}));
  EXPECT_EQ(all[407], (SweepSetting{true, 1.0, 8, true, 2.0}));
  // The default setting of `prism render` is among them.
  EXPECT_NE(std::find(all.begin(), all.end(), SweepSetting{}), all.end());
}

TEST(SweepGrid, EverySettingReadsBackFromTheTableAsWritten) {
  std::vector<SweepRow> rows;
  for (const SweepSetting& setting : SweepGrid{}.settings()) {
    SweepRow row;
    row.setting = setting;
    rows.push_back(row);
  }
  const std::vector<SweepRow> back = parseSweepCsv(formatSweepCsv(rows));
  ASSERT_EQ(back.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    EXPECT_EQ(back[i].setting, rows[i].setting) << settingOptions(rows[i].setting);
}

// ------------------------------------------------------------------- runSweep

TEST(RunSweep, EveryRowIsWhatAPlainRenderOfItsSettingGives) {
  const Scene scene = test::shipped("table.sc");
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  constexpr int W = 24, H = 18;
  ThreadPoolExecutor executor(2);
  ReferenceSettings referenceSettings;
  referenceSettings.width = W;
  referenceSettings.height = H;
  referenceSettings.lastDepth = 12; // the glass would take long; convergence is not the point
  const ReferencePicture reference = renderReference(scene, *accel, referenceSettings, executor);

  SweepGrid grid;
  grid.depths = {1, 3};
  grid.thresholds = {0.0, 0.1, 1.0};
  grid.jitters = {false, true};
  // At 0.5 levels the bailout traces its pilot but skips no ray of this
  // scene at these depths; at 8 it skips some.
  grid.bailouts = {0.0, 0.5, 8.0};
  const std::vector<SweepSetting> settings = grid.settings();
  ASSERT_EQ(settings.size(), 2u * 3u * (1u + 2u * 3u));
  // The order by hand: depth, bailout; no-aa, then jitter, then threshold.
  EXPECT_EQ(settings[0], (SweepSetting{false, 0.1, 1, false, 0.0}));
  EXPECT_EQ(settings[3], (SweepSetting{true, 1.0, 1, false, 0.0}));
  EXPECT_EQ(settings[4], (SweepSetting{true, 0.0, 1, true, 0.0}));
  EXPECT_EQ(settings[7], (SweepSetting{false, 0.1, 1, false, 0.5}));
  EXPECT_EQ(settings[14], (SweepSetting{false, 0.1, 1, false, 8.0}));
  EXPECT_EQ(settings[21], (SweepSetting{false, 0.1, 3, false, 0.0}));
  EXPECT_EQ(settings[41], (SweepSetting{true, 1.0, 3, true, 8.0}));

  std::vector<SweepProgress> progress;
  const std::vector<SweepRow> rows =
      runSweep(scene, *accel, grid, reference, executor,
               [&](const SweepProgress& p) { progress.push_back(p); });
  ASSERT_EQ(rows.size(), settings.size());

  const double pixels = double(W) * double(H);
  bool someSkipped = false, someSupersampled = false, somePartlySupersampled = false;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const SweepRow& row = rows[k];
    SCOPED_TRACE(settingOptions(row.setting));
    EXPECT_EQ(row.setting, settings[k]);
    EXPECT_FALSE(row.pareto);

    RenderSettings s;
    s.width = W;
    s.height = H;
    s.maxDepth = row.setting.depth;
    s.thresh = row.setting.thresh;
    s.jitter = row.setting.jitter;
    s.noAa = !row.setting.antialias;
    s.bailout = row.setting.bailout;
    s.threads = 1;
    const RenderResult plain = render(scene, *accel, s);

    // Rays per pixel times the pixels: the counts, to the ray.
    auto rays = [&](double perPixel) { return std::llround(perPixel * pixels); };
    EXPECT_EQ(rays(row.rays.eye), (long long)plain.counts.eye());
    EXPECT_EQ(rays(row.rays.shadow), (long long)plain.counts.shadow);
    EXPECT_EQ(rays(row.rays.reflected), (long long)plain.counts.reflected);
    EXPECT_EQ(rays(row.rays.transmitted), (long long)plain.counts.transmitted);
    EXPECT_EQ(rays(row.rays.pilot), (long long)plain.counts.bailoutPilot);
    EXPECT_EQ(rays(row.supersampled), plain.supersampledPixels);
    EXPECT_DOUBLE_EQ(row.rays.total(), double(plain.counts.total()) / pixels);

    const ImageError e = compareImages(plain.film.radiance, plain.avgmax, reference.radiance,
                                       reference.avgmax, W, H);
    EXPECT_EQ(row.error.rmse, e.rmse);
    EXPECT_EQ(row.error.psnr, e.psnr);
    EXPECT_EQ(row.error.worstLevels, e.worstLevels);
    EXPECT_EQ(row.error.worstX, e.worstX);
    EXPECT_EQ(row.error.worstY, e.worstY);
    EXPECT_EQ(row.error.over2, e.over2);

    EXPECT_GT(row.cpuSeconds, 0.0);
    EXPECT_TRUE(std::isfinite(row.cpuSeconds));
    EXPECT_GT(row.wallSeconds, 0.0);
    EXPECT_TRUE(std::isfinite(row.wallSeconds));
    if (!row.setting.antialias) {
      EXPECT_EQ(row.rays.eye, 1.0);
      EXPECT_EQ(row.supersampled, 0.0);
    } else {
      EXPECT_GE(row.rays.eye, 1.0);
      someSupersampled = someSupersampled || row.supersampled > 0.0;
      somePartlySupersampled =
          somePartlySupersampled || (row.supersampled > 0.0 && row.supersampled < 1.0);
    }
    someSkipped =
        someSkipped || plain.counts.reflectedSkipped + plain.counts.transmittedSkipped > 0;
    // A deeper trace of this scene is closer to the reference than depth 1.
    EXPECT_GT(row.error.rmse, 0.0);
  }
  // The grid exercised what sharing pass 1 could break: pass 2 on some
  // pixels but not all, and a bailout that skipped rays.
  EXPECT_TRUE(someSupersampled);
  EXPECT_TRUE(somePartlySupersampled);
  EXPECT_TRUE(someSkipped);

  ASSERT_FALSE(progress.empty());
  EXPECT_EQ(progress.back().done, int(rows.size()));
  EXPECT_EQ(progress.back().total, int(rows.size()));
  EXPECT_DOUBLE_EQ(progress.back().fraction, 1.0);
}

// minTimedSeconds 0 renders each setting of a group once; a minimum no run
// reaches renders each kSweepMaxRuns times: the hierarchy is asked exactly
// that many times the queries, and the rows are the same but for the times.
TEST(Sweep, MinTimedSecondsDecidesHowOftenEachSettingIsRendered) {
  const Scene scene = parseScene(kFacingMirrors, "mirrors.sc");
  const auto bvh = makeAccel(scene, AccelKind::Bvh);
  ThreadPoolExecutor executor(2);
  ReferenceSettings referenceSettings;
  referenceSettings.width = 8;
  referenceSettings.height = 6;
  referenceSettings.lastDepth = 12;
  const ReferencePicture reference = renderReference(scene, *bvh, referenceSettings, executor);
  SweepGrid grid;
  grid.depths = {3};
  grid.bailouts = {0.0};
  const std::vector<SweepSetting> settings = grid.settings();

  const test::CountingAccel once(*bvh), often(*bvh);
  const std::vector<SweepRow> onceRows =
      runSweepGroup(scene, once, settings, reference, executor, {}, 0.0);
  const std::vector<SweepRow> oftenRows =
      runSweepGroup(scene, often, settings, reference, executor, {}, 1e9);
  ASSERT_GT(once.queries(), 0);
  EXPECT_EQ(often.queries(), kSweepMaxRuns * once.queries());
  ASSERT_EQ(onceRows.size(), settings.size());
  ASSERT_EQ(oftenRows.size(), settings.size());
  for (std::size_t i = 0; i < settings.size(); ++i) {
    SweepRow a = onceRows[i], b = oftenRows[i];
    a.cpuSeconds = b.cpuSeconds = a.wallSeconds = b.wallSeconds = 0.0;
    EXPECT_EQ(formatSweepCsv({a}), formatSweepCsv({b})) << settingOptions(settings[i]);
  }
}

// ------------------------------------------------------------------ the command

class SweepCli : public ::testing::Test {
protected:
  test::RunResult prism(const std::string& args) {
    return test::runCaptured(test::quoted(PRISM_BINARY) + " " + args, dir_);
  }
  fs::path write(const std::string& name, const std::string& text) {
    test::writeFile(dir_ / name, text);
    return dir_ / name;
  }

  test::ScratchDir scratch_;
  const fs::path dir_ = scratch_.path();
};

const char* kSmallScene = R"(eye 0 0 4
lookat 0 0 0
light 2 3 4 30 30 30
ambient 0.1 0.1 0.1
surface 1 0.5 0.2 0.6 0.4 0 20 1
sphere 0 0 0 1
surface 0.4 0.6 0.9 0.8 0 0 1 1
polygon 4  -5 -1 -5  5 -1 -5  5 -1 5  -5 -1 5
)";

TEST_F(SweepCli, WritesTheTableTheSummaryTheReferenceAndThePlots) {
  const fs::path scene = write("small.sc", kSmallScene);
  const fs::path out = dir_ / "results";
  // --min-seconds 0: each setting rendered once (16 times each otherwise, at
  // this size); nothing below depends on how steady the times are.
  const test::RunResult run = prism("sweep " + test::quoted(scene) + " -o " + test::quoted(out) +
                                    " --size 16 12 --min-seconds 0 -q");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(run.err, ""); // -q: no progress, no summary

  const std::vector<SweepRow> rows = parseSweepCsv(test::slurp(out / "sweep.csv"));
  ASSERT_EQ(rows.size(), 408u);
  const std::vector<SweepSetting> grid = SweepGrid{}.settings();
  // In the grid's order (compared by their options: a --no-aa row read back
  // has no threshold, and the grid's has 0).
  for (std::size_t i = 0; i < rows.size(); ++i)
    EXPECT_EQ(settingOptions(rows[i].setting), settingOptions(grid[i])) << i;
  EXPECT_GT(std::count_if(rows.begin(), rows.end(), [](const SweepRow& r) { return r.pareto; }), 0);
  ASSERT_NE(findSetting(rows, SweepSetting{}), nullptr);
  for (const SweepRow& row : rows) {
    EXPECT_GT(row.cpuSeconds, 0.0);
    EXPECT_TRUE(std::isfinite(row.cpuSeconds));
  }

  const auto json = nlohmann::json::parse(test::slurp(out / "sweep.json"));
  EXPECT_EQ(json.at("scene"), "small.sc");
  EXPECT_EQ(json.at("width"), 16);
  EXPECT_EQ(json.at("height"), 12);
  EXPECT_EQ(json.at("settings"), 408);
  EXPECT_EQ(json.at("min_timed_seconds"), 0.0);
  EXPECT_GE(json.at("threads").get<int>(), 1);
  const auto& reference = json.at("reference");
  EXPECT_EQ(reference.at("samples_per_pixel"), 64);
  EXPECT_EQ(reference.at("first_depth"), 8);
  EXPECT_EQ(reference.at("last_depth"), 32);
  EXPECT_TRUE(reference.at("converged").get<bool>());
  EXPECT_GE(reference.at("deepest").get<int>(), 10);
  EXPECT_GT(reference.at("avgmax").get<double>(), 0.0);
  // At least 64 eye rays per pixel and a centre per pixel at depths 8 and 10.
  EXPECT_GE(reference.at("rays").get<long long>(), 16 * 12 * 66);

  auto in = OIIO::ImageInput::open((out / "reference.png").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 16);
  EXPECT_EQ(in->spec().height, 12);
  EXPECT_EQ(in->spec().nchannels, 3);
  std::vector<unsigned char> pixels(16 * 12 * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data()));
  // Exposed by avgmax: not black, and the sphere is brighter than the floor.
  EXPECT_GT(*std::max_element(pixels.begin(), pixels.end()), 100);
  in->close();

  for (const char* plot : {"time-vs-error.png", "error-vs-depth.png", "error-vs-threshold.png"}) {
    auto chart = OIIO::ImageInput::open((out / plot).string());
    ASSERT_TRUE(chart) << plot;
    EXPECT_GT(chart->spec().width, 100) << plot;
    EXPECT_GT(chart->spec().height, 100) << plot;
  }
}

TEST_F(SweepCli, SceneErrorExitsWith2AndWritesNoTable) {
  const fs::path bad = write("bad.sc", "eye 0 0 4\nsphere 0 0 0 -1\n");
  const fs::path out = dir_ / "results";
  const test::RunResult run =
      prism("sweep " + test::quoted(bad) + " -o " + test::quoted(out) + " --size 8 6 -q");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find(bad.string() + ":2:14: error:"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out / "sweep.csv"));
  EXPECT_FALSE(fs::exists(out / "sweep.json"));
  EXPECT_FALSE(fs::exists(out / "reference.png"));
}

TEST_F(SweepCli, NegativeOrNonNumericMinSecondsExitWith2) {
  const fs::path scene = write("small.sc", kSmallScene);
  for (const char* value : {"-1", "nan", "fast", "3601"}) {
    const fs::path out = dir_ / "results";
    const test::RunResult run = prism("sweep " + test::quoted(scene) + " -o " + test::quoted(out) +
                                      " --min-seconds " + value + " -q");
    EXPECT_EQ(run.exitCode, 2) << value;
    EXPECT_NE(run.err.find("--min-seconds"), std::string::npos) << value << ": " << run.err;
    EXPECT_FALSE(fs::exists(out / "sweep.csv")) << value;
  }
}

TEST_F(SweepCli, OutputThatIsAFileExitsWith1) {
  const fs::path scene = write("small.sc", kSmallScene);
  const fs::path file = write("taken", "not a folder\n");
  const test::RunResult run =
      prism("sweep " + test::quoted(scene) + " -o " + test::quoted(file) + " --size 8 6 -q");
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("prism: error:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(file.string()), std::string::npos) << run.err;
  EXPECT_EQ(test::slurp(file), "not a folder\n");
}

} // namespace
} // namespace prism
