// What the previewer's window computes from the session's progress, without a
// window: the exposure it shows while a render refines (steady, not pumping
// after an edit; locked; offset by EV), the time left (honest about pass 2)
// and counts with thousands separators. Expected values are worked out by
// hand from the progress given.
#include "viewer/live_exposure.h"
#include "viewer/number_text.h"
#include "viewer/progress_estimate.h"
#include "viewer/scene_files.h"

#include "core/render/exposure.h"

#include "test_files.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace prism {
namespace {

SessionProgress coarse(double live, double levels, std::uint64_t restarts = 0) {
  SessionProgress p;
  p.phase = SessionPhase::Coarse;
  p.liveAvgmax = live;
  p.levelsAvgmax = levels;
  p.avgmax = live;
  p.restarts = restarts;
  return p;
}

TEST(LiveExposure, SteadyWhileARenderRefines) {
  LiveExposure e;
  // The very first samples: nothing to hold, the live estimate it is.
  e.update(coarse(0.8, 0.0));
  EXPECT_EQ(e.avgmax(), 0.8);
  EXPECT_FALSE(e.holding());
  // Once a level is complete its avgmax is used, not the drifting live one.
  e.update(coarse(0.9, 0.5));
  EXPECT_EQ(e.avgmax(), 0.5);
  SessionProgress done = coarse(0.6, 0.6);
  done.phase = SessionPhase::Done;
  done.avgmax = 0.625;
  e.update(done);
  EXPECT_EQ(e.avgmax(), 0.625); // pass 1's own, exactly (docs/image-formation.md)
  EXPECT_EQ(e.scale(), exposureScale(0.625));
  EXPECT_TRUE(e.automatic());
  // An edit restarts the render: until its first level is complete the
  // previous value stands (the live estimate over a few tiles pumped).
  e.update(coarse(2.0, 0.0, 1));
  EXPECT_EQ(e.avgmax(), 0.625);
  EXPECT_TRUE(e.holding());
  e.update(coarse(2.1, 1.5, 1));
  EXPECT_EQ(e.avgmax(), 1.5);
  EXPECT_FALSE(e.holding());
}

TEST(LiveExposure, LockedAndOffsetByStops) {
  LiveExposure e;
  e.update(coarse(1.0, 1.0));
  e.setLocked(true);
  e.update(coarse(4.0, 4.0)); // a light was moved closer: four times brighter
  EXPECT_EQ(e.avgmax(), 1.0); // the picture shows it brighter
  EXPECT_EQ(e.scale(), exposureScale(1.0));
  e.setEv(1.0);
  EXPECT_FLOAT_EQ(e.scale(), 2.0f * exposureScale(1.0));
  EXPECT_FALSE(e.automatic());
  e.setEv(0.0);
  e.setLocked(false);
  e.update(coarse(4.0, 4.0));
  EXPECT_EQ(e.avgmax(), 4.0);
  EXPECT_TRUE(e.automatic());
}

SessionProgress at(SessionPhase phase, double elapsed, double pass1, double pass2,
                   double pass1Seconds = 0.0) {
  SessionProgress p;
  p.phase = phase;
  p.elapsedSeconds = elapsed;
  p.pass1Fraction = pass1;
  p.pass2Fraction = pass2;
  p.pass1Seconds = pass1Seconds;
  return p;
}

TEST(ProgressEstimate, HonestAboutPassTwo) {
  ProgressEstimate e;
  // A quarter of pass 1 in 1 s: 3 s more for pass 1; pass 2 unknown.
  e.update(at(SessionPhase::Coarse, 1.0, 0.25, 0.0));
  ASSERT_TRUE(e.pass1RemainingSeconds());
  EXPECT_DOUBLE_EQ(*e.pass1RemainingSeconds(), 3.0);
  EXPECT_FALSE(e.remainingSeconds());
  EXPECT_EQ(e.text(), "elapsed 1.0 s, about 3.0 s left in pass 1, then pass 2");
  // Pass 2, 20% done in 2 s of its own (pass 1 took 4 s): 8 s left.
  e.update(at(SessionPhase::Antialias, 6.0, 1.0, 0.2, 4.0));
  ASSERT_TRUE(e.remainingSeconds());
  EXPECT_DOUBLE_EQ(*e.remainingSeconds(), 8.0);
  EXPECT_DOUBLE_EQ(e.timeFraction(), 6.0 / 14.0);
  // Done in 12 s: pass 2 took 8 s, twice pass 1.
  e.update(at(SessionPhase::Done, 12.0, 1.0, 1.0, 4.0));
  EXPECT_DOUBLE_EQ(*e.remainingSeconds(), 0.0);
  EXPECT_EQ(e.text(), "");
  // The next render knows pass 2 costs twice pass 1: a quarter of pass 1 in
  // 1 s is 4 s of pass 1 and 8 of pass 2, 11 s left.
  SessionProgress next = at(SessionPhase::Coarse, 1.0, 0.25, 0.0);
  next.restarts = 1;
  e.update(next);
  ASSERT_TRUE(e.remainingSeconds());
  EXPECT_DOUBLE_EQ(*e.remainingSeconds(), 11.0);
  EXPECT_DOUBLE_EQ(e.timeFraction(), 1.0 / 12.0);
  EXPECT_EQ(e.text(), "elapsed 1.0 s, about 11 s left");
}

TEST(NumberText, ThousandsSeparators) {
  EXPECT_EQ(withSeparators(0), "0");
  EXPECT_EQ(withSeparators(999), "999");
  EXPECT_EQ(withSeparators(1000), "1,000");
  EXPECT_EQ(withSeparators(1054751), "1,054,751");
  EXPECT_EQ(withSeparators(-1234567), "-1,234,567");
  EXPECT_EQ(withSeparators(-123), "-123");
}

TEST(SceneFiles, AFoldersScenesAndFolders) {
  test::ScratchDir dir;
  for (const char* name : {"b.sc", "a.OBJ", "c.nff", "notes.txt", ".hidden.sc"})
    test::writeFile(dir / name, "");
  std::filesystem::create_directory(dir / "parts");
  std::filesystem::create_directory(dir / ".git");
  const std::vector<FolderEntry> entries = listSceneFolder(dir.path());
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries[0].name, "parts");
  EXPECT_TRUE(entries[0].folder);
  EXPECT_EQ(entries[1].name, "a.OBJ");
  EXPECT_EQ(entries[2].name, "b.sc");
  EXPECT_EQ(entries[3].name, "c.nff");
  EXPECT_FALSE(entries[3].folder);
  EXPECT_TRUE(listSceneFolder(dir / "missing").empty());
}

TEST(SceneFiles, RecentScenesAreKeptNewestFirstOnceEach) {
  test::ScratchDir dir;
  const std::filesystem::path store = dir / "config" / "recent-scenes";
  {
    RecentFiles recent(store);
    EXPECT_TRUE(recent.paths().empty());
    for (int i = 0; i < 12; ++i)
      recent.add(dir / ("s" + std::to_string(i) + ".sc"));
    recent.add(dir / "s5.sc"); // again: moves to the front, not twice
    ASSERT_EQ(recent.paths().size(), RecentFiles::kMaxRecent);
    EXPECT_EQ(recent.paths()[0], (dir / "s5.sc").string());
    EXPECT_EQ(recent.paths()[1], (dir / "s11.sc").string());
    EXPECT_EQ(std::count(recent.paths().begin(), recent.paths().end(), (dir / "s5.sc").string()),
              1);
  }
  // The next session finds them.
  const RecentFiles again(store);
  ASSERT_EQ(again.paths().size(), RecentFiles::kMaxRecent);
  EXPECT_EQ(again.paths()[0], (dir / "s5.sc").string());
}

} // namespace
} // namespace prism
