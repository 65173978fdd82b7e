// The pass schedule on executors of its own: the film does not depend on who
// runs the tiles or in which order, the sink hears every tile in the order of
// the passes, stopping drops unfinished tiles whole, keeping pass 1 traces
// pass 2 only, and the reduction points sit between the passes where a
// distributed executor needs them.
#include "core/render/pass_schedule.h"
#include "tests/render_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace prism {
namespace {

using test::shipped;
using test::smallSettings;

// Runs the items one at a time on the calling thread, in the order given
// (all items in reverse when none is), as `workerCount` workers taking turns.
class SequentialExecutor : public Executor {
public:
  explicit SequentialExecutor(int workerCount = 1) : workerCount_(workerCount) {}
  std::vector<int> order; // item order; empty: reverse
  std::vector<std::string> log;

  int workers() const override { return workerCount_; }
  void forEach(int itemCount, const ItemWork& work, const StopCheck& stop) override {
    log.push_back("forEach");
    std::vector<int> items = order;
    if (items.empty()) {
      items.resize(std::size_t(itemCount));
      std::iota(items.rbegin(), items.rend(), 0);
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (stop && stop()) return;
      work(items[i], int(i % std::size_t(workerCount_)));
    }
  }
  void forEachHere(int itemCount, const ItemWork& work, const StopCheck& stop) override {
    log.push_back("forEachHere");
    for (int item = 0; item < itemCount && !(stop && stop()); ++item)
      work(item, item % workerCount_);
  }
  void sumOverProcesses(ExactSum&) override { log.push_back("sumOverProcesses"); }
  void completePass1(Film&, std::span<const Tile>, const std::vector<std::uint8_t>&) override {
    log.push_back("completePass1");
  }
  void shareMarks(std::vector<std::uint8_t>&) override { log.push_back("shareMarks"); }
  void completeRender(Film&, RayCounts&) override { log.push_back("completeRender"); }

private:
  int workerCount_;
};

// Everything the schedule said, in order.
struct RecordingSink : ScheduleSink {
  std::vector<std::string> events;
  std::vector<TileSamples> tiles;
  double avgmax = -1.0;
  RayCounts counts;
  bool finished = false;

  void levelStarted(int level) override { events.push_back("level " + std::to_string(level)); }
  void tileDone(const TileSamples& tile) override {
    events.push_back("tile pass " + std::to_string(tile.pass));
    tiles.push_back(tile);
  }
  void pass1Complete(double a) override {
    events.push_back("pass1Complete");
    avgmax = a;
  }
  void done(const RayCounts& c) override {
    events.push_back("done");
    counts = c;
    finished = true;
  }
};

struct Fixture {
  explicit Fixture(const char* name, const RenderSettings& s = smallSettings())
      : scene(shipped(name)), accel(makeAccel(scene, AccelKind::Bvh)), settings(s),
        reference(render(scene, *accel, settings)) {}

  Scene scene;
  std::unique_ptr<Accel> accel;
  RenderSettings settings;
  RenderResult reference;
};

void expectFilmOfReference(const Film& film, const RecordingSink& sink, const Fixture& f) {
  EXPECT_TRUE(film.centre == f.reference.film.centre);
  EXPECT_TRUE(film.radiance == f.reference.film.radiance);
  EXPECT_TRUE(film.supersampled == f.reference.film.supersampled);
  EXPECT_EQ(sink.avgmax, f.reference.avgmax);
  EXPECT_EQ(sink.counts, f.reference.counts);
  EXPECT_TRUE(sink.finished);
}

TEST(PassSchedule, AnyExecutorAndAnyLevelsGiveRendersFilm) {
  for (const char* name : {"table.sc", "glass.sc"}) {
    const Fixture f(name);
    ASSERT_GT(f.reference.supersampledPixels, 0) << name; // pass 2 has work to do
    for (int coarsest : {1, 8}) {
      const PassSchedule schedule(f.scene, *f.accel, f.settings, coarsest);
      SequentialExecutor reverse; // one worker, the last tile first
      SequentialExecutor shuffled(3);
      shuffled.order.resize(std::size_t(schedule.tileCount()));
      std::iota(shuffled.order.begin(), shuffled.order.end(), 0);
      std::shuffle(shuffled.order.begin(), shuffled.order.end(), std::mt19937(12));
      for (SequentialExecutor* executor : {&reverse, &shuffled}) {
        Film film(f.settings.width, f.settings.height);
        RecordingSink sink;
        EXPECT_TRUE(schedule.run(film, *executor, sink));
        expectFilmOfReference(film, sink, f);
      }
    }
  }
}

TEST(PassSchedule, TheSinkHearsEveryTileInTheOrderOfThePasses) {
  const Fixture f("glass.sc");
  const PassSchedule schedule(f.scene, *f.accel, f.settings, 8);
  const int tiles = schedule.tileCount();
  ASSERT_EQ(tiles, 6); // 80x60 in tiles of 32
  SequentialExecutor executor;
  Film film(f.settings.width, f.settings.height);
  RecordingSink sink;
  ASSERT_TRUE(schedule.run(film, executor, sink));

  std::vector<std::string> expected;
  for (int level : {8, 4, 2, 1}) {
    expected.push_back("level " + std::to_string(level));
    expected.insert(expected.end(), std::size_t(tiles), "tile pass 1");
  }
  expected.push_back("pass1Complete");
  expected.insert(expected.end(), std::size_t(tiles), "tile pass 2");
  expected.push_back("done");
  EXPECT_EQ(sink.events, expected);
  EXPECT_EQ(executor.log,
            (std::vector<std::string>{"forEach", "forEach", "forEach", "forEach",
                                      "sumOverProcesses", "completePass1", "forEachHere",
                                      "shareMarks", "forEach", "completeRender"}));

  // Each pixel centre once, each supersampled pixel once; the tiles' counts
  // add up to the run's.
  std::vector<int> centres(film.pixelCount(), 0), means(film.pixelCount(), 0);
  RayCounts sum;
  for (const TileSamples& tile : sink.tiles) {
    for (const Sample& sample : tile.samples)
      ++(tile.pass == 1 ? centres : means)[film.index(sample.x, sample.y)];
    sum += tile.counts;
  }
  EXPECT_TRUE(std::all_of(centres.begin(), centres.end(), [](int n) { return n == 1; }));
  for (std::size_t i = 0; i < film.pixelCount(); ++i)
    EXPECT_EQ(means[i], int(film.supersampled[i])) << i;
  EXPECT_EQ(sum, sink.counts);
  EXPECT_EQ(sum, f.reference.counts);
}

TEST(PassSchedule, StoppingDropsTheTileInProgressWhole) {
  const Fixture f("table.sc");
  const PassSchedule schedule(f.scene, *f.accel, f.settings); // pass 1 in 8x8 blocks
  SequentialExecutor executor;
  executor.order = {4, 1, 0, 2, 3, 5};
  const Rgb unset(-1.0f);
  Film film(f.settings.width, f.settings.height);
  std::fill(film.centre.begin(), film.centre.end(), unset);
  RecordingSink sink;
  // Tile 4 (32x28: 16 blocks of 8x8) takes a check before it and one before
  // each block; the 20th check comes before the second block of tile 1.
  int checks = 0;
  EXPECT_FALSE(schedule.run(film, executor, sink, [&] { return ++checks >= 20; }));
  EXPECT_EQ(sink.events, (std::vector<std::string>{"level 1", "tile pass 1"}));
  ASSERT_EQ(sink.tiles.size(), 1u);
  EXPECT_EQ(sink.tiles[0].tile, 4);
  const Tile& done = schedule.tiles()[4];
  for (int y = 0; y < film.height; ++y) {
    for (int x = 0; x < film.width; ++x) {
      const bool inDone = x >= done.x0 && x < done.x1 && y >= done.y0 && y < done.y1;
      const Rgb& centre = film.centre[film.index(x, y)];
      EXPECT_EQ(centre != unset, inDone) << x << "," << y;
      if (inDone) {
        EXPECT_EQ(centre, f.reference.film.centre[film.index(x, y)]);
      }
    }
  }
}

TEST(PassSchedule, KeepingPassOneTracesPassTwoOnly) {
  const Fixture f("glass.sc");
  Film film(f.settings.width, f.settings.height);
  SequentialExecutor executor;
  RecordingSink first;
  ASSERT_TRUE(PassSchedule(f.scene, *f.accel, f.settings, 8).run(film, executor, first));

  // A higher threshold: fewer pixels supersampled, so the first run's extra
  // ones must go back to their centre samples.
  RenderSettings s = f.settings;
  s.thresh = 0.3;
  s.jitter = true;
  const Fixture changed("glass.sc", s);
  ASSERT_LT(changed.reference.supersampledPixels, f.reference.supersampledPixels);
  RecordingSink second;
  ASSERT_TRUE(PassSchedule(f.scene, *f.accel, s, 8).run(film, executor, second, {}, Pass1::Keep));
  EXPECT_EQ(second.counts.eyePrimary, 0u);
  EXPECT_EQ(second.counts.eyeAntialias, 16u * std::uint64_t(changed.reference.supersampledPixels));
  EXPECT_EQ(second.events.front(), "pass1Complete"); // no level, no pass-1 tile
  // The rays of pass 2 alone: the whole render's less pass 1's.
  RayCounts pass1;
  for (const TileSamples& tile : first.tiles)
    if (tile.pass == 1) pass1 += tile.counts;
  RayCounts whole = pass1;
  whole += second.counts;
  EXPECT_EQ(whole, changed.reference.counts);
  EXPECT_TRUE(film.radiance == changed.reference.film.radiance);
  EXPECT_TRUE(film.supersampled == changed.reference.film.supersampled);
  EXPECT_EQ(second.avgmax, changed.reference.avgmax);
  EXPECT_TRUE(second.finished);
}

// One of two processes: it traces the even tiles only, and at reduction
// point 1 receives the centres of the odd ones and their part of avgmax's
// sum (here from a finished render, standing for the other process).
class HalfExecutor final : public SequentialExecutor {
public:
  HalfExecutor(const Film* others, const std::vector<Tile>& tiles)
      : others_(others), tiles_(tiles) {
    for (int i = 0; i < int(tiles.size()); i += 2)
      order.push_back(i);
  }
  void sumOverProcesses(ExactSum& sum) override {
    if (!others_) return;
    for (std::size_t t = 1; t < tiles_.size(); t += 2)
      for (int y = tiles_[t].y0; y < tiles_[t].y1; ++y)
        for (int x = tiles_[t].x0; x < tiles_[t].x1; ++x) {
          const Rgb& c = others_->centre[others_->index(x, y)];
          sum.add(std::max({c.r, c.g, c.b}));
        }
  }
  void completePass1(Film& film, std::span<const Tile>, const std::vector<std::uint8_t>&) override {
    if (!others_) return;
    for (std::size_t t = 1; t < tiles_.size(); t += 2)
      for (int y = tiles_[t].y0; y < tiles_[t].y1; ++y)
        for (int x = tiles_[t].x0; x < tiles_[t].x1; ++x)
          film.centre[film.index(x, y)] = others_->centre[film.index(x, y)];
  }

private:
  const Film* others_;
  const std::vector<Tile>& tiles_;
};

TEST(PassSchedule, ReductionPointOneGivesPassTwoEveryCentre) {
  const Fixture f("glass.sc");
  const PassSchedule schedule(f.scene, *f.accel, f.settings);
  for (const bool exchange : {true, false}) {
    HalfExecutor executor(exchange ? &f.reference.film : nullptr, schedule.tiles());
    Film film(f.settings.width, f.settings.height);
    RecordingSink sink;
    ASSERT_TRUE(schedule.run(film, executor, sink));
    // Pass 2 on the even tiles decides from neighbours in odd tiles, and
    // avgmax is over every pixel: right only with the centres exchanged.
    bool same = sink.avgmax == f.reference.avgmax;
    for (std::size_t t = 0; t < schedule.tiles().size(); t += 2)
      for (int y = schedule.tiles()[t].y0; y < schedule.tiles()[t].y1; ++y)
        for (int x = schedule.tiles()[t].x0; x < schedule.tiles()[t].x1; ++x)
          same = same &&
                 film.radiance[film.index(x, y)] == f.reference.film.radiance[film.index(x, y)];
    EXPECT_EQ(same, exchange);
  }
}

TEST(PassSchedule, IsNewAtLevelCoversEveryPixelOnceForAnyFirstLevel) {
  for (int coarsest : {1, 2, 8, 16}) {
    for (int y = 0; y < 37; ++y) {
      for (int x = 0; x < 53; ++x) {
        int levels = 0;
        for (int level = coarsest; level >= 1; level /= 2)
          levels += isNewAtLevel(x, y, level, coarsest);
        EXPECT_EQ(levels, 1) << x << "," << y << " from " << coarsest;
      }
    }
  }
  EXPECT_TRUE(isNewAtLevel(2, 2, 1, 1)); // one level: every pixel
  EXPECT_FALSE(isNewAtLevel(2, 2, 1, 2));
}

TEST(PassSchedule, TheFirstLevelIsAPowerOfTwo) {
  const Scene scene = shipped("chex.sc");
  const auto accel = makeAccel(scene, AccelKind::Bvh);
  for (int coarsest : {0, 3, 6, -8})
    EXPECT_THROW(PassSchedule(scene, *accel, smallSettings(), coarsest), std::invalid_argument)
        << coarsest;
  EXPECT_NO_THROW(PassSchedule(scene, *accel, smallSettings(), 16));
}

} // namespace
} // namespace prism
