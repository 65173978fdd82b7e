// `prism info SCENE` and its alias `prism check`: counts, camera and bounds of
// scenes whose contents are known by construction or counted here from the
// text without Prism's reader; warnings; located errors and exit 2.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_files.h"

#include <filesystem>
#include <regex>
#include <set>
#include <string>

namespace {

namespace fs = std::filesystem;
using prism::test::quoted;
using prism::test::run;
using prism::test::runCaptured;
using prism::test::RunResult;
using prism::test::ScratchDir;
using prism::test::slurp;
using prism::test::writeFile;

class Info : public prism::test::ProgramTest {
protected:
  // `prism info --json FILE`, parsed; fails the test if it did not succeed.
  nlohmann::json infoJson(const fs::path& scene) {
    const RunResult r = prism("info --json " + quoted(scene));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(r.out);
  }
};

// 3 spheres, 2 polygons, 1 light, 2 materials; every extreme of the bounds is
// a sphere's centre +- radius or a polygon's vertex.
const char* kKnownScene = R"(resolution 320 240
eye 0 1 10
lookat 0 0 0
up 0 1 0
fov 50
light 5 5 5  1 1 1
surface 1 0 0  0.8 0.2 0  20 1
sphere 0 0 0 1
sphere 3 0 0 0.5
surface 0 1 0  0.8 0 0  1 1
sphere -2 1 0 2
polygon 4  -5 -1 -5  5 -1 -5  5 -1 5  -5 -1 5
polygon 3  0 5 -3  1 5 -3  0 6 -3
)";

void expectPoint(const nlohmann::json& p, double x, double y, double z) {
  ASSERT_EQ(p.size(), 3u) << p;
  EXPECT_NEAR(p[0].get<double>(), x, 1e-12) << p;
  EXPECT_NEAR(p[1].get<double>(), y, 1e-12) << p;
  EXPECT_NEAR(p[2].get<double>(), z, 1e-12) << p;
}

TEST_F(Info, CountsCameraAndBoundsOfASceneKnownByConstruction) {
  const fs::path scene = write("known.sc", kKnownScene);
  const nlohmann::json j = infoJson(scene);
  EXPECT_EQ(j["primitives"], 5);
  EXPECT_EQ(j["kinds"], nlohmann::json({{"sphere", 3}, {"polygon", 2}})) << j["kinds"];
  EXPECT_EQ(j["lights"], 1);
  EXPECT_EQ(j["materials"], 2);
  EXPECT_EQ(j["textured_materials"], 0);
  EXPECT_EQ(j["images"].size(), 0u);
  EXPECT_EQ(j["width"], 320);
  EXPECT_EQ(j["height"], 240);
  expectPoint(j["camera"]["eye"], 0, 1, 10);
  expectPoint(j["camera"]["lookat"], 0, 0, 0);
  expectPoint(j["camera"]["up"], 0, 1, 0);
  EXPECT_EQ(j["camera"]["fov"], 50.0);
  // x: the floor polygon's -5 and 5; y: its -1 and the small polygon's top 6;
  // z: the floor's -5 and 5 (the spheres lie within).
  expectPoint(j["bounds"]["min"], -5, -1, -5);
  expectPoint(j["bounds"]["max"], 5, 6, 5);
  EXPECT_EQ(j["warnings"].size(), 0u);
  EXPECT_EQ(j["files"].size(), 1u);

  // The text says the same.
  const RunResult text = prism("info " + quoted(scene));
  EXPECT_EQ(text.exitCode, 0) << text.err;
  EXPECT_EQ(text.err, "");
  EXPECT_NE(text.out.find("primitives  5: 3 spheres, 2 polygons\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("lights      1\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("materials   2 "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("image       320 x 240\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("camera      eye (0, 1, 10), lookat (0, 0, 0), up (0, 1, 0), fov 50\n"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("bounds      (-5, -1, -5) to (5, 6, 5)\n"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("warnings    0\n"), std::string::npos) << text.out;
}

// Occurrences of the command `word` in a .sc file and the files it includes,
// counted on the text: comments dropped, includes followed relative to the
// file that names them.
int countCommand(const fs::path& file, const std::string& word) {
  const std::string text = std::regex_replace(slurp(file), std::regex("#[^\n]*"), std::string(""));
  const std::regex command("(^|\\s)" + word + "(?=\\s)");
  int count = int(std::distance(std::sregex_iterator(text.begin(), text.end(), command),
                                std::sregex_iterator()));
  const std::regex include("(^|\\s)include\\s+\"?([^\\s\"]+)\"?");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), include);
       it != std::sregex_iterator(); ++it)
    count += countCommand(file.parent_path() / (*it)[2].str(), word);
  return count;
}

TEST_F(Info, CountsOfShippedScenesMatchTheirText) {
  for (const std::string name : {"glass.sc", "chex.sc"}) {
    SCOPED_TRACE(name);
    const fs::path scene = fs::path(PRISM_SOURCE_DIR) / "scenes" / name;
    const int spheres = countCommand(scene, "sphere");
    const int polygons = countCommand(scene, "polygon");
    const int lights = countCommand(scene, "light");
    const nlohmann::json j = infoJson(scene);
    EXPECT_EQ(j["kinds"].value("sphere", 0), spheres);
    EXPECT_EQ(j["kinds"].value("polygon", 0), polygons);
    EXPECT_EQ(j["primitives"], spheres + polygons) << j["kinds"];
    EXPECT_EQ(j["lights"], lights);
    EXPECT_EQ(j["warnings"].size(), 0u);
  }
  // Known independently too: glass.sc's 537 polygons, 6 of each of its two
  // cubes and 50 of the cup; chex.sc's 7530 polygons.
  EXPECT_EQ(countCommand(fs::path(PRISM_SOURCE_DIR) / "scenes/glass.sc", "polygon"), 599);
  EXPECT_EQ(countCommand(fs::path(PRISM_SOURCE_DIR) / "scenes/chex.sc", "polygon"), 7530);
}

TEST_F(Info, ABrokenSceneExitsWith2AndLocatesTheError) {
  const fs::path bad = write("bad.sc", "eye 0 0 4\nsphere 0 0 0 -1\nlight 1 2\n");
  for (const std::string command : {"info", "info --json", "check"}) {
    SCOPED_TRACE(command);
    const RunResult r = prism(command + " " + quoted(bad));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find(bad.string() + ":2:14: error:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(bad.string() + ":3:"), std::string::npos) << r.err;
  }
  EXPECT_EQ(prism("info " + quoted(dir_ / "missing.sc")).exitCode, 2);
  EXPECT_EQ(prism("info").exitCode, 2);
}

TEST_F(Info, CheckIsAnAliasOfInfo) {
  const fs::path scene = write("known.sc", kKnownScene);
  const RunResult info = prism("info " + quoted(scene));
  const RunResult check = prism("check " + quoted(scene));
  EXPECT_EQ(check.exitCode, 0) << check.err;
  EXPECT_EQ(check.out, info.out);
  // Even beside a file named `check`, which `prism FILE` would open in the
  // previewer.
  writeFile(dir_ / "check", "sphere 0 0 0 1\n");
  const RunResult beside = run(dir_, quoted(PRISM_BINARY) + " check known.sc");
  EXPECT_EQ(beside.exitCode, 0) << beside.err;
  EXPECT_NE(beside.out.find("primitives  5"), std::string::npos) << beside.out;
}

// The readers' warnings are part of the description, in the FILE:LINE:COLUMN
// form; the scene still reads, so the exit status is 0.
TEST_F(Info, WarningsAreListedAndTheSceneStillReads) {
  const fs::path obj = write("empty.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  const RunResult text = prism("info " + quoted(obj));
  EXPECT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("warnings    1\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("empty.obj:1:1: warning: the file has no faces"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("bounds      none (no primitives)\n"), std::string::npos) << text.out;
  const nlohmann::json j = infoJson(obj);
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_EQ(j["warnings"][0]["line"], 1);
  EXPECT_EQ(j["warnings"][0]["column"], 1);
  EXPECT_NE(j["warnings"][0]["message"].get<std::string>().find("no faces"), std::string::npos);
  EXPECT_TRUE(j["bounds"].is_null());
  EXPECT_EQ(j["primitives"], 0);
}

} // namespace
