// The library's public API (core/api/prism.h, docs/library.md): values
// against hand computation, edits, progress, cancellation, errors, files.
#include "core/api/prism.h"

#include "test_files.h"
#include "test_pictures.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <stop_token>

namespace prism::api {
namespace {

// A wall of C = (1, 0.5, 0.25), kdr = 0.5, at z = 0 facing the eye at
// (0, 0, 5); ambient 0.2; one light of 4 at the eye. The centre pixel of an
// odd-sized image sees the wall's point (0, 0, 0) head on: N.L = 1, r = 5,
// so its radiance is C kdr (I_a + I / r^2) = C 0.5 (0.2 + 0.16) = C 0.18.
constexpr const char* kWall = "resolution 5 5\n"
                              "ambient 0.2 0.2 0.2\n"
                              "light 0 0 5  4 4 4\n"
                              "surface 1 0.5 0.25  0.5 0 0  1 1\n"
                              "polygon 4  -10 -10 0  10 -10 0  10 10 0  -10 10 0\n";

Rgb centre(const Image& image) {
  return image.radiance[std::size_t(image.height / 2) * std::size_t(image.width) +
                        std::size_t(image.width / 2)];
}

void expectRgbNear(const Rgb& got, double r, double g, double b) {
  EXPECT_NEAR(got.r, r, 1e-6 * r);
  EXPECT_NEAR(got.g, g, 1e-6 * g);
  EXPECT_NEAR(got.b, b, 1e-6 * b);
}

TEST(Api, RendersTheShadingFormulaAtThePixelCentre) {
  const LoadedScene scene = LoadedScene::fromText(kWall);
  EXPECT_EQ(scene.width(), 5);
  EXPECT_EQ(scene.height(), 5);
  RenderOptions options;
  options.antialias = false;
  const Image image = render(scene, options);
  ASSERT_EQ(image.width, 5);
  ASSERT_EQ(image.height, 5);
  ASSERT_EQ(image.radiance.size(), 25u);
  expectRgbNear(centre(image), 0.18, 0.09, 0.045);
  EXPECT_EQ(image.stats.counts.eye(), 25u);
  EXPECT_EQ(image.stats.counts.shadow, 25u); // one light, every pixel on the wall
  EXPECT_EQ(image.stats.width, 5);
  EXPECT_EQ(image.stats.primitives, 1u);
}

TEST(Api, EditedLightsAndCameraChangeTheNextRender) {
  LoadedScene scene = LoadedScene::fromText(kWall);
  RenderOptions options;
  options.antialias = false;
  // Twice the light: C 0.5 (0.2 + 0.32) = C 0.26.
  scene.setLight(0, Light{Vec3(0.0, 0.0, 5.0), Color(8.0)});
  expectRgbNear(centre(render(scene, options)), 0.26, 0.13, 0.065);
  // A second light of 4 at distance 10 on the axis: + C 0.5 * 4/100 = C 0.02.
  scene.addLight(Light{Vec3(0.0, 0.0, 10.0), Color(4.0)});
  ASSERT_EQ(scene.lights().size(), 2u);
  expectRgbNear(centre(render(scene, options)), 0.28, 0.14, 0.07);
  scene.removeLight(0);
  scene.removeLight(0);
  // Ambient alone: C 0.5 0.2 = C 0.1.
  expectRgbNear(centre(render(scene, options)), 0.1, 0.05, 0.025);
  // The eye moved back to z = 10 still sees the wall's centre head on.
  CameraSpec camera = scene.camera();
  camera.eye = Vec3(0.0, 0.0, 10.0);
  scene.setCamera(camera);
  scene.addLight(Light{Vec3(0.0, 0.0, 10.0), Color(4.0)});
  expectRgbNear(centre(render(scene, options)), 0.12, 0.06, 0.03);
}

TEST(Api, RefusesValuesOutsideTheirRangesSayingWhich) {
  LoadedScene scene = LoadedScene::fromText(kWall);
  CameraSpec camera = scene.camera();
  camera.lookat = camera.eye;
  try {
    scene.setCamera(camera);
    FAIL() << "a camera with eye at lookat was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("eye and lookat are the same point"), std::string::npos)
        << e.what();
  }
  camera = scene.camera();
  camera.fov = 180.0;
  EXPECT_THROW(scene.setCamera(camera), std::invalid_argument);
  EXPECT_THROW(scene.setLight(1, Light{}), std::out_of_range);
  EXPECT_THROW(scene.addLight(Light{Vec3(0.0), Color(-1.0, 0.0, 0.0)}), std::invalid_argument);
  EXPECT_THROW(scene.addLight(Light{Vec3(0.0), Color(NAN)}), std::invalid_argument);
  EXPECT_EQ(scene.lights().size(), 1u); // nothing refused was kept

  RenderOptions options;
  options.depth = 0;
  EXPECT_THROW(render(scene, options), std::invalid_argument);
  options = {};
  options.thresh = 1.5;
  EXPECT_THROW(render(scene, options), std::invalid_argument);
  options = {};
  options.width = 10; // without a height
  EXPECT_THROW(render(scene, options), std::invalid_argument);
}

TEST(Api, ASceneErrorSaysWhereAndWhat) {
  try {
    (void)LoadedScene::fromText("sphere 0 0 0\n", "broken.sc");
    FAIL() << "a sphere without a radius was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("broken.sc:1:", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("error:"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)LoadedScene::fromFile("no/such/scene.sc"), SceneError);
}

TEST(Api, ProgressRisesToTheWholeAndAStopTokenCancels) {
  const LoadedScene scene = LoadedScene::fromText(kWall);
  RenderOptions options;
  options.width = options.height = 128; // 16 tiles of 32 x 32 per pass
  options.threads = 2;
  std::atomic<int> calls{0};
  std::atomic<double> last{0.0};
  std::atomic<bool> rising{true};
  (void)render(scene, options, [&](const Progress& p) {
    if (p.fraction < last.load()) rising = false;
    last = p.fraction;
    ++calls;
  });
  EXPECT_GE(calls.load(), 32);
  EXPECT_TRUE(rising.load());
  EXPECT_DOUBLE_EQ(last.load(), 1.0);

  // Stopped after the first tile: the render ends with Cancelled, early.
  std::stop_source stop;
  std::atomic<int> tiles{0};
  EXPECT_THROW(render(
                   scene, options,
                   [&](const Progress&) {
                     ++tiles;
                     stop.request_stop();
                   },
                   stop.get_token()),
               Cancelled);
  EXPECT_LT(tiles.load(), 32);
}

TEST(Api, ExposesByAvgmaxAndWritesThePicture) {
  const LoadedScene scene = LoadedScene::fromText(kWall);
  RenderOptions options;
  options.antialias = false;
  const Image image = render(scene, options);
  // The centre's max channel is 0.18; exposed as if avgmax were 0.18 it is
  // 128 exactly; its other channels scale with it: 64 and 32.
  const std::vector<std::uint8_t> bytes = expose(image, false, 0.18);
  ASSERT_EQ(bytes.size(), 75u);
  EXPECT_EQ(bytes[3 * 12 + 0], 128);
  EXPECT_EQ(bytes[3 * 12 + 1], 64);
  EXPECT_EQ(bytes[3 * 12 + 2], 32);
  // sRGB of 128/255 = 0.50196: 1.055 * 0.50196^(1/2.4) - 0.055 = 0.73536 -> 188.
  EXPECT_EQ(expose(image, true, 0.18)[3 * 12], 188);

  test::ScratchDir dir;
  write(dir / "wall.tif", image);
  const std::optional<test::Picture> picture = test::readPicture(dir / "wall.tif");
  ASSERT_TRUE(picture);
  EXPECT_EQ(picture->width, 5);
  EXPECT_EQ(picture->height, 5);
  EXPECT_EQ(picture->pixels, expose(image));
  EXPECT_THROW(write(dir.path() / "no-such-folder/wall.tif", image), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(dir / "no-such-folder"));
}

TEST(Api, TheRayTreeOfAPixelHoldsItsShadingTerms) {
  const LoadedScene scene = LoadedScene::fromText(kWall);
  std::string text;
  const RayTreeNode root = pixelRayTree(scene, RenderOptions{}, 2, 2, &text);
  EXPECT_TRUE(root.hit);
  EXPECT_EQ(root.depth, 1);
  ASSERT_EQ(root.lights.size(), 1u);
  EXPECT_NEAR(root.lights[0].distance, 5.0, 1e-12);
  EXPECT_NEAR(root.lights[0].cosine, 1.0, 1e-12);
  EXPECT_FALSE(root.lights[0].shadowed);
  EXPECT_NEAR(root.radiance.r, 0.18, 1e-12);
  EXPECT_TRUE(root.children.empty()); // kst = ksr = 0: nothing spawned
  EXPECT_NE(text.find("pixel (2, 2) of 5 x 5"), std::string::npos) << text;
  EXPECT_THROW(pixelRayTree(scene, RenderOptions{}, 5, 0), std::invalid_argument);
}

TEST(Api, StatisticsAsJsonNameTheSceneAndTheRays) {
  const LoadedScene scene = LoadedScene::fromText(kWall, "wall.sc");
  RenderOptions options;
  options.antialias = false;
  const std::string json = statsJson(render(scene, options));
  EXPECT_NE(json.find("\"scene\": \"wall.sc\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"eye\": 25"), std::string::npos) << json;
}

} // namespace
} // namespace prism::api
