// `prism view` without a display: one line says so, then the same render
// `prism render` would make is written (to -o, or SCENE-STEM.tiff here), exit 0.
// Also `prism SCENE` with no command, which means `prism view SCENE`.
#include "test_pictures.h"

namespace prism::test {
namespace {

const char* kScene = R"(eye 0 1 5
lookat 0 0 0
resolution 48 32
light 2 3 4 30 30 30
surface 1 0.5 0.2 0.8 0.2 0 20 1
sphere 0 0 0 1
surface 0.3 0.6 0.9 1 0 0 1 1
polygon 4 -3 -1 -3  -3 -1 3  3 -1 3  3 -1 -3
)";

const std::string kPrism = std::string("'") + PRISM_BINARY + "'";
// No X11 and no Wayland display, whatever the test runner has.
const std::string kNoDisplay = "env -u DISPLAY -u WAYLAND_DISPLAY " + kPrism;

// Why there is no window: no display, or a build without the previewer.
#ifdef PRISM_HAVE_PREVIEWER
const std::string kWhy = "prism: no display (DISPLAY is not set)";
#else
const std::string kWhy = "prism: this prism was built without the previewer";
#endif

std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

class ViewFallback : public ::testing::Test {
protected:
  void SetUp() override {
    writeFile(dir_ / "ball.sc", kScene);
    const RunResult ref = run(dir_.path(), kPrism + " render ball.sc -o ref.tiff --depth 3 -q");
    ASSERT_EQ(ref.exitCode, 0) << ref.err;
    reference_ = readPicture(dir_ / "ref.tiff");
    ASSERT_TRUE(reference_);
  }
  ScratchDir dir_;
  std::optional<Picture> reference_;
};

TEST_F(ViewFallback, SaysSoInOneLineAndWritesSceneStemTiff) {
  const RunResult r = run(dir_.path(), kNoDisplay + " view ball.sc --depth 3");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(firstLine(r.err), kWhy + "; rendering headless to ball.tiff instead") << r.err;
  // Exactly one line about it; what follows is the render's own statistics.
  EXPECT_EQ(r.err.find("display", firstLine(r.err).size()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rays per pixel"), std::string::npos) << r.err;
  const auto written = readPicture(dir_ / "ball.tiff");
  ASSERT_TRUE(written);
  EXPECT_TRUE(sameRgb(*written, *reference_));
}

TEST_F(ViewFallback, HonoursOutputAndSettings) {
  const RunResult r = run(
      dir_.path(), kNoDisplay + " view ball.sc -o out.png --depth 3 --size 24 16 --thresh 0.3 -q");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, kWhy + "; rendering headless to out.png instead\n");
  const RunResult ref = run(
      dir_.path(), kPrism + " render ball.sc -o ref2.png --depth 3 --size 24 16 --thresh 0.3 -q");
  ASSERT_EQ(ref.exitCode, 0) << ref.err;
  const auto a = readPicture(dir_ / "out.png"), b = readPicture(dir_ / "ref2.png");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->width, 24);
  EXPECT_TRUE(sameRgb(*a, *b));
}

TEST_F(ViewFallback, PlainSceneArgumentMeansView) {
  const RunResult r = run(dir_.path(), kNoDisplay + " ball.sc --depth 3");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(firstLine(r.err).find("rendering headless to ball.tiff instead"), std::string::npos)
      << r.err;
  const auto written = readPicture(dir_ / "ball.tiff");
  ASSERT_TRUE(written);
  EXPECT_TRUE(sameRgb(*written, *reference_));
}

TEST_F(ViewFallback, UnreachableDisplayAlsoFallsBack) {
  // DISPLAY names a server that does not exist: GLFW cannot start.
  const RunResult r = run(dir_.path(), "env -u WAYLAND_DISPLAY DISPLAY=:987 " + kPrism +
                                           " view ball.sc --depth 3 -q");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  EXPECT_NE(r.err.find("rendering headless to ball.tiff instead"), std::string::npos) << r.err;
  const auto written = readPicture(dir_ / "ball.tiff");
  ASSERT_TRUE(written);
  EXPECT_TRUE(sameRgb(*written, *reference_));
}

TEST_F(ViewFallback, SceneErrorsAreUsageErrors) {
  writeFile(dir_ / "bad.sc", "sphere 0 0 oops 1\n");
  const RunResult r = run(dir_.path(), kNoDisplay + " view bad.sc");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("bad.sc:1:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad.tiff"));
}

TEST_F(ViewFallback, CommandLineStillWorks) {
  const RunResult help = run(dir_.path(), kPrism + " --help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("view"), std::string::npos);
  EXPECT_NE(help.out.find("render"), std::string::npos);
  const RunResult viewHelp = run(dir_.path(), kPrism + " view --help");
  EXPECT_EQ(viewHelp.exitCode, 0);
  EXPECT_NE(viewHelp.out.find("--script"), std::string::npos);
  EXPECT_EQ(run(dir_.path(), kPrism + " --version").exitCode, 0);
  EXPECT_EQ(run(dir_.path(), kPrism).exitCode, 2);                // no command
  EXPECT_EQ(run(dir_.path(), kPrism + " nosuch.sc").exitCode, 2); // not a file, not a command
  EXPECT_EQ(run(dir_.path(), kNoDisplay + " view ball.sc --depth 0").exitCode, 2);
}

} // namespace
} // namespace prism::test
