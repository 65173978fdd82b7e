// Where the previewer's settings sit in a sweep of its scene (the panel's
// Sweep section), worked out from hand-made rows: the current settings' row
// and the Pareto-optimal setting at its cost, or "not in the sweep"; the
// file beside the scene, read silently when missing and with its place when
// malformed.
#include "viewer/sweep_view.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <limits>

namespace prism {
namespace {

using test::ScratchDir;
using test::writeFile;

SweepRow row(SweepSetting setting, double cpu, double psnr, bool pareto = false) {
  SweepRow r;
  r.setting = setting;
  r.cpuSeconds = cpu;
  r.error.psnr = psnr;
  r.pareto = pareto;
  return r;
}

SweepSetting aa(int depth, double thresh, bool jitter = false, double bailout = 0.0) {
  return {
      .antialias = true, .thresh = thresh, .depth = depth, .jitter = jitter, .bailout = bailout};
}

RenderSettings settings(int depth, double thresh, bool jitter = false, bool noAa = false,
                        double bailout = 0.0) {
  RenderSettings s;
  s.maxDepth = depth;
  s.thresh = thresh;
  s.jitter = jitter;
  s.noAa = noAa;
  s.bailout = bailout;
  return s;
}

// A sweep of five settings: the default one (depth 5, threshold 0.1) costs 2 s
// for 35 dB, where depth 3 gives 40 dB for 1.5 s.
LoadedSweep sweep() {
  LoadedSweep s;
  s.path = "scenes/room.sweep.csv";
  SweepRow current = row(aa(5, 0.1), 2.0, 35.0);
  current.error.over2 = 0.0123;
  current.error.worstLevels = 17;
  current.error.worstX = 3;
  current.error.worstY = 40;
  s.rows = {row({.antialias = false, .depth = 1}, 0.2, 20.0, true),
            row(aa(3, 0.1), 1.5, 40.0, true), current,
            row(aa(8, 0.0, false, 0.5), 9.0, std::numeric_limits<double>::infinity(), true),
            row(aa(8, 0.0, true), 12.0, 45.0)};
  return s;
}

TEST(SweepView, TheFileBesideTheScene) {
  EXPECT_EQ(sweepPathBeside("scenes/room.sc"), "scenes/room.sweep.csv");
  EXPECT_EQ(sweepPathBeside("/a/b.c/teapot.nff"), "/a/b.c/teapot.sweep.csv");
  EXPECT_EQ(sweepPathBeside("room.sc"), "room.sweep.csv");
}

TEST(SweepView, TheSweepsNameForTheRenderSettings) {
  EXPECT_EQ(sweepSettingOf(settings(5, 0.1)), aa(5, 0.1));
  EXPECT_EQ(sweepSettingOf(settings(2, 0.3, true, false, 0.5)), aa(2, 0.3, true, 0.5));
  // Without antialiasing jitter does not apply; the threshold is kept but ignored.
  const SweepSetting plain = sweepSettingOf(settings(3, 0.1, true, true, 2.0));
  EXPECT_FALSE(plain.antialias);
  EXPECT_FALSE(plain.jitter);
  EXPECT_EQ(plain.depth, 3);
  EXPECT_EQ(plain.bailout, 2.0);
  // The slider's threshold is a float: 0.1f is read as the 0.1 it shows ...
  EXPECT_EQ(sweepSettingOf(settings(5, double(0.1f))).thresh, 0.1);
  EXPECT_EQ(sweepSettingOf(settings(5, double(0.05f))).thresh, 0.05);
  EXPECT_EQ(sweepSettingOf(settings(5, 0.0)).thresh, 0.0);
  // ... and a double from the command line stays what it is.
  EXPECT_EQ(sweepSettingOf(settings(5, 0.123456789)).thresh, 0.123456789);
}

TEST(SweepView, NothingWithoutASweep) {
  const SweepStatus s = sweepStatus(LoadedSweep{}, settings(5, 0.1));
  EXPECT_FALSE(s.visible);
  EXPECT_TRUE(s.lines.empty());
}

TEST(SweepView, TheCurrentSettingsAndTheBestAtTheirCost) {
  const SweepStatus s = sweepStatus(sweep(), settings(5, double(0.1f)));
  EXPECT_TRUE(s.visible);
  EXPECT_TRUE(s.error.empty());
  ASSERT_TRUE(s.current);
  EXPECT_EQ(s.current->setting, aa(5, 0.1));
  EXPECT_FALSE(s.currentOnFront());
  ASSERT_TRUE(s.best);
  EXPECT_EQ(s.best->setting, aa(3, 0.1)); // cheaper and better
  const std::vector<std::string> want{
      "room.sweep.csv: 5 settings measured",
      "these settings: --depth 5 --thresh 0.1",
      "expected PSNR 35.00 dB",
      "pixels more than 2 levels off: 1.23%",
      "worst pixel: 17 levels off, at (3, 40)",
      "CPU time in the sweep: 2 s",
      "Pareto-optimal at the same cost: --depth 3 --thresh 0.1, 40.00 dB, 1.5 s",
  };
  EXPECT_EQ(s.lines, want);
}

TEST(SweepView, SaysWhenTheCurrentSettingIsOnTheFront) {
  const SweepStatus s = sweepStatus(sweep(), settings(8, 0.0, false, false, 0.5));
  ASSERT_TRUE(s.current && s.best);
  EXPECT_TRUE(s.currentOnFront());
  EXPECT_EQ(s.best->setting, s.current->setting);
  ASSERT_EQ(s.lines.size(), 7u);
  EXPECT_EQ(s.lines[1], "these settings: --depth 8 --thresh 0 --bailout 0.5");
  EXPECT_EQ(s.lines[2], "expected PSNR inf dB (the reference itself)");
  EXPECT_EQ(s.lines[6],
            "on the Pareto front: no setting of the sweep is as cheap and more accurate");

  // The dearest row is worse than a cheaper exact one: the best is the exact one.
  const SweepStatus dear = sweepStatus(sweep(), settings(8, 0.0, true));
  ASSERT_TRUE(dear.current && dear.best);
  EXPECT_FALSE(dear.currentOnFront());
  EXPECT_EQ(dear.best->setting, aa(8, 0.0, false, 0.5));
  EXPECT_EQ(dear.lines.back(), "Pareto-optimal at the same cost: --depth 8 --thresh 0 --bailout "
                               "0.5, inf dB (the reference itself), 9 s");

  // Without antialiasing, whatever the threshold and jitter.
  const SweepStatus plain = sweepStatus(sweep(), settings(1, 0.7, true, true));
  ASSERT_TRUE(plain.current);
  EXPECT_TRUE(plain.currentOnFront());
  EXPECT_EQ(plain.lines[1], "these settings: --depth 1 --no-aa");
}

TEST(SweepView, SettingsTheSweepDidNotMeasure) {
  for (const RenderSettings& r :
       {settings(4, 0.1), settings(5, 0.1, true), settings(5, 0.1, false, false, 2.0),
        settings(5, 0.2), settings(5, 0.1, false, true)}) {
    const SweepStatus s = sweepStatus(sweep(), r);
    EXPECT_TRUE(s.visible);
    EXPECT_FALSE(s.current);
    EXPECT_FALSE(s.best);
    ASSERT_EQ(s.lines.size(), 3u);
    EXPECT_EQ(s.lines[1], "these settings: " + settingOptions(sweepSettingOf(r)));
    EXPECT_EQ(s.lines[2], "not in the sweep");
  }
}

TEST(SweepView, AnUnreadableSweepShowsWhy) {
  LoadedSweep broken;
  broken.path = "room.sweep.csv";
  broken.error = "room.sweep.csv:3:7: cpu_s: expected a number, got 'fast'";
  const SweepStatus s = sweepStatus(broken, settings(5, 0.1));
  EXPECT_TRUE(s.visible);
  EXPECT_EQ(s.error, broken.error);
  EXPECT_EQ(s.lines, std::vector<std::string>({"The sweep table cannot be read:", broken.error}));
}

TEST(SweepView, LoadsTheFileMarksItsFrontAndReportsErrorsWithTheirPlace) {
  ScratchDir dir;
  const std::string path = (dir / "room.sweep.csv").string();
  // Missing: no sweep, no error; unless the user named it.
  EXPECT_FALSE(loadSweep(path, false).present());
  const LoadedSweep named = loadSweep(path, true);
  EXPECT_TRUE(named.present());
  EXPECT_EQ(named.error, path + ": no such file");

  // The file's Pareto column is not trusted: the front is of the rows there are.
  std::vector<SweepRow> rows = sweep().rows;
  for (SweepRow& r : rows)
    r.pareto = !r.pareto;
  writeFile(dir / "room.sweep.csv", formatSweepCsv(rows));
  const LoadedSweep good = loadSweep(path, false);
  EXPECT_EQ(good.path, path);
  EXPECT_EQ(good.error, "");
  ASSERT_EQ(good.rows.size(), 5u);
  for (std::size_t i = 0; i < rows.size(); ++i)
    EXPECT_EQ(good.rows[i].pareto, sweep().rows[i].pareto) << "row " << i;

  writeFile(dir / "room.sweep.csv", formatSweepCsv(rows) + "1,0.1,5\n");
  const LoadedSweep bad = loadSweep(path, false);
  EXPECT_TRUE(bad.rows.empty());
  EXPECT_EQ(bad.error, path + ":7:8: expected 22 fields as in the header, got 3");

  std::filesystem::create_directories(dir / "folder.sweep.csv");
  EXPECT_EQ(loadSweep((dir / "folder.sweep.csv").string(), false).error,
            (dir / "folder.sweep.csv").string() + ": a directory");
}

} // namespace
} // namespace prism
