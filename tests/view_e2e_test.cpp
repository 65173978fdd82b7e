// The previewer end to end, in a real window: each test starts its own X server
// (xvfb-run, so it runs the same with or without a display, and under CI), where
// Mesa's llvmpipe provides OpenGL, and drives `prism view --script`. Scripts
// synchronise on events (wait pass1, wait done, echo), never on sleeps.
#include "test_pictures.h"

#include <cstdio>

namespace prism::test {
namespace {

const std::string kPrism = std::string("'") + PRISM_BINARY + "'";

// The previewers these tests start keep their recent scenes here, not in the
// user's configuration folder.
const bool kPrivateConfig = [] {
  const std::string folder =
      (fs::temp_directory_path() / ("prism_e2e_config_" + std::to_string(getpid()))).string();
  return setenv("XDG_CONFIG_HOME", folder.c_str(), 1) == 0;
}();

// xvfb-run with a display number of its own. `-a` alone starts looking at :99,
// so two test runs on one machine (say, a Release and a sanitizer build) can
// race for the same number and one Xvfb fails to start: start elsewhere for
// each process and attempt, and try again when that happens. -noreset: when
// the last client leaves, Xvfb would reset and signal xvfb-run (SIGUSR1),
// which can hit xvfb-run's own clean-up and make it fail with exit status 5.
std::string xvfb(int attempt) {
  const int first = 100 + int((unsigned(getpid()) * 7u + unsigned(attempt) * 131u) % 800u);
  return "xvfb-run -a -n " + std::to_string(first) + " -s '-screen 0 1280x800x24 -noreset' ";
}

bool xvfbFailed(const std::string& err) {
  return err.find("Xvfb failed to start") != std::string::npos;
}

RunResult runInXvfb(const fs::path& dir, const std::string& command) {
  RunResult r;
  for (int attempt = 0; attempt < 5; ++attempt) {
    r = run(dir, xvfb(attempt) + command);
    if (!xvfbFailed(r.err)) break;
  }
  return r;
}

// Two spheres (one a mirror) on a checker-free floor, two lights at top level
// (no transform, so `light 1 X Y Z` in a script equals the same line in a file).
std::string scene(const std::string& light1) {
  return "eye 0 1.5 6\nlookat 0 0.3 0\nfov 40\nresolution 160 120\n"
         "ambient 0.05 0.05 0.05\n"
         "light " +
         light1 +
         "  40 38 34\n"
         "light -4 5 3  20 22 26\n"
         "surface 0.9 0.3 0.2  0.8 0.3 0  40 1\nsphere -0.8 0.3 0 0.8\n"
         "surface 0.9 0.9 0.9  0.1 0.8 0  200 1\nsphere 1 0.2 -0.5 0.7\n"
         "surface 0.4 0.6 0.8  0.9 0.1 0  10 1\n"
         "polygon 4  -6 -0.5 -6  -6 -0.5 6  6 -0.5 6  6 -0.5 -6\n";
}

// The panel (right of the image) shows widgets and text: many colours, not one.
int distinctColours(const Picture& p, int x0, int x1) {
  std::vector<bool> seen(1 << 24, false);
  int count = 0;
  for (int y = 0; y < p.height; ++y) {
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t* c = p.at(x, y);
      const int key = (c[0] << 16) | (c[1] << 8) | c[2];
      if (!seen[std::size_t(key)]) {
        seen[std::size_t(key)] = true;
        ++count;
      }
    }
  }
  return count;
}

TEST(ViewE2E, ScriptedSessionShowsTheImageAndSavesWhatRenderWrites) {
  ScratchDir dir;
  writeFile(dir / "a.sc", scene("3 4 4"));
  writeFile(dir / "b.sc", scene("-1 3 5")); // a.sc after the script's light edit
  writeFile(dir / "s.txt",
            R"(# A session a user could have: look, change settings, move a light, save.
wait coarse
wait pass1
depth 3
thresh 0.05
light 1 -1 3 5
markers off
wait done
screenshot shot.png
save saved.tiff
overlay on
markers on
screenshot overlay.png
quit
)");
  const RunResult r = runInXvfb(dir.path(), kPrism + " view a.sc --script s.txt");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;

  const RunResult ref =
      run(dir.path(), kPrism + " render b.sc -o ref.tiff --depth 3 --thresh 0.05 -q");
  ASSERT_EQ(ref.exitCode, 0) << ref.err;
  const auto reference = readPicture(dir / "ref.tiff");
  const auto saved = readPicture(dir / "saved.tiff");
  ASSERT_TRUE(reference && saved);
  EXPECT_EQ(saved->width, 160);
  EXPECT_TRUE(sameRgb(*saved, *reference)) << "Save differs from prism render";

  // The window shows exactly the exposed picture at 1:1 ...
  const auto shot = readPicture(dir / "shot.png");
  ASSERT_TRUE(shot);
  const auto at = findExact(*shot, *reference);
  ASSERT_TRUE(at) << "the rendered image is not in the screenshot";
  // ... left of a control panel that is not blank.
  const int panelStart = at->first + reference->width;
  EXPECT_GT(shot->width - panelStart, 300);
  EXPECT_GT(distinctColours(*shot, panelStart, shot->width), 20);

  // With the overlay and the markers, some pixels of the image change, not all.
  const auto overlay = readPicture(dir / "overlay.png");
  ASSERT_TRUE(overlay);
  int changed = 0;
  for (int y = 0; y < reference->height; ++y)
    for (int x = 0; x < reference->width; ++x)
      changed += overlay->at(at->first + x, at->second + y)[0] != reference->at(x, y)[0] ||
                 overlay->at(at->first + x, at->second + y)[1] != reference->at(x, y)[1];
  EXPECT_GT(changed, 0);
  EXPECT_LT(changed, reference->width * reference->height / 2);

  // The frame-time report of a scripted session.
  const std::size_t report = r.out.find("frames while rendering: ");
  ASSERT_NE(report, std::string::npos) << r.out;
  unsigned frames = 0;
  double seconds = 0.0, fps = 0.0;
  ASSERT_EQ(std::sscanf(r.out.c_str() + report, "frames while rendering: %u in %lf s = %lf fps",
                        &frames, &seconds, &fps),
            3)
      << r.out;
  EXPECT_GT(frames, 0u);
  std::printf("%s", r.out.c_str() + report);
}

// A script's edit in the window against the same edit made for `prism
// render`: runs `script` on dir/a.sc in the previewer (it must save
// saved.tiff), then `prism render` with the arguments `edited` (what Save
// must write) and `unedited` (what it must not: the edit changes the picture).
void expectSaveIsTheEditedRender(const fs::path& dir, const std::string& script,
                                 const std::string& edited, const std::string& unedited) {
  writeFile(dir / "s.txt", script);
  const RunResult r = runInXvfb(dir, kPrism + " view a.sc --script s.txt");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  ASSERT_EQ(run(dir, kPrism + " render " + edited + " -o edited.tiff -q").exitCode, 0);
  ASSERT_EQ(run(dir, kPrism + " render " + unedited + " -o unedited.tiff -q").exitCode, 0);
  const auto saved = readPicture(dir / "saved.tiff");
  const auto editedPicture = readPicture(dir / "edited.tiff");
  const auto uneditedPicture = readPicture(dir / "unedited.tiff");
  ASSERT_TRUE(saved && editedPicture && uneditedPicture);
  EXPECT_TRUE(sameRgb(*saved, *editedPicture)) << "Save differs from prism render " << edited;
  EXPECT_FALSE(sameRgb(*editedPicture, *uneditedPicture)) << "the script's edit changed nothing";
}

// The surfaces beyond spheres, polygons and cones (boxes, capped cylinders
// and cones, discs, a torus, a quadric, a blob, CSG) in the previewer: after
// a light is moved, Save writes what `prism render` writes of the scene with
// the light there, so the window traces them with the same code.
TEST(ViewE2E, TheNewSurfacesShowAndSaveWhatRenderWrites) {
  ScratchDir dir;
  const auto surfaces = [](const std::string& light1) {
    return "eye 0 3 7\nlookat 0 0.6 0\nfov 45\nresolution 120 80\n"
           "ambient 0.1 0.1 0.1\n"
           "light " +
           light1 +
           "  40 38 34\n"
           "surface 0.8 0.8 0.7  0.9 0 0  1 1\nbox -4 -0.2 -3  4 0 2\n"
           "surface 0.9 0.3 0.2  0.7 0.3 0  40 1\ncylinder -2.2 0 0  -2.2 1 0  0.4\n"
           "capped_cone -1.2 0 -1  0.4  -1.2 1.2 -1  0.1\n"
           "disc 2.5 0.01 1  0 1 0  0.5\n"
           "surface 0.3 0.5 0.9  0.6 0.4 0  60 1\ntorus 0 0.3 0.8  0 1 0  0.6 0.2\n"
           "quadric 1 1 0 0 0 0 0 -1 0 0  -0.5 0 -0.5  0.5 1 0.5\n"
           "surface 1 1 1  0 0.1 0.9  200 1.5\n"
           "csg difference\n  sphere 1.6 0.6 0  0.6\n  box 1.6 0.6 -1  2.4 1.4 1\nend\n"
           "surface 0.9 0.7 0.2  0.6 0.4 0  80 1\n"
           "blob 0.5 2  -0.3 1.8 -1.5 0.6 1  0.3 1.8 -1.5 0.6 1\n";
  };
  writeFile(dir / "a.sc", surfaces("3 4 4"));
  writeFile(dir / "b.sc", surfaces("-2 5 3")); // a.sc after the script's light edit
  expectSaveIsTheEditedRender(
      dir.path(), "wait pass1\nlight 1 -2 5 3\nwait done\nsave saved.tiff\nquit\n", "b.sc", "a.sc");
}

// The script's `fog` fogs the window's scene as a `fog` line fogs the file:
// Save writes what `prism render` writes of the scene with that line.
TEST(ViewE2E, FogFromAScriptSavesWhatRenderOfTheFoggedFileWrites) {
  ScratchDir dir;
  writeFile(dir / "a.sc", scene("3 4 4"));
  writeFile(dir / "b.sc", scene("3 4 4") + "fog 0.6 0.65 0.7  0.12\n");
  expectSaveIsTheEditedRender(
      dir.path(), "wait pass1\nfog 0.6 0.65 0.7 0.12\nwait done\nsave saved.tiff\nquit\n", "b.sc",
      "a.sc");
}

// The script's `texture` edits every object space of a texture as writing
// its values into the `texture` and `surface` lines does: Save writes what
// `prism render` writes of the file with those values.
TEST(ViewE2E, TextureFromAScriptSavesWhatRenderOfTheEditedFileWrites) {
  ScratchDir dir;
  const auto textured = [](const std::string& surface, const std::string& texture) {
    return "eye 0 1.5 6\nlookat 0 0.3 0\nfov 40\nresolution 80 60\n"
           "light 3 4 4  40 38 34\n"
           "surface " +
           surface + "  0.8 0.2 0  40 1\ntexture marble " + texture +
           "  0.8 0.2 0  40\n"
           "push\n  translate -0.8 0.3 0\n  sphere 0 0 0 0.8\npop\n"
           "push\n  translate 1 0.2 -0.5\n  sphere 0 0 0 0.7\npop\n"
           "surface 0.4 0.6 0.8  0.9 0.1 0  10 1\n"
           "polygon 4  -6 -0.5 -6  -6 -0.5 6  6 -0.5 6  6 -0.5 -6\n";
  };
  writeFile(dir / "a.sc", textured("0.9 0.85 0.8", "0.5  0.3 0.2 0.3"));
  writeFile(dir / "b.sc", textured("0.2 0.3 0.6", "0.25  0.9 0.8 0.1"));
  expectSaveIsTheEditedRender(
      dir.path(),
      "wait pass1\ntexture 1 0.25 0.9 0.8 0.1 0.2 0.3 0.6\nwait done\nsave saved.tiff\nquit\n",
      "b.sc", "a.sc");
}

// The script's `texture` on an image alone (texture N SCALE R G B: its size
// and tint) edits it as writing the sized `uv` and the tint's `surface` into
// the file does: Save writes what `prism render` writes of that file.
TEST(ViewE2E, TextureOnAnImageFromAScriptSavesWhatRenderOfTheEditedFileWrites) {
  ScratchDir dir;
  std::vector<std::uint8_t> rgb;
  for (int i = 0; i < 16; ++i)
    rgb.insert(rgb.end(), {std::uint8_t(40 + 13 * i), std::uint8_t(250 - 15 * i),
                           std::uint8_t(i % 3 == 0 ? 230 : 20)});
  ASSERT_TRUE(writePicture8(dir / "grid.png", 4, 4, rgb));
  const auto imaged = [](const std::string& surface, const std::string& uv) {
    return "eye 0 1.5 6\nlookat 0 0.3 0\nfov 40\nresolution 80 60\n"
           "light 3 4 4  40 38 34\n"
           "surface " +
           surface + "  0.8 0.2 0  40 1\nimage grid.png\nuv " + uv +
           "  0.1 0.2\n"
           "sphere -0.8 0.3 0 0.8\n"
           "polygon 4  -6 -0.5 -6  -6 -0.5 6  6 -0.5 6  6 -0.5 -6\n";
  };
  writeFile(dir / "a.sc", imaged("0.9 0.85 0.8", "0.5 0.25"));
  writeFile(dir / "b.sc", imaged("0.2 0.3 0.6", "2 1"));
  expectSaveIsTheEditedRender(dir.path(),
                              "wait pass1\ntexture 1 0.5 0.2 0.3 0.6\nwait done\nsave saved.tiff\n"
                              "quit\n",
                              "b.sc", "a.sc");
}

// The script's `no-aa on` switches antialiasing off as `prism render --no-aa`
// does: Save writes its picture, which is not the antialiased one.
TEST(ViewE2E, NoAntialiasingFromAScriptSavesWhatRenderNoAaWrites) {
  ScratchDir dir;
  writeFile(dir / "a.sc", scene("3 4 4"));
  expectSaveIsTheEditedRender(dir.path(), "wait done\nno-aa on\nwait done\nsave saved.tiff\nquit\n",
                              "a.sc --no-aa", "a.sc");
}

// The sweep table beside the scene (`prism sweep`'s CSV, here written by hand):
// the panel's Sweep section places the current settings in it, and `print
// sweep` prints what the section shows. Depth 5, threshold 0.1 (the defaults)
// cost 2.5 s for 38.5 dB where depth 3 gives 41.25 dB for 1.25 s.
TEST(ViewE2E, TheSweepSectionPlacesTheCurrentSettings) {
  ScratchDir dir;
  writeFile(dir / "a.sc", scene("3 4 4"));
  const std::string header =
      "antialias,thresh,depth,jitter,bailout,options,cpu_s,wall_s,eye_rpp,shadow_rpp,"
      "reflected_rpp,transmitted_rpp,pilot_rpp,total_rpp,supersampled,rmse,psnr_db,"
      "worst_levels,worst_x,worst_y,over2,pareto\r\n";
  writeFile(dir / "a.sweep.csv",
            header +
                "1,0.1,5,0,0,--depth 5 --thresh 0.1,2.5,1.3,1.2,2,0.5,0,0,3.7,0.1,0.001,38.5,12,"
                "80,60,0.004,0\r\n"
                "1,0.1,3,0,0,--depth 3 --thresh 0.1,1.25,0.7,1.2,2,0.3,0,0,3.5,0.1,0.001,41.25,6,"
                "10,20,0.001,1\r\n");
  writeFile(dir / "s.txt", "wait coarse\nprint sweep\ndepth 3\nprint sweep\ndepth 4\n"
                           "print sweep\nwait coarse\nquit\n");
  const RunResult r = runInXvfb(dir.path(), kPrism + " view a.sc --script s.txt");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const std::string defaults = "sweep: a.sweep.csv: 2 settings measured\n"
                               "sweep: these settings: --depth 5 --thresh 0.1\n"
                               "sweep: expected PSNR 38.50 dB\n"
                               "sweep: pixels more than 2 levels off: 0.40%\n"
                               "sweep: worst pixel: 12 levels off, at (80, 60)\n"
                               "sweep: CPU time in the sweep: 2.5 s\n"
                               "sweep: Pareto-optimal at the same cost: --depth 3 --thresh 0.1, "
                               "41.25 dB, 1.25 s\n";
  const std::string depth3 = "sweep: a.sweep.csv: 2 settings measured\n"
                             "sweep: these settings: --depth 3 --thresh 0.1\n"
                             "sweep: expected PSNR 41.25 dB\n"
                             "sweep: pixels more than 2 levels off: 0.10%\n"
                             "sweep: worst pixel: 6 levels off, at (10, 20)\n"
                             "sweep: CPU time in the sweep: 1.25 s\n"
                             "sweep: on the Pareto front: no setting of the sweep is as cheap and "
                             "more accurate\n";
  const std::string depth4 = "sweep: a.sweep.csv: 2 settings measured\n"
                             "sweep: these settings: --depth 4 --thresh 0.1\n"
                             "sweep: not in the sweep\n";
  EXPECT_EQ(r.out.substr(0, r.out.find("frames while rendering")), defaults + depth3 + depth4);

  // Named with --sweep, and malformed: the panel says where, the window runs on.
  writeFile(dir / "bad.csv", header + "1,0.1,5,0,0,x,fast\n");
  writeFile(dir / "p.txt", "wait coarse\nprint sweep\nquit\n");
  const RunResult bad = runInXvfb(dir.path(), kPrism + " view a.sc --sweep bad.csv --script p.txt");
  ASSERT_EQ(bad.exitCode, 0) << bad.out << bad.err;
  const std::string where = "bad.csv:2:19: expected 22 fields as in the header, got 7";
  EXPECT_NE(bad.out.find("sweep: The sweep table cannot be read:\nsweep: " + where + "\n"),
            std::string::npos)
      << bad.out;
  EXPECT_NE(bad.err.find(where), std::string::npos) << bad.err;
}

// Reads the app's stdout line by line while it runs, so the test can edit the
// scene exactly when the script says it is ready.
class Session {
public:
  explicit Session(const std::string& command) : pipe_(popen(command.c_str(), "r")) {}
  ~Session() {
    if (pipe_) pclose(pipe_);
  }
  // The next line of stdout, or nothing at the end.
  std::optional<std::string> line() {
    char buffer[4096];
    if (!pipe_ || !std::fgets(buffer, sizeof buffer, pipe_)) return std::nullopt;
    std::string text = buffer;
    if (!text.empty() && text.back() == '\n') text.pop_back();
    return text;
  }
  int close() {
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

private:
  FILE* pipe_;
};

TEST(ViewE2E, ReloadsWhenAFileChangesAndKeepsTheLastGoodSceneOnErrors) {
  ScratchDir dir;
  // The lights live in an included file: a change there must be noticed too.
  const std::string full = scene("3 4 4");
  const std::size_t lights = full.find("light ");
  const std::size_t afterLights = full.find("surface");
  writeFile(dir / "main.sc",
            full.substr(0, lights) + "include lights.sc\n" + full.substr(afterLights));
  writeFile(dir / "lights.sc", full.substr(lights, afterLights - lights));
  writeFile(dir / "good.sc", full);
  writeFile(dir / "s.txt", R"(wait done
markers off
echo ready
wait error
screenshot broken.png
echo broken
wait reload
wait done
save fixed.tiff
quit
)");
  std::string output;
  int status = -1;
  for (int attempt = 0; attempt < 5; ++attempt) {
    Session session("cd " + quoted(dir.path()) + " && " + xvfb(attempt) + kPrism +
                    " view main.sc --depth 2 --script s.txt 2>stderr.txt");
    output.clear();
    while (const auto line = session.line()) {
      output += *line + "\n";
      if (*line == "ready") writeFile(dir / "lights.sc", "light 1 2 oops\n");
      if (*line == "broken") writeFile(dir / "lights.sc", "light -2 4 5  50 50 50\n");
    }
    status = session.close();
    if (!xvfbFailed(slurp(dir / "stderr.txt"))) break;
  }
  ASSERT_EQ(status, 0) << output << slurp(dir / "stderr.txt");

  // The error was reported with its location ...
  const std::string err = slurp(dir / "stderr.txt");
  EXPECT_NE(err.find("lights.sc:1:11: error:"), std::string::npos) << err;
  // ... while the window kept showing the last good picture.
  ASSERT_EQ(run(dir.path(), kPrism + " render good.sc -o good.tiff --depth 2 -q").exitCode, 0);
  const auto good = readPicture(dir / "good.tiff");
  const auto broken = readPicture(dir / "broken.png");
  ASSERT_TRUE(good && broken);
  EXPECT_TRUE(findExact(*broken, *good)) << "the last good scene is not on screen";

  // The fixed scene was picked up by itself, and Save wrote its picture.
  writeFile(dir / "fixed.sc",
            full.substr(0, lights) + "light -2 4 5  50 50 50\n" + full.substr(afterLights));
  ASSERT_EQ(run(dir.path(), kPrism + " render fixed.sc -o ref.tiff --depth 2 -q").exitCode, 0);
  const auto reference = readPicture(dir / "ref.tiff");
  const auto fixed = readPicture(dir / "fixed.tiff");
  ASSERT_TRUE(reference && fixed);
  EXPECT_TRUE(sameRgb(*fixed, *reference));
}

TEST(ViewE2E, ScriptErrorsAreReportedWithTheirLine) {
  ScratchDir dir;
  writeFile(dir / "a.sc", scene("3 4 4"));
  writeFile(dir / "bad.txt", "wait pass1\nfly away\n");
  const RunResult parse = runInXvfb(dir.path(), kPrism + " view a.sc --script bad.txt");
  EXPECT_EQ(parse.exitCode, 2);
  EXPECT_NE(parse.err.find("bad.txt:2:1: error: unknown action 'fly'"), std::string::npos)
      << parse.err;
  writeFile(dir / "light.txt", "wait coarse\nlight 9 0 0 0\nquit\n");
  const RunResult runtime = runInXvfb(dir.path(), kPrism + " view a.sc --script light.txt");
  EXPECT_EQ(runtime.exitCode, 1);
  EXPECT_NE(
      runtime.err.find("script line 2 (light 9 0 0 0): there is no light 9 (the scene has 2)"),
      std::string::npos)
      << runtime.err;
}

} // namespace
} // namespace prism::test
