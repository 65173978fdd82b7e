// Image formation (docs/image-formation.md) on synthetic buffers and a one-polygon scene whose
// radiance is known exactly: the supersampling decision, sub-sample placement, avgmax, exposure.
#include "core/render/exposure.h"
#include "core/render/image_formation.h"
#include "core/scene/scene_builder.h"
#include "core/shapes/shape_kinds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace prism {
namespace {

Film uniformFilm(int w, int h, Rgb c) {
  Film film(w, h);
  std::fill(film.centre.begin(), film.centre.end(), c);
  film.radiance = film.centre;
  return film;
}

TEST(AverageMax, IsTheMeanOfTheLargestChannel) {
  const std::vector<Rgb> pixels{{1, 2, 3}, {0.5f, 0.25f, 0}, {0, 0, 0}, {4, 1, 1}};
  EXPECT_DOUBLE_EQ(averageMax(pixels), (3.0 + 0.5 + 0.0 + 4.0) / 4.0);
  EXPECT_EQ(averageMax({}), 0.0);
}

TEST(Supersampling, UniformImageNeedsNone) {
  const Film film = uniformFilm(5, 4, Rgb(0.3f, 0.2f, 0.1f));
  for (double thresh : {0.0, 0.1, 1.0})
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 5; ++x)
        EXPECT_FALSE(needsSupersampling(film, x, y, 0.3, thresh));
}

TEST(Supersampling, TestIsStrictlyGreaterThanAvgmaxTimesThresh) {
  // Differences chosen exactly representable: a 3-4-5 triangle in r and g.
  Film film = uniformFilm(3, 3, Rgb(0.0f));
  film.centre[film.index(1, 1)] = Rgb(0.375f, 0.5f, 0.0f); // distance 0.625 from its neighbours
  const double avgmax = 1.25;
  EXPECT_FALSE(needsSupersampling(film, 1, 1, avgmax, 0.5)); // limit 0.625: equal is not greater
  EXPECT_TRUE(needsSupersampling(film, 1, 1, avgmax, 0.49));
  // The neighbours see the same difference; diagonal pixels are not 4-neighbours.
  EXPECT_TRUE(needsSupersampling(film, 0, 1, avgmax, 0.49));
  EXPECT_TRUE(needsSupersampling(film, 1, 2, avgmax, 0.49));
  EXPECT_FALSE(needsSupersampling(film, 0, 0, avgmax, 0.49));
  EXPECT_FALSE(needsSupersampling(film, 2, 2, avgmax, 0.0));
}

TEST(Supersampling, ThresholdZeroCatchesAnyDifferenceAndOneOnlyLargeOnes) {
  Film film = uniformFilm(2, 1, Rgb(1.0f));
  film.centre[1] = Rgb(1.0f, 1.0f, std::nextafter(1.0f, 2.0f));
  EXPECT_TRUE(needsSupersampling(film, 0, 0, 1.0, 0.0));
  EXPECT_FALSE(needsSupersampling(film, 0, 0, 1.0, 1.0));
  film.centre[1] = Rgb(0.0f); // distance sqrt(3) > 1 * 1
  EXPECT_TRUE(needsSupersampling(film, 0, 0, 1.0, 1.0));
}

TEST(Supersampling, AllBlackImageWithAvgmaxZeroNeedsNone) {
  const Film film = uniformFilm(4, 4, Rgb(0.0f));
  EXPECT_EQ(averageMax(film.centre), 0.0);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      EXPECT_FALSE(needsSupersampling(film, x, y, 0.0, 0.0));
}

TEST(Supersampling, BordersHaveFewerNeighbours) {
  Film film = uniformFilm(3, 1, Rgb(0.0f));
  film.centre[2] = Rgb(1.0f);
  EXPECT_FALSE(needsSupersampling(film, 0, 0, 1.0, 0.5)); // only neighbour (1,0) is equal
  EXPECT_TRUE(needsSupersampling(film, 1, 0, 1.0, 0.5));
  EXPECT_TRUE(needsSupersampling(film, 2, 0, 1.0, 0.5)); // no right neighbour, no crash
}

TEST(Exposure, MapsAvgmaxTo128AndRoundsHalfAwayFromZero) {
  const float scale = exposureScale(0.5);
  EXPECT_FLOAT_EQ(scale, 256.0f);
  EXPECT_EQ(exposeChannel(0.5f, scale), 128);
  EXPECT_EQ(exposeChannel(0.0f, scale), 0);
  // 1.5 / 256 and 2.5 / 256 are exact in binary: halves go away from zero.
  EXPECT_EQ(exposeChannel(1.5f / 256.0f, scale), 2);
  EXPECT_EQ(exposeChannel(2.5f / 256.0f, scale), 3);
  EXPECT_EQ(exposeChannel(2.25f / 256.0f, scale), 2);
}

TEST(Exposure, PegsAt255) {
  const float scale = exposureScale(1.0);
  EXPECT_EQ(exposeChannel(254.4f / 128.0f, scale), 254);
  EXPECT_EQ(exposeChannel(254.5f / 128.0f, scale), 255);
  EXPECT_EQ(exposeChannel(1000.0f, scale), 255);
  EXPECT_EQ(exposeChannel(std::numeric_limits<float>::infinity(), scale), 255);
}

TEST(Exposure, AvgmaxZeroGivesBlackAndNoNaN) {
  const float scale = exposureScale(0.0);
  EXPECT_EQ(scale, 0.0f);
  EXPECT_EQ(exposeChannel(0.0f, scale), 0);
  EXPECT_EQ(exposeChannel(std::nanf(""), 1.0f), 0);
  const auto bytes = exposeImage({Rgb(0.0f), Rgb(0.0f)}, scale);
  EXPECT_EQ(bytes, std::vector<std::uint8_t>(6, 0));
}

TEST(Exposure, ImageIsInterleavedRgbInPixelOrder) {
  const auto bytes = exposeImage({Rgb(1.0f, 0.5f, 0.0f), Rgb(2.0f, 0.25f, 4.0f)}, 100.0f);
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{100, 50, 0, 200, 25, 255}));
}

// A camera at z = 1 looking down at z = 0 with a 90 degree field: on that plane
// the image spans x, y in [-1, 1] and screen x maps linearly to world x. A white
// polygon (ambient 1, kdr 1: radiance exactly 1) covers x >= edge; the rest is
// black background.
struct HalfPlaneScene {
  explicit HalfPlaneScene(double edge) {
    scene.camera = {Vec3(0, 0, 1), Vec3(0, 0, 0), Vec3(0, 1, 0), 90.0};
    scene.ambient = Color(1.0);
    SceneBuilder build(scene);
    const std::vector<Vec3> quad{{edge, -10, 0}, {10, -10, 0}, {10, 10, 0}, {edge, 10, 0}};
    build.polygon(quad, build.material(Material{}), Origin{});
    accel = makeAccel(scene, AccelKind::None);
  }
  Scene scene;
  std::unique_ptr<Accel> accel;
};

// World x of screen x on a 4-pixel-wide image.
double worldX(double sx) { return 2.0 * sx / 4.0 - 1.0; }

TEST(SupersamplePixel, SixteenSamplesAtCellCentres) {
  // Sub-sample columns of pixel 1 are at sx = 1.125, 1.375, 1.625, 1.875. An edge
  // at sx = 1.3 leaves three of the four columns white: mean exactly 0.75.
  HalfPlaneScene s(worldX(1.3));
  Tracer tracer(s.scene, *s.accel, 1);
  const Camera camera(s.scene.camera, 4, 4);
  RayCounts counts;
  const Rgb c = supersamplePixel(tracer, camera, 1, 2, false, counts);
  EXPECT_FLOAT_EQ(c.r, 0.75f);
  EXPECT_EQ(counts.eyeAntialias, 16u);
  EXPECT_EQ(counts.eyePrimary, 0u);
  // Edge at sx = 1.5: exactly half.
  HalfPlaneScene half(worldX(1.5));
  Tracer t2(half.scene, *half.accel, 1);
  EXPECT_FLOAT_EQ(supersamplePixel(t2, camera, 1, 0, false, counts).g, 0.5f);
}

TEST(SupersamplePixel, JitterStaysInsideCellsAndIsDeterministic) {
  // Edge on a cell boundary (sx = 1.25): a jittered sample never crosses it,
  // so the mean is the same as without jitter.
  HalfPlaneScene s(worldX(1.25));
  Tracer tracer(s.scene, *s.accel, 1);
  const Camera camera(s.scene.camera, 4, 4);
  RayCounts counts;
  EXPECT_FLOAT_EQ(supersamplePixel(tracer, camera, 1, 1, true, counts).r, 0.75f);
  // Edge inside a cell column: jitter gives some multiple of 1/16 between the
  // all-black and all-white outcomes of that column, the same on every call.
  HalfPlaneScene mid(worldX(1.3));
  Tracer t2(mid.scene, *mid.accel, 1);
  const Rgb a = supersamplePixel(t2, camera, 1, 1, true, counts);
  const Rgb b = supersamplePixel(t2, camera, 1, 1, true, counts);
  EXPECT_EQ(a, b);
  EXPECT_GE(a.r, 0.5f);
  EXPECT_LE(a.r, 0.75f);
  EXPECT_FLOAT_EQ(a.r * 16.0f, std::round(a.r * 16.0f));
}

TEST(AntialiasBlock, SupersamplesOnlyPixelsAtTheEdgeAndKeepsPassOne) {
  HalfPlaneScene s(worldX(2.3)); // edge inside pixel column 2
  Tracer tracer(s.scene, *s.accel, 1);
  const Camera camera(s.scene.camera, 4, 4);
  Film film(4, 4);
  RayCounts counts;
  const Tile all{0, 0, 4, 4};
  std::vector<Pixel> pixels;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      pixels.push_back({x, y});
  std::vector<Sample> centres;
  tracePixelCentres(tracer, camera, pixels, centres, counts);
  storeCentres(centres, film);
  EXPECT_EQ(counts.eyePrimary, 16u);
  // Centres at sx = 0.5, 1.5 are black, 2.5 and 3.5 white.
  EXPECT_EQ(film.centre[film.index(1, 0)], Rgb(0.0f));
  EXPECT_EQ(film.centre[film.index(2, 0)], Rgb(1.0f));
  const double avgmax = averageMax(film.centre);
  EXPECT_DOUBLE_EQ(avgmax, 0.5);
  std::vector<std::uint8_t> marks(film.pixelCount(), 0);
  markForSupersampling(all, film, avgmax, 0.1, marks);
  std::vector<Sample> means;
  antialiasBlock(tracer, camera, all, film, marks, false, means, counts);
  storeSupersampled(means, film);
  EXPECT_EQ(means.size(), 8u); // columns 1 and 2, every row
  EXPECT_EQ(counts.eyeAntialias, 16u * 8u);
  for (int y = 0; y < 4; ++y) {
    EXPECT_EQ(film.supersampled[film.index(0, y)], 0);
    EXPECT_EQ(film.supersampled[film.index(1, y)], 1);
    EXPECT_EQ(film.supersampled[film.index(3, y)], 0);
    EXPECT_FLOAT_EQ(film.radiance[film.index(1, y)].r, 0.0f);  // all sub-samples black
    EXPECT_FLOAT_EQ(film.radiance[film.index(2, y)].r, 0.75f); // 3 of 4 columns white
    EXPECT_EQ(film.centre[film.index(2, y)], Rgb(1.0f));       // pass 1 untouched
  }
}

TEST(Tiles, CoverTheImageExactlyOnce) {
  const auto tiles = makeTiles(70, 33, 32);
  std::vector<int> covered(70 * 33, 0);
  for (const Tile& t : tiles)
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x)
        ++covered[std::size_t(y * 70 + x)];
  for (int c : covered)
    EXPECT_EQ(c, 1);
  EXPECT_EQ(tiles.size(), 3u * 2u);
}

} // namespace
} // namespace prism
