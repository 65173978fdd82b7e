// The prism program as users run it: exit codes (docs/command-line.md), located scene errors,
// no partial output file, the written image and statistics.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/progress.h"
#include "core/render/exposure.h"
#include "test_files.h"
#include "test_pictures.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace {

namespace fs = std::filesystem;
using prism::test::leakCheckerCrashed;
using prism::test::quoted;
using prism::test::runCaptured;
using prism::test::RunResult;
using prism::test::ScratchDir;
using prism::test::slurp;
using prism::test::writeFile;

class Cli : public prism::test::ProgramTest {
protected:
  std::string scene(const std::string& name) {
    return std::string(PRISM_SOURCE_DIR) + "/scenes/" + name;
  }
};

const char* kSmallScene = R"(eye 0 0 4
lookat 0 0 0
light 2 3 4 30 30 30
surface 1 0.5 0.2 0.8 0.2 0 20 1
sphere 0 0 0 1
)";

TEST_F(Cli, HelpAndVersionSucceed) {
  const RunResult help = prism("--help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("render"), std::string::npos);
  const RunResult renderHelp = prism("render --help");
  EXPECT_EQ(renderHelp.exitCode, 0);
  EXPECT_NE(renderHelp.out.find("--thresh"), std::string::npos);
  EXPECT_NE(renderHelp.out.find("--no-aa"), std::string::npos);
  EXPECT_NE(renderHelp.out.find("--bailout"), std::string::npos);
  const RunResult version = prism("--version");
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_NE(version.out.find("prism "), std::string::npos);
}

TEST_F(Cli, UsageErrorsExitWith2) {
  const std::string s = write("s.sc", kSmallScene).string();
  const std::string out = (dir_ / "o.tiff").string();
  EXPECT_EQ(prism("").exitCode, 2);
  EXPECT_EQ(prism("render " + s).exitCode, 2); // no -o
  EXPECT_EQ(prism("render " + s + " -o " + out + " --depth 0").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --thresh 1.5").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --thresh -0.1").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --thresh nan").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --bailout nan").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --scale nan").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --fov nan").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --eye nan 0 0").exitCode, 2);
  EXPECT_EQ(prism("bench " + s + " --budget nan").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --size 0 10").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --accel fast").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --bailout -0.5").exitCode, 2);
  EXPECT_EQ(prism("render " + s + " -o " + out + " --bailout 256").exitCode, 2);
  EXPECT_EQ(prism("render " + (dir_ / "missing.sc").string() + " -o " + out).exitCode, 2);
  EXPECT_EQ(prism("render " + s + " --pixel 600 0").exitCode, 2); // default size 512
  EXPECT_FALSE(fs::exists(out));
}

// --config: a [render] section of settings, which the command line overrides.
TEST_F(Cli, ASettingsFileGivesTheRendersSettingsAndTheCommandLineWins) {
  const std::string small = quoted(write("small.sc", kSmallScene));
  const std::string toml =
      quoted(write("render.toml", "# kept with the picture\n[render]\ndepth = 2\nsize = [24, 16]\n"
                                  "no-aa = true\nthresh = 0.25\n"));
  auto in = [&](const std::string& name) { return quoted(dir_ / name); };
  const RunResult fromFile = prism("render " + small + " -o " + in("a.tif") + " --config " + toml +
                                   " --stats-json " + in("a.json") + " -q");
  ASSERT_EQ(fromFile.exitCode, 0) << fromFile.err;
  const auto stats = nlohmann::json::parse(slurp(dir_ / "a.json"));
  EXPECT_EQ(stats["width"], 24);
  EXPECT_EQ(stats["height"], 16);
  EXPECT_EQ(stats["max_depth"], 2);
  EXPECT_EQ(stats["no_aa"], true);
  EXPECT_DOUBLE_EQ(stats["thresh"].get<double>(), 0.25);

  const RunResult overridden = prism("render " + small + " -o " + in("b.tif") + " --config " +
                                     toml + " --depth 4 --stats-json " + in("b.json") + " -q");
  ASSERT_EQ(overridden.exitCode, 0) << overridden.err;
  const auto stats2 = nlohmann::json::parse(slurp(dir_ / "b.json"));
  EXPECT_EQ(stats2["max_depth"], 4);
  EXPECT_EQ(stats2["width"], 24);
}

TEST_F(Cli, MistakesInASettingsFileAreLocatedAndNothingIsWritten) {
  const std::string run = "render " + quoted(write("small.sc", kSmallScene)) + " -o " +
                          quoted(dir_ / "out.tif") + " --config ";
  write("bad.toml", "depth = 2\n[render]\n  bogus = 1\n[paint]\nx = 1\n");
  const RunResult bad = prism(run + quoted(dir_ / "bad.toml"));
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(
      bad.err.find((dir_ / "bad.toml").string() + ":1:1: error: `depth` is outside a section"),
      std::string::npos)
      << bad.err;
  EXPECT_NE(bad.err.find((dir_ / "bad.toml").string() +
                         ":3:3: error: prism render has no option --bogus"),
            std::string::npos)
      << bad.err;
  EXPECT_NE(
      bad.err.find((dir_ / "bad.toml").string() + ":5:1: error: [paint] is not a command of prism"),
      std::string::npos)
      << bad.err;

  write("value.toml", "[render]\nsize = [24, 16]\nthresh = 2\n");
  const RunResult value = prism(run + quoted(dir_ / "value.toml"));
  EXPECT_EQ(value.exitCode, 2);
  EXPECT_EQ(value.err.rfind((dir_ / "value.toml").string() + ":3:1: error: --thresh", 0), 0u)
      << value.err;
  // The same value on the command line is the command line's mistake.
  const RunResult line = prism(run + quoted(dir_ / "value.toml") + " --thresh 3");
  EXPECT_EQ(line.exitCode, 2);
  EXPECT_EQ(line.err.find("value.toml:"), std::string::npos) << line.err;

  const RunResult missing = prism(run + quoted(dir_ / "none.toml"));
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(
      missing.err.find((dir_ / "none.toml").string() + ": error: cannot read the settings file"),
      std::string::npos)
      << missing.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.tif"));
}

TEST_F(Cli, SceneErrorsAreLocatedAndLeaveNoOutput) {
  const fs::path bad = write("bad.sc", "eye 0 0 4\nsphere 0 0 0 -1\nlight 1 2\n");
  const fs::path out = dir_ / "bad.tiff";
  const RunResult run = prism("render " + bad.string() + " -o " + out.string());
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find(bad.string() + ":2:14: error:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(bad.string() + ":3:"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
  // Nothing else was left in the directory either (no temporary file).
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_TRUE(entry.path().extension() != ".tiff") << entry.path();
}

TEST_F(Cli, UnwritableOutputExitsWith1BeforeRendering) {
  const std::string s = write("s.sc", kSmallScene).string();
  const RunResult run = prism("render " + s + " -o " + (dir_ / "no/such/dir/x.tiff").string());
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.err.find("no such directory"), std::string::npos) << run.err;
  const RunResult format = prism("render " + s + " -o " + (dir_ / "x.unknownformat").string());
  EXPECT_EQ(format.exitCode, 1);
  EXPECT_FALSE(fs::exists(dir_ / "x.unknownformat"));
}

// Every output is checked before any work: an unwritable statistics file was
// found only after rendering, when the picture had already been written.
TEST_F(Cli, EveryOutputIsCheckedBeforeAnyWork) {
  const std::string s = write("s.sc", kSmallScene).string();
  const fs::path out = dir_ / "o.tiff";
  const RunResult json = prism("render " + s + " -o " + out.string() + " --stats-json " +
                               (dir_ / "no/s.json").string());
  EXPECT_EQ(json.exitCode, 1);
  EXPECT_NE(
      json.err.find("cannot write '" + (dir_ / "no/s.json").string() + "': no such directory"),
      std::string::npos)
      << json.err;
  EXPECT_EQ(json.err.find("render CPU"), std::string::npos) << "rendered before failing";
  EXPECT_FALSE(fs::exists(out));
  // A directory where the file should go.
  fs::create_directory(dir_ / "taken.json");
  const RunResult taken = prism("render " + s + " -o " + out.string() + " --stats-json " +
                                (dir_ / "taken.json").string());
  EXPECT_EQ(taken.exitCode, 1);
  EXPECT_NE(taken.err.find("it is a directory"), std::string::npos) << taken.err;
  EXPECT_FALSE(fs::exists(out));
  // convert checks its output before reading the input (here a broken one).
  const fs::path bad = write("bad.sc", "sphere 0 0 0 -1\n");
  const RunResult convert = prism("convert " + bad.string() + " " + (dir_ / "no/out.sc").string());
  EXPECT_EQ(convert.exitCode, 1);
  EXPECT_EQ(convert.err.find("bad.sc:1"), std::string::npos) << convert.err;
}

// A render too large for the memory that can be had is refused up front with
// exit 1 (it died of an uncaught std::bad_alloc, exit 134, or asked for 27 GB).
TEST_F(Cli, ARenderTooLargeForMemoryIsRefusedBeforeStarting) {
  const std::string s = write("s.sc", kSmallScene).string();
  const fs::path out = dir_ / "big.tiff";
  const RunResult run = runCaptured("PRISM_MEMORY_LIMIT=1G " + quoted(PRISM_BINARY) + " render " +
                                        s + " --size 32768 32768 -o " + out.string(),
                                    dir_);
  EXPECT_EQ(run.exitCode, 1);
  // 32768^2 pixels of 28 bytes each: 28 GiB.
  EXPECT_NE(run.err.find("prism: error: a 32768 x 32768 render needs about 28.0 GiB of memory, but "
                         "only 1.0 GiB is available (limited by PRISM_MEMORY_LIMIT)"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(out));
  // The same limit lets a small render through.
  EXPECT_EQ(runCaptured("PRISM_MEMORY_LIMIT=1G " + quoted(PRISM_BINARY) + " render " + s +
                            " --size 64 64 -q -o " + out.string(),
                        dir_)
                .exitCode,
            0);
  EXPECT_TRUE(fs::exists(out));
}

TEST_F(Cli, WritesAn8BitRgbTiffAndJsonStatistics) {
  const std::string s = write("s.sc", kSmallScene).string();
  const fs::path out = dir_ / "o.tiff", json = dir_ / "stats.json";
  const RunResult run =
      prism("render " + s + " -o " + out.string() + " --size 40 30 --depth 3 --thresh 0.2 " +
            "--stats-json " + json.string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.err.find("rays per pixel"), std::string::npos);
  EXPECT_NE(run.err.find("machine"), std::string::npos);

  auto in = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, 40);
  EXPECT_EQ(spec.height, 30);
  EXPECT_EQ(spec.nchannels, 3);
  EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT8);
  EXPECT_EQ(std::string(in->format_name()), "tiff");
  std::vector<unsigned char> pixels(40 * 30 * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data()));
  const auto stats = nlohmann::json::parse(slurp(json));
  // The same render as float radiance, exposed by hand (docs/image-formation.md, exposure):
  // min(255, round(radiance * 128 / avgmax)) must give the bytes of the TIFF.
  const fs::path exr = dir_ / "o.exr";
  ASSERT_EQ(prism("render " + s + " -o " + exr.string() + " --size 40 30 --depth 3 --thresh 0.2 -q")
                .exitCode,
            0);
  auto raw = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(raw);
  std::vector<float> radiance(40 * 30 * 3);
  ASSERT_TRUE(raw->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, radiance.data()));
  const double scale = 128.0 / stats["avgmax"].get<double>();
  std::size_t exact = 0, clipped = 0;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const double expected = std::min(255.0, std::round(double(radiance[i]) * scale));
    EXPECT_NEAR(double(pixels[i]), expected, 1.0) << "channel " << i;
    exact += double(pixels[i]) == expected;
    clipped += pixels[i] == 255;
  }
  EXPECT_GE(double(exact), 0.99 * double(pixels.size()));
  EXPECT_GT(clipped, 0u); // the lit sphere on black is brighter than avgmax: it pegs
  EXPECT_EQ(stats["width"], 40);
  EXPECT_EQ(stats["pixels"], 1200);
  EXPECT_EQ(stats["max_depth"], 3);
  EXPECT_DOUBLE_EQ(stats["thresh"].get<double>(), 0.2);
  EXPECT_EQ(stats["rays"]["eye_pass1"], 1200);
  EXPECT_GT(stats["cpu_seconds"].get<double>(), 0.0);
}

// The knobs reach the render and its statistics: --no-aa traces one eye ray
// per pixel (a sphere's edge is there to antialias), --bailout is reported
// with the rays it skipped and its pilot's (an eye ray per pixel, and a
// shadow ray where the sphere's lit side shows). At depth 6 a ray could be
// skipped (0.2^4 of the bound fits in half a level), so the pilot is traced.
TEST_F(Cli, TheKnobsAreInTheStatistics) {
  const std::string s = write("s.sc", kSmallScene).string();
  const fs::path out = dir_ / "o.tiff", json = dir_ / "stats.json";
  const RunResult run =
      prism("render " + s + " -o " + out.string() +
            " --size 40 30 --depth 6 --no-aa --bailout 0.5 --stats-json " + json.string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.err.find("(no antialiasing)"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("bailout             0.5 levels"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("rays skipped"), std::string::npos) << run.err;
  const auto stats = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(stats["no_aa"], true);
  EXPECT_DOUBLE_EQ(stats["bailout"].get<double>(), 0.5);
  EXPECT_EQ(stats["rays"]["eye_pass1"], 1200);
  EXPECT_EQ(stats["rays"]["eye_antialias"], 0);
  EXPECT_EQ(stats["supersampled_pixels"], 0);
  EXPECT_GT(stats["rays"]["bailout_pilot"].get<int>(), 1200);
  EXPECT_TRUE(stats["bailout_skipped"].contains("reflected"));
  const auto exact = prism("render " + s + " -o " + out.string() +
                           " --size 40 30 --depth 3 --stats-json " + json.string());
  ASSERT_EQ(exact.exitCode, 0) << exact.err;
  EXPECT_NE(exact.err.find("bailout             0 levels (exact)"), std::string::npos);
  EXPECT_EQ(exact.err.find("rays skipped"), std::string::npos);
  const auto exactStats = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(exactStats["no_aa"], false);
  EXPECT_EQ(exactStats["rays"]["bailout_pilot"], 0);
  EXPECT_GT(exactStats["supersampled_pixels"].get<int>(), 0);
}

TEST_F(Cli, ExrKeepsFloatRadiance) {
  const std::string s = write("s.sc", kSmallScene).string();
  const fs::path out = dir_ / "o.exr";
  ASSERT_EQ(prism("render " + s + " -o " + out.string() + " --size 16 16 -q").exitCode, 0);
  auto in = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(in);
  EXPECT_TRUE(in->spec().format == OIIO::TypeDesc::FLOAT ||
              in->spec().format == OIIO::TypeDesc::HALF);
}

TEST_F(Cli, FloatFlagWritesRadianceTiff) {
  const std::string s = write("s.sc", kSmallScene).string();
  const fs::path out = dir_ / "radiance.tif";
  ASSERT_EQ(prism("render " + s + " -o " + out.string() + " --size 16 16 --float -q").exitCode, 0);
  auto in = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT);
  std::vector<float> radiance(16 * 16 * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, radiance.data()));
  // Radiance is not clamped: the lit sphere is brighter than 1 somewhere.
  EXPECT_GT(*std::max_element(radiance.begin(), radiance.end()), 1.0f);
}

TEST_F(Cli, PixelPrintsTheRayTree) {
  const std::string s = write("s.sc", kSmallScene).string();
  const RunResult run = prism("render " + s + " --size 21 21 --pixel 10 10");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("eye ray, depth 1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("hits sphere #0 (s.sc:5)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("entering"), std::string::npos);
  EXPECT_NE(run.out.find("light 1:"), std::string::npos);
  EXPECT_NE(run.out.find("reflected ray, depth 2"), std::string::npos) << run.out;
}

// A ray that hits a CSG node is reported with the operand whose surface it
// met: the centre ray enters the box's face at z = 1 inside the subtracted
// sphere, so the surface it hits is the sphere's, at z = 0.5.
TEST_F(Cli, PixelNamesTheCsgOperandHit) {
  const std::string s = write("c.sc", "eye 0 0 4\nlookat 0 0 0\nlight 2 3 4 30 30 30\n"
                                      "csg difference\n"
                                      "  box -1 -1 -1 1 1 1\n"
                                      "  sphere 0 0 1 0.5\n"
                                      "end\n")
                            .string();
  const RunResult run = prism("render " + s + " --size 21 21 --pixel 10 10");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("hits csg #0 (c.sc:4), operand sphere (c.sc:6) at t = 3.5,"),
            std::string::npos)
      << run.out;
}

TEST_F(Cli, RendersEveryShippedScene) {
  for (const char* name :
       {"table.sc", "glass.sc", "chex.sc", "tree.sc", "tree-solid.sc", "solids.sc", "torus.sc",
        "quadrics.sc", "csg.sc", "blobs.sc", "fog.sc", "textures.sc"}) {
    const fs::path out = dir_ / (std::string(name) + ".png");
    const RunResult run =
        prism("render " + scene(name) + " -o " + out.string() + " --size 32 32 -q");
    EXPECT_EQ(run.exitCode, 0) << name << ": " << run.err;
    EXPECT_TRUE(fs::exists(out)) << name;
  }
}

TEST_F(Cli, BenchPrintsItsTablesAndScalingData) {
  const std::string s = write("s.sc", kSmallScene).string();
  const fs::path data = dir_ / "scaling.dat";
  const RunResult run = prism("bench " + s + " --size 16 --accel bvh,none --budget 0.05 " +
                              "--scaling-max 1000 --data " + data.string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("| eye | eye 1-by-1 | shadow |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| s.sc | 1 | bvh |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| s.sc | 1 | none |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| soup | 1000 | bvh |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| scaled-soup | 1000 | bvh |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| sphereflake | 1001 | none |"), std::string::npos) << run.out;
  const std::string table = slurp(data);
  EXPECT_NE(table.find("soup 1000 bvh "), std::string::npos) << table;
  EXPECT_EQ(prism("bench --accel fast").exitCode, 2);
}

// --eye, --lookat and --fov replace the scene's camera lines: the picture is
// the one of the file with those lines written in, byte for byte, for
// `render` and for `view`'s headless fallback.
TEST_F(Cli, CameraOverridesRenderAsTheSceneWithThoseCameraLines) {
  const std::string body = "light 2 3 4 30 30 30\nsurface 1 0.5 0.2 0.8 0.2 0 20 1\n"
                           "sphere 0 0 0 1\nsurface 0.3 0.6 0.9 1 0 0 1 1\n"
                           "polygon 4 -3 -1 -3  -3 -1 3  3 -1 3  3 -1 -3\n";
  const std::string s = write("s.sc", "eye 0 0 4\nlookat 0 0 0\n" + body).string();
  const std::string written =
      write("w.sc", "eye 1.5 2 5\nlookat 0 -0.25 0\nfov 30\n" + body).string();
  const std::string common = " --size 36 24 --depth 3 -q -o ";
  const std::string camera = " --eye 1.5 2 5 --lookat 0 -0.25 0 --fov 30";
  ASSERT_EQ(prism("render " + written + common + (dir_ / "want.png").string()).exitCode, 0);
  const RunResult run = prism("render " + s + camera + common + (dir_ / "got.png").string());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string want = slurp(dir_ / "want.png");
  EXPECT_EQ(slurp(dir_ / "got.png"), want);
  // The file's own camera gives another picture: the options were applied.
  ASSERT_EQ(prism("render " + s + common + (dir_ / "file.png").string()).exitCode, 0);
  EXPECT_NE(slurp(dir_ / "file.png"), want);

  // prism view without a display renders headless, with the same camera.
  const RunResult view =
      runCaptured("env -u DISPLAY -u WAYLAND_DISPLAY " + quoted(PRISM_BINARY) + " view " + s +
                      camera + common + (dir_ / "view.png").string(),
                  dir_);
  ASSERT_EQ(view.exitCode, 0) << view.err;
  EXPECT_EQ(slurp(dir_ / "view.png"), want);

  // One option alone changes only its own line; the others stay the file's.
  write("fov.sc", "eye 0 0 4\nlookat 0 0 0\nfov 20\n" + body);
  ASSERT_EQ(prism("render " + (dir_ / "fov.sc").string() + common + (dir_ / "want20.png").string())
                .exitCode,
            0);
  ASSERT_EQ(prism("render " + s + " --fov 20" + common + (dir_ / "got20.png").string()).exitCode,
            0);
  EXPECT_EQ(slurp(dir_ / "got20.png"), slurp(dir_ / "want20.png"));
}

// Each camera option is checked as the scene language checks the camera; a
// bad one is a usage error (exit 2) with its reason, and nothing is written.
TEST_F(Cli, InvalidCameraOverridesExitWith2AndSayWhy) {
  // The scene: eye 0 0 4, lookat 0 0 0, up 0 1 0 (the default).
  const std::string s = write("s.sc", kSmallScene).string();
  const fs::path out = dir_ / "o.png";
  const struct {
    std::string options, message;
  } cases[] = {
      {"--fov 0", "--fov: DEGREES must be greater than 0 and less than 180, found 0"},
      {"--fov 180", "--fov: DEGREES must be greater than 0 and less than 180, found 180"},
      {"--fov -10", "--fov: DEGREES must be greater than 0 and less than 180, found -10"},
      {"--eye 2e30 0 0", "--eye 2e+30 0 0: the point must be within +-1e30"},
      {"--lookat 0 0 -1e31", "--lookat 0 0 -1e+31: the point must be within +-1e30"},
      {"--eye 0 0 0", "--eye: eye and lookat are the same point (0 0 0), so there is no view "
                      "direction"},
      {"--lookat 0 0 4", "--lookat: eye and lookat are the same point (0 0 4)"},
      {"--eye 1 2 3 --lookat 1 2 3", "--eye and --lookat: eye and lookat are the same point"},
      {"--lookat 0 1e-320 4", "--lookat: eye and lookat are too close together or too far apart "
                              "to give a view direction"},
      {"--eye 0 5 0", "--eye: the scene's up (0 1 0) is parallel to the view direction from eye "
                      "to lookat (eye 0 5 0, lookat 0 0 0)"},
      {"--eye 1 7 1 --lookat 1 -2 1", "--eye and --lookat: the scene's up (0 1 0) is parallel"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.options);
    const RunResult render = prism("render " + s + " " + c.options + " -q -o " + out.string());
    EXPECT_EQ(render.exitCode, 2);
    EXPECT_EQ(render.err.rfind("prism: error: " + c.message, 0), 0u) << render.err;
    EXPECT_FALSE(fs::exists(out));
    // `prism view` checks them the same way, before any window or fallback.
    const RunResult view = prism("view " + s + " " + c.options + " -q -o " + out.string());
    EXPECT_EQ(view.exitCode, 2);
    EXPECT_NE(view.err.find("prism: error: " + c.message), std::string::npos) << view.err;
    EXPECT_FALSE(fs::exists(out));
  }
  // CLI11 itself insists on three numbers.
  EXPECT_EQ(prism("render " + s + " --eye 1 2 -q -o " + out.string()).exitCode, 2);
}

// The sRGB transfer function (IEC 61966-2-1), written out here rather than
// taken from the renderer.
double srgbEncode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// Whether a PNG file holds a chunk of type `type` (its length, then its type).
bool hasPngChunk(const std::string& bytes, const std::string& type) {
  return bytes.find(type) != std::string::npos &&
         bytes.find(std::string("\0\0\0\x01", 4) + type) != std::string::npos;
}

TEST(Exposure, SrgbEncodesTheExposedFraction) {
  EXPECT_EQ(prism::exposeChannelSrgb(0.0f, 1.0f), 0);
  EXPECT_EQ(prism::exposeChannelSrgb(-1.0f, 1.0f), 0);
  EXPECT_EQ(prism::exposeChannelSrgb(NAN, 1.0f), 0);
  EXPECT_EQ(prism::exposeChannelSrgb(255.0f, 1.0f), 255);
  EXPECT_EQ(prism::exposeChannelSrgb(1000.0f, 1.0f), 255);
  // Linear 128 of 255 is about 0.502: sRGB 0.7354..., 187.5 -> 188.
  EXPECT_EQ(prism::exposeChannelSrgb(64.0f, 2.0f), std::lround(255.0 * srgbEncode(128.0 / 255.0)));
  // The linear segment near black: 0.5 of 255 -> 12.92 * 0.5 = 6.46 -> 6.
  EXPECT_EQ(prism::exposeChannelSrgb(0.5f, 1.0f), 6);
}

// --srgb: the exposed value, as a fraction of 255 clamped to 1, through the
// sRGB transfer function; the PNG carries an sRGB chunk, the TIFF says so in
// its ImageDescription. Checked against the float radiance of the same render.
TEST_F(Cli, SrgbEncodesTheExposedPictureAndSaysSo) {
  const std::string s = write("s.sc", kSmallScene).string();
  const std::string common = " --size 40 30 --depth 3 --thresh 0.2 -q";
  const fs::path png = dir_ / "srgb.png", tiff = dir_ / "srgb.tiff", exr = dir_ / "o.exr";
  const fs::path json = dir_ / "stats.json";
  ASSERT_EQ(prism("render " + s + common + " --srgb -o " + png.string() + " --stats-json " +
                  json.string())
                .exitCode,
            0);
  ASSERT_EQ(prism("render " + s + common + " --srgb -o " + tiff.string()).exitCode, 0);
  ASSERT_EQ(prism("render " + s + common + " -o " + exr.string()).exitCode, 0);
  const std::optional<prism::test::Picture> picture = prism::test::readPicture(png);
  ASSERT_TRUE(picture);
  ASSERT_EQ(picture->width, 40);
  ASSERT_EQ(picture->channels, 3);
  auto raw = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(raw);
  std::vector<float> radiance(40 * 30 * 3);
  ASSERT_TRUE(raw->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, radiance.data()));
  const double avgmax = nlohmann::json::parse(slurp(json))["avgmax"].get<double>();
  std::size_t exact = 0, middle = 0;
  for (std::size_t i = 0; i < radiance.size(); ++i) {
    const double e = std::clamp(double(radiance[i]) * 128.0 / avgmax / 255.0, 0.0, 1.0);
    const double expected = std::round(255.0 * srgbEncode(e));
    EXPECT_NEAR(double(picture->pixels[i]), expected, 1.0) << "channel " << i;
    exact += double(picture->pixels[i]) == expected;
    middle += expected > 20 && expected < 235;
  }
  EXPECT_GE(double(exact), 0.99 * double(radiance.size()));
  EXPECT_GT(middle, 100u); // the test sees the curve, not only black and white
  // The tags.
  auto in = OIIO::ImageInput::open(png.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().get_string_attribute("oiio:ColorSpace"), "sRGB");
  EXPECT_TRUE(hasPngChunk(slurp(png), "sRGB"));
  EXPECT_NE(in->spec().get_string_attribute("ImageDescription").find("sRGB-encoded"),
            std::string::npos);
  const std::optional<prism::test::Picture> fromTiff = prism::test::readPicture(tiff);
  ASSERT_TRUE(fromTiff);
  EXPECT_TRUE(prism::test::sameRgb(*fromTiff, *picture));
  auto tiffIn = OIIO::ImageInput::open(tiff.string());
  ASSERT_TRUE(tiffIn);
  EXPECT_NE(tiffIn->spec().get_string_attribute("ImageDescription").find("sRGB-encoded"),
            std::string::npos)
      << tiffIn->spec().get_string_attribute("ImageDescription");
  // The default stays the model's linear values, with no sRGB chunk.
  const fs::path linear = dir_ / "linear.png";
  ASSERT_EQ(prism("render " + s + common + " -o " + linear.string()).exitCode, 0);
  EXPECT_FALSE(hasPngChunk(slurp(linear), "sRGB"));
  const std::optional<prism::test::Picture> plain = prism::test::readPicture(linear);
  ASSERT_TRUE(plain);
  EXPECT_FALSE(prism::test::sameRgb(*plain, *picture));
  // Float pictures are not exposed: --srgb with them is a usage error.
  EXPECT_EQ(prism("render " + s + common + " --srgb -o " + exr.string()).exitCode, 2);
  EXPECT_EQ(
      prism("render " + s + common + " --srgb --float -o " + (dir_ / "f.tif").string()).exitCode,
      2);
  EXPECT_FALSE(fs::exists(dir_ / "f.tif"));
}

// `-o -` writes the picture's bytes to stdout (the format from --format),
// `--stats-json -` the statistics, `prism render -` reads the scene from stdin.
TEST_F(Cli, DashIsStandardInputOrOutput) {
  const std::string s = write("s.sc", kSmallScene).string();
  const std::string common = " --size 24 16 --depth 3 -q";
  const fs::path file = dir_ / "file.png";
  ASSERT_EQ(prism("render " + s + common + " -o " + file.string()).exitCode, 0);
  const RunResult piped = prism("render " + s + common + " -o - --format png");
  ASSERT_EQ(piped.exitCode, 0) << piped.err;
  EXPECT_EQ(piped.out, slurp(file)); // PNG bytes carry no time stamp
  writeFile(dir_ / "piped.png", piped.out);
  const std::optional<prism::test::Picture> read = prism::test::readPicture(dir_ / "piped.png");
  ASSERT_TRUE(read);
  EXPECT_EQ(read->width, 24);
  // Another format, through a pipe as well; OpenImageIO reads what came out.
  const RunResult tiff = runCaptured(
      quoted(PRISM_BINARY) + " render " + s + common + " -o - --format TIFF | cat", dir_);
  ASSERT_EQ(tiff.exitCode, 0) << tiff.err;
  writeFile(dir_ / "piped.tif", tiff.out);
  const std::optional<prism::test::Picture> readTiff = prism::test::readPicture(dir_ / "piped.tif");
  ASSERT_TRUE(readTiff);
  EXPECT_TRUE(prism::test::sameRgb(*readTiff, *read));
  const RunResult exr = prism("render " + s + common + " -o - --format .exr");
  ASSERT_EQ(exr.exitCode, 0) << exr.err;
  writeFile(dir_ / "piped.exr", exr.out);
  auto exrIn = OIIO::ImageInput::open((dir_ / "piped.exr").string());
  ASSERT_TRUE(exrIn);
  EXPECT_EQ(exrIn->spec().width, 24);
  // No temporary is left behind in the temporary directory.
  for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
    EXPECT_EQ(entry.path().filename().string().find(".prism-"), std::string::npos) << entry.path();

  // The statistics on stdout; the progress and statistics text stay on stderr.
  const RunResult stats = prism("render " + s + " --size 24 16 --depth 3 -o " +
                                (dir_ / "o.png").string() + " --stats-json -");
  ASSERT_EQ(stats.exitCode, 0) << stats.err;
  const auto parsed = nlohmann::json::parse(stats.out);
  EXPECT_EQ(parsed["width"], 24);
  EXPECT_EQ(parsed["pixels"], 24 * 16);
  EXPECT_NE(stats.err.find("rays per pixel"), std::string::npos);

  // The usage errors.
  EXPECT_EQ(prism("render " + s + common + " -o - --stats-json -").exitCode, 2);
  EXPECT_EQ(prism("render " + s + common + " -o -").exitCode, 2);
  EXPECT_EQ(prism("render " + s + common + " -o " + (dir_ / "x.png").string() + " --format tiff")
                .exitCode,
            2);
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
  const RunResult unknown = prism("render " + s + common + " -o - --format nosuchformat");
  EXPECT_EQ(unknown.exitCode, 1);
  EXPECT_NE(unknown.err.find("--format nosuchformat: no image format"), std::string::npos)
      << unknown.err;
  EXPECT_TRUE(unknown.out.empty());

  // The scene from stdin, its include resolved against the working directory.
  write("parts/ball.sc", "sphere 0 0 0 1\n");
  write("main.sc", "eye 0 0 4\nlookat 0 0 0\nlight 2 3 4 30 30 30\n"
                   "surface 1 0.5 0.2 0.8 0.2 0 20 1\ninclude parts/ball.sc\n");
  ASSERT_EQ(prism("render " + (dir_ / "main.sc").string() + common + " -o " +
                  (dir_ / "want.png").string())
                .exitCode,
            0);
  const RunResult fromStdin =
      prism::test::run(dir_, quoted(PRISM_BINARY) + " render -" + common + " -o got.png < main.sc");
  ASSERT_EQ(fromStdin.exitCode, 0) << fromStdin.err;
  EXPECT_EQ(slurp(dir_ / "got.png"), slurp(dir_ / "want.png"));
  EXPECT_EQ(slurp(dir_ / "want.png"), slurp(file)); // the include is the same sphere
  // Both ends at once: a scene piped in, the picture piped out.
  const RunResult through = prism::test::run(dir_, "cat main.sc | " + quoted(PRISM_BINARY) +
                                                       " render -" + common + " -o - --format png");
  ASSERT_EQ(through.exitCode, 0) << through.err;
  EXPECT_EQ(through.out, slurp(file));
  // A scene error on stdin is located in <stdin>.
  write("bad.sc", "eye 0 0 4\nsphere 0 0 0 -1\n");
  const RunResult bad =
      prism::test::run(dir_, quoted(PRISM_BINARY) + " render -" + common + " -o bad.png < bad.sc");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("<stdin>:2:"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad.png"));
}

// --scale renders at a share of the scene's resolution, each side rounded
// (half away from zero), at least one pixel.
TEST_F(Cli, ScaleShrinksTheScenesResolution) {
  const std::string s = write("r.sc", std::string("resolution 41 30\n") + kSmallScene).string();
  const fs::path out = dir_ / "o.png";
  const struct {
    std::string percent;
    int width, height;
  } cases[] = {{"50", 21, 15}, {"100", 41, 30}, {"10", 4, 3}, {"1", 1, 1}, {"0.5", 1, 1}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.percent);
    const RunResult r = prism("render " + s + " --scale " + c.percent + " -q -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::optional<prism::test::Picture> picture = prism::test::readPicture(out);
    ASSERT_TRUE(picture);
    EXPECT_EQ(picture->width, c.width);
    EXPECT_EQ(picture->height, c.height);
  }
  for (const char* bad : {"--scale 0", "--scale -5", "--scale 101", "--scale 50 --size 10 10"})
    EXPECT_EQ(prism("render " + s + " " + bad + " -q -o " + (dir_ / "x.png").string()).exitCode, 2)
        << bad;
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

// --crop renders pass 2 only inside the region and writes only it, exposed
// by the whole frame's avgmax: the region of the full render, pixel for pixel.
TEST_F(Cli, CropIsTheRegionOfTheFullRender) {
  const std::string s = write("s.sc", kSmallScene).string();
  const std::string common = " --size 40 30 --depth 3 --thresh 0.05 -q";
  const fs::path full = dir_ / "full.png", part = dir_ / "part.png";
  const fs::path fullJson = dir_ / "full.json", partJson = dir_ / "part.json";
  ASSERT_EQ(
      prism("render " + s + common + " -o " + full.string() + " --stats-json " + fullJson.string())
          .exitCode,
      0);
  const RunResult r = prism("render " + s + common + " --crop 6 4 29 21 -o " + part.string() +
                            " --stats-json " + partJson.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::optional<prism::test::Picture> whole = prism::test::readPicture(full);
  const std::optional<prism::test::Picture> region = prism::test::readPicture(part);
  ASSERT_TRUE(whole && region);
  ASSERT_EQ(region->width, 23);
  ASSERT_EQ(region->height, 17);
  for (int y = 0; y < region->height; ++y)
    for (int x = 0; x < region->width; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(region->at(x, y)[c], whole->at(x + 6, y + 4)[c]) << x << ", " << y;
  // Pass 2 ran inside the region only: fewer pixels supersampled, but some
  // (the sphere's edge crosses the region), and the same avgmax.
  const auto fullStats = nlohmann::json::parse(slurp(fullJson));
  const auto partStats = nlohmann::json::parse(slurp(partJson));
  EXPECT_GT(partStats["supersampled_pixels"].get<int>(), 0);
  EXPECT_LT(partStats["supersampled_pixels"].get<int>(),
            fullStats["supersampled_pixels"].get<int>());
  EXPECT_EQ(partStats["avgmax"].get<double>(), fullStats["avgmax"].get<double>());
  // The whole frame as the region is the full render.
  ASSERT_EQ(prism("render " + s + common + " --crop 0 0 40 30 -o " + part.string()).exitCode, 0);
  EXPECT_EQ(slurp(part), slurp(full));
  // A region outside the image, or empty, is a usage error.
  for (const char* bad : {"--crop 0 0 41 30", "--crop 5 5 5 10", "--crop 10 5 4 8",
                          "--crop 0 0 10 31", "--crop 1 2 3"})
    EXPECT_EQ(
        prism("render " + s + common + " " + bad + " -o " + (dir_ / "x.png").string()).exitCode, 2)
        << bad;
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

// The progress line's time left: pass 1's from its own pace, and no guess
// at pass 2 until it runs; pass 2's from its own pace since pass 1 ended.
TEST(Progress, TheLineGivesTheTimeLeftAtThePaceSoFar) {
  using prism::progressLine;
  // Pass 2 began at 3 s; 26% of it (63% of the render) in 1.1 s more.
  EXPECT_EQ(progressLine({2, 0.63}, 4.1, 3.0, true),
            "rendering: pass 2,  63% done, 4.1 s, about 3.1 s left");
  // A tenth of pass 1 in 1.2 s: 10.8 s more for pass 1, pass 2 unknown.
  EXPECT_EQ(progressLine({1, 0.05}, 1.2, 0.0, true),
            "rendering: pass 1,   5% done, 1.2 s, about 10.8 s left in pass 1, then pass 2");
  // --no-aa: pass 1 is the whole render, and its share the share shown.
  EXPECT_EQ(progressLine({1, 0.25}, 30.0, 0.0, false),
            "rendering: pass 1,  50% done, 30.0 s, about 30.0 s left");
  EXPECT_EQ(progressLine({1, 0.125}, 20.0, 0.0, false),
            "rendering: pass 1,  25% done, 20.0 s, about 1 min 00 s left");
  // Nothing done yet, or a pass complete: no estimate.
  EXPECT_EQ(progressLine({1, 0.0}, 1.2, 0.0, true), "rendering: pass 1,   0% done, 1.2 s");
  EXPECT_EQ(progressLine({1, 0.5}, 2.0, 0.0, true), "rendering: pass 1,  50% done, 2.0 s");
  EXPECT_EQ(progressLine({2, 1.0}, 9.0, 2.0, true), "rendering: pass 2, 100% done, 9.0 s");
  EXPECT_EQ(prism::durationText(59.94), "59.9 s");
  EXPECT_EQ(prism::durationText(59.96), "1 min 00 s");
  EXPECT_EQ(prism::durationText(125.4), "2 min 05 s");
  EXPECT_EQ(prism::durationText(3725.0), "1 h 02 min");
  EXPECT_EQ(prism::durationText(-1.0), "0.0 s");
}

TEST_F(Cli, TreeGeneratorReproducesTheCommittedTree) {
  fs::create_directories(dir_ / "parts");
  const std::string command = std::string("'") + PRISM_TREE_GEN + "' '" + dir_.string() + "'";
  ASSERT_EQ(std::system(command.c_str()), 0);
  for (const char* file : {"tree.sc", "forest.sc", "parts/tree_body.sc", "tree-solid.sc",
                           "parts/tree_solid_body.sc"}) {
    SCOPED_TRACE(file);
    const std::string generated = slurp(dir_ / file);
    EXPECT_FALSE(generated.empty());
    EXPECT_EQ(generated, slurp(scene(file)));
  }
}

// The one failure a child process is run again for: the leak checker's own
// crash, alone; never a leak or a sanitizer's error report.
TEST(ChildProcesses, OnlyTheLeakCheckersOwnCrashIsRunAgain) {
  const std::string crash = "Tracer caught signal 11: addr=0x17e8 pc=0x7f sp=0x7f\n"
                            "==944==LeakSanitizer has encountered a fatal error.\n";
  EXPECT_TRUE(leakCheckerCrashed({134, "", "frames while rendering: 1\n" + crash}));
  EXPECT_FALSE(
      leakCheckerCrashed({134, "", "==9==ERROR: LeakSanitizer: detected memory leaks\n" + crash}));
  EXPECT_FALSE(
      leakCheckerCrashed({1, "", "==9==ERROR: AddressSanitizer: heap-use-after-free\n" + crash}));
  EXPECT_FALSE(leakCheckerCrashed({134, "", "Tracer caught signal 11\n"}));
  EXPECT_FALSE(leakCheckerCrashed({2, "", "a.sc:1:1: error: unknown command\n"}));
}

} // namespace
