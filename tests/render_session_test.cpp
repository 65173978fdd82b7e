// The previewer's render session, without a window: the progressive schedule
// takes each sample once, the finished film is exactly render()'s, edits restart
// and change only what they should, cancellation is prompt.
#include "core/io/image_io.h"
#include "core/io/scene_parser.h"
#include "core/render/render_session.h"
#include "tests/render_fixtures.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace prism {
namespace {

using test::shipped;
using test::smallSettings;

RenderResult renderDirect(const Scene& scene, const RenderSettings& s) {
  const auto accel = makeAccel(scene, AccelKind::Groups);
  return render(scene, *accel, s);
}

void expectSameFilm(const RenderResult& a, const RenderResult& b) {
  EXPECT_EQ(a.avgmax, b.avgmax);
  EXPECT_EQ(a.counts, b.counts);
  EXPECT_EQ(a.supersampledPixels, b.supersampledPixels);
  EXPECT_TRUE(a.film.centre == b.film.centre);
  EXPECT_TRUE(a.film.radiance == b.film.radiance);
  EXPECT_TRUE(a.film.supersampled == b.film.supersampled);
}

TEST(CoarseLevels, EveryPixelIsNewAtExactlyOneLevel) {
  for (int y = 0; y < 37; ++y) {
    for (int x = 0; x < 53; ++x) {
      int levels = 0;
      for (int level : {8, 4, 2, 1})
        levels += isNewAtLevel(x, y, level);
      EXPECT_EQ(levels, 1) << x << "," << y;
    }
  }
  EXPECT_TRUE(isNewAtLevel(0, 0, 8));
  EXPECT_TRUE(isNewAtLevel(4, 0, 4));
  EXPECT_TRUE(isNewAtLevel(8, 4, 4));
  EXPECT_FALSE(isNewAtLevel(8, 8, 4));
  EXPECT_TRUE(isNewAtLevel(3, 5, 1));
}

TEST(RenderSession, FinishedFilmEqualsRenderBitForBit) {
  for (const char* name : {"table.sc", "glass.sc"}) {
    const Scene scene = shipped(name);
    RenderSession session(scene, smallSettings());
    const RenderResult progressive = session.waitForResult();
    expectSameFilm(progressive, renderDirect(scene, smallSettings()));
    // No sample traced twice: one centre per pixel, sixteen per supersampled pixel.
    EXPECT_EQ(progressive.counts.eyePrimary, 80u * 60u);
    EXPECT_EQ(progressive.counts.eyeAntialias, 16u * std::uint64_t(progressive.supersampledPixels));
    EXPECT_TRUE(session.finished());
    const SessionProgress p = session.progress();
    EXPECT_EQ(p.phase, SessionPhase::Done);
    EXPECT_DOUBLE_EQ(p.fraction, 1.0);
    EXPECT_EQ(p.avgmax, progressive.avgmax);
    EXPECT_EQ(session.progress().elapsedSeconds, p.elapsedSeconds); // the clock stopped
    // When done, the display shows the final picture.
    SessionImage image;
    ASSERT_TRUE(session.copyImage(image));
    EXPECT_TRUE(image.radiance == progressive.film.radiance);
    EXPECT_FALSE(session.copyImage(image)); // nothing new since
  }
}

// Two rooms side by side, separated by an opaque wall; light 1 lights the left
// room only, light 2 the right room only.
const char* kTwoRooms = R"(
eye 0 3 12  lookat 0 1 0  fov 50
ambient 0.02 0.02 0.02
light -3 3 2  30 30 30
light 3 3 2   20 25 30
surface 0.8 0.8 0.8  0.9 0.1 0  20 1
polygon 4  -8 0 -4  -8 0 6  8 0 6  8 0 -4
polygon 4  -8 0 -4  8 0 -4  8 8 -4  -8 8 -4
# the dividing wall, both faces
polygon 4  0 0 -4  0 8 -4  0 8 6  0 0 6
surface 0.9 0.3 0.2  0.8 0.2 0  30 1
sphere -3 1 0 1
sphere 3 1 0 1
)";

TEST(RenderSession, MovingALightChangesExactlyWhereThatLightReaches) {
  const Scene scene = parseScene(kTwoRooms, "rooms.sc");
  const RenderSettings s = smallSettings();
  RenderSession session(scene, s);
  const RenderResult before = session.waitForResult();

  Light moved = scene.lights[0];
  moved.position = glm::dvec3(-5, 2, 3);
  session.apply({.lights = {{0, moved}}});
  EXPECT_EQ(session.progress().restarts, 1u);
  const RenderResult after = session.waitForResult();

  // The restarted session equals a fresh render of the edited scene...
  Scene edited = scene;
  edited.lights[0] = moved;
  expectSameFilm(after, renderDirect(edited, s));

  // ...and its pass 1 differs from the old one only where light 1 reaches, in
  // either position: where switching light 1 off changes the picture.
  Scene off = scene, offMoved = edited;
  off.lights[0].intensity = Color(0.0);
  offMoved.lights[0].intensity = Color(0.0);
  const RenderResult dark = renderDirect(off, s);
  EXPECT_TRUE(dark.film.centre == renderDirect(offMoved, s).film.centre);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < before.film.centre.size(); ++i) {
    if (before.film.centre[i] == after.film.centre[i]) continue;
    ++changed;
    const bool reachedBefore = before.film.centre[i] != dark.film.centre[i];
    const bool reachedAfter = after.film.centre[i] != dark.film.centre[i];
    EXPECT_TRUE(reachedBefore || reachedAfter) << "pixel " << i;
  }
  EXPECT_GT(changed, 100u);
  // The right room, lit by light 2 only, did not change: its right third.
  for (int y = 0; y < s.height; ++y)
    for (int x = s.width * 3 / 4; x < s.width; ++x)
      EXPECT_EQ(before.film.centre[before.film.index(x, y)],
                after.film.centre[after.film.index(x, y)]);
}

TEST(RenderSession, ThresholdChangeKeepsPassOneAndRedoesOnlyPassTwo) {
  const Scene scene = shipped("glass.sc");
  RenderSettings s = smallSettings();
  RenderSession session(scene, s);
  const RenderResult first = session.waitForResult();
  s.thresh = 0.02;
  session.apply({.settings = s});
  const RenderResult second = session.waitForResult();
  expectSameFilm(second, renderDirect(scene, s));
  EXPECT_GT(second.supersampledPixels, first.supersampledPixels);
  EXPECT_EQ(second.counts.eyePrimary, 80u * 60u); // pass 1 was kept, not retraced
  s.maxDepth = 2;                                 // depth changes every sample
  session.apply({.settings = s});
  expectSameFilm(session.waitForResult(), renderDirect(scene, s));
}

TEST(RenderSession, NoAntialiasingKeepsPassOneAndBailoutRetracesIt) {
  const Scene scene = shipped("glass.sc");
  RenderSettings s = smallSettings();
  RenderSession session(scene, s);
  EXPECT_GT(session.waitForResult().supersampledPixels, 0);
  s.noAa = true;
  session.apply({.settings = s});
  const RenderResult plain = session.waitForResult();
  expectSameFilm(plain, renderDirect(scene, s));
  EXPECT_EQ(plain.supersampledPixels, 0);
  EXPECT_EQ(plain.counts.eyeAntialias, 0u);
  EXPECT_EQ(plain.film.radiance, plain.film.centre);
  // The bailout changes pass 1's samples (and traces its pilot first).
  s.bailout = 0.5;
  session.apply({.settings = s});
  const RenderResult bailed = session.waitForResult();
  expectSameFilm(bailed, renderDirect(scene, s));
  EXPECT_GT(bailed.counts.bailoutPilot, 0u);
}

TEST(RenderSession, CameraAndAmbientEditsRestartWithTheEditedScene) {
  const Scene scene = shipped("table.sc");
  const RenderSettings s = smallSettings();
  RenderSession session(scene, s);
  Scene edited = scene;
  edited.ambient = Color(0.3, 0.2, 0.1);
  edited.camera.eye += glm::dvec3(1.0, 0.5, 0.0);
  session.apply({.ambient = edited.ambient});
  session.apply({.camera = edited.camera});
  expectSameFilm(session.waitForResult(), renderDirect(edited, s));
  EXPECT_EQ(session.progress().restarts, 2u);
}

// A scene without fog gains it by an edit (its tracers take the fog's path
// from then on) and loses it again at density 0. The expected pictures are
// fresh renders of the files: one with the `fog` line, one without.
TEST(RenderSession, FogEditsRenderAsTheFileSaysAndDensityZeroIsTheFogFreePicture) {
  const Scene clear = parseScene(kTwoRooms, "rooms.sc");
  const Scene fogged =
      parseScene(std::string(kTwoRooms) + "fog 0.5 0.6 0.7  0.08\n", "rooms-fog.sc");
  const RenderSettings s = smallSettings();
  const RenderResult clearFilm = renderDirect(clear, s);
  const RenderResult foggedFilm = renderDirect(fogged, s);
  ASSERT_FALSE(foggedFilm.film.radiance == clearFilm.film.radiance); // the fog shows

  RenderSession session(clear, s);
  session.waitForResult(); // pass 1 complete: a fog edit must not keep it, as thresh may
  session.apply({.fog = Fog{Color(0.5, 0.6, 0.7), 0.08}});
  EXPECT_EQ(session.progress().restarts, 1u);
  expectSameFilm(session.waitForResult(), foggedFilm);

  // Density 0 with the colour kept: no fog, the same bits as no `fog` line.
  session.apply({.fog = Fog{Color(0.5, 0.6, 0.7), 0.0}});
  EXPECT_EQ(session.progress().restarts, 2u);
  expectSameFilm(session.waitForResult(), clearFilm);
}

// Two textures: one `texture` line over two spheres in spaces of their own
// (two materials, one group) and another on the floor. The scale and the
// colours of the first are written in, so that an edit's picture can be
// compared with the file that says the same.
std::string texturedRoom(double scale, const Color& colour, const Color& base) {
  std::ostringstream text;
  text.precision(17);
  text << "eye 0 2 8  lookat 0 0.5 0  fov 45\n"
          "ambient 0.1 0.1 0.1\n"
          "light 3 5 4  30 30 30\n"
       << "surface " << base.r << " " << base.g << " " << base.b << "  0.9 0.1 0  20 1\n"
       << "texture checker " << scale << "  " << colour.r << " " << colour.g << " " << colour.b
       << "  0.9 0.1 0  20\n"
       << "push\n  translate -1.2 0.6 0\n  sphere 0 0 0 0.6\npop\n"
          "push\n  translate 1.2 0.6 0\n  rotate 0 1 0 30\n  sphere 0 0 0 0.6\npop\n"
          "surface 0.3 0.5 0.7  0.9 0 0  1 1\n"
          "texture stripes 0.4  0.9 0.9 0.8  0.9 0 0  1\n"
          "polygon 4  -5 0 -5  -5 0 5  5 0 5  5 0 -5\n";
  return text.str();
}

// A texture edit restarts from pass 1 and changes every material of its
// group: the picture is the file's with the edited values written in. The
// file's values put back give the file's picture, bit for bit.
TEST(RenderSession, TextureEditsRenderAsTheFileSaysAndTheFilesValuesGiveItsPicture) {
  const TextureValues file{0.5, Color(0.1, 0.2, 0.3), Color(0.8, 0.7, 0.6)};
  const TextureValues edited{0.3, Color(0.9, 0.2, 0.1), Color(0.2, 0.6, 0.3)};
  const Scene scene = parseScene(texturedRoom(file.scale, file.color, file.base), "textured.sc");
  const Scene written =
      parseScene(texturedRoom(edited.scale, edited.color, edited.base), "edited.sc");
  const RenderSettings s = smallSettings();
  const RenderResult fileFilm = renderDirect(scene, s);
  const RenderResult writtenFilm = renderDirect(written, s);
  ASSERT_FALSE(writtenFilm.film.radiance == fileFilm.film.radiance); // the edit shows

  RenderSession session(scene, s);
  ASSERT_EQ(session.textureGroups().size(), 2u);
  EXPECT_EQ(session.textureGroups()[0].materials.size(), 2u); // the two spheres' spaces
  EXPECT_EQ(session.textureGroups()[1].kind, TextureKind::Stripes);
  session.waitForResult(); // pass 1 complete: a texture edit must not keep it
  session.apply({.textures = {{0, edited}}});
  EXPECT_EQ(session.progress().restarts, 1u);
  expectSameFilm(session.waitForResult(), writtenFilm);
  for (const std::uint32_t m : session.textureGroups()[0].materials)
    EXPECT_EQ(textureValuesOf(session.scene().materials[m]), edited);

  // A texture the scene does not have: refused before anything changes.
  EXPECT_THROW(session.apply({.textures = {{0, file}, {2, file}}}), std::out_of_range);
  EXPECT_EQ(session.progress().restarts, 1u);
  EXPECT_TRUE(session.finished());

  session.apply({.textures = {{0, file}}});
  EXPECT_EQ(session.progress().restarts, 2u);
  expectSameFilm(session.waitForResult(), fileFilm);
}

// An image (a 4 x 4 PNG) on a sphere and the floor, one `image` line, and
// the same image under a marble texture on another sphere. The `uv` scales,
// the tint and the marble's scale are written in, so that an edit's picture
// can be compared with the file that says the same.
std::string imageRoom(const std::string& floorUv, const Color& tint, double marbleScale,
                      const std::string& marbleUv) {
  std::ostringstream text;
  text.precision(17);
  text << "eye 0 2 8  lookat 0 0.5 0  fov 45\n"
          "ambient 0.1 0.1 0.1\n"
          "light 3 5 4  30 30 30\n"
       << "surface " << tint.r << " " << tint.g << " " << tint.b << "  0.9 0.1 0  20 1\n"
       << "image grid.png\nuv " << floorUv << "  0.1 0.2\n"
       << "sphere -1.2 0.6 0 0.6\n"
          "polygon 4  -5 0 -5  -5 0 5  5 0 5  5 0 -5\n"
          "surface 0.9 0.9 0.9  0.9 0.1 0  20 1\n"
       << "texture marble " << marbleScale << "  0.2 0.1 0.1  0.9 0.1 0  20\n"
       << "image grid.png\nuv " << marbleUv << "  0 0\n"
       << "push\n  translate 1.2 0.6 0\n  sphere 0 0 0 0.6\npop\n";
  return text.str();
}

// An image's edit (its size: SU and SV alike; its tint: the surface colour)
// renders as the file with the edited `uv` and `surface` written in, and so
// does a texture with an image, whose scale sizes both. The file's values
// put back give the file's picture, bit for bit.
TEST(RenderSession, ImageEditsRenderAsTheFileSaysAndTheFilesValuesGiveItsPicture) {
  test::ScratchDir dir;
  std::vector<std::uint8_t> rgb;
  for (int i = 0; i < 16; ++i)
    rgb.insert(rgb.end(), {std::uint8_t(40 + 13 * i), std::uint8_t(250 - 15 * i),
                           std::uint8_t(i % 3 == 0 ? 230 : 20)});
  writeImage8(dir / "grid.png", 4, 4, rgb);
  const Color tint(0.8, 0.7, 0.6);
  const Scene scene = parseScene(imageRoom("2 4", tint, 0.5, "1 1"), (dir / "image.sc").string());
  const Scene written = parseScene(imageRoom("4 8", Color(0.3, 0.9, 0.5), 1.0, "0.5 0.5"),
                                   (dir / "edited.sc").string());
  const RenderSettings s = smallSettings();
  const RenderResult fileFilm = renderDirect(scene, s);
  const RenderResult writtenFilm = renderDirect(written, s);
  ASSERT_FALSE(writtenFilm.film.radiance == fileFilm.film.radiance); // the edit shows

  RenderSession session(scene, s);
  ASSERT_EQ(session.textureGroups().size(), 2u);
  const TextureGroup& image = session.textureGroups()[0];
  EXPECT_TRUE(image.imageOnly());
  EXPECT_EQ(image.scale, 0.5); // one repeat: 1 / SU
  const TextureValues file = textureValuesOf(scene.materials[image.materials.front()]);
  const TextureValues marbleFile =
      textureValuesOf(scene.materials[session.textureGroups()[1].materials.front()]);
  TextureValues edited = file;
  edited.scale = 0.25;
  edited.base = Color(0.3, 0.9, 0.5);
  TextureValues marbleEdited = marbleFile;
  marbleEdited.scale = 1.0;
  session.waitForResult();
  session.apply({.textures = {{0, edited}, {1, marbleEdited}}});
  EXPECT_EQ(session.progress().restarts, 1u);
  expectSameFilm(session.waitForResult(), writtenFilm);
  EXPECT_EQ(session.scene().materials[image.materials.front()].image.scale, Vec2(4, 8));

  session.apply({.textures = {{0, file}, {1, marbleFile}}});
  expectSameFilm(session.waitForResult(), fileFilm);
  for (std::size_t m = 0; m < scene.materials.size(); ++m)
    EXPECT_EQ(session.scene().materials[m], scene.materials[m]);
}

TEST(RenderSession, OneApplyChangesSeveralValuesWithOneRestart) {
  const Scene scene = parseScene(kTwoRooms, "rooms.sc");
  RenderSettings s = smallSettings();
  RenderSession session(scene, s);
  Scene edited = scene;
  edited.camera.eye += glm::dvec3(-1.0, 0.5, 0.0);
  edited.ambient = Color(0.1, 0.05, 0.0);
  edited.lights[1].position = glm::dvec3(4, 2, 1);
  edited.lights[0].intensity = Color(5, 10, 20);
  s.maxDepth = 3;
  SessionEdit edit;
  edit.settings = s;
  edit.camera = edited.camera;
  edit.ambient = edited.ambient;
  edit.lights = {{1, edited.lights[1]}, {0, edited.lights[0]}};
  session.apply(edit);
  EXPECT_EQ(session.progress().restarts, 1u);
  expectSameFilm(session.waitForResult(), renderDirect(edited, s));

  // Nothing to change: no restart, the finished render stays.
  session.apply(SessionEdit{});
  EXPECT_EQ(session.progress().restarts, 1u);
  EXPECT_TRUE(session.finished());

  // A light the scene does not have: refused before anything stops or changes.
  SessionEdit bad;
  bad.ambient = Color(1.0);
  bad.lights = {{2, edited.lights[0]}};
  EXPECT_THROW(session.apply(bad), std::out_of_range);
  EXPECT_EQ(session.progress().restarts, 1u);
  EXPECT_TRUE(session.finished());
  EXPECT_EQ(session.scene().ambient, edited.ambient);

  // Threshold and jitter with nothing else keep pass 1; with a light they do not.
  s.thresh = 0.05;
  s.jitter = true;
  SessionEdit pass2;
  pass2.settings = s;
  session.apply(pass2);
  EXPECT_EQ(session.progress().pass1Pixels, 80 * 60); // kept at once, not being retraced
  const RenderResult kept = session.waitForResult();
  EXPECT_EQ(kept.counts.eyePrimary, 80u * 60u);
  expectSameFilm(kept, renderDirect(edited, s));
  s.thresh = 0.2;
  edited.lights[0].intensity = Color(20, 10, 5);
  SessionEdit both;
  both.settings = s;
  both.lights = {{0, edited.lights[0]}};
  session.apply(both);
  expectSameFilm(session.waitForResult(), renderDirect(edited, s));
}

TEST(RenderSession, CancellationIsPromptComparedWithTheRenderItStops) {
  // A render that takes a good fraction of a second, cancelled right after it
  // has started: the edit must return long before the render could have ended.
  const Scene scene = shipped("tree.sc");
  RenderSettings s = smallSettings();
  s.width = 240;
  s.height = 180;
  using Clock = std::chrono::steady_clock;
  const auto fullStart = Clock::now();
  RenderSession full(scene, s);
  full.waitForResult();
  const double fullSeconds = std::chrono::duration<double>(Clock::now() - fullStart).count();

  RenderSession session(scene, s);
  while (session.progress().pass1Pixels == 0)
    std::this_thread::yield();
  const auto cancelStart = Clock::now();
  session.apply({.ambient = Color(0.1)}); // cancels, joins the workers, restarts
  const double cancelSeconds = std::chrono::duration<double>(Clock::now() - cancelStart).count();
  EXPECT_LT(cancelSeconds, 0.25 * fullSeconds)
      << "cancel took " << cancelSeconds << " s; a full render takes " << fullSeconds << " s";
  EXPECT_FALSE(session.finished());
}

TEST(RenderSession, DisplayAlwaysHasTheImageSizeAndEndsAsTheFilm) {
  const Scene scene = shipped("chex.sc");
  RenderSession session(scene, smallSettings());
  SessionImage image;
  session.copyImage(image);
  EXPECT_EQ(image.width, 80);
  EXPECT_EQ(image.radiance.size(), 80u * 60u);
  const RenderResult r = session.waitForResult();
  session.copyImage(image);
  EXPECT_TRUE(image.radiance == r.film.radiance);
  EXPECT_TRUE(image.supersampled == r.film.supersampled);
}

} // namespace
} // namespace prism
