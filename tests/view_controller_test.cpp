// The previewer's controller without a window: Save writes the picture a
// headless render of the same settings gives, scene files are watched and
// reloaded, a broken edit keeps the last good scene and lists its errors;
// edits are undone and redone, survive reloads where their value still
// exists, and Save scene as writes them.
#include "viewer/file_watch.h"
#include "viewer/view_controller.h"

#include "core/io/image_io.h"
#include "core/io/scene_loader.h"
#include "core/io/scene_parser.h"
#include "core/render/exposure.h"

#include "viewer/camera_controls.h"

#include "test_pictures.h"

#include <sstream>
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

// Calls update() until `done` holds (each call is one "frame"). Bounded by
// time, not by a count of frames: a reload or a render runs on other threads,
// which on a loaded machine (the sanitizer suite, two tests at once) can take
// longer than any fixed number of quick frames.
template <class Done> void updateUntil(ViewController& c, Done done) {
  auto now = ViewController::Clock::now();
  const auto giveUp = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (!done() && std::chrono::steady_clock::now() < giveUp) {
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

// An image a surface reads is watched like an include: a new picture in the
// file reloads the scene, and the reloaded scene has the new texels.
TEST(ViewController, ReloadsAChangedImage) {
  ScratchDir dir;
  writeImage8(dir / "tex.png", 1, 1, {0, 0, 255});
  writeFile(dir / "main.sc", std::string(kMain) + "surface 1 1 1 1 0 0 1 1\nimage tex.png\n"
                                                  "sphere 2 0 0 0.5\n");
  writeFile(dir / "lights.sc", "light 2 3 4 30 30 30\n");
  const Scene scene = loadScene(dir / "main.sc");
  ViewController c(scene, optionsFor(scene, dir / "main.sc"));
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
  writeImage8(dir / "tex.png", 2, 1, {255, 0, 0, 255, 0, 0}); // red, and another size
  updateUntil(c, [&] { return c.successfulReloads() == 1; });
  ASSERT_NE(c.scene().images, nullptr);
  EXPECT_EQ(c.scene().images->info(0).width, 2);
  EXPECT_EQ(c.scene().images->info(0).peak, Color(1, 0, 0));
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

// Opening another scene: it takes this one's place once read, without this
// one's edits or history; the render settings stay. A scene with errors
// leaves the current one in place.
TEST(ViewController, OpensAnotherSceneAFreshStart) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  ViewController c(scene, optionsFor(scene, dir / "main.sc"));
  CameraSpec moved = c.scene().camera;
  moved.eye += Vec3(1.0, 0.0, 0.0);
  c.apply(CameraEdit{moved});
  RenderSettings deeper = c.settings();
  deeper.maxDepth = 3;
  c.apply(SettingsEdit{deeper});
  ASSERT_TRUE(c.canUndo());
  writeFile(dir / "other.sc", "eye 0 0 9\nlight 1 1 1 5 5 5\nlight 2 2 2 5 5 5\n"
                              "light 3 3 3 5 5 5\nsphere 0 0 0 1\n");
  c.open((dir / "other.sc").string());
  updateUntil(c, [&] { return c.successfulReloads() == 1; });
  EXPECT_EQ(c.scenePath(), (dir / "other.sc").string());
  EXPECT_EQ(c.scene().lights.size(), 3u);
  EXPECT_EQ(c.scene().camera.eye, Vec3(0, 0, 9)); // the new file's, not the edited one
  EXPECT_FALSE(c.canUndo());
  EXPECT_EQ(c.settings().maxDepth, 3);
  // A broken one: the scene stays, the errors say why.
  writeFile(dir / "broken.sc", "sphere 0 0 0 -1\n");
  c.open((dir / "broken.sc").string());
  updateUntil(c, [&] { return c.failedReloads() == 1; });
  EXPECT_EQ(c.scenePath(), (dir / "other.sc").string());
  ASSERT_FALSE(c.sceneErrors().empty());
  EXPECT_NE(c.sceneErrors()[0].find("broken.sc:1:"), std::string::npos);
  // Asked for while a reload is being read: opened right after it.
  c.reload();
  c.open((dir / "main.sc").string());
  updateUntil(c, [&] { return c.scenePath() == (dir / "main.sc").string(); });
  EXPECT_EQ(c.scene().lights.size(), 1u);
}

// A sweep table of main.sc's settings as optionsFor() sets them (depth 3,
// threshold 0.1) and of one cheaper and better setting.
std::string sweepCsv(double currentPsnr) {
  SweepRow current, better;
  current.setting = {.antialias = true, .thresh = 0.1, .depth = 3};
  current.cpuSeconds = 2.0;
  current.error.psnr = currentPsnr;
  better.setting = {.antialias = true, .thresh = 0.2, .depth = 2};
  better.cpuSeconds = 1.0;
  better.error.psnr = 40.0;
  return formatSweepCsv({current, better});
}

TEST(ViewController, ReadsTheSweepBesideTheSceneWithEveryLoad) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  writeFile(dir / "main.sweep.csv", sweepCsv(30.0));
  ViewController c(scene, optionsFor(scene, dir / "main.sc"));
  EXPECT_EQ(c.sweep().path, (dir / "main.sweep.csv").string());
  ASSERT_EQ(c.sweep().rows.size(), 2u);
  SweepStatus status = c.sweepStatus();
  ASSERT_TRUE(status.visible && status.current && status.best);
  EXPECT_EQ(status.current->error.psnr, 30.0);
  EXPECT_EQ(status.best->setting.depth, 2);

  // The status follows the settings ...
  RenderSettings deeper = c.settings();
  deeper.maxDepth = 4;
  c.apply(SettingsEdit{deeper});
  status = c.sweepStatus();
  EXPECT_FALSE(status.current);
  EXPECT_EQ(status.lines.back(), "not in the sweep");
  c.undo();
  // ... and the table is read again with the scene.
  writeFile(dir / "main.sweep.csv", sweepCsv(45.0));
  c.reload();
  updateUntil(c, [&] { return c.successfulReloads() == 1; });
  status = c.sweepStatus();
  ASSERT_TRUE(status.current);
  EXPECT_EQ(status.current->error.psnr, 45.0);
  EXPECT_TRUE(status.currentOnFront());

  // A malformed table says where; the scene is shown all the same.
  writeFile(dir / "main.sweep.csv", sweepCsv(45.0) + "1,2\n");
  c.reload();
  updateUntil(c, [&] { return c.successfulReloads() == 2; });
  EXPECT_TRUE(c.sceneErrors().empty());
  EXPECT_EQ(c.sweep().error,
            (dir / "main.sweep.csv").string() + ":4:4: expected 22 fields as in the header, got 2");
  EXPECT_TRUE(c.sweepStatus().visible);

  // Gone: no sweep, silently.
  fs::remove(dir / "main.sweep.csv");
  c.reload();
  updateUntil(c, [&] { return c.successfulReloads() == 3; });
  EXPECT_FALSE(c.sweep().present());
  EXPECT_FALSE(c.sweepStatus().visible);
}

TEST(ViewController, ASweepNamedOnTheCommandLineIsThisScenesOnly) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  writeFile(dir / "elsewhere" / "measured.csv", sweepCsv(33.0));
  writeFile(dir / "main.sweep.csv", sweepCsv(30.0)); // not the one named
  ViewOptions options = optionsFor(scene, dir / "main.sc");
  options.sweepPath = (dir / "elsewhere" / "measured.csv").string();
  ViewController c(scene, options);
  ASSERT_TRUE(c.sweepStatus().current);
  EXPECT_EQ(c.sweepStatus().current->error.psnr, 33.0);
  c.reload();
  updateUntil(c, [&] { return c.successfulReloads() == 1; });
  EXPECT_EQ(c.sweep().path, options.sweepPath);

  // Another scene: the table beside it (here none).
  writeFile(dir / "other.sc", "eye 0 0 9\nlight 1 1 1 5 5 5\nsphere 0 0 0 1\n");
  c.open((dir / "other.sc").string());
  updateUntil(c, [&] { return c.successfulReloads() == 2; });
  EXPECT_FALSE(c.sweep().present());
  writeFile(dir / "other.sweep.csv", sweepCsv(20.0));
  c.reload();
  updateUntil(c, [&] { return c.successfulReloads() == 3; });
  EXPECT_EQ(c.sweep().path, (dir / "other.sweep.csv").string());
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
  c.apply(CameraEdit{moved});
  EXPECT_FALSE(c.snapshotCurrent());
  EXPECT_EQ(c.scene().camera.eye, Vec3(4, 4, 4));
  c.apply(ResetCamera{});
  EXPECT_EQ(c.scene().camera.eye, scene.camera.eye);
  c.update();
  EXPECT_TRUE(c.snapshotCurrent());
}

// ---------------------------------------------------------------------------
// Undo and redo

bool sameCamera(const CameraSpec& a, const CameraSpec& b) {
  return a.eye == b.eye && a.lookat == b.lookat && a.up == b.up && a.fov == b.fov;
}

bool sameLight(const Light& a, const Light& b) {
  return a.position == b.position && a.intensity == b.intensity;
}

// Lets the render finish; returns the picture the window shows then.
std::vector<Rgb> finishedImage(ViewController& c) {
  // One update first: after an edit, undo or revert the progress snapshot
  // still says Done for the picture before it until the next update.
  c.update(ViewController::Clock::now());
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
  return c.image().radiance;
}

// A headless render of `scene` with the controller's settings.
std::vector<Rgb> renderOf(const Scene& scene, const ViewOptions& options) {
  const auto accel = makeAccel(scene, options.accel);
  return render(scene, *accel, options.settings).film.radiance;
}

// After an edit (or undo, redo): the session restarted once more, and the
// snapshot is stale until the next update().
void expectRestarted(ViewController& c, std::uint64_t& restarts) {
  EXPECT_FALSE(c.snapshotCurrent());
  c.update();
  EXPECT_EQ(c.progress().restarts, restarts + 1);
  restarts = c.progress().restarts;
}

TEST(ViewControllerUndo, UndoAndRedoRestoreExactValuesAndRestartTheRender) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  const ViewOptions options = optionsFor(scene, dir / "main.sc");
  ViewController c(scene, options);
  EXPECT_FALSE(c.canUndo());
  EXPECT_FALSE(c.canRedo());
  EXPECT_FALSE(c.undo());
  c.update();
  std::uint64_t restarts = c.progress().restarts;

  Light moved = scene.lights[0];
  moved.position = Vec3(-2.5, 3.25, 1.125);
  moved.intensity = Color(10, 20, 30);
  c.apply(LightEdit{0, moved});
  expectRestarted(c, restarts);
  const CameraSpec orbited = orbit(scene.camera, 30.0, 10.0);
  c.apply(CameraEdit{orbited});
  expectRestarted(c, restarts);
  RenderSettings deeper = c.settings();
  deeper.maxDepth = 1;
  c.apply(SettingsEdit{deeper});
  expectRestarted(c, restarts);

  ASSERT_TRUE(c.undo()); // the depth
  expectRestarted(c, restarts);
  EXPECT_EQ(c.settings().maxDepth, 3);
  ASSERT_TRUE(c.undo()); // the camera
  expectRestarted(c, restarts);
  EXPECT_TRUE(sameCamera(c.scene().camera, scene.camera));
  EXPECT_TRUE(sameLight(c.scene().lights[0], moved));
  EXPECT_TRUE(c.canRedo());
  // The render restarted with the light moved and the file's camera.
  Scene expected = scene;
  expected.lights[0] = moved;
  EXPECT_EQ(finishedImage(c), renderOf(expected, options));

  ASSERT_TRUE(c.undo()); // the light
  expectRestarted(c, restarts);
  EXPECT_TRUE(sameLight(c.scene().lights[0], scene.lights[0]));
  EXPECT_FALSE(c.canUndo());
  EXPECT_FALSE(c.undo());
  EXPECT_FALSE(c.edits().sceneEdited());
  EXPECT_EQ(finishedImage(c), renderOf(scene, options));

  ASSERT_TRUE(c.redo());
  expectRestarted(c, restarts);
  EXPECT_TRUE(sameLight(c.scene().lights[0], moved));
  ASSERT_TRUE(c.redo());
  EXPECT_TRUE(sameCamera(c.scene().camera, orbited));
  ASSERT_TRUE(c.redo());
  EXPECT_EQ(c.settings().maxDepth, 1);
  EXPECT_FALSE(c.canRedo());
  EXPECT_FALSE(c.redo());
}

TEST(ViewControllerUndo, ANewEditDropsWhatCouldBeRedone) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  ViewController c(scene, optionsFor(scene, dir / "main.sc"));
  c.apply(AmbientEdit{Color(0.1)});
  c.apply(AmbientEdit{Color(0.2)});
  ASSERT_TRUE(c.undo());
  EXPECT_EQ(c.scene().ambient, Color(0.1));
  EXPECT_TRUE(c.canRedo());
  c.apply(AmbientEdit{Color(0.3)});
  EXPECT_FALSE(c.canRedo());
  EXPECT_FALSE(c.redo());
  ASSERT_TRUE(c.undo());
  EXPECT_EQ(c.scene().ambient, Color(0.1));
  // An edit that changes nothing is no step and no restart.
  c.update();
  const std::uint64_t restarts = c.progress().restarts;
  c.apply(AmbientEdit{Color(0.1)});
  EXPECT_TRUE(c.snapshotCurrent());
  EXPECT_TRUE(c.canRedo()); // still there
  c.update();
  EXPECT_EQ(c.progress().restarts, restarts);
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
}

TEST(ViewControllerUndo, ADragIsOneStep) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  ViewController c(scene, optionsFor(scene, dir / "main.sc"));
  c.apply(AmbientEdit{Color(0.05)}); // a step before the drags

  // A mouse drag: one camera edit per frame.
  c.beginGesture();
  EXPECT_TRUE(c.inGesture());
  CameraSpec camera = scene.camera;
  for (int frame = 0; frame < 40; ++frame) {
    camera = orbit(camera, 2.0, 0.5);
    c.apply(CameraEdit{camera});
    c.update();
  }
  c.endGesture();
  EXPECT_TRUE(sameCamera(c.scene().camera, camera));
  // A slider drag of light 1 (position, then intensity), the same way.
  c.beginGesture();
  Light light = scene.lights[0];
  for (int frame = 0; frame < 25; ++frame) {
    light.position.x += 0.1;
    light.intensity *= 1.01;
    c.apply(LightEdit{0, light});
  }
  c.endGesture();

  ASSERT_TRUE(c.undo()); // the whole light drag
  EXPECT_TRUE(sameLight(c.scene().lights[0], scene.lights[0]));
  EXPECT_TRUE(sameCamera(c.scene().camera, camera));
  ASSERT_TRUE(c.undo()); // the whole camera drag
  EXPECT_TRUE(sameCamera(c.scene().camera, scene.camera));
  EXPECT_EQ(c.scene().ambient, Color(0.05));
  ASSERT_TRUE(c.undo()); // the ambient
  EXPECT_FALSE(c.canUndo());
  ASSERT_TRUE(c.redo());
  ASSERT_TRUE(c.redo());
  EXPECT_TRUE(sameCamera(c.scene().camera, camera)); // the drag's end, in one step

  // A drag that ends where it began leaves no step.
  ASSERT_TRUE(c.redo());
  c.beginGesture();
  Light away = light;
  away.position.y += 5.0;
  c.apply(LightEdit{0, away});
  c.apply(LightEdit{0, light});
  c.endGesture();
  EXPECT_FALSE(c.canRedo());
  ASSERT_TRUE(c.undo());
  EXPECT_TRUE(sameLight(c.scene().lights[0], scene.lights[0])); // the light drag's step

  // Undo in the middle of a drag: the rest of the drag is a new step.
  c.beginGesture();
  c.apply(AmbientEdit{Color(0.5)});
  ASSERT_TRUE(c.undo());
  EXPECT_EQ(c.scene().ambient, Color(0.05));
  c.apply(AmbientEdit{Color(0.6)});
  c.apply(AmbientEdit{Color(0.7)});
  c.endGesture();
  ASSERT_TRUE(c.undo());
  EXPECT_EQ(c.scene().ambient, Color(0.05));
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
}

TEST(ViewControllerUndo, TheHistoryIsBounded) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  ViewOptions options = optionsFor(scene, dir / "main.sc");
  options.settings.threads = 1;
  ViewController c(scene, options);
  const int edits = int(ViewController::kMaxUndoSteps) + 5;
  for (int i = 1; i <= edits; ++i)
    c.apply(AmbientEdit{Color(0.001 * i)});
  std::size_t undone = 0;
  while (c.undo())
    ++undone;
  EXPECT_EQ(undone, ViewController::kMaxUndoSteps);
  EXPECT_EQ(c.scene().ambient, Color(0.001 * 5)); // the oldest steps went first
}

TEST(ViewControllerUndo, ResetsAreUndoableEdits) {
  ScratchDir dir;
  writeFile(dir / "main.sc", kMain);
  writeFile(dir / "lights.sc", "light 2 3 4 30 30 30\nlight -2 3 4 10 10 10\n");
  const Scene scene = loadScene(dir / "main.sc");
  ViewController c(scene, optionsFor(scene, dir / "main.sc"));
  Light a = scene.lights[0], b = scene.lights[1];
  a.position = Vec3(0, 4, 0);
  b.intensity = Color(1, 2, 3);
  c.apply(LightEdit{0, a});
  c.apply(LightEdit{1, b});
  const CameraSpec zoomed = zoom(scene.camera, 0.5);
  c.apply(CameraEdit{zoomed});
  c.apply(AmbientEdit{Color(0.2)});
  EXPECT_EQ(c.edits().names(),
            (std::vector<std::string>{"camera", "ambient", "light 1", "light 2"}));

  c.apply(ResetLight{1});
  EXPECT_TRUE(sameLight(c.scene().lights[1], scene.lights[1]));
  EXPECT_TRUE(sameLight(c.scene().lights[0], a)); // the other light stays edited
  c.apply(ResetCamera{});
  EXPECT_TRUE(sameCamera(c.scene().camera, scene.camera));
  ASSERT_TRUE(c.undo());
  EXPECT_TRUE(sameCamera(c.scene().camera, zoomed));
  ASSERT_TRUE(c.undo());
  EXPECT_TRUE(sameLight(c.scene().lights[1], b));

  RenderSettings s = c.settings();
  s.thresh = 0.25;
  c.apply(SettingsEdit{s});
  c.apply(RevertToFile{});
  EXPECT_TRUE(sameCamera(c.scene().camera, scene.camera));
  EXPECT_EQ(c.scene().ambient, scene.ambient);
  EXPECT_TRUE(sameLight(c.scene().lights[0], scene.lights[0]));
  EXPECT_TRUE(sameLight(c.scene().lights[1], scene.lights[1]));
  EXPECT_EQ(c.settings().thresh, 0.25); // not a scene value
  EXPECT_FALSE(c.edits().sceneEdited());
  ASSERT_TRUE(c.undo());
  EXPECT_TRUE(sameCamera(c.scene().camera, zoomed));
  EXPECT_TRUE(sameLight(c.scene().lights[0], a));
  EXPECT_TRUE(sameLight(c.scene().lights[1], b));
  EXPECT_EQ(c.scene().ambient, Color(0.2));

  // An edit of a light the scene does not have is refused, and changes nothing.
  EXPECT_THROW(c.apply(LightEdit{2, a}), std::out_of_range);
  EXPECT_TRUE(sameLight(c.scene().lights[1], b));
  ASSERT_TRUE(c.redo());
  EXPECT_FALSE(c.canRedo());
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
}

// ---------------------------------------------------------------------------
// Reloads keep the user's edits

// Reloads after the test changed a file, until the scene has `lights` lights
// and no reload runs. (The file watch may reload once more: the same files,
// the same result.)
void reloadUntil(ViewController& c, std::size_t lights) {
  c.reload();
  updateUntil(c, [&] { return !c.reloading() && c.scene().lights.size() == lights; });
}

TEST(ViewControllerReload, KeepsEditsWhoseValuesStillExistAndDropsTheOthers) {
  ScratchDir dir;
  writeFile(dir / "main.sc", kMain);
  writeFile(dir / "lights.sc", "light 2 3 4 30 30 30\nlight -2 3 4 10 10 10\n");
  const Scene scene = loadScene(dir / "main.sc");
  ViewOptions options = optionsFor(scene, dir / "main.sc");
  ViewController c(scene, options);

  Light second = scene.lights[1];
  second.position = Vec3(-1, 6, 2);
  const CameraSpec orbited = orbit(scene.camera, -20.0, 15.0);
  c.apply(LightEdit{1, second});
  c.apply(CameraEdit{orbited});
  c.apply(AmbientEdit{Color(0.1, 0.2, 0.3)});
  RenderSettings s = c.settings();
  s.maxDepth = 2;
  s.thresh = 0.3;
  s.jitter = true;
  c.apply(SettingsEdit{s});

  // The file now has one light, at a new place: light 2's edit has nothing to
  // go on; the camera, the ambient and the settings stay.
  writeFile(dir / "lights.sc", "light 1 5 1 20 20 20\n");
  reloadUntil(c, 1);
  EXPECT_EQ(c.keptEdits().kept, (std::vector<std::string>{"camera", "ambient"}));
  EXPECT_EQ(c.keptEdits().dropped, (std::vector<std::string>{"light 2"}));
  ASSERT_EQ(c.scene().lights.size(), 1u);
  EXPECT_EQ(c.scene().lights[0].position, Vec3(1, 5, 1)); // the file's, not edited
  EXPECT_TRUE(sameCamera(c.scene().camera, orbited));
  EXPECT_EQ(c.scene().ambient, Color(0.1, 0.2, 0.3));
  EXPECT_EQ(c.settings().maxDepth, 2);
  EXPECT_EQ(c.settings().thresh, 0.3);
  EXPECT_TRUE(c.settings().jitter);
  // The file's values are there for the resets.
  ASSERT_EQ(c.fileValues().lights.size(), 1u);
  EXPECT_EQ(c.fileValues().lights[0].position, Vec3(1, 5, 1));
  EXPECT_TRUE(sameCamera(c.fileValues().camera, scene.camera));
  // The picture is the new file's scene with the kept edits over it.
  Scene expected = loadScene(dir / "main.sc");
  expected.camera = orbited;
  expected.ambient = Color(0.1, 0.2, 0.3);
  options.settings = c.settings();
  EXPECT_EQ(finishedImage(c), renderOf(expected, options));

  // The history lost the step of the vanished light's edit: three undos, not
  // four, lead back to the file.
  int undone = 0;
  while (c.undo())
    ++undone;
  EXPECT_EQ(undone, 3);
  EXPECT_FALSE(c.edits().sceneEdited());
  EXPECT_TRUE(c.keptEdits().dropped.empty()); // the notice goes with the user's next step
  EXPECT_EQ(c.settings().maxDepth, 3);
  while (c.redo()) {
  }

  // An edited light that the file moves keeps the user's value, and a reset
  // goes to the file's new one.
  Light first = c.scene().lights[0];
  first.intensity = Color(50, 5, 5);
  c.apply(LightEdit{0, first});
  writeFile(dir / "lights.sc", "light 3 3 3 20 20 20\nlight 0 9 0 1 1 1\n");
  reloadUntil(c, 2);
  EXPECT_EQ(c.keptEdits().kept, (std::vector<std::string>{"camera", "ambient", "light 1"}));
  EXPECT_TRUE(c.keptEdits().dropped.empty()); // the user edited since the last drop
  ASSERT_EQ(c.scene().lights.size(), 2u);
  EXPECT_TRUE(sameLight(c.scene().lights[0], first));
  EXPECT_EQ(c.scene().lights[1].position, Vec3(0, 9, 0));
  c.apply(ResetLight{0});
  EXPECT_EQ(c.scene().lights[0].position, Vec3(3, 3, 3));

  // Revert to the file: the re-read file's values; undoable.
  c.apply(RevertToFile{});
  EXPECT_TRUE(sameCamera(c.scene().camera, scene.camera));
  EXPECT_EQ(c.scene().ambient, scene.ambient);
  EXPECT_EQ(c.settings().maxDepth, 2); // the settings stay
  ASSERT_TRUE(c.undo());
  EXPECT_TRUE(sameCamera(c.scene().camera, orbited));
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
}

TEST(ViewControllerReload, ACommandLineCameraIsAnEditOverTheFile) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir);
  ViewOptions options = optionsFor(scene, dir / "main.sc");
  CameraSpec given = scene.camera;
  given.eye = Vec3(3, 2, 4);
  given.fov = 30.0;
  options.camera = given;
  ViewController c(scene, options);
  EXPECT_TRUE(sameCamera(c.scene().camera, given));
  EXPECT_FALSE(c.canUndo()); // where the session starts
  EXPECT_EQ(c.edits().names(), std::vector<std::string>{"camera"});
  writeFile(dir / "lights.sc", "light 2 3 5 30 30 30\nlight 0 5 0 1 1 1\n");
  reloadUntil(c, 2);
  EXPECT_EQ(c.keptEdits().kept, std::vector<std::string>{"camera"});
  EXPECT_TRUE(sameCamera(c.scene().camera, given));
  c.apply(ResetCamera{});
  EXPECT_TRUE(sameCamera(c.scene().camera, scene.camera));
  ASSERT_TRUE(c.undo());
  EXPECT_TRUE(sameCamera(c.scene().camera, given));
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
}

// ---------------------------------------------------------------------------
// Fog, edited like ambient

bool sameFog(const Fog& a, const Fog& b) { return a.color == b.color && a.density == b.density; }

// kMain with fog in it, and the same scene without (clear.sc), beside one light.
const char* kFogLine = "fog 0.3 0.3 0.35  0.1\n";
Scene writeFoggedScene(const ScratchDir& dir) {
  writeFile(dir / "main.sc", std::string(kMain) + kFogLine);
  writeFile(dir / "clear.sc", kMain);
  writeFile(dir / "lights.sc", "light 2 3 4 30 30 30\n");
  return loadScene(dir / "main.sc");
}

// Each fog edit is one undo step that restarts the render; "fog" is listed
// among the edits; Back to the file's values puts the file's fog back,
// undoably. Density 0 shows the picture of the file without its `fog` line.
TEST(ViewControllerFog, EditsUndoRedoAndRevertLikeAmbient) {
  ScratchDir dir;
  const Scene scene = writeFoggedScene(dir);
  const ViewOptions options = optionsFor(scene, dir / "main.sc");
  ViewController c(scene, options);
  const Fog file{Color(0.3, 0.3, 0.35), 0.1}; // kFogLine
  EXPECT_TRUE(sameFog(c.fileValues().fog, file));
  c.update();
  std::uint64_t restarts = c.progress().restarts;

  const Fog thick{Color(0.8, 0.7, 0.6), 0.4}, none{Color(0.8, 0.7, 0.6), 0.0};
  c.apply(FogEdit{thick});
  expectRestarted(c, restarts);
  c.apply(FogEdit{none});
  expectRestarted(c, restarts);
  EXPECT_EQ(c.edits().names(), std::vector<std::string>{"fog"});
  EXPECT_EQ(finishedImage(c), renderOf(loadScene(dir / "clear.sc"), options));

  ASSERT_TRUE(c.undo());
  expectRestarted(c, restarts);
  EXPECT_TRUE(sameFog(c.scene().fog, thick));
  ASSERT_TRUE(c.undo());
  EXPECT_TRUE(sameFog(c.scene().fog, file));
  EXPECT_FALSE(c.canUndo());
  ASSERT_TRUE(c.redo());
  ASSERT_TRUE(c.redo());
  EXPECT_TRUE(sameFog(c.scene().fog, none));
  EXPECT_FALSE(c.canRedo());

  c.apply(RevertToFile{});
  EXPECT_TRUE(sameFog(c.scene().fog, file));
  EXPECT_FALSE(c.edits().sceneEdited());
  ASSERT_TRUE(c.undo());
  EXPECT_TRUE(sameFog(c.scene().fog, none));
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
}

// A reload puts the user's fog over the re-read file (which changed its
// own fog), and says so; a revert then goes to the new file's fog.
TEST(ViewControllerFog, AReloadKeepsTheFogEdit) {
  ScratchDir dir;
  const Scene scene = writeFoggedScene(dir);
  ViewOptions options = optionsFor(scene, dir / "main.sc");
  ViewController c(scene, options);
  const Fog edited{Color(0.9, 0.85, 0.8), 0.25};
  c.apply(FogEdit{edited});

  writeFile(dir / "main.sc", std::string(kMain) + "fog 0.1 0.1 0.1  0.02\n");
  writeFile(dir / "lights.sc", "light 2 3 4 30 30 30\nlight -2 3 4 10 10 10\n");
  reloadUntil(c, 2);
  EXPECT_EQ(c.keptEdits().kept, std::vector<std::string>{"fog"});
  EXPECT_TRUE(sameFog(c.scene().fog, edited));
  EXPECT_TRUE(sameFog(c.fileValues().fog, Fog{Color(0.1), 0.02}));
  // The picture is the new file's, with the edited fog written in it.
  writeFile(dir / "expected.sc", std::string(kMain) + "fog 0.9 0.85 0.8  0.25\n");
  EXPECT_EQ(finishedImage(c), renderOf(loadScene(dir / "expected.sc"), options));

  c.apply(RevertToFile{});
  EXPECT_TRUE(sameFog(c.scene().fog, Fog{Color(0.1), 0.02}));
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
}

// ---------------------------------------------------------------------------
// Textures: a group of materials (one `texture` line in every object space)
// edited as one value

// A scene with a marble texture over two spheres in spaces of their own, a
// checker floor, and `lights` lights; with `noiseFirst`, a noise-textured
// sphere before them (which numbers them 2 and 3). The marble's and the
// checker's values are written in; `marbleKdr` is one value no edit changes.
struct TexturedFile {
  TextureValues marble{0.5, Color(0.2, 0.1, 0.3), Color(1, 0.5, 0.2)};
  TextureValues checker{1.0, Color(0.9, 0.9, 0.9), Color(0.3, 0.6, 0.9)};
  double marbleKdr = 0.8;
  bool noiseFirst = false;
  int lights = 1;

  std::string text() const {
    std::ostringstream t;
    t.precision(17);
    const auto rgb = [&](const Color& c) { t << " " << c.r << " " << c.g << " " << c.b << " "; };
    t << "eye 0 1 5\nlookat 0 0 0\nresolution 40 30\n";
    for (int i = 0; i < lights; ++i)
      t << "light " << 2 - 4 * i << " 3 4  30 30 30\n";
    if (noiseFirst)
      t << "surface 0.1 0.1 0.5  1 0 0  1 1\ntexture noise 0.3  1 1 1  1 0 0  1\n"
           "sphere 0 1.2 -1 0.4\n";
    t << "surface";
    rgb(marble.base);
    t << " 0.8 0.2 0  20 1\ntexture marble " << marble.scale;
    rgb(marble.color);
    t << " " << marbleKdr << " 0.2 0  20\n"
      << "push\n  translate -1 0 0\n  sphere 0 0 0 0.8\npop\n"
         "push\n  translate 1 0 0\n  sphere 0 0 0 0.8\npop\n"
      << "surface";
    rgb(checker.base);
    t << " 1 0 0  1 1\ntexture checker " << checker.scale;
    rgb(checker.color);
    t << " 1 0 0  1\npolygon 4 -3 -1 -3  -3 -1 3  3 -1 3  3 -1 -3\n";
    return t.str();
  }
};

// The values the scene shows for texture `index` (every member alike).
TextureValues shownTexture(const ViewController& c, std::size_t index) {
  const TextureGroup& group = c.fileValues().textures.at(index).group;
  const TextureValues values = textureValuesOf(c.scene().materials[group.materials.front()]);
  for (const std::uint32_t m : group.materials)
    EXPECT_EQ(textureValuesOf(c.scene().materials[m]), values);
  return values;
}

// Each texture edit is one undo step that restarts the render and shows the
// file with the edited values written in; undo, reset and revert put the
// file's values back, and with them the file's picture, bit for bit.
TEST(ViewControllerTexture, EditsUndoRedoResetAndRevert) {
  ScratchDir dir;
  const TexturedFile file;
  writeFile(dir / "main.sc", file.text());
  const Scene scene = loadScene(dir / "main.sc");
  const ViewOptions options = optionsFor(scene, dir / "main.sc");
  ViewController c(scene, options);
  ASSERT_EQ(c.fileValues().textures.size(), 2u);
  const FileTexture& marble = c.fileValues().textures[0];
  EXPECT_EQ(marble.group.kind, TextureKind::Marble);
  EXPECT_EQ(marble.group.materials.size(), 2u); // two object spaces, one texture
  EXPECT_EQ(marble.place, "sphere #0 (main.sc:9)");
  EXPECT_EQ(marble.values(), file.marble);
  EXPECT_EQ(c.fileValues().textures[1].place, "polygon #0 (main.sc:17)");
  c.update();
  std::uint64_t restarts = c.progress().restarts;

  const TextureValues veins{0.25, Color(0.05, 0.3, 0.1), Color(0.9, 0.9, 0.8)};
  const TextureValues tiles{2.5, Color(0.1, 0.1, 0.1), Color(0.8, 0.2, 0.2)};
  c.apply(TextureEdit{0, veins});
  expectRestarted(c, restarts);
  c.apply(TextureEdit{1, tiles});
  expectRestarted(c, restarts);
  EXPECT_EQ(c.edits().names(), (std::vector<std::string>{"texture 1", "texture 2"}));
  EXPECT_EQ(shownTexture(c, 0), veins);
  TexturedFile written = file;
  written.marble = veins;
  written.checker = tiles;
  writeFile(dir / "written.sc", written.text());
  const std::vector<Rgb> original = renderOf(scene, options);
  const std::vector<Rgb> edited = finishedImage(c);
  EXPECT_EQ(edited, renderOf(loadScene(dir / "written.sc"), options));
  EXPECT_NE(edited, original);
  EXPECT_THROW(c.apply(TextureEdit{2, veins}), std::out_of_range);

  ASSERT_TRUE(c.undo());
  expectRestarted(c, restarts);
  EXPECT_EQ(shownTexture(c, 1), file.checker);
  EXPECT_EQ(shownTexture(c, 0), veins);
  ASSERT_TRUE(c.undo());
  EXPECT_EQ(shownTexture(c, 0), file.marble);
  EXPECT_FALSE(c.canUndo());
  EXPECT_EQ(finishedImage(c), original);
  ASSERT_TRUE(c.redo());
  ASSERT_TRUE(c.redo());
  EXPECT_EQ(shownTexture(c, 1), tiles);

  c.apply(ResetTexture{0});
  EXPECT_EQ(shownTexture(c, 0), file.marble);
  EXPECT_EQ(shownTexture(c, 1), tiles);
  c.apply(RevertToFile{});
  EXPECT_EQ(shownTexture(c, 1), file.checker);
  EXPECT_FALSE(c.edits().sceneEdited());
  EXPECT_EQ(finishedImage(c), original);
  ASSERT_TRUE(c.undo());
  EXPECT_EQ(shownTexture(c, 1), tiles);
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
}

// A reload keeps a texture's edit on that texture wherever the file now puts
// it (another texture before it renumbers it), over the file's new colours;
// a texture the file changed in more than an edit holds is another one: its
// edit is dropped.
TEST(ViewControllerTexture, AReloadKeepsAnEditOnItsTextureWhereverItIsAndDropsAGoneOne) {
  ScratchDir dir;
  TexturedFile file;
  writeFile(dir / "main.sc", file.text());
  const Scene scene = loadScene(dir / "main.sc");
  const ViewOptions options = optionsFor(scene, dir / "main.sc");
  ViewController c(scene, options);
  const TextureValues veins{0.25, Color(0.05, 0.3, 0.1), Color(0.9, 0.9, 0.8)};
  const TextureValues tiles{2.5, Color(0.1, 0.1, 0.1), Color(0.8, 0.2, 0.2)};
  c.apply(TextureEdit{0, veins});
  c.apply(TextureEdit{1, tiles});

  file.noiseFirst = true;
  file.checker.color = Color(0.5, 0.5, 0.0); // the user's edit stays over it
  file.lights = 2;
  writeFile(dir / "main.sc", file.text());
  reloadUntil(c, 2);
  ASSERT_EQ(c.fileValues().textures.size(), 3u);
  EXPECT_EQ(c.keptEdits().kept, (std::vector<std::string>{"texture 2", "texture 3"}));
  EXPECT_TRUE(c.keptEdits().dropped.empty());
  EXPECT_EQ(shownTexture(c, 1), veins);
  EXPECT_EQ(shownTexture(c, 2), tiles);
  TexturedFile expected = file;
  expected.marble = veins;
  expected.checker = tiles;
  writeFile(dir / "expected.sc", expected.text());
  EXPECT_EQ(finishedImage(c), renderOf(loadScene(dir / "expected.sc"), options));

  file.marbleKdr = 0.5;
  file.lights = 1;
  writeFile(dir / "main.sc", file.text());
  reloadUntil(c, 1);
  EXPECT_EQ(c.keptEdits().kept, std::vector<std::string>{"texture 3"});
  EXPECT_EQ(c.keptEdits().dropped, std::vector<std::string>{"texture 2"});
  EXPECT_EQ(shownTexture(c, 1), file.marble);
  EXPECT_EQ(shownTexture(c, 2), tiles);
  // The dropped edit is gone from the history: one undo leads to the file.
  ASSERT_TRUE(c.undo());
  EXPECT_FALSE(c.canUndo());
  EXPECT_EQ(shownTexture(c, 2), file.checker);
  updateUntil(c, [&] { return c.progress().phase == SessionPhase::Done; });
}

// Save scene as writes the edited texture (the `surface` colour with it) in
// every object space: the saved file renders the window's picture.
TEST(ViewControllerTexture, SaveSceneAsWritesTheEditedTexture) {
  ScratchDir dir;
  writeFile(dir / "main.sc", TexturedFile{}.text());
  const Scene scene = loadScene(dir / "main.sc");
  const ViewOptions options = optionsFor(scene, dir / "main.sc");
  ViewController c(scene, options);
  const TextureValues veins{0.25, Color(0.05, 0.3, 0.1), Color(0.9, 0.9, 0.8)};
  c.apply(TextureEdit{0, veins});
  c.saveSceneAs((dir / "view.sc").string());
  updateUntil(c, [&] { return !c.sceneSaveBusy(); });
  ASSERT_EQ(c.sceneSaveState(), ViewController::SceneSaveState::Saved) << c.sceneSaveMessage();
  EXPECT_NE(slurp(dir / "view.sc").find("with edits of: texture 1."), std::string::npos);
  const Scene back = loadScene(dir / "view.sc");
  // (The writer puts the top level's floor first: the marble is texture 2 there.)
  const std::vector<TextureGroup> groups = textureGroups(back);
  ASSERT_EQ(groups.size(), 2u);
  ASSERT_EQ(groups[1].kind, TextureKind::Marble);
  ASSERT_EQ(groups[1].materials.size(), 2u);
  for (const std::uint32_t m : groups[1].materials)
    EXPECT_EQ(textureValuesOf(back.materials[m]), veins);
  EXPECT_EQ(renderOf(back, options), finishedImage(c));
}

// A checker floor (texture 1) and an image on two spheres (texture 2: one
// `image` line). The image's file, its `uv` scale, the spheres' tint and the
// number of lights are written in.
struct ImageFile {
  std::string image = "grid.png";
  std::string uv = "2 4";
  Color tint{0.8, 0.7, 0.6};
  int lights = 1;

  std::string text() const {
    std::ostringstream t;
    t.precision(17);
    t << "eye 0 1 5\nlookat 0 0 0\nresolution 40 30\n";
    for (int i = 0; i < lights; ++i)
      t << "light " << 2 - 4 * i << " 3 4  30 30 30\n";
    t << "surface 0.3 0.6 0.9  1 0 0  1 1\ntexture checker 1  0.9 0.9 0.9  1 0 0  1\n"
         "polygon 4 -3 -1 -3  -3 -1 3  3 -1 3  3 -1 -3\n"
      << "surface " << tint.r << " " << tint.g << " " << tint.b << "  0.8 0.2 0  20 1\n"
      << "image " << image << "\nuv " << uv << "  0.1 0.2\n"
      << "push\n  translate -1 0 0\n  sphere 0 0 0 0.8\npop\n"
         "push\n  translate 1 0 0\n  sphere 0 0 0 0.8\npop\n";
    return t.str();
  }
};

// Two small PNGs in `dir`: grid.png (4 x 4) and other.png (2 x 2).
void writeImages(const ScratchDir& dir) {
  std::vector<std::uint8_t> rgb;
  for (int i = 0; i < 16; ++i)
    rgb.insert(rgb.end(), {std::uint8_t(40 + 13 * i), std::uint8_t(250 - 15 * i),
                           std::uint8_t(i % 3 == 0 ? 230 : 20)});
  writeImage8(dir / "grid.png", 4, 4, rgb);
  writeImage8(dir / "other.png", 2, 2, {255, 255, 255, 0, 0, 0, 0, 0, 0, 255, 255, 255});
}

// An image is a texture like the others: its size (1 / SU, SV alike) and
// tint (the surface colour) are one edit, one undo step, restarting the
// render and showing the file with the edited `uv` and `surface` written in;
// undo, reset and revert give the file's picture bit for bit; Save scene as
// writes the edit.
TEST(ViewControllerTexture, AnImageIsEditedUndoneResetAndSaved) {
  ScratchDir dir;
  writeImages(dir);
  const ImageFile file;
  writeFile(dir / "main.sc", file.text());
  const Scene scene = loadScene(dir / "main.sc");
  const ViewOptions options = optionsFor(scene, dir / "main.sc");
  ViewController c(scene, options);
  ASSERT_EQ(c.fileValues().textures.size(), 2u);
  EXPECT_EQ(c.fileValues().textures[0].description(), "checker");
  const FileTexture& image = c.fileValues().textures[1];
  EXPECT_EQ(image.description(), "image grid.png");
  EXPECT_EQ(image.imagePath, (dir / "grid.png").string());
  EXPECT_TRUE(image.group.imageOnly());
  EXPECT_EQ(image.group.materials.size(), 1u); // one material: an image needs no object space
  EXPECT_EQ(image.place, "sphere #0 (main.sc:13)");
  EXPECT_EQ(image.values().scale, 0.5);
  EXPECT_EQ(image.values().base, file.tint);
  c.update();
  std::uint64_t restarts = c.progress().restarts;

  TextureValues edited = image.values();
  edited.scale = 0.25;
  edited.base = Color(0.3, 0.9, 0.5);
  c.apply(TextureEdit{1, edited});
  expectRestarted(c, restarts);
  EXPECT_EQ(c.edits().names(), std::vector<std::string>{"texture 2"});
  const Material& shown = c.scene().materials[image.group.materials.front()];
  EXPECT_EQ(shown.image.scale, Vec2(4, 8));
  EXPECT_EQ(shown.image.offset, Vec2(0.1, 0.2));
  ImageFile written = file;
  written.uv = "4 8";
  written.tint = edited.base;
  writeFile(dir / "written.sc", written.text());
  const std::vector<Rgb> original = renderOf(scene, options);
  const std::vector<Rgb> editedImage = finishedImage(c);
  EXPECT_EQ(editedImage, renderOf(loadScene(dir / "written.sc"), options));
  EXPECT_NE(editedImage, original);

  ASSERT_TRUE(c.undo());
  expectRestarted(c, restarts);
  EXPECT_TRUE(c.scene().materials == scene.materials);
  EXPECT_EQ(finishedImage(c), original);
  ASSERT_TRUE(c.redo());
  expectRestarted(c, restarts);
  EXPECT_EQ(finishedImage(c), editedImage);
  c.apply(ResetTexture{1});
  EXPECT_TRUE(c.scene().materials == scene.materials);
  ASSERT_TRUE(c.undo());
  c.apply(RevertToFile{});
  EXPECT_TRUE(c.scene().materials == scene.materials);
  c.update(); // the progress of the render the revert started
  EXPECT_EQ(finishedImage(c), original);
  ASSERT_TRUE(c.undo());
  c.update();

  c.saveSceneAs((dir / "view.sc").string());
  updateUntil(c, [&] { return !c.sceneSaveBusy(); });
  ASSERT_EQ(c.sceneSaveState(), ViewController::SceneSaveState::Saved) << c.sceneSaveMessage();
  EXPECT_NE(slurp(dir / "view.sc").find("uv 4 8"), std::string::npos) << slurp(dir / "view.sc");
  const Scene back = loadScene(dir / "view.sc");
  EXPECT_EQ(renderOf(back, options), finishedImage(c));
}

// A reload keeps an image's edit over the file's new tint; a file that puts
// another image in its place drops it.
TEST(ViewControllerTexture, AReloadKeepsAnImagesEditAndDropsItForAnotherImage) {
  ScratchDir dir;
  writeImages(dir);
  ImageFile file;
  writeFile(dir / "main.sc", file.text());
  const Scene scene = loadScene(dir / "main.sc");
  const ViewOptions options = optionsFor(scene, dir / "main.sc");
  ViewController c(scene, options);
  TextureValues edited = c.fileValues().textures[1].values();
  edited.scale = 0.25;
  edited.base = Color(0.3, 0.9, 0.5);
  c.apply(TextureEdit{1, edited});

  file.tint = Color(0.2, 0.2, 0.9); // the user's tint stays over it
  file.uv = "1 2";                  // and the user's size
  file.lights = 2;
  writeFile(dir / "main.sc", file.text());
  reloadUntil(c, 2);
  EXPECT_EQ(c.keptEdits().kept, std::vector<std::string>{"texture 2"});
  EXPECT_TRUE(c.keptEdits().dropped.empty());
  ImageFile expected = file;
  expected.uv = "4 8";
  expected.tint = edited.base;
  writeFile(dir / "expected.sc", expected.text());
  EXPECT_EQ(finishedImage(c), renderOf(loadScene(dir / "expected.sc"), options));

  file.image = "other.png";
  file.lights = 1;
  writeFile(dir / "main.sc", file.text());
  reloadUntil(c, 1);
  EXPECT_TRUE(c.keptEdits().kept.empty());
  EXPECT_EQ(c.keptEdits().dropped, std::vector<std::string>{"texture 2"});
  EXPECT_EQ(c.fileValues().textures[1].description(), "image other.png");
  EXPECT_EQ(finishedImage(c), renderOf(loadScene(dir / "main.sc"), options));
}

// ---------------------------------------------------------------------------
// Save scene as

TEST(ViewControllerSaveScene, WritesTheEditedSceneThatRendersTheSamePicture) {
  ScratchDir dir;
  const Scene scene = writeMainScene(dir); // light 1 comes from an included file
  ViewOptions options = optionsFor(scene, dir / "main.sc");
  ViewController c(scene, options);
  const CameraSpec camera = pan(orbit(scene.camera, 25.0, -10.0), 3.0, -2.0, 30);
  Light light = scene.lights[0];
  light.position = Vec3(-1.0 / 3.0, 2.5, 1e-3);
  light.intensity = Color(12.5, 7.0, 3.0);
  c.apply(CameraEdit{camera});
  c.apply(LightEdit{0, light});
  c.apply(AmbientEdit{Color(0.05, 0.04, 0.03)});
  c.apply(FogEdit{Fog{Color(0.5, 0.55, 0.6), 0.125}});

  const fs::path saved = dir / "sub" / "view.sc";
  fs::create_directory(dir / "sub");
  c.saveSceneAs(saved.string());
  EXPECT_EQ(c.sceneSaveState(), ViewController::SceneSaveState::Writing);
  updateUntil(c, [&] { return !c.sceneSaveBusy(); });
  ASSERT_EQ(c.sceneSaveState(), ViewController::SceneSaveState::Saved) << c.sceneSaveMessage();
  EXPECT_EQ(c.sceneSaveMessage(), "saved scene " + saved.string());

  const Scene back = loadScene(saved); // no include left to find from sub/
  EXPECT_TRUE(sameCamera(back.camera, camera));
  ASSERT_EQ(back.lights.size(), 1u);
  EXPECT_TRUE(sameLight(back.lights[0], light));
  EXPECT_EQ(back.ambient, Color(0.05, 0.04, 0.03));
  EXPECT_TRUE(sameFog(back.fog, Fog{Color(0.5, 0.55, 0.6), 0.125}));
  EXPECT_EQ(back.files.size(), 1u);
  const std::string text = slurp(saved);
  EXPECT_NE(text.find("# Saved by prism view from " + (dir / "main.sc").string() +
                      ", with edits of: camera, ambient, fog, light 1."),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("\ninclude"), std::string::npos) << text; // flattened
  // The same picture as the window's.
  EXPECT_EQ(renderOf(back, options), finishedImage(c));

  // Failures are a state and a message, never an exception.
  c.saveSceneAs((dir / "view.png").string());
  EXPECT_EQ(c.sceneSaveState(), ViewController::SceneSaveState::Failed);
  EXPECT_NE(c.sceneSaveMessage().find("scene files end in .sc"), std::string::npos)
      << c.sceneSaveMessage();
  c.saveSceneAs((dir / "no such dir" / "x.sc").string());
  EXPECT_EQ(c.sceneSaveState(), ViewController::SceneSaveState::Failed);
  EXPECT_NE(c.sceneSaveMessage().find("no such directory"), std::string::npos)
      << c.sceneSaveMessage();
  EXPECT_FALSE(fs::exists(dir / "view.png"));
}

} // namespace
} // namespace prism::test
