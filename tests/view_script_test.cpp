// The previewer's script language: every action parses to what it says, bad
// lines are reported with file, line and column, and the runner waits for
// actions to complete and enforces the timeout.
#include "viewer/view_script.h"

#include "core/io/image_io.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

namespace prism {
namespace {

std::vector<Diagnostic> errorsOf(const std::string& text) {
  try {
    parseScript(text, "s.txt");
  } catch (const SceneError& error) {
    return error.diagnostics();
  }
  return {};
}

TEST(ViewScript, ParsesEveryAction) {
  const auto a = parseScript(R"(# a comment line
wait pass1
  wait   done   # trailing comment
wait coarse
wait reload
wait error
frames 3
timeout 2.5
depth 3
thresh 0.05
jitter on
ambient 0.1 0.2 0.3
light 2 1 -2 3.5
intensity 1 10 20 30
orbit 15 -5
pan 4 -2
zoom 0.8
reset
overlay off
markers on
reload
save out dir/picture one.tiff
screenshot shot.png
echo ready for the edit
quit
)",
                             "s.txt");
  ASSERT_EQ(a.size(), 24u);
  EXPECT_EQ(a[0].op, ScriptOp::Wait);
  EXPECT_EQ(a[0].waitFor, WaitFor::Pass1);
  EXPECT_EQ(a[0].line, 2);
  EXPECT_EQ(a[1].waitFor, WaitFor::Done);
  EXPECT_EQ(a[2].waitFor, WaitFor::Coarse);
  EXPECT_EQ(a[3].waitFor, WaitFor::Reload);
  EXPECT_EQ(a[4].waitFor, WaitFor::Error);
  EXPECT_EQ(a[5].op, ScriptOp::Frames);
  EXPECT_EQ(a[5].index, 3);
  EXPECT_EQ(a[6].values, std::vector<double>({2.5}));
  EXPECT_EQ(a[7].op, ScriptOp::Depth);
  EXPECT_EQ(a[7].index, 3);
  EXPECT_EQ(a[8].values, std::vector<double>({0.05}));
  EXPECT_EQ(a[9].values, std::vector<double>({1.0}));
  EXPECT_EQ(a[10].values, std::vector<double>({0.1, 0.2, 0.3}));
  EXPECT_EQ(a[11].op, ScriptOp::Light);
  EXPECT_EQ(a[11].index, 2);
  EXPECT_EQ(a[11].values, std::vector<double>({1.0, -2.0, 3.5}));
  EXPECT_EQ(a[12].op, ScriptOp::Intensity);
  EXPECT_EQ(a[12].values, std::vector<double>({10.0, 20.0, 30.0}));
  EXPECT_EQ(a[13].values, std::vector<double>({15.0, -5.0}));
  EXPECT_EQ(a[14].values, std::vector<double>({4.0, -2.0}));
  EXPECT_EQ(a[15].values, std::vector<double>({0.8}));
  EXPECT_EQ(a[16].op, ScriptOp::Reset);
  EXPECT_EQ(a[17].values, std::vector<double>({0.0}));
  EXPECT_EQ(a[18].values, std::vector<double>({1.0}));
  EXPECT_EQ(a[19].op, ScriptOp::Reload);
  EXPECT_EQ(a[20].path, "out dir/picture one.tiff"); // paths may hold spaces
  EXPECT_EQ(a[21].path, "shot.png");
  EXPECT_EQ(a[22].path, "ready for the edit");
  EXPECT_EQ(a[23].op, ScriptOp::Quit);
  EXPECT_EQ(a[23].line, 25);
}

TEST(ViewScript, ParsesTheNoAntialiasingSwitch) {
  const auto a = parseScript("no-aa on\nno-aa off\n", "s.txt");
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].op, ScriptOp::NoAa);
  EXPECT_EQ(a[0].values, std::vector<double>({1.0}));
  EXPECT_EQ(a[1].op, ScriptOp::NoAa);
  EXPECT_EQ(a[1].values, std::vector<double>({0.0}));
}

TEST(ViewScript, ParsesTheInspectionAndComparisonActions) {
  const auto a = parseScript("exposure lock\nev -1.5\nexposure auto\npicture fit\npicture 400\n"
                             "inspect 12 34\npin\ncompare split 0.25\ncompare flip\n"
                             "compare off\n",
                             "s.txt");
  ASSERT_EQ(a.size(), 10u);
  EXPECT_EQ(a[0].op, ScriptOp::Exposure);
  EXPECT_EQ(a[0].values, std::vector<double>({1.0}));
  EXPECT_EQ(a[1].values, std::vector<double>({-1.5}));
  EXPECT_EQ(a[2].values, std::vector<double>({0.0}));
  EXPECT_EQ(a[3].values, std::vector<double>({0.0})); // fit
  EXPECT_EQ(a[4].values, std::vector<double>({400.0}));
  EXPECT_EQ(a[5].values, std::vector<double>({12.0, 34.0}));
  EXPECT_EQ(a[6].op, ScriptOp::Pin);
  EXPECT_EQ(a[7].index, 2);
  EXPECT_EQ(a[7].values, std::vector<double>({0.25}));
  EXPECT_EQ(a[8].index, 1);
  EXPECT_EQ(a[9].index, 0);
  const auto errors = errorsOf("exposure maybe\nev 9\npicture 1\ninspect -1 2\ncompare sideways\n"
                               "pin now\n");
  ASSERT_EQ(errors.size(), 6u);
  EXPECT_EQ(errors[0].format(), "s.txt:1:10: error: exposure: expected auto or lock, got 'maybe'");
  EXPECT_EQ(errors[4].format(),
            "s.txt:5:9: error: compare: expected off, flip or split, got 'sideways'");
}

TEST(ViewScript, ParsesFogAndReportsItsErrors) {
  const auto a = parseScript("fog 0.5 0.6 0.7 0.08\n\nfog 0 0 0 0\n", "s.txt");
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].op, ScriptOp::Fog);
  EXPECT_EQ(a[0].values, std::vector<double>({0.5, 0.6, 0.7, 0.08}));
  EXPECT_EQ(a[1].line, 3);
  EXPECT_EQ(a[1].values, std::vector<double>({0.0, 0.0, 0.0, 0.0}));
  const auto errors = errorsOf("fog 0.5 0.5 0.5\n"
                               "fog 1 1 1 -0.5\n"
                               "fog 1 -1 1 0.1\n"
                               "fog 1 1 x 0.1\n"
                               "fog 1 1 1 0.1 2\n");
  ASSERT_EQ(errors.size(), 5u);
  EXPECT_EQ(errors[0].format(), "s.txt:1:1: error: fog: expected R G B DENSITY, got 3 arguments");
  EXPECT_EQ(errors[1].format(), "s.txt:2:11: error: fog density must be in [0, 1e+30], got -0.5");
  EXPECT_EQ(errors[2].format(), "s.txt:3:7: error: fog colour must be in [0, 1e+30], got -1");
  EXPECT_EQ(errors[3].format(), "s.txt:4:9: error: fog colour: expected a number, got 'x'");
  EXPECT_EQ(errors[4].format(), "s.txt:5:15: error: fog: expected R G B DENSITY, got 5 arguments");
}

TEST(ViewScript, ParsesTextureAndReportsItsErrors) {
  const auto a = parseScript("texture 2 0.5 0.1 0.2 0.3\ntexture 1 2 1 1 1  0.5 0.25 0\n", "s.txt");
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].op, ScriptOp::Texture);
  EXPECT_EQ(a[0].index, 2);
  EXPECT_EQ(a[0].values, std::vector<double>({0.5, 0.1, 0.2, 0.3}));
  EXPECT_EQ(a[1].index, 1);
  EXPECT_EQ(a[1].values, std::vector<double>({2, 1, 1, 1, 0.5, 0.25, 0}));
  const auto errors = errorsOf("texture 1 0.5 1 1\n"
                               "texture 0 1 1 1 1\n"
                               "texture 1.5 1 1 1 1\n"
                               "texture 1 0 1 1 1\n"
                               "texture 1 -2 1 1 1\n"
                               "texture 1 1 1 -1 1\n"
                               "texture 1 1 1 1 1 0.5 0.5 x\n"
                               "texture 1 1 1 1 1 0.5\n"
                               "texture 1 1 1 1 1 1 1 1 1\n");
  ASSERT_EQ(errors.size(), 9u);
  EXPECT_EQ(errors[0].format(),
            "s.txt:1:1: error: texture: expected N SCALE R G B [R0 G0 B0], got 4 arguments");
  EXPECT_EQ(errors[1].format(), "s.txt:2:9: error: texture number must be in [1, 1e+06], got 0");
  EXPECT_EQ(errors[2].format(), "s.txt:3:9: error: texture number: expected an integer, got 1.5");
  EXPECT_EQ(errors[3].format(), "s.txt:4:11: error: texture scale must be positive, got 0");
  EXPECT_EQ(errors[4].format(), "s.txt:5:11: error: texture scale must be in [0, 1e+30], got -2");
  EXPECT_EQ(errors[5].format(), "s.txt:6:15: error: texture colour must be in [0, 1e+30], got -1");
  EXPECT_EQ(errors[6].format(), "s.txt:7:27: error: surface colour: expected a number, got 'x'");
  EXPECT_EQ(errors[7].format(),
            "s.txt:8:1: error: texture: expected N SCALE R G B [R0 G0 B0], got 6 arguments");
  EXPECT_EQ(errors[8].format(),
            "s.txt:9:25: error: texture: expected N SCALE R G B [R0 G0 B0], got 9 arguments");
}

// A `texture` action over the values shown: for a procedural texture (with
// an image or not) the value-1 colour and, if given, the value-0 one; for an
// image alone its size and tint (texture N SCALE R G B), and the form with
// R0 G0 B0 is refused. (And what the panel's rows say each texture is.)
TEST(ViewScript, TextureActionsEditTexturesAndImages) {
  test::ScratchDir dir;
  writeImage8(dir / "a.png", 1, 1, {200, 100, 50});
  const Scene scene = parseScene("surface 0.5 0.5 0.5  1 0 0  1 1\n"
                                 "texture checker 2  0.1 0.2 0.3  1 0 0  1\nsphere 0 0 0 1\n"
                                 "surface 0.8 0.6 0.4  1 0 0  1 1\nimage a.png\nuv 2 2 0 0\n"
                                 "sphere 3 0 0 1\n"
                                 "texture marble 1  0.1 0.1 0.1  1 0 0  1\nsphere 6 0 0 1\n",
                                 (dir / "t.sc").string());
  const FileValues file = FileValues::of(scene);
  ASSERT_EQ(file.textures.size(), 3u);
  EXPECT_EQ(file.textures[0].description(), "checker");
  EXPECT_EQ(file.textures[1].description(), "image a.png");
  EXPECT_EQ(file.textures[2].description(), "marble and image a.png");
  UserEdits edits;
  edits.textures[1] = {0.25, Color(1.0), Color(0.9)}; // shown: the image already edited
  const auto action = [](const std::string& line) { return parseScript(line, "s.txt").at(0); };

  const TextureEdit pattern = textureEditOf(action("texture 1 4 1 0 0\n"), file, edits);
  EXPECT_EQ(pattern.index, 0u);
  EXPECT_EQ(pattern.values, (TextureValues{4, Color(1, 0, 0), Color(0.5)}));
  EXPECT_EQ(textureEditOf(action("texture 1 4 1 0 0  0 1 0\n"), file, edits).values,
            (TextureValues{4, Color(1, 0, 0), Color(0, 1, 0)}));
  const TextureEdit image = textureEditOf(action("texture 2 1.5 0 0 1\n"), file, edits);
  EXPECT_EQ(image.index, 1u);
  EXPECT_EQ(image.values, (TextureValues{1.5, Color(1.0), Color(0, 0, 1)}));
  const auto message = [&](const std::string& line) {
    try {
      textureEditOf(action(line), file, edits);
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message("texture 2 1 1 1 1  0 0 1\n"),
            "texture 2 is an image: give SCALE R G B (its size and the surface colour)");
  // A texture with an image takes both forms, as a texture.
  EXPECT_EQ(textureEditOf(action("texture 3 2 1 0 0  0 1 0\n"), file, edits).values,
            (TextureValues{2, Color(1, 0, 0), Color(0, 1, 0)}));
  EXPECT_EQ(message("texture 4 1 1 1 1\n"), "there is no texture 4 (the scene has 3)");
}

TEST(ViewScript, ParsesPrintSweep) {
  const auto a = parseScript("print sweep\n", "s.txt");
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].op, ScriptOp::Print);
  EXPECT_EQ(a[0].path, "sweep");
  const auto errors = errorsOf("print\nprint lights\nprint sweep now\n");
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].format(), "s.txt:1:1: error: print: expected sweep, got 0 arguments");
  EXPECT_EQ(errors[1].format(), "s.txt:2:7: error: print: expected sweep, got 'lights'");
  EXPECT_EQ(errors[2].format(), "s.txt:3:13: error: print: expected sweep, got 2 arguments");
}

TEST(ViewScript, ReportsEveryBadLineWithItsPosition) {
  const auto errors = errorsOf("wait pass1\n"
                               "  jump 3\n"
                               "wait forever\n"
                               "depth 0\n"
                               "depth 2.5\n"
                               "thresh 1.5\n"
                               "light 1 2 3\n"
                               "light 1 2 3 x\n"
                               "intensity 1 1 -1 1\n"
                               "jitter maybe\n"
                               "save\n"
                               "quit now\n"
                               "zoom 0\n"
                               "ambient nan 0 0\n");
  ASSERT_EQ(errors.size(), 13u);
  EXPECT_EQ(errors[0].format(), "s.txt:2:3: error: unknown action 'jump'");
  EXPECT_EQ(errors[1].format(),
            "s.txt:3:6: error: wait: expected coarse, pass1, done, reload or error, got 'forever'");
  EXPECT_EQ(errors[2].format(), "s.txt:4:7: error: depth must be in [1, 1000], got 0");
  EXPECT_EQ(errors[3].format(), "s.txt:5:7: error: depth: expected an integer, got 2.5");
  EXPECT_EQ(errors[4].format(), "s.txt:6:8: error: thresh must be in [0, 1], got 1.5");
  EXPECT_EQ(errors[5].format(), "s.txt:7:1: error: light: expected N X Y Z, got 3 arguments");
  EXPECT_EQ(errors[6].format(), "s.txt:8:13: error: light position: expected a number, got 'x'");
  EXPECT_EQ(errors[7].line, 9);
  EXPECT_EQ(errors[8].format(), "s.txt:10:8: error: expected on or off, got 'maybe'");
  EXPECT_EQ(errors[9].format(), "s.txt:11:1: error: save: expected PATH");
  EXPECT_EQ(errors[10].format(), "s.txt:12:6: error: quit: expected no arguments, got 1 argument");
  EXPECT_EQ(errors[11].line, 13);
  EXPECT_EQ(errors[12].line, 14);
}

TEST(ViewScript, MissingFileIsAnError) {
  EXPECT_THROW(loadScript("/nonexistent/script.txt"), SceneError);
}

// A host that completes an action after a given number of polls and logs calls.
class FakeHost : public ScriptHost {
public:
  int pollsNeeded = 0;
  std::vector<std::string> log;
  int polls = 0;

  void start(const ScriptAction& a) override {
    log.push_back("start " + a.text);
    polls = 0;
  }
  bool finished(const ScriptAction& a) override {
    if (a.op != ScriptOp::Wait) return true;
    return ++polls > pollsNeeded;
  }
};

TEST(ViewScript, RunnerWaitsFrameByFrameAndStopsAtQuit) {
  ScriptRunner runner(parseScript("depth 2\nwait done\nthresh 0.5\nquit\ndepth 9\n", "s"));
  FakeHost host;
  host.pollsNeeded = 2;
  const auto t0 = ScriptRunner::Clock::now();
  EXPECT_TRUE(runner.step(host, t0)); // depth 2 runs, the wait starts and is not reached
  EXPECT_EQ(host.log, std::vector<std::string>({"start depth 2", "start wait done"}));
  EXPECT_TRUE(runner.step(host, t0));
  EXPECT_FALSE(runner.step(host, t0)); // reached; thresh and quit run; nothing after quit
  EXPECT_EQ(host.log.size(), 4u);
  EXPECT_EQ(host.log[3], "start quit");
  EXPECT_TRUE(runner.done());
}

TEST(ViewScript, RunnerTimesOutAWaitThatNeverCompletes) {
  ScriptRunner runner(parseScript("timeout 1\nwait pass1\n", "s"));
  FakeHost host;
  host.pollsNeeded = 1000000;
  const auto t0 = ScriptRunner::Clock::now();
  EXPECT_TRUE(runner.step(host, t0));
  EXPECT_TRUE(runner.step(host, t0 + std::chrono::milliseconds(900)));
  try {
    runner.step(host, t0 + std::chrono::milliseconds(1100));
    FAIL() << "no timeout";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "script line 2 (wait pass1): did not complete within 1 s");
  }
}

TEST(ViewScript, HostFailuresNameTheLine) {
  class Failing : public ScriptHost {
    void start(const ScriptAction&) override { throw std::runtime_error("there is no light 7"); }
    bool finished(const ScriptAction&) override { return true; }
  } host;
  ScriptRunner runner(parseScript("\n\nlight 7 0 0 0\n", "s"));
  try {
    runner.step(host);
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "script line 3 (light 7 0 0 0): there is no light 7");
  }
}

} // namespace
} // namespace prism
