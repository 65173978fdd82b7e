// The previewer's controller without a window: Save writes the picture a
// headless render of the same settings gives, scene files are watched and
// reloaded, a broken edit keeps the last good scene and lists its errors.
#include "viewer/file_watch.h"
#include "viewer/view_controller.h"

#include "core/exposure.h"
#include "core/scene_loader.h"
#include "core/scene_parser.h"

#include "test_pictures.h"

#include <thread>

namespace prism::test {
namespace {

const char* kMain = R"(eye 0 1 5
lookat 0 0 0
resolution 40 30
include lights.sc
surface 1 0.5 0.2 0.8 0.2 0 20 1
sphere 0 0 0 1
surface 0.3 0.6 0.9 1 0 0 1 1
polygon 4 -3 -1 -3  -3 -1 3  3 -1 3  3 -1 -3
)";

ViewOptions optionsFor(const Scene& scene, const fs::path& path) {
  ViewOptions o;
  o.scenePath = path.string();
  o.settings.width = scene.width;
  o.settings.height = scene.height;
  o.settings.maxDepth = 3;
  o.settings.threads = 2;
  return o;
}

// kMain and its include with one light, written to `dir`; returns the scene.
Scene writeMainScene(const ScratchDir& dir) {
  writeFile(dir / "main.sc", kMain);
  writeFile(dir / "lights.sc", "light 2 3 4 30 30 30\n");
  return loadScene(dir / "main.sc");
}

// Calls update() until `done` holds (each call is one "frame").
template <class Done> void updateUntil(ViewController& c, Done done) {
  auto now = ViewController::Clock::now();
  for (int frame = 0; frame < 200000 && !done(); ++frame) {
    now += std::chrono::milliseconds(20); // the controller's clock, for its file polling
    c.update(now);
    std::this_thread::yield();
  }
  ASSERT_TRUE(done());
}

TEST(FileWatch, ReportsEachChangeOnce) {
  ScratchDir dir;
  writeFile(dir / "a.sc", "one");
  FileWatch watch;
  watch.watch({(dir / "a.sc").string(), (dir / "missing.sc").string()});
  EXPECT_FALSE(watch.changed());
  writeFile(dir / "a.sc", "three"); // size changes even within one mtime tick
  EXPECT_TRUE(watch.changed());
  EXPECT_FALSE(watch.changed());
  writeFile(dir / "missing.sc", "now here");
  EXPECT_TRUE(watch.changed());
  fs::remove(dir / "a.sc");
  EXPECT_TRUE(watch.changed());
}

TEST(ViewController, SaveWritesWhatAHeadlessRenderGives) {
  ScratchDir dir;
  Scene scene = writeMainScene(dir);
  const ViewOptions options = optionsFor(scene, dir / "main.sc");
  const auto accel = makeAccel(scene, options.accel);
  const RenderResult expected = render(scene, *accel, options.settings);

  ViewController c(scene, options);
  c.save((dir / "saved.png").string()); // before the render is done: it waits for it
  EXPECT_TRUE(c.saveJob().busy());
  updateUntil(c, [&] { return !c.saveJob().busy(); });
  ASSERT_EQ(c.saveJob().state(), SaveJob::State::Saved) << c.saveJob().message();
  const auto saved = readPicture(dir / "saved.png");
  ASSERT_TRUE(saved);
  EXPECT_EQ(saved->pixels, exposeImage(expected.film.radiance, exposureScale(expected.avgmax)));

  c.save((dir / "no such dir" / "x.png").string());
  EXPECT_EQ(c.saveJob().state(), SaveJob::State::Failed);
  EXPECT_NE(c.saveJob().message().find("no such directory"), std::string::npos);
}

TEST(ViewController, ReloadsChangedIncludesAndKeepsTheLastGoodSceneOnErrors) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  ViewController c(scene, optionsFor(scene, dir / "main.sc"));
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });

  writeFile(dir / "lights.sc", "light 2 3 oops\n");
  updateUntil(c, [&] { return c.failedReloads() == 1; });
  ASSERT_EQ(c.sceneErrors().size(), 1u);
  EXPECT_EQ(c.sceneErrors()[0].rfind((dir / "lights.sc").string() + ":1:11: error:", 0), 0u)
      << c.sceneErrors()[0];
  EXPECT_EQ(c.scene().lights.size(), 1u); // still the last good scene
  EXPECT_EQ(c.scene().lights[0].position, Vec3(2, 3, 4));

  writeFile(dir / "lights.sc", "light -2 3 4 30 30 30\nlight 0 5 0 10 10 10\n");
  updateUntil(c, [&] { return c.successfulReloads() == 1; });
  EXPECT_TRUE(c.sceneErrors().empty());
  EXPECT_EQ(c.scene().lights.size(), 2u);
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
}

TEST(ViewController, ReloadsInTheBackgroundAndPutsTheSceneInPlaceOnUpdate) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  ViewController c(scene, optionsFor(scene, dir / "main.sc"));

  writeFile(dir / "lights.sc", "light 1 1 1 5 5 5\nlight 0 5 0 10 10 10\n");
  c.reload();
  c.reload(); // asked again while the first runs: read once more after it
  EXPECT_TRUE(c.reloading());
  // Only update() changes the scene, whenever the loader thread finishes.
  EXPECT_EQ(c.scene().lights.size(), 1u);
  updateUntil(c, [&] { return c.successfulReloads() == 1; });
  EXPECT_EQ(c.scene().lights.size(), 2u);
  updateUntil(c, [&] { return c.successfulReloads() == 2; });
  EXPECT_FALSE(c.reloading());
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
  EXPECT_EQ(c.successfulReloads(), 2);
  EXPECT_EQ(c.failedReloads(), 0);
}

TEST(ViewController, ShowsWhatLoadingTheSceneWarnedAbout) {
  ScratchDir dir;
  writeFile(dir / "main.nff", "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\n"
                              "resolution 8 8\nl 1 1 1\nf 1 0 0 1 0 0 0 1\ns 0 0 0 1\n"
                              "p 3 0 0 0 1 0 0 2 0 0\n");
  std::vector<Diagnostic> warnings;
  const Scene scene = loadAnyScene(dir / "main.nff", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  ViewController c(scene, optionsFor(scene, dir / "main.nff"), {formatWarning(warnings[0])});
  ASSERT_EQ(c.sceneWarnings().size(), 1u);
  EXPECT_NE(c.sceneWarnings()[0].find("main.nff:11:"), std::string::npos) << c.sceneWarnings()[0];
  EXPECT_NE(c.sceneWarnings()[0].find("degenerate polygon"), std::string::npos);

  // A reload reports the warnings of the files as they are now.
  writeFile(dir / "main.nff", "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\n"
                              "resolution 8 8\nl 1 1 1\nf 1 0 0 1 0 0 0 1\ns 0 0 0 1\n");
  c.reload();
  updateUntil(c, [&] { return c.successfulReloads() == 1; });
  EXPECT_TRUE(c.sceneWarnings().empty());
}

TEST(ViewController, ResetCameraGoesBackToTheFile) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  ViewController c(scene, optionsFor(scene, dir / "main.sc"));
  CameraSpec moved = scene.camera;
  moved.eye = Vec3(4, 4, 4);
  c.setCamera(moved);
  EXPECT_FALSE(c.snapshotCurrent());
  EXPECT_EQ(c.scene().camera.eye, Vec3(4, 4, 4));
  c.resetCamera();
  EXPECT_EQ(c.scene().camera.eye, scene.camera.eye);
  c.update();
  EXPECT_TRUE(c.snapshotCurrent());
}

} // namespace
} // namespace prism::test
